#!/usr/bin/env bash
# Opens a voxel world's 3D page (aco/drawing/voxel_html.hpp) in headless Chromium with WebGL drawn by
# SwiftShader (software: no GPU needed, the same pixels everywhere): the page must load from disk
# with no network, its script must draw (data-rendered on <body>), and the screenshot must show the
# voxels, the path, the start and the goal in their colours (tests/voxel_page_check.py). The SVG
# of the same world must be well-formed XML. Skipped (77) where Chromium is not installed.
#   tests/voxel_page_in_chromium.sh ACO_VOXEL_SAMPLE WORK_DIR
set -euo pipefail
sample=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  echo "SKIPPED: chromium is not installed (tools/setup.sh installs it)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
"$sample" small "$work/world.html" "$work/world.svg"
/usr/bin/python3 -c "import sys, xml.etree.ElementTree as t; t.parse(sys.argv[1])" "$work/world.svg"
# --use-angle=swiftshader --enable-unsafe-swiftshader: WebGL in software (Chromium refuses
# SwiftShader for WebGL without the second flag); --use-gl=swiftshader is gone from Chromium.
flags=(--headless --no-sandbox --disable-dev-shm-usage --no-first-run --hide-scrollbars
       --use-angle=swiftshader --enable-unsafe-swiftshader --force-device-scale-factor=1
       --window-size=800,600 --user-data-dir="$work/profile")
"$chromium" "${flags[@]}" --dump-dom "file://$work/world.html" > "$work/dom.html" 2>"$work/chromium.log"
rendered=$(grep -oE '<body[^>]*>' "$work/dom.html" | grep -oE 'data-rendered="[0-9]+"' || true)
error=$(grep -oE '<body[^>]*data-error="[^"]*"' "$work/dom.html" | sed -E 's/.*data-error="//; s/"$//' || true)
echo "page: $(stat -c %s "$work/world.html") bytes; script: ${rendered:-did not draw} ${error:+(error: $error)}"
[ -n "$rendered" ] || { echo "the page's script did not draw (see $work/dom.html, $work/chromium.log)" >&2; exit 1; }
"$chromium" "${flags[@]}" --screenshot="$work/world.png" "file://$work/world.html" >>"$work/chromium.log" 2>&1
# The legend is a column 280 pixels wide: only the 3D view right of it is checked.
/usr/bin/python3 "$here/voxel_page_check.py" "$work/world.png" 280
echo "voxel page: ok ($work/world.png)"
