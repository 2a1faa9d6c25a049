#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/*_fuzz.cc) with clang in build-fuzz/ and runs each
# for SECONDS_PER_TARGET (default 60) on a copy of its seed corpus, so the repository is never
# modified. Prints the executions per target; exits non-zero on any crash, leak, sanitizer
# report, timeout (> 5 s on one input) or memory blow-up (> 2 GB). A finding's input is kept
# in build-fuzz/findings/<target>/: fix the bug, then add the file to tests/fuzz/regressions/.
#   usage: scripts/fuzz.sh [SECONDS_PER_TARGET]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz.sh: SECONDS_PER_TARGET must be a positive integer, got '$seconds'" >&2
  exit 2
fi
start=$SECONDS
# -O2 with line tables only (-g1): a sanitizer's report still names file and line. -O1 built
# only 34 s faster and ran no more inputs per minute (docs/testing.md).
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DHEXGAIT_FUZZ=ON -DHEXGAIT_WERROR=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
  -DHEXGAIT_BUILD_TESTS=OFF -DHEXGAIT_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=()
for source in tests/fuzz/*_fuzz.cc; do
  target=$(basename "$source" .cc)
  name=${target%_fuzz}
  corpus=$work/corpus/$name
  mkdir -p "$corpus" build-fuzz/findings/"$name"
  cp tests/fuzz/corpus/"$name"/* "$corpus"/
  [ -d tests/fuzz/regressions/"$name" ] && cp tests/fuzz/regressions/"$name"/* "$corpus"/
  log=build-fuzz/findings/$name/fuzz.log
  set +e
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    build-fuzz/tests/fuzz/"$target" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
    -malloc_limit_mb=2048 -print_final_stats=1 -artifact_prefix=build-fuzz/findings/"$name"/ \
    "$corpus" >"$log" 2>&1
  code=$?
  set -e
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
