#!/usr/bin/env bash
# The image viewer of `ssgraph view` in headless Chromium (tests/view_zoom.py, with
# view_page.py's helpers; the same packages as test_view_browser.sh): wheel zoom about the
# mouse to single pixels with a readout that names them, Ctrl + wheel for the camera, 1:1
# and fit; the A/B difference modes (|A - B|, A - B, relative, FLIP) against the floats the
# server sends, the scale bar; X swaps A and B; an EXR written by `ssgraph run --show
# img.out --out` opens as the reference (and a missing or non-EXR path shows an error).
# graphs/ssdo_realtime.graph at 160x90. Screenshots: $TMP/viewer-*.png.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_zoom"

source "$(dirname "$0")/view_lib.sh"
view_need_browser test_view_zoom

mkdir -p "$TMP/home"
export HOME=$TMP/home XDG_CONFIG_HOME=$TMP/home XDG_CACHE_HOME=$TMP/home
"$BIN" run graphs/ssdo_realtime.graph --size 160x90 --show img.out --out "$TMP/cli" -q \
    > "$TMP/cli.log" 2>&1 || fail "ssgraph run --show img.out: $(cat "$TMP/cli.log")"

view_start "$TMP/server.log" graphs/ssdo_realtime.graph --size 160x90 --port 0 || {
    fail "ssgraph view printed no URL"; finish test_view_zoom; }

/usr/bin/python3 "$(dirname "$0")/view_zoom.py" "$B/?token=$token" "$TMP" "$TMP/cli/img.out.exr" ||
    fail "the image viewer in headless chromium (screenshots in $TMP, server log $TMP/server.log)"

view_stop_within 10000 INT
finish test_view_zoom
