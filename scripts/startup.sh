#!/usr/bin/env bash
# What a process pays before its command runs: the median wall time of short commands (hyperfine)
# and the shared objects each one opens (strace), for one hexgait binary or two side by side.
#   usage: scripts/startup.sh [HEXGAIT [BASELINE_HEXGAIT]]   (default: build/hexgait)
# Needs Debian's hyperfine and strace (scripts/deps.sh --test installs them). Prints one
# Markdown table; docs/speed.md quotes it.
set -euo pipefail
cd "$(dirname "$0")/.."
bins=("${1:-build/hexgait}")
[ $# -ge 2 ] && bins+=("$2")
for b in "${bins[@]}"; do
  [ -x "$b" ] || { echo "startup.sh: no executable at $b (build first: scripts/build.sh)" >&2; exit 2; }
done
for tool in hyperfine strace; do
  command -v "$tool" >/dev/null || { echo "startup.sh: needs $tool (apt-get install $tool)" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name|arguments: text only, a short simulation, then commands that draw and encode.
cases=(
  "--help|--help"
  "simulate --time 1|simulate --time 1"
  "inspect|inspect"
  "still 320x240|still --size 320x240 --out $work/s.png"
  "render 100 time units 320x240|render --time 100 --size 320x240 --out $work/m.mp4"
)

# The shared objects a run opens (successful openat of a .so, every thread and child).
objects() {
  strace -f -qq -e trace=openat -o "$work/trace" "$@" >/dev/null 2>&1 || true
  grep -v ENOENT "$work/trace" | grep -oE '"[^"]+\.so[^"]*"' | sort -u | wc -l
}

median_ms() {  # hyperfine's median, in ms, of one command line
  hyperfine -N --warmup 3 --min-runs "$2" --export-json "$work/h.json" "$1" >/dev/null 2>&1
  python3 -c "import json,sys; print('%.1f' % (1000*json.load(open(sys.argv[1]))['results'][0]['median']))" "$work/h.json"
}

header="| command |"
rule="|---|"
for b in "${bins[@]}"; do
  header+=" $b: median ms | shared objects |"
  rule+="---:|---:|"
done
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
echo "$header"
echo "$rule"
for c in "${cases[@]}"; do
  name=${c%%|*}
  args=${c#*|}
  row="| \`$name\` |"
  for b in "${bins[@]}"; do
    case "$name" in render*) runs=5 ;; *) runs=20 ;; esac
    # shellcheck disable=SC2086
    row+=" $(median_ms "$b $args" $runs) | $(objects $b $args) |"
  done
  echo "$row"
done
