#!/usr/bin/env bash
# The viewer's camera and history (issue 46): the camera panel, keyboard fly, undo/redo and
# camera path recording in a real headless Chromium (tests/view_camera.py, as
# test_view_browser.sh drives view_browser.py), on a copy of graphs/ssdo_realtime.graph at
# 160x90 with examples/cornell_path.scene, a scene that has a camera path of its own. Then:
# - the saved flight.scene includes that scene and its 3 camera_key lines replace its path:
#   `run --frames 3` accepts it, its last frame differs from its first, and its first frame
#   is the pixels of the scene rewritten by hand with the first key as its camera line;
# - POST /api/save_path refuses a bad name (400), bad keys (400), a name that exists in any
#   form (409: a file, a FIFO, never opened);
# - a scene's include: a cycle and a bad include are errors at file:line:col; an included
#   mesh loads from its own folder and `check` names its own file's line.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_camera"
source "$(dirname "$0")/view_lib.sh"
ROOT=$(pwd)

# what view_camera.py needs (tools/debian-packages-test.txt), every missing one named
missing=$(for t in /usr/bin/chromium /usr/bin/chromedriver /usr/bin/python3; do
    [ -x "$t" ] || printf '%s ' "$t"; done)
/usr/bin/python3 -c 'import selenium' 2> /dev/null || missing="${missing}python3-selenium"
if [ -n "$missing" ]; then
    fail "missing: $missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
    finish test_view_camera
fi

G=$TMP/graph/ssdo_realtime.graph
mkdir -p "$TMP/graph" "$TMP/home"
sed "s|^scene \"\.\./|scene \"$ROOT/|" graphs/ssdo_realtime.graph > "$G"
export HOME=$TMP/home XDG_CONFIG_HOME=$TMP/home XDG_CACHE_HOME=$TMP/home
view_start "$TMP/server.log" "$G" --scene examples/cornell_path.scene --size 160x90 \
    --threads 2 || { fail "ssgraph view printed no URL"; finish test_view_camera; }

if /usr/bin/python3 "$(dirname "$0")/view_camera.py" "$B/?token=$token" "$TMP" > "$TMP/page.log" 2>&1; then
    cat "$TMP/page.log"
else
    fail "the page in headless chromium: $(cat "$TMP/page.log") (screenshots in $TMP)"
fi

# --- the saved path: 3 keys after an include of the server's scene, and it flies
S=$TMP/graph/flight.scene
[ -f "$S" ] || fail "the page saved no $S"
run_show() { # OUT SCENE FRAMES: img.out of the graph's last frame into $TMP/OUT
    "$BIN" run "$G" --scene "$2" --size 160x90 --frames "$3" --show img.out --out "$TMP/$1" \
        -q > "$TMP/$1.log" 2>&1 || fail "run --scene $2 --frames $3: $(cat "$TMP/$1.log")"
}
if [ -f "$S" ]; then
    [ "$(grep -c '^camera_key(' "$S")" = 3 ] || fail "flight.scene has not 3 camera_key lines: $(cat "$S")"
    grep -qxF "include \"$ROOT/examples/cornell_path.scene\"" "$S" ||
        fail "flight.scene does not include the server's scene: $(cat "$S")"
    run_show f1 "$S" 1
    run_show f3 "$S" 3
    cmp -s "$TMP/f1/img.out.exr" "$TMP/f3/img.out.exr" &&
        fail "frames 0 and 2 of flight.scene are the same image: the path does not move"
    # frame 0 is the first key: the scene by hand, its path gone and that key its camera
    key=$(grep -m1 '^camera_key(' "$S")
    pos=$(sed 's/.*position=\(\[[^]]*\]\).*/\1/' <<< "$key")
    tgt=$(sed 's/.*target=\(\[[^]]*\]\).*/\1/' <<< "$key")
    fov=$(sed 's/.*fov=\([0-9.e+-]*\).*/\1/' <<< "$key")
    grep -v '^camera_key(\|^camera(' examples/cornell_path.scene > "$TMP/graph/by_hand.scene"
    echo "camera(position=$pos, target=$tgt, fov=$fov, near=0.05, far=20)" >> "$TMP/graph/by_hand.scene"
    run_show h1 "$TMP/graph/by_hand.scene" 1
    cmp -s "$TMP/f1/img.out.exr" "$TMP/h1/img.out.exr" ||
        fail "frame 0 of flight.scene differs from its first key as a camera line: the scene's own path was not replaced"
fi

# --- the endpoint's refusals
K='0,0,1,3.9,0,1,0,0,1,0,40;1,0.5,1,3.5,0,1,0,0,1,0,40'
post_path() { expect_code "$1" --max-time 20 -H "$H" -d "$2" "$B/api/save_path"; }
post_path 400 "name=../evil&keys=$K"
post_path 400 "name=a.b&keys=$K"
post_path 400 "name=k1&keys=0,1,2"
post_path 400 "name=k1&keys=0,0,1,3.9,0,1,0,0,1,0,40"
post_path 400 "name=k1&keys=1,0,1,3.9,0,1,0,0,1,0,40;0.5,0,1,3.5,0,1,0,0,1,0,40"
post_path 400 "name=k1&keys=0,0,1,3.9,0,1,0,0,1,0,400;1,0,1,3.5,0,1,0,0,1,0,40"
post_path 400 "name=k1"
post_path 200 "name=k2&keys=$K"
post_path 409 "name=k2&keys=$K"
mkfifo "$TMP/graph/fifo.scene"
post_path 409 "name=fifo&keys=$K"
ls "$TMP/graph" | grep -q 'tmp-' && fail "a refused save left a temporary file: $(ls "$TMP/graph")"
"$BIN" check "$TMP/graph/k2.scene" > "$TMP/k2.log" 2>&1 || fail "k2.scene does not load: $(cat "$TMP/k2.log")"
view_stop_within 10000 INT

# --- include in scene files: a cycle and a bad argument are errors where they are written
printf 'include "b.scene"\n' > "$TMP/graph/a.scene"
printf '\ninclude "a.scene"\n' > "$TMP/graph/b.scene"
"$BIN" check "$TMP/graph/a.scene" > "$TMP/cycle.log" 2>&1 && fail "an include cycle loaded"
grep -q 'a.scene:1:9: error.*included more than 16 deep' "$TMP/cycle.log" ||
    fail "the include cycle's error: $(cat "$TMP/cycle.log")"
printf 'include 3\n' > "$TMP/graph/bad.scene"
"$BIN" check "$TMP/graph/bad.scene" > "$TMP/bad.log" 2>&1 && fail "include 3 loaded"
grep -q 'bad.scene:1:1: error.*include takes one file name' "$TMP/bad.log" ||
    fail "include 3's error: $(cat "$TMP/bad.log")"
# an included scene's mesh: found in its own folder, reported at its own file's line
printf 'include "%s/examples/bunny.scene"\n' "$ROOT" > "$TMP/graph/bunny_again.scene"
"$BIN" check "$TMP/graph/bunny_again.scene" > "$TMP/bunny.log" 2>&1 || fail "bunny_again.scene: $(cat "$TMP/bunny.log")"
grep -q "^    $ROOT/examples/bunny.scene:[0-9]*:[0-9]*: mesh \"bunny.gltf\"" "$TMP/bunny.log" &&
    grep -q '^      up: +Y' "$TMP/bunny.log" ||
    fail "the included mesh's line or up axis: $(cat "$TMP/bunny.log")"
finish test_view_camera
