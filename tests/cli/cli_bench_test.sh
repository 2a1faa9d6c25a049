#!/usr/bin/env bash
# `hexgait bench accuracy|stability --quick` write CSVs with the agreed headers (gnuplot figures
# read them); bad flags fail cleanly; a diverging simulation is a one-line error naming time,
# step and the largest stable step, with no output file.
set -eu
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
fail() { echo "FAIL: $*" >&2; exit 1; }

"$hexgait" bench accuracy --quick --out "$work/b" >"$work/acc.txt" 2>"$work/acc.err"
[ "$(head -1 "$work/b/accuracy.csv")" = \
  "integrator,program,dt,stable,pos_error_t10,pos_error_cycle1,fitness,fitness_rel_error,wall_s_per_1000tu" ] ||
  fail "accuracy.csv header"
# 5 integrators and euler in float lanes x 3 steps, one program, all stable at these steps.
[ "$(tail -n +2 "$work/b/accuracy.csv" | wc -l)" -eq 18 ] || fail "accuracy.csv rows"
[ "$(grep -c "^euler-float,unoptimized," "$work/b/accuracy.csv")" -eq 3 ] || fail "euler-float rows"
[ "$(tail -n +2 "$work/b/accuracy.csv" | cut -d, -f4 | sort -u)" = "1" ] || fail "accuracy stable"
grep -q "Fastest way to the paper's accuracy" "$work/acc.txt" || fail "accuracy summary"
passed=$((passed + 1))

"$hexgait" bench stability --quick --integrators euler,implicit-euler --out "$work/b" \
  >"$work/stab.txt" 2>/dev/null
[ "$(head -1 "$work/b/stability.csv")" = "integrator,stiffness_multiplier,dt,stable,max_energy_ratio" ] ||
  fail "stability.csv header"
[ "$(head -1 "$work/b/energy_drift.csv")" = "integrator,time,energy_relative_drift" ] ||
  fail "energy_drift.csv header"
# Explicit Euler diverges somewhere on the map (x100 at dt 0.02) and implicit Euler nowhere.
grep -q "^euler,100,0.02,0," "$work/b/stability.csv" || fail "euler x100 dt 0.02 should diverge"
! grep -q "^implicit-euler,.*,0,[^,]*$" "$work/b/stability.csv" || fail "implicit-euler diverged"
grep -q "silent NaN" "$work/stab.txt" || fail "genome table"
passed=$((passed + 1))

# Bad flags: one line, non-zero exit.
if "$hexgait" bench accuracy --integrators euler,nope --out "$work/c" 2>"$work/err"; then
  fail "unknown integrator accepted"
fi
[ "$(wc -l <"$work/err")" -eq 1 ] && grep -q "unknown integrator 'nope'" "$work/err" || fail "message"
[ ! -e "$work/c" ] || fail "output folder created for bad flags"
passed=$((passed + 1))

# Divergence: simulate at a step far too large is an error naming time, step and a stable step,
# and writes no trace.
if "$hexgait" simulate --unoptimized --dt 0.05 --time 20 --csv "$work/trace.csv" 2>"$work/err" \
  >/dev/null; then
  fail "diverging run succeeded"
fi
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "divergence message is not one line"
grep -q "diverged at t = .* (step [0-9]* of dt 0.05, euler).*largest stable step found by halving dt is" \
  "$work/err" || fail "divergence message: $(cat "$work/err")"
[ ! -e "$work/trace.csv" ] || fail "trace written for a diverged run"
passed=$((passed + 1))

# A GA on a deliberately stiff creature (every spring 100x stiffer: explicit Euler diverges at
# the paper's step): each diverged individual gets fitness 0 and a warning line, and the run
# goes on to the end and writes its files.
python3 - "$(dirname "$0")/../../assets/hexapod.json" "$work/stiff.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
for s in d["springs"]:
    s["stiffness"] *= 100
json.dump(d, open(sys.argv[2], "w"))
PY
"$hexgait" evolve --creature "$work/stiff.json" --generations 2 --time 5 --out "$work/stiff" \
  >"$work/out" 2>"$work/err" || fail "evolve stopped on diverging individuals"
warnings=$(grep -c "^hexgait: warning: generation [0-9]*, individual [0-9]* diverged at t = .* (step [0-9]*).*fitness set to 0$" "$work/err")
# One line per diverged evaluation, the elite carried over not repeated: 4 + 3 + 3.
[ "$warnings" -eq 10 ] || fail "expected 10 divergence warnings, got $warnings"
[ "$(tail -n 1 "$work/stiff/fitness.csv")" = "2,0,0,0,3" ] || fail "diverged fitness is not 0, or not counted"
passed=$((passed + 1))
echo "$passed passed, 0 failed"
