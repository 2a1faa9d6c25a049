#!/usr/bin/env bash
# `hexgait compare` and `--expect`: golden-image checks of PNG stills and of movies frame by
# frame. Exit 0 when the files match within the tolerance, 1 when they differ (a one-line
# summary, a diff image that shows where), 2 when they cannot be compared (nothing written, no
# input changed).
#   usage: compare_test.sh HEXGAIT
set -euo pipefail
hexgait=$(realpath "$1")
support=$(realpath "$(dirname "$0")/../support")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# check STATUS PATTERN ARGS...: hexgait ARGS exits STATUS and its output contains PATTERN.
check() {
  local want=$1 pattern=$2
  shift 2
  local status=0
  "$hexgait" "$@" >out.txt 2>&1 || status=$?
  [ "$status" = "$want" ] || fail "$* exited $status, expected $want: $(cat out.txt)"
  grep -q -- "$pattern" out.txt || fail "$*: no '$pattern' in: $(cat out.txt)"
}

# Images: 320x240 = 76,800 pixels; the rule allows 0.02 % (15 pixels) off by more than 24 levels.
python3 "$support/make_png.py" base.png 320 240
python3 "$support/make_png.py" few.png 320 240 15 100    # 15 pixels: within the tolerance
python3 "$support/make_png.py" many.png 320 240 16 100   # 16: over it
python3 "$support/make_png.py" faint.png 320 240 300 24  # 300 pixels by 24 levels: not different
python3 "$support/make_png.py" small.png 160 120
check 0 "match: 0 of 76800 pixels" compare base.png base.png
check 0 "match: 15 of 76800 pixels" compare base.png few.png
check 0 "match: 0 of 76800 pixels .* largest change 24" compare base.png faint.png
check 1 "differ: 16 of 76800 pixels (0.02083%) differ by more than 24 levels" \
  compare base.png many.png --diff diff.png
[ "$(head -1 out.txt | wc -l)" = 1 ] || fail "the summary is not one line"
[ -f diff.png ] || fail "no diff image"
# The diff: the 16 changed pixels in red, everything else a faded copy of the expected image.
check 1 "differ: 76800 of 76800" compare diff.png base.png --pixel-threshold 0
check 0 "match" compare base.png many.png --tolerance 0.001
check 1 "differ: 300 of 76800" compare base.png faint.png --pixel-threshold 23
check 1 "differ: sizes differ: expected 320x240, actual 160x120" compare base.png small.png \
  --diff nodiff.png
[ ! -e nodiff.png ] || fail "a diff image of images of different sizes"

# Movies, frame by frame: the same run twice, another genome, a shorter run, a smaller frame.
movie=(render --time 6 --speed 1 --size 160x120 --fps 5)
"$hexgait" "${movie[@]}" --out a.mp4 >/dev/null
"$hexgait" "${movie[@]}" --out b.mp4 >/dev/null
"$hexgait" "${movie[@]}" --damage left_front:locked --out damaged.mp4 >/dev/null
"$hexgait" render --time 3 --speed 1 --size 160x120 --fps 5 --out short.mp4 >/dev/null
"$hexgait" render --time 6 --speed 1 --size 96x64 --fps 5 --out tiny.mp4 >/dev/null
check 0 "match: 0 of 3[0-9] frames over the tolerance" compare a.mp4 b.mp4
check 1 "differ: [0-9]* of 3[0-9] frames over the tolerance; worst frame" \
  compare a.mp4 damaged.mp4 --diff movie_diff.png
[ -f movie_diff.png ] || fail "no diff image of the worst frame"
check 1 "differ: frame counts differ: expected 3[0-9], actual 1[0-9]" compare a.mp4 short.mp4
check 1 "differ: frame sizes differ: expected 160x120, actual 96x64" compare a.mp4 tiny.mp4

# Cannot compare: exit 2, one line, nothing written, the inputs unchanged.
sum_before=$(cat base.png a.mp4 | md5sum)
check 2 "is not a file" compare base.png missing.png
check 2 "is not a movie like expected" compare a.mp4 base.png
check 2 "not a .png image or a .mp4" compare out.txt base.png
check 2 "--tolerance must be between 0 and 1" compare base.png base.png --tolerance 2
check 2 "--pixel-threshold must be between 0 and 255" compare base.png base.png \
  --pixel-threshold 256
check 2 "is the same file as the input" compare base.png many.png --diff base.png
check 2 "expected a name ending in .png" compare base.png many.png --diff d.jpg
[ "$(wc -l <out.txt)" = 1 ] || fail "an error of more than one line"
head -c 3000 a.mp4 >cut.mp4  # a movie cut short: FFmpeg's reason in the one line, not its log
check 2 "cut.mp4: corrupt video stream (Invalid data" compare a.mp4 cut.mp4
[ "$(wc -l <out.txt)" = 1 ] || fail "a movie cut short gave more than one line: $(cat out.txt)"
[ "$(cat base.png a.mp4 | md5sum)" = "$sum_before" ] || fail "an input changed"
[ ! -e d.jpg ] || fail "a diff written after an error"

# --expect: render, then compare with the approved file in one step.
"$hexgait" still --size 320x240 --out approved.png >/dev/null
check 0 "--expect: match" still --size 320x240 --out again.png --expect approved.png
[ ! -e again.diff.png ] || fail "a diff beside a matching still"
check 1 "--expect: differ" still --size 320x240 --time 2 --out later.png --expect approved.png
[ -f later.png ] && [ -f later.diff.png ] || fail "a differing still or its diff missing"
"$hexgait" filmstrip --size 320x240 --out strip.png >/dev/null
check 0 "--expect: match" filmstrip --size 320x240 --out strip2.png --expect strip.png
check 1 "--expect: differ" filmstrip --size 320x240 --unoptimized --cycle 2 --out strip3.png \
  --expect strip.png
check 0 "--expect: match: 0 of 3[0-9] frames" "${movie[@]}" --out c.mp4 --expect a.mp4
check 1 "--expect: differ" "${movie[@]}" --damage left_front:locked --out d.mp4 --expect a.mp4
[ -f d.diff.png ] || fail "no diff beside a differing movie"
check 1 "is not a file" still --out x.png --expect missing.png
[ ! -e x.png ] || fail "a still written although --expect was missing"
check 1 "is not the same kind of file" render --out y.mp4 --expect approved.png
[ ! -e y.mp4 ] || fail "a movie written although --expect was of another kind"

[ "$failures" = 0 ] || { echo "$failures failures"; exit 1; }
echo "compare: every case passed"
