# Sourced by the tests that open a page in headless Chromium (report_in_chromium.sh,
# player_in_chromium.sh): load a file with no network, keep its DOM after the scripts ran, and
# check the screenshot.

# render URL SIZE PNG WORK: writes WORK/dom.html (the DOM after parsing and scripts) and the
# screenshot PNG of a window of SIZE ("w,h"); Chromium's messages go to WORK/chromium.log.
render() {
  local url=$1 size=$2 png=$3 work=$4 chromium
  chromium=$(command -v chromium || command -v chromium-browser || true)
  if [ -z "$chromium" ]; then
    echo "chromium is not installed (tools/setup.sh installs it)" >&2
    exit 1
  fi
  local flags=(--headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run --user-data-dir="$work/profile")
  "$chromium" "${flags[@]}" --dump-dom "$url" > "$work/dom.html" 2>"$work/chromium.log"
  "$chromium" "${flags[@]}" --window-size="$size" --screenshot="$png" "$url" >>"$work/chromium.log" 2>&1
}

# check_screenshot PNG: a real PNG, not a mostly blank one (which would mean nothing rendered).
check_screenshot() {
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || { echo "no PNG written" >&2; exit 1; }
  [ "$(stat -c %s "$1")" -gt 20000 ] || { echo "screenshot suspiciously small" >&2; exit 1; }
}
