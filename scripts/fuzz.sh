#!/usr/bin/env bash
# Runs every libFuzzer target (tests/fuzz/*_fuzz.cc) for SECONDS_PER_TARGET (default 60) on a
# copy of its seed corpus, so the repository is never modified, as many at once as there are
# cores. The targets come from BUILD_DIR (scripts/test.sh's sanitizer build, which builds them
# too) or, without it, from a build of the core library and the fuzzers alone in build-fuzz/. Prints the executions per target; exits non-zero on any crash, leak, sanitizer
# report, timeout (> 5 s on one input) or memory blow-up (> 2 GB). A finding's input is kept
# in BUILD_DIR/findings/<target>/: fix the bug, then add the file to tests/fuzz/regressions/.
#   usage: scripts/fuzz.sh [SECONDS_PER_TARGET [BUILD_DIR]]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cmake_generator.sh
seconds=${1:-60}
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz.sh: SECONDS_PER_TARGET must be a positive integer, got '$seconds'" >&2
  exit 2
fi
start=$SECONDS
build=${2:-}
if [ -z "$build" ]; then
  build=build-fuzz
  # -O2 with line tables only (-g1): a sanitizer's report still names file and line.
  CC=clang CXX=clang++ cmake -S . -B "$build" -DHEXGAIT_FUZZ=ON -DHEXGAIT_WERROR=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
    -DHEXGAIT_BUILD_TESTS=OFF -DHEXGAIT_BUILD_BENCHMARKS=OFF >/dev/null
  cmake --build "$build" -j"$(nproc)"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# fuzz NAME: runs one target; its exit code goes to $work/NAME.code.
fuzz() {
  local name=$1 target=$1_fuzz
  local corpus=$work/corpus/$name findings=$build/findings/$1
  mkdir -p "$corpus" "$findings"
  cp tests/fuzz/corpus/"$name"/* "$corpus"/
  [ -d tests/fuzz/regressions/"$name" ] && cp tests/fuzz/regressions/"$name"/* "$corpus"/
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build"/tests/fuzz/"$target" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
    -malloc_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings"/ \
    "$corpus" >"$findings"/fuzz.log 2>&1
  echo $? >"$work/$name.code"
}

names=()
for source in tests/fuzz/*_fuzz.cc; do
  target=$(basename "$source" .cc)
  names+=("${target%_fuzz}")
  [ -x "$build/tests/fuzz/$target" ] || { echo "fuzz: $build/tests/fuzz/$target not built" >&2; exit 1; }
done
# As many targets at once as there are cores, each on one.
running=0
for name in "${names[@]}"; do
  fuzz "$name" &
  running=$((running + 1))
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

failed=()
for name in "${names[@]}"; do
  target=${name}_fuzz
  log=$build/findings/$name/fuzz.log
  code=$(cat "$work/$name.code" 2>/dev/null || echo 99)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$code" -ne 0 ] || grep -q "runtime error:" "$log"; then
    echo "fuzz: $target FAILED (exit $code) after ${runs:-?} executions; see $log:"
    grep -m 5 -E "ERROR|runtime error|Test unit written" "$log" || tail -n 20 "$log"
    failed+=("$target")
  else
    echo "fuzz: $target ok, ${runs:-?} executions in ${seconds} s"
  fi
done
echo "fuzz: done in $((SECONDS - start)) s"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
