#!/usr/bin/env bash
# What one creature-step costs as a creature grows: the measurements behind the long-run
# estimate's size model (src/run/work_size.cc). Creatures of PARTICLES particles are the hexapod
# with beads hung from it (tests/support/make_big_creature.py), each bead tied by 2 springs, or by 6
# (--springs 6 adds four more to other particles). For each, one core times
#   scalar:  `hexgait simulate` of one creature (what simulate, movies, stills and figures run)
#   batched: `hexgait evolve --generations 1` of one population in double (evolve, repertoire)
# and prints ns per creature-step, median of 3 runs, with the ratio to the hexapod's.
#
#   scripts/step_cost.sh [HEXGAIT] > step_cost.csv
set -euo pipefail
cd "$(dirname "$0")/.."
hexgait=$(realpath "${1:-build/hexgait}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

calc() { python3 -c "print($1)"; }

# The median wall time in seconds of three runs of a command.
median_seconds() {
  local times=()
  for _ in 1 2 3; do
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null
    end=$(date +%s.%N)
    times+=("$(calc "$end - $start")")
  done
  printf '%s\n' "${times[@]}" | sort -g | sed -n 2p
}

# A creature file of PARTICLES particles, SPRINGS springs per bead.
make_creature() {
  local particles=$1 springs=$2 out=$3
  python3 tests/support/make_big_creature.py assets/hexapod.json "$out" "$particles"
  [ "$springs" = 2 ] && return 0
  python3 - "$out" "$springs" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
n0 = 14
beads = len(d["particles"]) - n0
for i in range(beads):
    for j in range(int(sys.argv[2]) - 2):  # to further particles of the hexapod
        d["springs"].append({"name": f"bead{i}_extra{j}", "ends": [(i + 2 + j) % n0, n0 + i],
                             "stiffness": 10.0, "damping": 0.1, "leg": None, "motor": False})
json.dump(d, open(sys.argv[1], "w"))
PY
}

echo "particles,springs,scalar_ns_per_step,batched_ns_per_step,scalar_ratio,batched_ratio"
base_scalar="" base_batched=""
for spec in 14:2 100:2 300:2 1000:2 300:6 1000:6; do
  particles=${spec%:*} per_bead=${spec#*:}
  if [ "$particles" = 14 ]; then
    creature=hexapod
    springs=40
  else
    creature="$work/c$particles-$per_bead.json"
    make_creature "$particles" "$per_bead" "$creature"
    springs=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["springs"]))' \
      "$creature")
  fi
  # About a second of work each: steps scaled down with the size. A step of 0.0004 keeps the
  # beads from diverging (a diverged run would end early); a step costs the same at any dt.
  size=$((particles + springs))
  time_units=$((400 * 54 / size + 4))
  steps=$((time_units * 2500))
  scalar=$(median_seconds "$hexgait" simulate --creature "$creature" --time "$time_units" --dt 0.0004)
  population=16
  batched=$(median_seconds "$hexgait" evolve --creature "$creature" --population "$population" \
    --generations 1 --threads 1 --time "$time_units" --dt 0.0004 --quiet --out "$work/run")
  evaluations=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["evaluations"])' \
    "$work/run/run.json")
  scalar_ns=$(calc "$scalar / $steps * 1e9")
  batched_ns=$(calc "$batched / ($steps * $evaluations) * 1e9")
  [ -n "$base_scalar" ] || { base_scalar=$scalar_ns; base_batched=$batched_ns; }
  printf '%d,%d,%.1f,%.2f,%.2f,%.2f\n' "$particles" "$springs" "$scalar_ns" "$batched_ns" \
    "$(calc "$scalar_ns / $base_scalar")" "$(calc "$batched_ns / $base_batched")"
done
