#!/usr/bin/env bash
# 'hexgait report' end to end: a small evolve run, its figures and short movies, the report
# page; then headless Chromium opens the page and must load every image and each video's
# metadata (duration and size), and a screenshot goes to SCREENSHOT for people to look at.
# Exits 77 (skipped) only when no chromium is installed; the checks before it still run.
# Usage: report_test.sh HEXGAIT SOURCE_DIR SCREENSHOT
set -eu
hexgait=$(realpath "$1")
source_dir=$(realpath "$2")
screenshot=$3
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$hexgait" evolve --seed 3 --population 4 --generations 2 --time 200 --quiet --out "$work/run"
"$hexgait" figures --run "$work/run" --time 200 --bench "$source_dir/tests/data/bench_synthetic" \
  --out "$work/figures" >/dev/null
# Movies: short and small. 'hexgait movie' will make all three; until then the comparison
# slot holds a copy of the evolved movie.
mkdir "$work/movies"
unopt_line=$("$hexgait" render --unoptimized --time 50 --size 320x240 \
  --out "$work/movies/unoptimized.mp4")
"$hexgait" render --genome "$work/run/best.genome" --time 50 --size 320x240 \
  --out "$work/movies/evolved.mp4" >/dev/null
cp "$work/movies/evolved.mp4" "$work/movies/comparison.mp4"
"$hexgait" replay --unoptimized --time 50 --out "$work/movies/unoptimized.html" >/dev/null
"$hexgait" replay --genome "$work/run/best.genome" --time 50 \
  --out "$work/movies/evolved.html" >/dev/null
# "wrote FILE: 23 frames, 320x240 at 30 fps ...": the duration every video must report.
[[ $unopt_line =~ ([0-9]+)\ frames,\ 320x240\ at\ ([0-9]+)\ fps ]] || fail "render said: $unopt_line"
expected_duration=$(awk -v f="${BASH_REMATCH[1]}" -v r="${BASH_REMATCH[2]}" 'BEGIN{print f / r}')

# Missing inputs: one line naming the file and the command that makes it, no output folder.
if "$hexgait" report --run "$work/run" --movies "$work/run" --figures "$work/figures" \
     --out "$work/bad" 2>"$work/err"; then fail "report without movies succeeded"; fi
grep -q "no $work/run/unoptimized.mp4: run 'hexgait movie" "$work/err" || fail "$(cat "$work/err")"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one error line"
if "$hexgait" report --run "$work/run" --movies "$work/movies" --figures "$work/run" \
     --out "$work/bad" 2>"$work/err"; then fail "report without figures succeeded"; fi
grep -q "figures.json: run 'hexgait figures" "$work/err" || fail "$(cat "$work/err")"
[ ! -e "$work/bad" ] || fail "a failed report left $work/bad"

# A small repertoire, its movie grid as long and as large as the other movies.
"$hexgait" repertoire --evaluations 120 --batch 40 --bins 3 --time 100 --movie-time 50 \
  --movie-size 320x240 --showcase 4 --quiet --out "$work/repertoire" >/dev/null
# Adapting to a damage from that repertoire, its movie as long and as large as the others.
"$hexgait" adapt --repertoire "$work/repertoire" --damage left_rear:weak=0.5 --movie-time 50 \
  --movie-size 320x240 --out "$work/adapt" >/dev/null
"$hexgait" report --run "$work/run" --movies "$work/movies" --figures "$work/figures" \
  --repertoire "$work/repertoire" --adapt "$work/adapt" --out "$work/report" >/dev/null
page="$work/report/index.html"
grep -q '<h2 id="adapt">' "$page" || fail "no section on adapting to damage"
grep -q '<video controls preload="auto" src="adapt/adapt.mp4">' "$page" || fail "no adapt movie"
grep -q '<video controls preload="auto" src="repertoire/grid.mp4">' "$page" ||
  fail "no movie grid on the page"
grep -q '<img src="repertoire/map.png"' "$page" || fail "no repertoire map on the page"
# Static and self-contained: no scripts, stylesheets or fonts from anywhere, and every file the
# page names is in its folder.
if grep -Eiq '<script|<link|@import|@font-face|https?:' "$page"; then
  fail "index.html refers to something outside itself"
fi
grep -o -E '(src|href)="[^"]+"' "$page" | sed -E 's/^[a-z]+="(.*)"$/\1/; s/#.*//' | sort -u \
  >"$work/refs"
[ "$(wc -l <"$work/refs")" -ge 20 ] || fail "too few references in index.html"
while read -r ref; do
  [ -f "$work/report/$ref" ] || fail "index.html names $ref, which is not in the report folder"
done <"$work/refs"
for movie in unoptimized evolved comparison; do
  grep -q "<video controls preload=\"auto\" src=\"$movie.mp4\">" "$page" || fail "no $movie video"
done
for replay in unoptimized evolved; do
  grep -q "<iframe class=\"replay\" [^>]*src=\"$replay.html#t=0\"" "$page" || fail "no $replay replay"
  cmp -s "$work/movies/$replay.html" "$work/report/$replay.html" || fail "$replay.html not copied"
done
grep -q "<th>seed</th><td>–</td><td class=\"num\">3</td>" "$page" || fail "the seed is not in the results table"

# A second report replaces the first whole; an unfinished repertoire is refused.
"$hexgait" report --run "$work/run" --movies "$work/movies" --figures "$work/figures" \
  --repertoire "$work/repertoire" --adapt "$work/adapt" --out "$work/report" >/dev/null
sed -i 's/state: complete/state: running/' "$work/repertoire/.hexgait-repertoire"
if "$hexgait" report --run "$work/run" --movies "$work/movies" --figures "$work/figures" \
     --repertoire "$work/repertoire" --out "$work/bad" 2>"$work/err"; then
  fail "an unfinished repertoire was accepted"
fi
grep -q "did not finish" "$work/err" || fail "$(cat "$work/err")"

chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  echo "SKIP: no chromium (Debian package 'chromium'; scripts/deps.sh installs it)"
  exit 77
fi
browser=("$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
  --disable-background-networking --disable-component-update --disable-sync
  --user-data-dir="$work/profile")
# The probe runs in a copy of the page, so the report itself stays script-free.
cp "$source_dir/tests/support/report_probe.js" "$work/report/probe.js"
sed 's#</body>#<script src="probe.js"></script></body>#' "$page" >"$work/report/check.html"
timeout 120 "${browser[@]}" --virtual-time-budget=30000 --dump-dom \
  "file://$work/report/check.html" >"$work/dom.html" 2>"$work/chromium.log" ||
  fail "chromium failed: $(tail -3 "$work/chromium.log")"
grep -q '<pre id="results">' "$work/dom.html" || fail "the probe did not report"
images=$(grep -c '^IMG ' "$work/dom.html" || true)
expected_images=$(grep -c '<img ' "$page")
[ "$images" -eq "$expected_images" ] && [ "$images" -ge 9 ] ||
  fail "$images images reported, $expected_images on the page"
if grep '^IMG ' "$work/dom.html" | grep -v ' ok 1200x800$'; then fail "an image did not load"; fi
[ "$(grep -c '^VIDEO ' "$work/dom.html")" -eq 5 ] || fail "not 5 videos"
while read -r _ src ready duration size error; do
  [ "$ready" -ge 1 ] && [ "$error" = noerror ] ||
    fail "$src: no metadata (readyState $ready, $error): can this chromium decode H.264?"
  [ "$size" = 320x240 ] || fail "$src: size $size, expected 320x240"
  awk -v d="$duration" -v e="$expected_duration" 'BEGIN{exit !(d > e - 0.05 && d < e + 0.05)}' ||
    fail "$src: duration $duration, expected $expected_duration"
done < <(grep '^VIDEO ' "$work/dom.html")

mkdir -p "$(dirname "$screenshot")"
rm -f "$screenshot"
timeout 120 "${browser[@]}" --hide-scrollbars --window-size=1280,2000 \
  --virtual-time-budget=10000 --screenshot="$screenshot" "file://$page" \
  >/dev/null 2>>"$work/chromium.log" || fail "chromium screenshot failed"
[ -s "$screenshot" ] || fail "no screenshot"
echo "report checked: $images images, 5 videos of ${expected_duration} s at 320x240;" \
  "screenshot $screenshot"
