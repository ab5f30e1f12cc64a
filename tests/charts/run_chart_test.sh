#!/usr/bin/env bash
# Draws one chart with the facet tool, renders it in headless Chromium
# (Debian's chromium) with chart_check.js, and asserts the checker's verdict:
# labels pairwise disjoint, every curve and point visible (chart_check.js
# says exactly what is checked). The figure cases also compare the chart
# with the one committed under docs/figures, so the docs show what the code
# draws; the checker cases feed it a chart that must fail.
# Usage: run_chart_test.sh FACET SOURCE_DIR WORK_DIR CASE
set -euo pipefail
facet=$1 source=$2 work=$3 case=$4
command -v chromium > /dev/null || { echo "chromium is not installed: run scripts/install-deps.sh"; exit 1; }
here=$source/tests/charts
figures=$source/docs/figures
rm -rf "$work"
mkdir -p "$work"
chart=$work/chart.svg

# check_page SVG: the verdict line of chart_check.js on a page holding SVG.
check_page() {
  {
    printf '<!DOCTYPE html>\n<html><head><meta charset="utf-8"></head><body style="margin:0">\n'
    cat "$1"
    printf '<pre id="verdict">NOT RUN</pre>\n<script>\n'
    cat "$here/chart_check.js"
    printf '</script></body></html>\n'
  } > "$work/page.html"
  local flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
               --disable-component-update --disable-sync --hide-scrollbars "--user-data-dir=$work/profile"
               --window-size=1400,2600)
  timeout 120 chromium "${flags[@]}" --dump-dom "file://$work/page.html" > "$work/dom.html" 2> "$work/chromium.log" ||
    { cat "$work/chromium.log"; exit 1; }
  sed -n 's/.*<pre id="verdict">\([^<]*\)<\/pre>.*/\1/p' "$work/dom.html" | sed 's/&amp;/\&/g; s/&quot;/"/g'
}

# expect VERDICT_PATTERN: the verdict must match the extended regex, whole.
expect() {
  local verdict
  verdict=$(check_page "$chart")
  echo "verdict: $verdict"
  [[ $verdict =~ ^$1$ ]] || { echo "expected: $1"; exit 1; }
}

# same_as FIGURE: the chart is the committed figure, byte for byte.
same_as() {
  cmp -s "$chart" "$figures/$1" || {
    echo "docs/figures/$1 is not what the code draws now; regenerate it (docs/accuracy.md or docs/brdf-explorer.md says how)"
    exit 1
  }
}

case $case in
  accuracy-h200)
    "$facet" bench accuracy --from "$figures/accuracy-h200.json" --out "$chart"
    expect 'PASS [0-9]+ labels disjoint, 0 curves visible, 52 points visible'
    ! grep -q 'class="caveat"' "$chart" || { echo "a caveat on GPU timings"; exit 1; }
    same_as accuracy-pareto-h200.svg ;;
  accuracy-lavapipe)
    # The same rows as if timed on lavapipe: the chart must say that its times are relative only.
    sed 's/"device": "NVIDIA H200"/"device": "llvmpipe (LLVM 15.0.6, 256 bits)"/; s/"device_type": "discrete-gpu"/"device_type": "cpu"/' \
      "$figures/accuracy-h200.json" > "$work/lavapipe.json"
    "$facet" bench accuracy --from "$work/lavapipe.json" --out "$chart"
    expect 'PASS [0-9]+ labels disjoint, 0 curves visible, 52 points visible'
    grep -q 'class="caveat"[^>]*>Caveat: times measured on lavapipe, a CPU implementation of Vulkan: relative only' "$chart" ||
      { echo "no caveat on lavapipe timings"; exit 1; } ;;
  accuracy-crowded)
    # Every row timed within 8 % of 0.3 ps: the labels need leader lines and the numbered legend.
    awk '/"ns_per_eval": [0-9]/ { n++; sub(/"ns_per_eval": [0-9.e-]+/, sprintf("\"ns_per_eval\": %.8f", 0.0003 * (1 + (n % 5) * 0.02))) }
         { print }' "$figures/accuracy-h200.json" > "$work/crowded.json"
    "$facet" bench accuracy --from "$work/crowded.json" --out "$chart"
    expect 'PASS [0-9]+ labels disjoint, 0 curves visible, 52 points visible'
    grep -q 'class="leader"' "$chart" && grep -q 'class="legend"' "$chart" ||
      { echo "the crowded chart has no leader line or no numbered legend: it does not test them"; exit 1; } ;;
  brdf-polar)
    "$facet" brdf ggx:roughness=0.5 ggx-fast:roughness=0.5 ggx-schlick:roughness=0.5 ggx-karis:roughness=0.5 \
      --view polar --incidence 75 -o "$chart"
    expect 'PASS [0-9]+ labels disjoint, 4 curves visible, 0 points visible'
    same_as brdf-polar-visibility.svg ;;
  brdf-albedo)
    "$facet" brdf ggx:roughness=1,f0=1 ggx-ms:roughness=1,f0=1 burley:roughness=1 --view albedo -o "$chart"
    expect 'PASS [0-9]+ labels disjoint, 3 curves visible, 0 points visible'
    same_as brdf-albedo-energy.svg ;;
  brdf-coincident)
    # Three identical curves: each must still show.
    "$facet" brdf lambert lambert:albedo=1 lambert --view polar -o "$chart"
    expect 'PASS [0-9]+ labels disjoint, 3 curves visible, 0 points visible' ;;
  checker-overlap)
    cp "$here/overlapping_labels.svg" "$chart"
    expect 'FAIL labels overlap: "F_Schlick" x "F_SchlickSG"' ;;
  checker-hidden)
    cp "$here/hidden_curve.svg" "$chart"
    expect 'FAIL curve 0 is hidden: none of its 1 markers is on top; curves 0 and 1 share a style \(#1f77b4 solid circle\)' ;;
  *)
    echo "unknown case '$case'"; exit 2 ;;
esac
echo "chart check '$case' passed"
