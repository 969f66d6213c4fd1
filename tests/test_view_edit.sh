#!/usr/bin/env bash
# The graph editor of `ssgraph view`'s page in a real headless Chromium (tests/view_edit.py,
# the same tools as test_view_browser.sh): add a node from the type menu, rewire an input,
# remove a node (and be refused removing one that others read, at file:line:column), save
# as a new graph file, and check that `ssgraph check` / `ssgraph dot` of the saved file give
# the nodes and connections of the page's /api/state. The server runs on a copy of
# graphs/ssdo_realtime.graph at 160x90 with a compare appended (a node nothing reads, to
# remove). Screenshots: $TMP/viewer-edit-*.png.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_edit"

source "$(dirname "$0")/view_lib.sh"
view_need_browser

mkdir -p "$TMP/graph" "$TMP/home"
G=$TMP/graph/ssdo_realtime.graph
sed "s|^scene \"\.\./|scene \"$PWD/|" graphs/ssdo_realtime.graph > "$G"
printf '\n# the editor test: a sink nothing reads, to remove\nc = compare(img.out, img.out)\n' >> "$G"
export HOME=$TMP/home XDG_CONFIG_HOME=$TMP/home XDG_CACHE_HOME=$TMP/home

view_start "$TMP/server.log" "$G" --size 160x90 --port 0 ||
    { fail "ssgraph view printed no URL"; finish test_view_edit; }
url="$B/?token=$token"

/usr/bin/python3 "$(dirname "$0")/view_edit.py" "$url" "$TMP" "$G" "$BIN" ||
    fail "the editor in headless chromium (screenshots in $TMP, server log $TMP/server.log)"
view_stop_within 10000 INT
finish test_view_edit
