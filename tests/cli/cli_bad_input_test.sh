#!/usr/bin/env bash
# Bad input on the command line: each case must exit non-zero, print exactly one line on
# stderr that contains the expected words, and leave no output file behind. Each expected
# message must appear in docs/errors.md, and each message that table credits to cli_bad_input
# must be tried here, so the table cannot drift from the tests.
#   usage: cli_bad_input_test.sh HEXGAIT DATA_DIR ERRORS_MD [SHARD/SHARDS | sample]
# SHARD/SHARDS (e.g. 1/2) runs every SHARDS-th case, so CTest can spread the cases over the
# cores; `sample` runs the first case of every class (each commented block below) and every
# fifth, for the quick tier (scripts/test.sh --quick). Either way every case's message is still
# checked against docs/errors.md.
set -u
selection=${4:-1/1}
hexgait=$(realpath "$1")
errors_md=$(realpath "$3")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
cases=0
ran=0
tried=()  # every expected message, for the check against docs/errors.md
first_in_class=1
section() { first_in_class=1; }  # a new class of cases begins

# Whether case number $cases runs under $selection.
selected() {
  if [ "$selection" = sample ]; then
    [ "$first_in_class" -eq 1 ] || [ $(((cases - 1) % 5)) -eq 0 ]
  else
    local shard=${selection%/*} shards=${selection#*/}
    [ $(((cases - 1) % shards)) -eq $((shard - 1)) ]
  fi
}

# expect_error "expected text" ARGS...   (run from $work; checks no new files appear in $work/out)
# With WITHIN=SECONDS set, the error must also come within that time: checked before the work.
expect_error() {
  local expected=$1
  shift
  cases=$((cases + 1))
  tried+=("$expected")
  if ! grep -qF -- "\`$expected\`" "$errors_md"; then
    echo "FAIL: '$expected' is not in docs/errors.md"; failures=$((failures + 1))
  fi
  selected || return 0
  first_in_class=0
  ran=$((ran + 1))
  mkdir -p "$work/out"
  local before after
  before=$(find "$work/out" | sort)
  timeout "${WITHIN:-0}" "$hexgait" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  after=$(find "$work/out" | sort)
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ "$code" -eq 0 ]; then
    echo "FAIL: exit 0 for: $*"; failures=$((failures + 1))
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL: $lines stderr lines for: $*"; cat "$work/stderr"; failures=$((failures + 1))
  elif ! grep -qF -- "$expected" "$work/stderr"; then
    echo "FAIL: expected '$expected' for: $*"; cat "$work/stderr"; failures=$((failures + 1))
  elif [ "$before" != "$after" ]; then
    echo "FAIL: files left behind for: $*"; echo "$after"; failures=$((failures + 1))
  fi
}

# Input files made from the built-in creature.
"$hexgait" simulate --time 1 --json >/dev/null || { echo "FAIL: hexgait does not run"; exit 1; }
# Absolute: the cases below run in $work, and the script may be given by a relative path.
here=$(realpath "$(dirname "$0")")
asset_dir=$here/../../assets
edit_json() {  # edit_json OUT PYTHON-STATEMENTS-ON-d [SOURCE-JSON]
  python3 - "${3:-$asset_dir/hexapod.json}" "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[3])
open(sys.argv[2], "w").write(json.dumps(d))
PY
}
edit_motor() {  # edit_motor OUT PYTHON-STATEMENTS-ON-d
  edit_json "$1" "$2" "$asset_dir/metachronal.json"
}
edit_json "$work/p99.json" 'd["springs"][5]["ends"][1] = 99'
edit_json "$work/negmass.json" 'd["particles"][3]["mass"] = -2.0'
edit_json "$work/missing.json" 'del d["springs"][0]["stiffness"]'
edit_json "$work/stiff.json" 'd["springs"][0]["stiffness"] *= 2'
python3 -c "import sys; t=open(sys.argv[1]).read(); open(sys.argv[2],'w').write(t.replace('\"mass\": 1.0', '\"mass\": NaN', 1))" \
  "$asset_dir/hexapod.json" "$work/nan.json"
: >"$work/empty.json"
"$hexgait" evolve --generations 1 --time 5 --out "$work/run" --quiet
"$hexgait" evolve --generations 1 --time 5 --creature wedge --out "$work/wedgerun" --quiet
# A small repertoire of 200-time-unit gaits, for adapt.
"$hexgait" repertoire --evaluations 60 --batch 20 --time 200 --no-movie --compare-ga 0 --quiet \
  --out "$work/rep" >/dev/null
# Its copy whose recorded output choices were edited badly.
cp -r "$work/rep" "$work/rep_outputs"
printf '{"--showcase": 40}\n' >"$work/rep_outputs/outputs.json"
head -n -1 "$work/run/best.genome" >"$work/short.genome"
sed '$ s/ [-0-9]*$/ 9/' "$work/run/best.genome" >"$work/range.genome"

# More creature files: one defect each.
edit_json "$work/extra.json" 'd["particles"][0]["colour"] = "red"'
edit_json "$work/type.json" 'd["springs"][0]["stiffness"] = "stiff"'
edit_json "$work/zeromass.json" 'd["particles"][0]["mass"] = 0'
edit_json "$work/tinymass.json" 'd["particles"][0]["mass"] = 1e-320'
edit_json "$work/zerok.json" 'd["springs"][2]["stiffness"] = 0'
edit_json "$work/negdamp.json" 'd["springs"][2]["damping"] = -1'
edit_json "$work/self.json" 'd["springs"][0]["ends"] = [4, 4]'
edit_json "$work/dup.json" 's = dict(d["springs"][0]); s["name"] = "copy"; s["ends"] = s["ends"][::-1]; d["springs"].append(s)'
edit_json "$work/dupname.json" 'd["springs"][1]["name"] = d["springs"][0]["name"]'
edit_json "$work/poly99.json" 'd["polygons"][0]["vertices"][0] = 99'
edit_json "$work/poly2.json" 'd["polygons"][0]["vertices"] = [0, 1]'
edit_json "$work/skinsum.json" 'd["skin_vertices"][2]["blend"][0][1] = 0.5'
edit_json "$work/skindup.json" 'd["skin_vertices"][0]["blend"][1][0] = d["skin_vertices"][0]["blend"][0][0]'
edit_json "$work/skin99.json" 'd["skin_vertices"][0]["blend"][0][0] = 99'
edit_json "$work/skinterms.json" 'd["skin_vertices"][0]["blend"] = [[i, 0.1] for i in range(10)]'
edit_json "$work/skinweight.json" 'd["skin_vertices"][0]["blend"] = [[0, 1e6], [1, 1 - 1e6]]'
edit_json "$work/foot99.json" 'd["legs"][0]["foot"] = 99'
edit_json "$work/noleg.json" 'next(s for s in d["springs"] if s["leg"])["leg"] = "tail"'
edit_json "$work/legmissing.json" 'del d["springs"][0]["leg"]'
edit_json "$work/array.json" 'd = [d]'
edit_json "$work/far.json" 'd["particles"][0]["position"][0] = 1e300'
edit_json "$work/bigindex.json" 'd["springs"][0]["ends"][0] = 18446744073709551615'
sed '0,/"stiffness": [0-9.]*/s//"stiffness": 1e400/' "$asset_dir/hexapod.json" >"$work/inf.json"
python3 -c "print('[' * 100 + ']' * 100)" >"$work/deep.json"
printf '{"name": "\x00\x01\x02\xff"}' >"$work/binary.json"
printf '{"name": "caf\xe9"}\n' >"$work/latin1.json"
head -c 17000000 /dev/zero | tr '\0' ' ' >"$work/huge.json"
# Motor programs.
edit_motor "$work/m_leg.json" 'd["instructions"][0]["leg"] = "tail"'
edit_motor "$work/m_time.json" 'd["instructions"][0]["time"] = d["cycle_period"]'
edit_motor "$work/m_pos.json" 'd["instructions"][0]["position"] = "dance"'
edit_motor "$work/m_nopos.json" 'd["positions"] = []'
edit_motor "$work/m_unused.json" 'd["positions"].append({"name": "spare", "foot_offset": [0, 0, 0]})'
edit_motor "$work/m_noinstr.json" 'leg = d["instructions"][0]["leg"]; d["instructions"] = [i for i in d["instructions"] if i["leg"] != leg]'
edit_motor "$work/m_extra.json" 'd["tempo"] = 2'
head -c 200 "$asset_dir/metachronal.json" >"$work/m_cut.json"
# Genomes (the full layout, from the evolve run above).
genome=$work/run/best.genome
sed '$ s/ [-0-9]*$//' "$genome" >"$work/words.genome"
sed '$ s/ [-0-9]*$/ 2.5/' "$genome" >"$work/float.genome"
sed '$ s/^[^ ]*/no_such_spring/' "$genome" >"$work/spring.genome"
{ cat "$genome"; tail -n 1 "$genome"; } >"$work/twice.genome"
grep -v '^layout' "$genome" >"$work/nolayout.genome"
sed 's/^layout full/layout symmetric/' "$genome" >"$work/layout.genome"
{ cat "$genome"; printf '\x00\x01'; } >"$work/binary.genome"
: >"$work/empty.genome"

cd "$work" || exit 1
section "numbers and flags"
expect_error "--time must be a positive" simulate --time 0
expect_error "--time must be a positive" simulate --time -5
expect_error "--dt must be a positive" simulate --dt 0
expect_error "--dt must be a positive" evolve --dt -0.001 --out out/e
expect_error "--dt must be a positive" inspect --dt nan
expect_error "--dt must be at most 1" inspect --dt 5
expect_error "Could not convert: --time = abc" simulate --time abc
expect_error "not expected" simulate --bogus
expect_error "unknown integrator 'rk9'" simulate --integrator rk9
expect_error "--gl: vulkan not in" still --gl vulkan --out out/s.png
HEXGAIT_GL=vulkan expect_error "HEXGAIT_GL: unknown backend 'vulkan'" render --time 1 --out out/m.mp4
# Checked before the evaluations (MAP-Elites, the paper's GA), not after them.
HEXGAIT_GL=vulkan expect_error "unknown backend 'vulkan' (choose" repertoire --evaluations 100 --batch 50 --out out/r
HEXGAIT_GL=vulkan expect_error "unknown backend 'vulkan' (choose" movie --time 5 --out out/mv
# A still of a late moment: before the minute of simulation it needs, not after it.
WITHIN=10 HEXGAIT_GL=vulkan expect_error "unknown backend 'vulkan' (choose" still --time 900000 --out out/s.png
expect_error "excludes" simulate --unoptimized --genome "$work/run/best.genome"
expect_error "--population must be at least 2" evolve --population 1 --out out/e
expect_error "--generations must be at least 1" evolve --generations 0 --out out/e
expect_error "--threads must be in" evolve --threads -1 --out out/e
expect_error "--batch-lanes must be in" evolve --batch-lanes 17 --out out/e
expect_error "--precision: half not in {double,float}" evolve --precision half --out out/e
expect_error "--precision float needs --integrator euler" evolve --precision float --integrator rk4 --out out/e
expect_error "--seconds must be in" bench speed --seconds 0
expect_error "--repeats must be in" bench speed --repeats 0
expect_error "--genomes must be in" bench early-stop --genomes 0
expect_error "expected rank counts from 1 to 64" bench scale --ranks 1,0
expect_error "expected rank counts from 1 to 1000000" bench scale --model-ranks 16,0
expect_error "--model-evaluations must be in" bench scale --model-evaluations -5
expect_error "runs backwards" sweep --seeds 5-1 --out out/sw
expect_error "appears twice" sweep --seeds 1-3,2 --out out/sw
expect_error "is not a seed" sweep --seeds 1-x --out out/sw
expect_error "expected seeds like 1-20" sweep --seeds 1, --out out/sw
expect_error "--horizon must be from 2 to --long" endurance --genome "$work/run/best.genome" --horizon 1 --out out/en
expect_error "--jitter must be from 0 to 0.5" endurance --genome "$work/run/best.genome" --jitter 0.7 --out out/en
expect_error "--slope must be from 0 (none) to under 45 degrees" endurance --genome "$work/run/best.genome" --slope 50 --out out/en
expect_error "unknown integrator 'rk9'" endurance --genome "$work/run/best.genome" --other-integrator rk9 --out out/en
expect_error "pass --allow-long to run it anyway" endurance --genome "$work/run/best.genome" --step-factor 1e-9 --random 0 --out out/en
expect_error "would replace the input --run" endurance --run "$work/run" --out "$work/run"
expect_error "--descriptor 'speed': unknown (known: duty, pairs)" repertoire --descriptor speed --out out/rep
expect_error "more than 1000000 cells" repertoire --bins 11 --out out/rep
expect_error "--batch must be in [1, 100000]" repertoire --batch 0 --out out/rep
expect_error "--compare-ga must be at least 2" repertoire --compare-ga 1 --out out/rep
expect_error "--algorithm 'cma-es' is not one of map-elites, cma-mae, iso-line" repertoire --algorithm cma-es --out out/rep
expect_error "--sigma is not a parameter of map-elites" repertoire --sigma 1 --out out/rep
expect_error "--learning-rate must be in [0, 1] for cma-mae" repertoire --algorithm cma-mae --learning-rate 2 --out out/rep
expect_error "--emitters must be a whole number" repertoire --algorithm cma-mae --emitters 2.5 --out out/rep
expect_error "--batch must be at least 2 x --emitters for cma-mae (50)" repertoire --algorithm cma-mae --batch 40 --evaluations 100 --out out/rep
expect_error "--sigma cannot be combined with --resume" repertoire --resume "$work/run" --sigma 1
expect_error "--no-confirm needs --precision float" repertoire --precision double --no-confirm --out out/rep
expect_error "--no-confirm needs --precision float" repertoire --no-confirm --out out/rep
expect_error "--precision float needs --integrator euler" repertoire --precision float --integrator rk4 --evaluations 100 --out out/rep
expect_error "no archive.json there" repertoire --resume "$work/run"
expect_error "cannot be combined with --resume" repertoire --resume "$work/run" --seed 2
expect_error "outputs.json: [json.exception.out_of_range" repertoire --resume "$work/rep_outputs"
expect_error "was not written by hexgait repertoire" repertoire --out "$work/run" --evaluations 10
expect_error "--population must be in [1, 1000000]" bench scale --population 0
expect_error "--bandwidth-gbs must be in" bench scale --bandwidth-gbs 0
expect_error "A subcommand is required" bench
expect_error "particle index 99 out of range" simulate --creature "$work/p99.json"
expect_error "must be positive" simulate --creature "$work/negmass.json"
expect_error "missing field 'stiffness'" simulate --creature "$work/missing.json"
expect_error "malformed JSON at line" simulate --creature "$work/nan.json"
expect_error "file is empty" simulate --creature "$work/empty.json"
expect_error "is a directory" simulate --creature "$work"
expect_error "no such file" simulate --creature "$work/nope.json"
section
expect_error "unknown leg 'right_fornt' (legs: right_rear, right_middle, right_front" simulate --damage right_fornt:weak=0.2
expect_error "unknown kind 'broken' (kinds: weak=F, locked, short=F, lost)" simulate --damage right_front:broken
expect_error "factor 2 is outside [0.01, 1] for weak" still --damage right_front:weak=2 --out out/s.png
expect_error "factor 5e-324 is outside [0.01, 1] for weak" simulate --damage right_front:weak=5e-324
expect_error "factor 0.3 is outside [0.5, 1] for short" render --damage left_rear:short=0.3 --out out/g.mp4
expect_error "weak needs a factor (weak=F, F in [0.01, 1])" simulate --damage right_front:weak
expect_error "factor 'x' is not a number" repertoire --damage right_front:weak=x --out out/rep
expect_error "locked takes no factor" simulate --damage right_front:locked=1
expect_error "lost takes no factor" still --damage right_front:lost=1 --out out/s.png
expect_error "damages leg right_front twice with locked" evolve --damage right_front:locked,right_front:locked --out out/e
expect_error "must be LEG:KIND" simulate --damage right_front
expect_error "has 119 genes" simulate --genome "$work/short.genome"
expect_error "outside [-8, 7]" simulate --genome "$work/range.genome"
expect_error "does not exist" simulate --csv "$work/no/such/dir/trace.csv"
expect_error "no such file" evolve --motor "$work/nope.json" --out out/e
expect_error "expected WIDTHxHEIGHT" still --size big --out out/s.png
expect_error "must be between 16 and 7680" still --size 8x8 --out out/s.png
expect_error "does not exist" still --out "$work/no/such/dir/s.png"
touch "$work/plain_file"
expect_error "is a file, not a folder" still --out "$work/plain_file/s.png"
expect_error "--time must be between" still --time -1 --out out/s.png
expect_error "needs even width and height" render --size 641x360 --time 5 --out out/m.mp4
expect_error "--fps must be between 1 and 240" render --fps 0 --time 5 --out out/m.mp4
expect_error "does not exist" render --time 5 --out "$work/no/such/dir/m.mp4"
expect_error "expected WIDTHxHEIGHT" render --size hd --time 5 --out out/m.mp4
expect_error "--fps must be between 1 and 240" render --fps 1000 --time 5 --out out/m.mp4
expect_error "--msaa must be 0, 2, 4 or 8" render --msaa 3 --time 5 --out out/m.mp4
expect_error "--preset 'warp': not an x264 preset" render --preset warp --time 5 --out out/m.mp4
expect_error "--crf must be between 0 and 51" movie --crf 52 --time 5 --out out
expect_error "--speed must be a positive" render --speed -1 --time 5 --out out/m.mp4
expect_error "is under one step a frame: at --dt 0.0025 and --fps 30 the slowest is 0.075" render --speed 0.01 --time 5 --out out/m.mp4
mkdir -p "$work/photos" && echo keep >"$work/photos/holiday.png"
expect_error "(no .hexgait-frames)" render --frames "$work/photos" --time 5 --out out/m.mp4
expect_error "folder 'nope' does not exist" render --frames nope/frames --time 5 --out out/m.mp4
expect_error "no best.genome there" movie --run "$work" --time 5 --out out/movies
expect_error "needs even width and height" movie --run "$work/run" --size 320x241 --out out/movies
expect_error "--msaa must be 0, 2, 4 or 8" still --msaa 5 --out out/s.png
section
# Cameras and gait cues: the same checks in still, render, movie, filmstrip and figures.
expect_error "unknown view" still --view sideways --out out/s.png
expect_error "unknown view" render --view birdseye --time 5 --out out/m.mp4
expect_error "unknown view" figures --view nope --out out/figs
expect_error "use follow, x or fixed" still --track y --out out/s.png
expect_error "use follow, x or fixed" render --track orbit --time 5 --out out/m.mp4
expect_error "needs three numbers X,Y,Z" still --camera "eye=1,2" --out out/s.png
expect_error "needs three numbers X,Y,Z" render --camera "target=0,0,x" --time 5 --out out/m.mp4
expect_error "fov must be between 5 and 120" still --camera "fov=170" --out out/s.png
expect_error "unknown key 'zoom'" still --camera "zoom=2" --out out/s.png
expect_error "is not KEY=VALUE" still --camera "eye" --out out/s.png
# A camera that sees nothing of the creature is refused before any work (a far eye is not: the
# depth range follows it).
expect_error "the frame would show nothing: the creature is outside the field of view" still --camera "target=0,0,80" --out out/s.png
expect_error "the frame would show nothing: the creature is outside the field of view" movie --camera "eye=-1,0,-0.05;target=0,0,-50" --time 1 --out out/m.mp4
expect_error "the frame would show nothing" filmstrip --camera "target=0,60,0" --out out/f.png
expect_error "eye given twice" still --camera "eye=1,1,1;eye=2,2,2" --out out/s.png
expect_error "eye must be away from the target" still --camera "eye=0,0,0" --out out/s.png
expect_error "unknown cue 'shadows'" render --cues footprints,shadows --time 5 --out out/m.mp4
expect_error "unknown cue ''" still --cues "trail," --out out/s.png
expect_error "--frames must be between 2 and 24" filmstrip --frames 1 --out out/f.png
section
# Browser replays: the run's length, the page's size, where the genome comes from.
expect_error "--time must be greater than 0 and at most 1e6" replay --time 0 --out out/r.html
expect_error "a replay holds at most 9000 frames" replay --time 500000 --out out/r.html
expect_error "expected a name ending in .html" replay --out out/r.png
expect_error "give --run, --genome or --unoptimized, not two" replay --run "$work/run" --unoptimized --out out/r.html
expect_error "no best.genome there (make one with 'hexgait evolve" replay --run "$work" --out out/r.html
expect_error "unknown view" replay --view below --out out/r.html
expect_error "unknown cue 'legs'" replay --cues legs --out out/r.html
section
# Adapting to damage: the damage, the repertoire, and a damage nothing survives.
all_weak=right_front:weak=0.01,left_front:weak=0.01,right_middle:weak=0.01,left_middle:weak=0.01,right_rear:weak=0.01,left_rear:weak=0.01
expect_error "--damage is required" adapt --repertoire "$work/rep" --out out/a
expect_error "unknown leg 'right_fore' (legs: right_rear" adapt --repertoire "$work/rep" --damage right_fore:weak=0.2 --out out/a
expect_error "factor 1.5 is outside [0.01, 1] for weak" adapt --repertoire "$work/rep" --damage right_front:weak=1.5 --out out/a
expect_error "contradicts --repertoire" adapt --repertoire "$work/rep" --creature wedge --damage right_front:weak=0.2 --out out/a
expect_error "no archive.json there" adapt --repertoire "$work/run" --damage right_front:weak=0.2 --out out/a
expect_error "elites falls on the damaged creature" adapt --repertoire "$work/rep" --damage "$all_weak" --no-movie --out out/a
expect_error "--stop must be in (0, 1]" adapt --repertoire "$work/rep" --damage right_front:weak=0.2 --stop 1.5 --out out/a
expect_error "--normalise must be none, best or spread (got 'max')" adapt --repertoire "$work/rep" --damage right_front:weak=0.2 --normalise max --out out/a
expect_error "--cycle must be between 1 and 10000" filmstrip --cycle 0 --out out/f.png
expect_error "--frames x width must be at most 16384" filmstrip --frames 24 --size 1000x300 --out out/f.png
expect_error "unknown view" filmstrip --view under --out out/f.png
expect_error "--population cannot be combined with --resume" evolve --resume "$work/run" --population 8
expect_error "--mutation-rate cannot be combined with --resume" evolve --resume "$work/run" --mutation-rate 0.1
expect_error "no checkpoint.json there" evolve --resume "$work"
expect_error "that run is complete" evolve --resume "$work/run"
expect_error "different creature or motor program" evolve --resume "$work/run" --creature "$work/stiff.json"
section
# A wedge run's checkpoint names its creature: resuming without --creature reloads the wedge (the
# fingerprint matches, so the next check is reached), and the hexapod is refused.
expect_error "that run is complete" evolve --resume "$work/wedgerun"
expect_error "different creature or motor program" evolve --resume "$work/run" --creature wedge
expect_error "different creature or motor program" evolve --resume "$work/run" --damage right_front:weak=0.5
section
# Creature files.
expect_error "unknown field 'colour'" simulate --creature "$work/extra.json"
expect_error "expected a number, got string" simulate --creature "$work/type.json"
expect_error "mass: must be positive" simulate --creature "$work/zeromass.json"
expect_error "must be between 1e-6 and 1e6" simulate --creature "$work/tinymass.json"
expect_error "stiffness: must be positive" simulate --creature "$work/zerok.json"
expect_error "damping: must not be negative" simulate --creature "$work/negdamp.json"
expect_error "cannot join particle 4 to itself" simulate --creature "$work/self.json"
expect_error "duplicate spring between particles" simulate --creature "$work/dup.json"
expect_error "duplicate spring name" simulate --creature "$work/dupname.json"
expect_error "polygons[0].vertices[0]: vertex index 99 out of range" simulate --creature "$work/poly99.json"
expect_error "skin_vertices[2].blend: weights sum to" simulate --creature "$work/skinsum.json"
expect_error "appears twice in one blend" simulate --creature "$work/skindup.json"
expect_error "skin_vertices[0].blend[0][0]: particle index 99 out of range" simulate --creature "$work/skin99.json"
expect_error "expected 1 to 8 [particle, weight] terms" simulate --creature "$work/skinterms.json"
expect_error "weight must be a finite number within +-1000" simulate --creature "$work/skinweight.json"
expect_error "not a built-in creature (hexapod, wedge)" simulate --creature beetle
expect_error "a polygon needs at least 3 vertices" simulate --creature "$work/poly2.json"
expect_error "legs[0].foot: particle index 99 out of range" simulate --creature "$work/foot99.json"
expect_error "no leg named 'tail'" simulate --creature "$work/noleg.json"
expect_error "missing field 'leg'" simulate --creature "$work/legmissing.json"
expect_error "top level: expected an object" simulate --creature "$work/array.json"
expect_error "coordinates must be within" simulate --creature "$work/far.json"
expect_error "integer out of range" simulate --creature "$work/bigindex.json"
expect_error "malformed JSON: number overflow" simulate --creature "$work/inf.json"
expect_error "JSON nested deeper than 32 levels" simulate --creature "$work/deep.json"
expect_error "not a text file (control byte" simulate --creature "$work/binary.json"
expect_error "not a text file (invalid UTF-8" simulate --creature "$work/latin1.json"
expect_error "file is larger than 16 MB" simulate --creature "$work/huge.json"
expect_error "is a device, expected a regular file" simulate --creature /dev/zero
section
# Motor programs.
expect_error "the creature has no leg named 'tail'" simulate --motor "$work/m_leg.json"
expect_error "time: must be below cycle_period" simulate --motor "$work/m_time.json"
expect_error "no position named 'dance'" simulate --motor "$work/m_pos.json"
expect_error "expected 1 to 16 positions, got 0" simulate --motor "$work/m_nopos.json"
expect_error "position 'spare' is never used" simulate --motor "$work/m_unused.json"
expect_error "has no instructions (nor has its mirror)" simulate --motor "$work/m_noinstr.json"
expect_error "unknown field 'tempo'" simulate --motor "$work/m_extra.json"
expect_error "malformed JSON at line" simulate --motor "$work/m_cut.json"
section
# Genome files.
expect_error "expected '<spring> <position> <gene>', got 2 words" simulate --genome "$work/words.genome"
expect_error "gene value '2.5' is not an integer" simulate --genome "$work/float.genome"
expect_error "no gene for spring 'no_such_spring'" simulate --genome "$work/spring.genome"
expect_error "already given on line" simulate --genome "$work/twice.genome"
expect_error "expected 'layout full' or 'layout symmetric'" simulate --genome "$work/nolayout.genome"
expect_error "no gene for spring" simulate --genome "$work/layout.genome"
expect_error "not a text file (control byte" simulate --genome "$work/binary.genome"
expect_error "file is empty" simulate --genome "$work/empty.genome"
expect_error "is a directory" simulate --genome "$work"
section
# Flags.
expect_error "--time must be a positive" simulate --time inf
expect_error "--time must be a positive" simulate --time nan
expect_error "--dt must be at most 1" simulate --dt 2
expect_error "--time / --dt is more than 1e15 steps" simulate --time 1e10 --dt 1e-6
expect_error "--csv-interval must be between --dt and --time" simulate --csv out/t.csv --csv-interval 0
expect_error "--population must be at most 100000" evolve --population 100001 --out out/e
expect_error "--generations must be at most 100000" evolve --generations 100001 --out out/e
expect_error "--crossover-rate must be in [0, 1] for ga" evolve --crossover-rate 1.5 --out out/e
expect_error "--mutation-rate must be in [0, 1] for ga" evolve --mutation-rate -0.1 --out out/e
expect_error "--initial-mutation-rate must be in [0, 1] for ga" evolve --initial-mutation-rate 2 --out out/e
expect_error "--elites must be in [0, population - 1]" evolve --population 4 --elites 4 --out out/e
expect_error "--algorithm: nope not in {ga,cmaes}" evolve --algorithm nope --out out/e
expect_error "--sigma must be in [0.001, 16] for cmaes" evolve --algorithm cmaes --sigma 0 --out out/e
expect_error "--sigma is not a parameter of ga" evolve --sigma 1 --out out/e
expect_error "--out: the path is not UTF-8 text" evolve --out "out/$(printf 'run-\377')"
expect_error "--elites is not a parameter of cmaes" evolve --algorithm cmaes --elites 2 --out out/e
expect_error "--elites must be a whole number" evolve --elites 1.5 --out out/e
expect_error "--population must be at least 4 for cmaes" evolve --algorithm cmaes --population 2 --out out/e
expect_error "--threads must be in" evolve --threads 5000 --out out/e
expect_error "--time must be a positive" evolve --time 0 --out out/e
expect_error "--seed: must be a non-negative integer" evolve --seed -1 --out out/e
expect_error "--seed: must be a non-negative integer" movie --seed -5 --out out/movies
expect_error "--seed: must be a non-negative integer" bench scale --seed -1
expect_error "--seed: must be a non-negative integer" bench stability --seed -1
expect_error "--time must be between 0 and 1e6" still --time nan --out out/s.png
expect_error "each side must be between 16 and 7680" render --size 0x0 --time 5 --out out/m.mp4
expect_error "--fps must be between 1 and 240" movie --run "$work/run" --fps 0 --out out/movies
expect_error "--repeats must be 1 to 100" bench movie --repeats 0
section
# Outputs that would destroy an input (the same file by another name, a hard link, a folder
# replaced whole), empty values, and output paths that are not regular files.
cp "$genome" "$work/g.genome" && ln "$work/g.genome" "$work/hard.genome"
cp "$asset_dir/hexapod.json" "$work/h.json"
mkfifo "$work/fifo"
expect_error "is the same file as the input" simulate --genome "$work/g.genome" --csv "$work/g.genome"
expect_error "is the same file as the input" simulate --genome g.genome --csv "$work/../$(basename "$work")/hard.genome"
expect_error "is the same file as the input" still --creature h.json --out ./h.json
expect_error "is the same file as the input" evolve --creature "$work/run/run.json" --out "$work/run"
expect_error "would replace the input" figures --run "$work/run" --out "$work/run"
expect_error "would replace the input" report --figures "$work/run" --out "$work/run/"
expect_error "--resume: empty value" evolve --resume ""
expect_error "--genome: empty value" simulate --genome ""
expect_error "--run: empty value" movie --run "" --out out/movies
expect_error "--out: empty value" still --out ""
section
# A device: as root a private copy of /dev/null, so a hexgait that replaced its output with a
# regular file (as older versions did) cannot break the machine's /dev/null.
devnull=/dev/null
if [ "$(id -u)" -eq 0 ] && mknod "$work/devnull" c 1 3 2>/dev/null; then devnull=$work/devnull; fi
expect_error "not a regular file (a device, FIFO or socket)" simulate --time 1 --csv "$devnull"
expect_error "not a regular file (a device, FIFO or socket)" simulate --time 1 --csv "$work/fifo"
expect_error "is a symbolic link" simulate --time 1 --csv /proc/self/fd/1
expect_error "is a FIFO or socket, expected a regular file" simulate --creature "$work/fifo"
section
# Inputs that are not regular files are refused before they are opened: reading a FIFO would
# wait for a writer forever, a terminal for the user.
expect_error "is a FIFO or socket, expected a regular file" simulate --genome "$work/fifo"
expect_error "is a FIFO or socket, expected a regular file" simulate --motor "$work/fifo"
mkdir -p "$work/fiforun" && cp "$work/run/"* "$work/fiforun/" && rm "$work/fiforun/best.genome"
mkfifo "$work/fiforun/best.genome"
expect_error "is a FIFO or socket, expected a regular file" movie --run "$work/fiforun" --time 5 --out out/movies
expect_error "is a device, expected a regular file" simulate --genome /dev/null
section
# `--csv -` writes the trace to standard output, so it cannot share it with --json; alone it
# prints the table and nothing else there.
expect_error "--csv - and --json both write to standard output" simulate --time 1 --csv - --json
cases=$((cases + 1))
(cd "$work/out" && "$hexgait" simulate --time 1 --csv - >"$work/stdout.csv" 2>/dev/null) &&
  [ "$(head -c 11 "$work/stdout.csv")" = "time,centre" ] && [ "$(wc -l <"$work/stdout.csv")" -eq 12 ] &&
  [ -z "$(ls "$work/out")" ] || { echo "FAIL: simulate --csv - did not write the table to stdout"; failures=$((failures + 1)); }
section
# Absurd sizes are refused up front with the estimate and the flag that allows them.
expect_error "pass --allow-long to run it anyway" simulate --time 1e12
expect_error "pass --allow-long to run it anyway" still --time 1e6 --dt 1e-5 --out out/s.png
expect_error "pass --allow-long to run it anyway" figures --run "$work/run" --time 1e12 --out out/figs
expect_error "pass --allow-long to run it anyway" evolve --population 100000 --generations 100000 --out out/e
expect_error "is 5000 runs: at least" sweep --seeds 1-5000 --population 100 --generations 100 --out out/sw
# The estimate counts the creature's particles and springs: a population the hexapod runs in a
# minute and a half, on a creature of 1,000 particles (beads hung from the hexapod's), is refused.
python3 "$here/../support/make_big_creature.py" "$asset_dir/hexapod.json" "$work/big.json"
expect_error "--population 2000 and --generations 20 are 4.2e+04 evaluations" evolve --creature "$work/big.json" --population 2000 --generations 20 --threads 2 --out out/e
expect_error "frames, more than 100000; pass --allow-long" render --speed 0.08 --out out/m.mp4
expect_error "frames, more than 100000; pass --allow-long" movie --run "$work/run" --speed 0.08 --out out/movies
section
# A run folder whose last evolve did not finish (its results may be an older run's).
mkdir -p "$work/unfinished" && cp "$work/run/"* "$work/unfinished/"
printf 'written by hexgait evolve; a new run may replace it\nstate: running\n' >"$work/unfinished/.hexgait-evolve"
expect_error "its last evolve did not finish" figures --run "$work/unfinished" --out out/figs
expect_error "its last evolve did not finish" figures --runs "$work/unfinished" --run "$work/run" --out out/figs
expect_error "its last evolve did not finish" movie --run "$work/unfinished" --time 5 --out out/movies
expect_error "its last evolve did not finish" report --run "$work/unfinished" --out out/report
section
# evolve over a folder it did not write, or one another run is writing.
mkdir -p "$work/foreign" && echo notes >"$work/foreign/notes.txt"
expect_error "was not written by hexgait evolve" evolve --out "$work/foreign"
# A page of someone else's is not replaced by a replay.
echo "<p>my notes</p>" >"$work/notes.html"
expect_error "a file hexgait did not write as a replay page" replay --time 5 --out "$work/notes.html"
grep -q "my notes" "$work/notes.html" || { echo "FAIL: replay replaced notes.html"; failures=$((failures + 1)); }
# A folder another command marked as its own, though it holds a run.json like an old evolve's.
mkdir -p "$work/a-report" && touch "$work/a-report/.hexgait-report" "$work/a-report/run.json"
expect_error "(no .hexgait-evolve)" evolve --out "$work/a-report"
# The repertoire's movie options are named as given, not as render's.
expect_error "--movie-size '15x15'" repertoire --evaluations 100 --batch 50 --movie-size 15x15 --out out/r
expect_error "--movie-cues 'sparkles'" repertoire --evaluations 100 --batch 50 --movie-cues sparkles --out out/r
expect_error "--movie-time must be a positive" repertoire --evaluations 100 --batch 50 --movie-time -1 --out out/r
expect_error "--run 'nofolder': " endurance --run nofolder --random 0 --out out/en
expect_error "is shorter than one step" simulate --time 0.001
"$hexgait" evolve --generations 100000 --time 200 --out "$work/busy" --quiet &
busy=$!
for _ in $(seq 500); do [ -e "$work/busy/checkpoint.json" ] && break; sleep 0.02; done
expect_error "is writing this folder" evolve --generations 1 --time 5 --out "$work/busy"
kill -9 $busy; wait $busy 2>/dev/null
section
# Checkpoints: an edited parameter (the checksum), a non-finite or inflated fitness (consistency).
edit_ck() {  # edit_ck NAME PYTHON-STATEMENTS-ON-d: a copy of the run with its checkpoint edited
  mkdir -p "$work/$1" && cp "$work/run/"* "$work/$1/"
  python3 - "$work/$1/checkpoint.json" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[2])
open(sys.argv[1], "w").write(json.dumps(d, indent=1))
PY
}
edit_ck ck_seed 'd["params"]["seed"] = "2"'
edit_ck ck_nan 'd["population"][1]["fitness"] = "nan"'
edit_ck ck_big 'd["population"][1]["fitness"] = 1e9'
edit_ck ck_nosum 'del d["checksum"]'
expect_error "checksum does not match the content" evolve --resume "$work/ck_seed"
expect_error "fitness is not a finite number" evolve --resume "$work/ck_nan"
expect_error "fitness does not match its result" evolve --resume "$work/ck_big"
expect_error "missing field 'checksum'" evolve --resume "$work/ck_nosum"
section
# What evolve writes, resume reads: a population of 14,000 writes an 18 MB checkpoint. The
# sanitizer build (HEXGAIT_SANITIZED, set by tests/CMakeLists.txt) took 21 s over writing and
# parsing it, against 4 s in the release build, which checks the size: 1,400 there (1.8 MB).
big_population=14000
[ -z "${HEXGAIT_SANITIZED:-}" ] || big_population=1400
"$hexgait" evolve --population $big_population --generations 1 --time 0.2 --threads 2 --out "$work/big" --quiet
expect_error "that run is complete" evolve --resume "$work/big"

section
# Smaller ones: a seed above 2^64 - 1, a key twice in one JSON object, a control character in a
# name, an output whose extension does not match what is written, --speed too large.
python3 -c "import sys; t=open(sys.argv[1]).read(); i=t.index('{'); open(sys.argv[2],'w').write(t[:i+1]+'\"name\": \"x\", '+t[i+1:])" \
  "$asset_dir/hexapod.json" "$work/dupkey.json"
edit_json "$work/ctrl.json" 'd["springs"][0]["name"] = "a\x1b[31mred"'
expect_error "--seed: must be at most 18446744073709551615" evolve --seed 99999999999999999999 --out out/e
expect_error "appears twice in one object" simulate --creature "$work/dupkey.json"
expect_error "control character in a string" simulate --creature "$work/ctrl.json"
expect_error "expected a name ending in .mp4" render --time 5 --out out/m.png
expect_error "expected a name ending in .png" still --out out/s.mp4
expect_error "--speed must be at most 1e6" render --speed 1e9 --time 5 --out out/m.mp4

section
# A folder without write permission (skipped as root, who may write anywhere).
mkdir -p "$work/locked" && chmod a-w "$work/locked"
if [ "$(id -u)" -ne 0 ]; then
  expect_error "not writable" render --time 5 --out "$work/locked/m.mp4"
  expect_error "not writable" movie --run "$work/run" --time 5 --out "$work/locked"
  cp "$genome" "$work/secret.genome" && chmod a-r "$work/secret.genome"
  expect_error "cannot be opened for reading" simulate --genome "$work/secret.genome"
else
  # Root reads and writes anywhere: the permission rows of docs/errors.md count as tried.
  tried+=("not writable" "cannot be opened for reading")
fi
chmod u+w "$work/locked"

# The other direction: every message docs/errors.md credits to this test was tried above.
while IFS= read -r documented; do
  found=0
  for t in "${tried[@]}"; do [ "$t" = "$documented" ] && found=1; done
  if [ "$found" -eq 0 ]; then
    echo "FAIL: docs/errors.md lists '$documented' for cli_bad_input, but no case tries it"
    failures=$((failures + 1))
  fi
done < <(grep -F '| cli_bad_input |' "$errors_md" | sed -n 's/^|[^|]*| `\(.*\)` | cli_bad_input |.*$/\1/p')

echo "$ran of $cases cases run ($selection): $((ran - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
