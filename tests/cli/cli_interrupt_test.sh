#!/usr/bin/env bash
# Interrupted runs: Ctrl-C (SIGINT), SIGTERM and kill -9 at points in the middle of an evolve,
# a render, a movie set, and commands without safe points (figures, every bench, simulate,
# still, filmstrip). After each, the outputs are either the old complete files or absent,
# never half-written; a stopped evolve says how to resume, and the resumed run is bit-identical
# to one that was never interrupted.
set -u
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
cases=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source "$(dirname "$0")/../support/signal_ready.sh"
# wait_for FILE: until FILE exists (at most 60 s)
wait_for() {
  for _ in $(seq 3000); do [ -e "$1" ] && return 0; sleep 0.02; done
  return 1
}
# wait_for_partial DIR: until a temporary output file appears in DIR (work has started)
wait_for_partial() {
  for _ in $(seq 3000); do ls "$1" 2>/dev/null | grep -q partial && return 0; sleep 0.02; done
  return 1
}
# no_partial DIR: no temporary file of an atomic write is left in DIR
no_partial() { ! ls "$1" | grep -q "partial"; }

# Enough generations that the signal, sent as soon as the first checkpoint appears, always
# arrives before the end, however fast the machine. The sanitizer build (HEXGAIT_SANITIZED, set
# by tests/CMakeLists.txt) runs several times slower: shorter runs stop at the same points (a
# checkpoint every generation, so a signal at the first still leaves most of the run to resume).
evolve_time=200 generations=60 cmaes_generations=40 long_gait_time=4000
[ -z "${HEXGAIT_SANITIZED:-}" ] || { evolve_time=80 generations=30 cmaes_generations=20 long_gait_time=1000; }
evolve=(evolve --generations $generations --time $evolve_time --threads 2 --quiet)
"$hexgait" "${evolve[@]}" --seed 3 --out "$work/whole"

# 1-2. SIGINT and SIGTERM after the first checkpoint: clean stop, checkpoint kept, how to resume
# printed, exit 128 + signal; then --resume gives the uninterrupted run's files exactly.
for signal in INT TERM; do
  cases=$((cases + 1))
  dir="$work/sig$signal"
  "$hexgait" "${evolve[@]}" --seed 3 --out "$dir" 2>"$work/err" &
  pid=$!
  wait_for "$dir/checkpoint.json" || fail "no checkpoint from evolve ($signal)"
  kill -$signal $pid
  wait $pid
  code=$?
  expected=$([ $signal = INT ] && echo 130 || echo 143)
  [ $code -eq $expected ] || fail "evolve stopped by SIG$signal exited $code, expected $expected"
  grep -q "hexgait evolve --resume $dir" "$work/err" || { fail "no resume hint ($signal)"; cat "$work/err"; }
  # Acknowledged when it arrives, before the safe point (issue: a stop seconds away said nothing).
  grep -q "SIG$signal received: stopping " "$work/err" ||
    { fail "the signal was not acknowledged ($signal)"; cat "$work/err"; }
  [ ! -e "$dir/fitness.csv" ] || fail "fitness.csv written by a stopped run ($signal)"
  no_partial "$dir" || fail "temporary files left after SIG$signal"
  "$hexgait" evolve --resume "$dir" --quiet || fail "resume after SIG$signal failed"
  cmp -s "$work/whole/fitness.csv" "$dir/fitness.csv" || fail "resumed fitness.csv differs ($signal)"
  cmp -s "$work/whole/best.genome" "$dir/best.genome" || fail "resumed best.genome differs ($signal)"
done

# 2b. The same for CMA-ES, whose checkpoint holds a distribution (mean, step size, covariance,
# paths) instead of a population: SIGINT after its first checkpoint, then --resume.
cases=$((cases + 1))
cmaes=(evolve --algorithm cmaes --population 8 --generations $cmaes_generations --time 100 --threads 2 --quiet)
"$hexgait" "${cmaes[@]}" --seed 3 --out "$work/cmaes_whole"
dir="$work/cmaes_int"
"$hexgait" "${cmaes[@]}" --seed 3 --out "$dir" 2>"$work/err" &
pid=$!
wait_for "$dir/checkpoint.json" || fail "no checkpoint from evolve --algorithm cmaes"
kill -INT $pid
wait $pid
code=$?
[ $code -eq 130 ] || fail "cmaes stopped by SIGINT exited $code, expected 130"
[ ! -e "$dir/fitness.csv" ] || fail "fitness.csv written by a stopped cmaes run"
"$hexgait" evolve --resume "$dir" --quiet || fail "resume of cmaes after SIGINT failed"
for f in fitness.csv best.genome; do
  cmp -s "$work/cmaes_whole/$f" "$dir/$f" || fail "resumed cmaes $f differs"
done

# 3. kill -9 in the middle of an evolve that overwrites an earlier run: the earlier run's
# outputs stay whole, but the folder now mixes them with the new run's checkpoint, so figures,
# movie and report refuse it until the run is resumed to the same result.
cases=$((cases + 1))
dir="$work/kill9"
cp -r "$work/whole" "$dir"
rm "$dir/checkpoint.json"
"$hexgait" "${evolve[@]}" --seed 4 --out "$dir" &
pid=$!
wait_for "$dir/checkpoint.json" || fail "no checkpoint from evolve (kill -9)"
kill -9 $pid
wait $pid 2>/dev/null
cmp -s "$work/whole/fitness.csv" "$dir/fitness.csv" || fail "kill -9 damaged the old fitness.csv"
cmp -s "$work/whole/best.genome" "$dir/best.genome" || fail "kill -9 damaged the old best.genome"
python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$dir/checkpoint.json" ||
  fail "checkpoint.json half-written after kill -9"
for reader in "figures --run $dir --time 5 --no-figure1 --out $work/figs9" \
  "movie --run $dir --time 5 --size 160x120 --out $work/movies9" "report --run $dir --out $work/report9"; do
  # shellcheck disable=SC2086
  "$hexgait" $reader >/dev/null 2>"$work/err" && fail "$reader read a folder whose run was killed"
  grep -q "its last evolve did not finish" "$work/err" || { fail "no unfinished-run message: $reader"; cat "$work/err"; }
done
"$hexgait" "${evolve[@]}" --seed 4 --out "$work/whole4"
"$hexgait" evolve --resume "$dir" --quiet || fail "resume after kill -9 failed"
cmp -s "$work/whole4/fitness.csv" "$dir/fitness.csv" || fail "resumed (kill -9) fitness.csv differs"
"$hexgait" figures --run "$dir" --time 5 --no-figure1 --out "$work/figs9" >/dev/null ||
  fail "figures refused the folder of a resumed, finished run"

# 4-6. A render stopped by SIGINT, SIGTERM or kill -9 mid-movie: no movie at the final name (an
# earlier movie there is kept whole), and after SIGINT/SIGTERM no temporary file either.
render=(render --time 20000 --size 320x240)
"$hexgait" render --time 20 --size 320x240 --out "$work/old.mp4" >/dev/null
for signal in INT TERM KILL; do
  cases=$((cases + 1))
  out="$work/movie_$signal"
  mkdir -p "$out"
  cp "$work/old.mp4" "$out/gait.mp4"
  "$hexgait" "${render[@]}" --out "$out/gait.mp4" --frames "$out/frames" >/dev/null 2>"$work/err" &
  pid=$!
  wait_for_partial "$out" || fail "render did not start"
  sleep 0.5
  kill -$signal $pid
  wait $pid 2>/dev/null
  code=$?
  [ $code -ne 0 ] || fail "render killed by SIG$signal exited 0"
  cmp -s "$work/old.mp4" "$out/gait.mp4" || fail "the earlier movie was damaged by SIG$signal"
  if [ $signal != KILL ]; then
    grep -q "no movie written" "$work/err" || { fail "no message after SIG$signal"; cat "$work/err"; }
    no_partial "$out" || fail "temporary movie left after SIG$signal"
    # --frames owns its folder: a stopped movie leaves none of its frames.
    [ ! -e "$out/frames" ] || { fail "frames left after SIG$signal"; ls "$out"; }
  fi
done

# 7. `hexgait movie` stopped by SIGTERM while making its first movie: no movie at all, no
# temporary file, exit 143.
cases=$((cases + 1))
out="$work/movies"
mkdir -p "$out"
"$hexgait" movie --run "$work/whole" --time 20000 --size 320x240 --out "$out" >/dev/null 2>&1 &
pid=$!
wait_for_partial "$out" || fail "movie did not start"
sleep 0.3
kill -TERM $pid
wait $pid
[ $? -eq 143 ] || fail "movie stopped by SIGTERM did not exit 143"
[ -z "$(ls "$out")" ] || { fail "files left by a stopped 'movie'"; ls "$out"; }

# 8. `hexgait movie` over an earlier set, stopped by SIGTERM once its first movie is finished:
# the set is written whole or not at all, so all three earlier movies are kept unchanged and no
# staged or temporary file is left.
cases=$((cases + 1))
out="$work/movieset"
mkdir -p "$out"
"$hexgait" movie --run "$work/whole" --time 5 --size 160x120 --out "$out" >/dev/null 2>&1 ||
  fail "movie (the earlier set) failed"
cp -r "$out" "$work/movieset_old"
"$hexgait" movie --run "$work/whole" --time 4000 --size 160x120 --out "$out" >/dev/null 2>"$work/err" &
pid=$!
for _ in $(seq 3000); do ls "$out" | grep -q '^evolved.mp4.staged' && break; sleep 0.02; done
kill -TERM $pid
wait $pid
[ $? -eq 143 ] || fail "movie over a set stopped by SIGTERM did not exit 143"
for name in unoptimized.mp4 evolved.mp4 comparison.mp4 unoptimized.html evolved.html; do
  cmp -s "$work/movieset_old/$name" "$out/$name" || fail "$name of the earlier set was replaced"
done
[ "$(ls "$out" | wc -l)" -eq 5 ] || { fail "staged files left by a stopped movie set"; ls "$out"; }
grep -q "no movie of the set replaced" "$work/err" || { fail "no set message"; cat "$work/err"; }

# 9-18. Commands without safe points stop on the first SIGINT or SIGTERM too, within about a
# second, exit 128 + signal and leave no temporary file or folder: figures (a long gait run),
# every bench, simulate writing a CSV, simulate past the size check with --allow-long, still at a
# late time, filmstrip of a late cycle at a small step.
# About a second in a release build; the sanitizer build runs several times slower and CI runs
# it beside other tests on two cores, so tests/CMakeLists.txt gives it a longer limit there.
stop_limit_ms=${HEXGAIT_STOP_LIMIT_MS:-1500}
stop_within() {  # stop_within SIGNAL DIR ARGS...: start, signal after 1 s, check exit, time, leftovers
  local signal=$1 dir=$2
  shift 2
  cases=$((cases + 1))
  mkdir -p "$dir"
  "$hexgait" "$@" >/dev/null 2>"$work/err" &
  local pid=$! start
  wait_until_catching $pid || fail "$1 $2 never installed its signal handlers"
  sleep 1  # into the work
  start=$(date +%s%N)
  kill -$signal $pid
  # At most 60 s: a signal that is not acted on fails the case rather than run the command out.
  for _ in $(seq 3000); do kill -0 $pid 2>/dev/null || break; sleep 0.02; done
  kill -KILL $pid 2>/dev/null
  wait $pid
  local code=$? ms=$((($(date +%s%N) - start) / 1000000))
  local expected=$([ $signal = INT ] && echo 130 || echo 143)
  [ $code -eq $expected ] || { fail "$1 $2 stopped by SIG$signal exited $code, expected $expected"; cat "$work/err"; }
  [ $ms -lt "$stop_limit_ms" ] || fail "$1 $2 took $ms ms to stop after SIG$signal (limit $stop_limit_ms ms)"
  echo "stopped by SIG$signal in $ms ms: $*"
  ! ls -a "$dir" "$(dirname "$dir")" | grep -q "partial" || fail "$1 $2 left a temporary file after SIG$signal"
  ! ls -a "$dir" "$(dirname "$dir")" | grep -q "hexgait-lock" || fail "$1 $2 left a lock file after SIG$signal"
}
stop_within INT "$work/stop/figs" figures --run "$work/whole" --time 100000 --out "$work/stop/figs/out"
stop_within TERM "$work/stop/bench" bench stability --out "$work/stop/bench/out"
stop_within INT "$work/stop/sim" simulate --time 1000000 --csv "$work/stop/sim/trace.csv"
stop_within TERM "$work/stop/still" still --time 900000 --out "$work/stop/still/s.png"
stop_within INT "$work/stop/replay" replay --time 110000 --dt 0.0005 --out "$work/stop/replay/r.html"
# A repertoire of 4,000-time-unit gaits: adapting it to this damage takes about 12 s. The
# sanitizer build's gaits last 1,000, which it still adapts to for longer than the 1 s wait.
"$hexgait" repertoire --evaluations 32 --batch 32 --time $long_gait_time --no-movie --compare-ga 0 --quiet \
  --out "$work/long_gaits" >/dev/null
stop_within TERM "$work/stop/adapt" adapt --repertoire "$work/long_gaits" --damage left_rear:short=0.95 --out "$work/stop/adapt/out"
[ ! -e "$work/stop/adapt/out" ] || fail "adapt stopped by SIGTERM left its folder"
stop_within TERM "$work/stop/long" simulate --time 1e12 --allow-long
stop_within INT "$work/stop/strip" filmstrip --cycle 10000 --dt 0.0001 --out "$work/stop/strip/f.png"
stop_within INT "$work/stop/accuracy" bench accuracy --out "$work/stop/accuracy/out"
stop_within TERM "$work/stop/speed" bench speed
stop_within INT "$work/stop/early" bench early-stop
stop_within TERM "$work/stop/bmovie" bench movie --out "$work/stop/bmovie"
# Commands with safe points stop within the same limit with their default settings: a
# repertoire batch of 500 (the evaluator starts no further batch of lanes after the signal and
# drops the population), a large GA population, a sweep of runs on every thread.
stop_within INT "$work/stop/rep" repertoire --no-movie --out "$work/stop/rep/out"
grep -q "received: stopping within about" "$work/err" || { fail "repertoire: no time in the acknowledgement"; cat "$work/err"; }
stop_within TERM "$work/stop/pop" evolve --population 400 --out "$work/stop/pop/out"
stop_within INT "$work/stop/sweep" sweep --seeds 1-100 --out "$work/stop/sweep/out"
[ ! -e "$work/stop/figs/out" ] || fail "figures stopped by SIGINT left its output folder"
[ ! -e "$work/stop/bench/out" ] || fail "bench stability stopped by SIGTERM left the --out folder it made"
[ ! -e "$work/stop/accuracy/out" ] || fail "bench accuracy stopped by SIGINT left the --out folder it made"
[ -z "$(ls -A "$work/stop/bmovie")" ] || { fail "bench movie stopped by SIGTERM left scratch files"; ls -A "$work/stop/bmovie"; }

echo "$((cases - failures)) passed, $failures failed ($cases kill points)"
[ "$failures" -eq 0 ]
