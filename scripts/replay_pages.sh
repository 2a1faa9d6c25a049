#!/usr/bin/env bash
# Browser replays of the evolved (tests/data/evolved_seed1.genome, `evolve --seed 1`) and the
# unoptimized program, their screenshots in headless Chromium for docs/figures.md, and how long
# a page takes to open: the median of 5 opens, each in a new browser.
#   scripts/replay_pages.sh [OUT_DIR]     (default out/replays; screenshots go to docs/images)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/replays}
hexgait=build/hexgait
python=/usr/bin/python3
[ -x "$hexgait" ] || { echo "build first: cmake --build build" >&2; exit 1; }
mkdir -p "$out"
"$hexgait" replay --genome tests/data/evolved_seed1.genome --cues footprints,swing,strip --no-overlay \
  --out "$out/evolved.html"
"$hexgait" replay --unoptimized --cues footprints,swing,strip --no-overlay --out "$out/unoptimized.html"
shots=(
  "evolved.html|#t=330&view=three-quarter|docs/images/replay_evolved.png"
  "evolved.html|#t=330&view=top|docs/images/replay_evolved_top.png"
  "unoptimized.html|#t=154&view=side|docs/images/replay_unoptimized_fall.png"
)
for shot in "${shots[@]}"; do
  IFS='|' read -r page at png <<<"$shot"
  $python tests/support/replay_browser.py "$out/$page" --at "$at" --size 1280x720 --screenshot "$png"
done
$python tests/support/replay_browser.py "$out/evolved.html" --size 1280x720 --opens 5
"$hexgait" replay --unoptimized --time 100000 --out "$out/long.html"
$python tests/support/replay_browser.py "$out/long.html" --size 1280x720 --opens 5
