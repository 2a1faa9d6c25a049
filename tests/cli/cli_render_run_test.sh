#!/usr/bin/env bash
# A movie shows exactly the run `simulate` computes: for every integrator, `render --json` and
# `simulate --json` report the same distance, fall, steps and extremes, to the last digit. The
# frame spacing (--fps 23 at the default speed: 1148 steps) is not a multiple of the fall
# check's interval (40 steps), and 300 time units take the unoptimized program past its fall
# (with explicit Euler; implicit Euler's damping keeps it up).
set -eu
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fields='["distance","fell","fall_time","fall_cycle","diverged","steps","time","min_body_height","max_tilt_degrees","mean_feet_on_ground","duty_factors","legs"]'
passed=0 failed=0
for integrator in euler symplectic-euler verlet rk4 implicit-euler; do
  # Implicit Euler's solves are 30 times explicit Euler's cost under the sanitizers (73 s of
  # this test's 78 there at 300 time units): a cycle of it is enough to compare.
  time=300
  [ "$integrator" = implicit-euler ] && time=70
  run=(--unoptimized --integrator "$integrator" --time "$time")
  "$hexgait" simulate "${run[@]}" --json >"$work/simulate.json"
  "$hexgait" render "${run[@]}" --size 64x48 --fps 23 --out "$work/m.mp4" --json >"$work/render.json"
  if python3 - "$work/simulate.json" "$work/render.json" "$fields" "$integrator" <<'PY'; then
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
fields = json.loads(sys.argv[3])
bad = [f"{k}: render {b.get(k)!r}, simulate {a.get(k)!r}" for k in fields if a.get(k) != b.get(k)]
if sys.argv[4] == "euler" and not a["fell"]:
    bad.append("the unoptimized program did not fall: the test needs a fall")
for k in ("path", "frames", "size", "fps", "wall_seconds"):
    if k not in b:
        bad.append(f"render --json has no '{k}'")
if bad:
    print(f"{sys.argv[4]}: " + "; ".join(bad))
    sys.exit(1)
PY
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
  [ -s "$work/m.mp4" ] || { echo "$integrator: no movie written"; failed=$((failed + 1)); }
done
# --frames DIR holds one movie's frames: a second, shorter movie replaces the first's whole.
"$hexgait" render --time 40 --size 64x48 --fps 10 --frames "$work/frames" --out "$work/f.mp4" >/dev/null
first=$(ls "$work/frames" | grep -c '^frame_.*\.png$')
"$hexgait" render --time 20 --size 64x48 --fps 10 --frames "$work/frames" --out "$work/f.mp4" >/dev/null
second=$(ls "$work/frames" | grep -c '^frame_.*\.png$')
if [ "$first" -le "$second" ] || [ ! -e "$work/frames/.hexgait-frames" ]; then
  echo "--frames: $first frames, then $second (stale frames kept, or no marker)"
  failed=$((failed + 1))
else
  passed=$((passed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
