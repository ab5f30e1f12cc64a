#!/usr/bin/env bash
# Renders facetc's HTML report in headless Chromium (Debian's chromium) and
# checks the screenshot: both inline SVG charts must be drawn, i.e. pixels
# of the set-bar and time-bar colours (compiler/src/report/html.cpp) appear,
# and the rendered DOM holds their bars.
# Usage: html_report_screenshot_test.sh FACETC SOURCE_DIR WORK_DIR
set -euo pipefail
facetc=$1 source=$2 work=$3
command -v chromium > /dev/null || { echo "chromium is not installed: run scripts/install-deps.sh"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
"$facetc" --report=html -o "$work/report.html" \
  "$source/examples/shaders/Keywords.shader" "$source/examples/shaders/PhongMultiLight.shader"
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --hide-scrollbars "--user-data-dir=$work/profile")
timeout 120 chromium "${flags[@]}" --window-size=1280,1800 "--screenshot=$work/report.png" \
  "file://$work/report.html" > "$work/chromium.log" 2>&1 || { cat "$work/chromium.log"; exit 1; }
test -s "$work/report.png" || { echo "no screenshot"; cat "$work/chromium.log"; exit 1; }
timeout 120 chromium "${flags[@]}" --dump-dom "file://$work/report.html" > "$work/dom.html" 2> /dev/null
bars=$(grep -o 'class="bar"' "$work/dom.html" | wc -l)
charts=$(grep -o '<svg class="chart-' "$work/dom.html" | wc -l)
echo "rendered DOM: $charts charts, $bars bars"
[ "$charts" -ge 4 ] && [ "$bars" -ge 8 ] || { echo "the charts are missing from the rendered page"; exit 1; }
# Pixel counts of the two bar colours (sRGB bytes / 255), alpha ignored.
counts=$(oiiotool "$work/report.png" --ch R,G,B \
  --colorcount:eps=0.02,0.02,0.02 "0.1843,0.4353,0.8745;0.9098,0.5765,0.0471" 2>&1)
echo "$counts"
# oiiotool prints "<count>  <colour>" per colour, in the order given.
set_px=$(echo "$counts" | awk '$2 ~ /^0\.1843,/ {print $1; exit}')
time_px=$(echo "$counts" | awk '$2 ~ /^0\.9098,/ {print $1; exit}')
echo "set-bar pixels: ${set_px:-0}, time-bar pixels: ${time_px:-0}"
[ "${set_px:-0}" -gt 500 ] && [ "${time_px:-0}" -gt 500 ] || { echo "a chart is not drawn in the screenshot"; exit 1; }
echo "HTML report renders with its charts"
