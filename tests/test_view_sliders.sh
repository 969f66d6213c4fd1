#!/usr/bin/env bash
# The viewer's number sliders span each parameter's useful range (its soft_min .. soft_max),
# in a real headless Chromium (tests/view_sliders.py; Debian's chromium, chromedriver and
# python3-selenium, everything at 127.0.0.1, as test_view_browser.sh): do.radius of
# graphs/ssdo_realtime.graph at 160x90 has its ends at 0.05 and 5, a 30 px drag moves it by
# less than a factor 4, and a valid value typed outside the range is kept and widens the
# slider. Screenshots: $TMP/viewer-sliders*.png.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_sliders"
source "$(dirname "$0")/view_lib.sh"
view_need_browser

# The copy names its scene by absolute path, so it loads from the scratch folder.
mkdir -p "$TMP/graph"
sed "s|^scene \"\.\./|scene \"$PWD/|" graphs/ssdo_realtime.graph > "$TMP/graph/ssdo_realtime.graph"
view_start "$TMP/server.log" "$TMP/graph/ssdo_realtime.graph" --size 160x90 --port 0 || {
    fail "ssgraph view printed no URL"; finish test_view_sliders; }

/usr/bin/python3 "$(dirname "$0")/view_sliders.py" "$B/?token=$token" "$TMP" ||
    fail "the sliders in headless chromium (screenshots in $TMP, server log $TMP/server.log)"
view_stop_within 10000 INT
finish test_view_sliders
