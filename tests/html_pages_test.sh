#!/usr/bin/env bash
# The HTML pages open in a browser and draw: a case view (a hand-computed
# case, and a failing one) and the reports of `check` and `diff`, each opened
# in headless Chromium, its DOM read after the scripts ran and a screenshot
# taken. A page passes when no script error was recorded, its canvases were
# drawn with ink, and its SVG charts hold elements. Two broken pages (a
# script error; a view with no data) must fail the same test, so that the
# test is seen to fail. Screenshots stay in OUT (default: a temporary folder).
#
#   tests/html_pages_test.sh MANIFUZZ SOURCE_DIR PLUGIN_DIR [OUT]
set -euo pipefail
manifuzz=$1 source=$2 plugins=$3
out=${4:-$(mktemp -d)}
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "FAIL: no chromium (scripts/bootstrap.sh --tests installs it)"
  exit 1
fi

# Chromium as root needs --no-sandbox; its own profile keeps runs apart.
# One launch reads the page after its scripts ran and takes its screenshot.
open_page() {  # open_page FILE PNG -> the DOM on stdout, the screenshot in PNG
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run \
    --user-data-dir="$work/profile" --hide-scrollbars --window-size=1300,1500 --screenshot="$2" \
    --dump-dom "file://$1" 2>/dev/null
}
body_number() {  # body_number DOM NAME -> the body's data-NAME, or -1
  sed -n "s/.*<body[^>]*data-$2=\"\\([0-9]*\\)\".*/\\1/p" <<<"$1" | head -1 | grep . || echo -1
}

# page_drew FILE CANVASES SVGS PNG: true when the page drew at least that
# many canvases (with ink) and SVGs with elements, recorded no script error,
# and its screenshot is not blank.
page_drew() {
  local dom drawn inked svgs bytes
  dom=$(open_page "$1" "$4")
  if grep -q '<html[^>]*data-script-error=' <<<"$dom"; then
    echo "  $(basename "$1"): script error: $(sed -n 's/.*<html[^>]*data-script-error="\([^"]*\)".*/\1/p' <<<"$dom" | head -1)"
    return 1
  fi
  drawn=$(body_number "$dom" drawn) inked=$(body_number "$dom" inked) svgs=$(body_number "$dom" svgs)
  bytes=$(stat -c %s "$4" 2>/dev/null || echo 0)
  echo "  $(basename "$1"): canvases $drawn, inked pixels $inked, SVGs with elements $svgs, screenshot $bytes bytes"
  [ "$drawn" -ge "$2" ] && [ "$inked" -ge $((2000 * $2)) ] && [ "$svgs" -ge "$3" ] && [ "$bytes" -ge 20000 ]
}

fail=0
check_page() {  # check_page FILE CANVASES SVGS
  if ! page_drew "$1" "$2" "$3" "$out/$(basename "$1" .html).png"; then
    echo "FAIL: $1 did not draw"
    fail=1
  fi
}

echo "== case views"
"$manifuzz" render "$source/corpus/box_on_box.case" -o "$work/box_on_box.html"
status=0
"$manifuzz" render --generator "$plugins/libmanifuzz_tutorial.so" \
  "$source/corpus/regressions/f1-frustum-side-planes-slope-inwards.case" -o "$work/f1_tutorial.html" || status=$?
[ "$status" -eq 1 ] || { echo "FAIL: render of a failing case ended $status, not 1"; fail=1; }
check_page "$work/box_on_box.html" 1 1
check_page "$work/f1_tutorial.html" 1 1
grep -q 'on-surface' "$work/f1_tutorial.html" || { echo "FAIL: the failing case's view does not name its check"; fail=1; }

echo "== reports"
status=0
"$manifuzz" check --generator "$plugins/libmanifuzz_tutorial.so" --cases 400 --seed 1 --quiet \
  --out "$work/failures" --report "$work/check" >/dev/null 2>&1 || status=$?
[ "$status" -eq 1 ] || { echo "FAIL: check on the tutorial ended $status, not 1"; fail=1; }
cp "$work/check/report.html" "$work/check_report.html"
check_page "$work/check_report.html" 1 4
status=0
"$manifuzz" diff --generator builtin --against "$plugins/libmanifuzz_tutorial.so" --cases 150 --seed 2 --quiet \
  --out "$work/diff-failures" --report "$work/diff" >/dev/null 2>&1 || status=$?
[ "$status" -le 1 ] || { echo "FAIL: diff ended $status"; fail=1; }
cp "$work/diff/report.html" "$work/diff_report.html"
check_page "$work/diff_report.html" 0 2

echo "== the test fails on broken pages"
# The error comes before the viewer, which still draws: only the trap sees it.
sed 's|<h1>|<script>window.noSuchObject.call();</script><h1>|' "$work/box_on_box.html" > "$work/script_error.html"
sed 's|class="case-data">[^<]*<|class="case-data">[]<|' "$work/box_on_box.html" > "$work/no_data.html"
for broken in script_error no_data; do
  if page_drew "$work/$broken.html" 1 1 "$work/$broken.png"; then
    echo "FAIL: the broken page $broken passed"
    fail=1
  fi
done

[ "$fail" -eq 0 ] && echo "PASS: every page drew; screenshots in $out"
exit "$fail"
