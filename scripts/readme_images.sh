#!/usr/bin/env bash
# Re-makes the pictures in README.md (docs/images/) from a build: Figure 1, and filmstrips of
# gait cycle 3 for the evolved program of `evolve --seed 1` and for the unoptimized program.
set -euo pipefail
cd "$(dirname "$0")/.."
hexgait=${HEXGAIT:-build/hexgait}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$hexgait" evolve --seed 1 --quiet --out "$work/run"
"$hexgait" still --size 640x360 --msaa 4 --out docs/images/figure1.png
"$hexgait" filmstrip --genome "$work/run/best.genome" --size 260x200 --out docs/images/filmstrip_evolved.png
"$hexgait" filmstrip --unoptimized --size 260x200 --out docs/images/filmstrip_unoptimized.png
