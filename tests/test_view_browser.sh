#!/usr/bin/env bash
# The page of `ssgraph view` in a real headless Chromium (Debian's chromium and chromedriver,
# driven by python3-selenium: tests/view_browser.py): it loads the page, checks that it is ES
# modules drawing in WebGL2 and that its tone curves give the CLI's PNG bytes, clicks a node, moves
# a slider, drags the camera, sets an A/B split and checks the canvas pixels, the nodes that
# ran and the metrics; a bad value and a broken graph file show their errors. The server runs
# on a copy of graphs/ssdo_realtime.graph at 160x90 (the copy is what the watcher sees edited
# and where the saved variant goes). Screenshots: $TMP/viewer-*.png (docs/images has copies).
# Everything is reached at 127.0.0.1, never by the name localhost (a minimal system has no
# /etc/hosts): the server, chromedriver, and chromium, which view_browser.py starts itself.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_browser"

source "$(dirname "$0")/view_lib.sh"
view_need_browser

# The copy names its scene by absolute path, so it loads from the scratch folder.
mkdir -p "$TMP/graph"
sed "s|^scene \"\.\./|scene \"$PWD/|" graphs/ssdo_realtime.graph > "$TMP/graph/ssdo_realtime.graph"
# a compare last, as the tutorial's sweep.graph has: its outputs are on-demand and nothing
# reads them, so the last output has no image (the page must open on one that has)
# (FLIP off: HDR-FLIP takes 0.4 s at 160x90, 1.4 s under the sanitizers, and the compare runs
# again with every slider step: the slider drag's runs would be its)
printf '\n# the viewer test: a sink whose outputs nothing reads\nc = compare(img.out, img.out, flip=off)\n' \
    >> "$TMP/graph/ssdo_realtime.graph"
# What the page's shader must show at +1 stop: the CLI's PNGs of a colour and a one-channel
# port under each tone curve.
for curve in clamp reinhard aces; do
    "$BIN" run "$TMP/graph/ssdo_realtime.graph" --size 160x90 --show img.out,f.out --exposure 1 \
        --tonemap "$curve" --out "$TMP/ref_$curve" -q > "$TMP/ref_$curve.log" 2>&1 ||
        fail "ssgraph run --tonemap $curve: $(cat "$TMP/ref_$curve.log")"
done

"$BIN" view "$TMP/graph/ssdo_realtime.graph" --size 160x90 --port 0 > "$TMP/server.log" 2>&1 &
server=$!
trap 'kill "$server" 2> /dev/null' EXIT

# the URL line, once the graph has loaded and run (up to 60 s on busy cores)
url=
for _ in $(seq 600); do
    url=$(grep -o 'http://127\.0\.0\.1:[0-9]*/?token=[0-9a-f]*' "$TMP/server.log" | head -1)
    [ -n "$url" ] || ! kill -0 "$server" 2> /dev/null && break
    sleep 0.1
done
if [ -z "$url" ]; then
    fail "ssgraph view printed no URL: $(cat "$TMP/server.log")"
    finish test_view_browser
fi

/usr/bin/python3 "$(dirname "$0")/view_browser.py" "$url" "$TMP" "$TMP/graph/ssdo_realtime.graph" \
    160x90 "$TMP" ||
    fail "the page in headless chromium (screenshots in $TMP, server log $TMP/server.log)"

# SIGINT ends the server cleanly
kill -INT "$server"
wait "$server"
rc=$?
trap - EXIT
[ "$rc" -eq 0 ] || fail "ssgraph view exited $rc after SIGINT: $(tail -5 "$TMP/server.log")"
finish test_view_browser
