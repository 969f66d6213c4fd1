#!/usr/bin/env bash
# `ssgraph view` over HTTP, from outside (tests/view_client.py; curl for the raw requests):
# - safety: no token, a wrong token (one that differs from it in the last character only),
#   a foreign Host (DNS rebinding) or Origin: 403; paths that try to leave the page (../,
#   encoded): 404; a body over 64 KiB: 413 (announced or chunked); a method it does not
#   serve: 405; many clients at once: every answer whole, the server alive and its state
#   consistent;
# - a parameter change re-runs only the changed node and those after it (the stats say
#   which ran), its image is bit for bit what `ssgraph run --show` writes with the same
#   --set; a refused value answers 400 with file:line:col and changes nothing;
# - the camera (preview size while dragging), metrics, the diagram, save as variant (the
#   variant then runs from the command line to the same pixels), the file watcher (an
#   edit reloads, a broken graph shows its error at file:line:col and keeps serving, the
#   fix clears it), SIGTERM ends it with status 0.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_http"
source "$(dirname "$0")/view_lib.sh"
ROOT=$(pwd)
mkdir -p "$TMP/graphs"
cp graphs/ssdo_realtime.graph "$TMP/graphs/"
G=$TMP/graphs/ssdo_realtime.graph
SIZE=96x54
common=(--scene "$ROOT/examples/cornell.scene" --size $SIZE --threads 2)

view_start "$TMP/view.log" "$G" "${common[@]}" --out "$TMP/out" || {
    fail "no URL printed"; finish test_view_http; }
client() { python3 "$ROOT/tests/view_client.py" "$B" "$token" "$@"; }

# --- safety
expect_code 403 "$B/api/state"
expect_code 403 "$B/api/state?token=0123456789abcdef0123456789abcdef"
expect_code 403 -H "X-SSG-Token: ${token}0" "$B/api/state"
# near misses: the token with only its last (or only its first) character changed, each way
# a token may come (a compare that stops before the end lets the first through)
last=${token: -1}; first=${token:0:1}
near_last=${token:0:31}$([ "$last" = 0 ] && echo 1 || echo 0)
near_first=$([ "$first" = 0 ] && echo 1 || echo 0)${token:1}
for near in "$near_last" "$near_first"; do
    expect_code 403 "$B/api/state?token=$near"
    expect_code 403 -H "X-SSG-Token: $near" "$B/api/state"
    expect_code 403 -b "ssg_token=$near" "$B/api/state"
    expect_code 403 -H "X-SSG-Token: $near" -d "do.radius=0.2" "$B/api/set"
done
expect_code 200 "$B/api/state?token=$token"
expect_code 200 -H "$H" "$B/api/state"
expect_code 200 -b "ssg_token=$token" "$B/api/state"
expect_code 403 -H "$H" -H "Host: attacker.example:$port" "$B/api/state"
expect_code 403 -H "$H" -H "Host: 127.0.0.1:1" "$B/api/state"
expect_code 403 -H "$H" -H "Origin: http://attacker.example" "$B/api/state"
expect_code 200 -H "$H" -H "Origin: http://localhost:$port" -H "Host: localhost:$port" "$B/api/state"
expect_code 403 -H "$H" -H "Origin: http://attacker.example" -d "do.radius=0.2" "$B/api/set"
for path in "/../../etc/passwd" "/%2e%2e/%2e%2e/etc/passwd" "/api/../../etc/passwd" \
    "/..%2fCMakeLists.txt" "/cli/view/server.c" "//etc/passwd"; do
    expect_code 404 --path-as-is -H "$H" "$B$path"
done
head -c 70000 /dev/zero | tr '\0' 'a' >"$TMP/big"
expect_code 413 -H "$H" --data-binary @"$TMP/big" "$B/api/set"
expect_code 413 -H "$H" -H "Transfer-Encoding: chunked" --data-binary @"$TMP/big" "$B/api/set"
expect_code 405 -H "$H" -X DELETE "$B/api/state"
expect_code 405 -H "$H" -X POST "$B/api/state"
expect_code 404 -H "$H" "$B/api/nothing"
# the page's own request sets the token cookie for what it loads next
curl -s -D "$TMP/headers" -o /dev/null -H "$H" "$B/" 
grep -qi "^Set-Cookie: ssg_token=$token; HttpOnly; SameSite=Strict" "$TMP/headers" ||
    fail "GET / sets no strict HttpOnly token cookie: $(cat "$TMP/headers")"

# --- a parameter change: only do and what follows it run; the pixels are the CLI's
expect_code 200 -H "$H" -d "do.radius=0.3" "$B/api/set"
ran=$(client ran)
[ "$ran" = "do f img u" ] || fail "after do.radius the nodes that ran were '$ran', not 'do f img u'"
"$BIN" run "$G" "${common[@]}" --quiet --set do.radius=0.3 --out "$TMP/cli" --show u.out,img.out ||
    fail "the CLI run with the same --set"
for port_name in u.out img.out; do
    client dump $port_name "$TMP/$port_name.pfm" || fail "no image of $port_name"
    oiiotool "$TMP/$port_name.pfm" "$TMP/cli/$port_name.exr" --fail 0 --failpercent 0 --diff \
        >"$TMP/diff.txt" 2>&1 || fail "the viewer's $port_name is not the CLI's: $(tail -3 "$TMP/diff.txt")"
done
expect_code 400 -H "$H" -d "do.radius=-3" "$B/api/set"
grep -q 'ssdo_realtime.graph:[0-9]*:[0-9]*: error: do.radius=-3: .*radius.*expects' "$TMP/body" ||
    fail "a refused value names no position: $(cat "$TMP/body")"
[ "$(client param do radius)" = 0.3 ] || fail "a refused value changed do.radius"
expect_code 400 -H "$H" -d "nosuch.radius=1" "$B/api/set"
expect_code 400 -H "$H" -d "no equals sign" "$B/api/set"

# which outputs the last run made: an on-demand output nothing reads has no image (the page
# marks it and opens on an output that has one, issue 46)
client images > "$TMP/images"
grep -qx "g.position true" "$TMP/images" && grep -qx "g.motion false" "$TMP/images" ||
    fail "the state's output images: $(tr '\n' ' ' < "$TMP/images")"

# --- camera, metrics, diagram
cam="position=0,1,3.5&target=0,1,0&up=0,1,0&fov=40"
expect_code 200 -H "$H" -d "$cam&preview=1" "$B/api/camera"
grep -q '"last_run":"preview"' "$TMP/body" || fail "a drag did not run the preview"
[ "$(client size img.out 1)" = "48 27 3" ] || fail "preview image is $(client size img.out 1)"
# the full graph has the new camera but has not run it: asked for, it runs
[ "$(client size img.out)" = "96 54 3" ] || fail "full image after a drag: $(client size img.out)"
expect_code 200 -H "$H" -d "$cam&preview=0" "$B/api/camera"
[ "$(client size img.out)" = "96 54 3" ] || fail "full image is $(client size img.out)"
# a drag's last preview fetch, late behind the full-size run of the same camera, gets the
# full image and runs nothing: running the preview again made every drag end on it (issue 46)
gen=$(client state generation)
expect_code 200 -H "$H" -d "$cam&preview=1" "$B/api/camera"
expect_code 200 -H "$H" -d "$cam&preview=0" "$B/api/camera"
gen=$(client state generation)
[ "$(client size img.out 1)" = "96 54 3" ] ||
    fail "a preview asked for after the full run is $(client size img.out 1), not the full image"
[ "$(client state generation)" = "$gen" ] && [ "$(client state last_run)" = full ] ||
    fail "a late preview fetch ran the graph again: run $(client state generation) ($(client state last_run))"
expect_code 400 -H "$H" -d "position=0,1,0&target=0,1,0&up=0,1,0&fov=40" "$B/api/camera"
expect_code 400 -H "$H" -d "position=0,1&fov=40" "$B/api/camera"
expect_code 200 -H "$H" "$B/api/metrics?ref=u.out&a=u.out&b=g.depth"
expect_code 400 -H "$H" "$B/api/metrics?ref=img.out&a=u.out"  # 1 vs 3 channels
expect_code 200 -H "$H" "$B/api/metrics?ref=img.out&a=img.out"
grep -q '"rmse":0,"ssim":1' "$TMP/body" || fail "a port against itself: $(cat "$TMP/body")"
expect_code 200 -H "$H" "$B/api/graph.svg"
grep -q '<title>do</title>' "$TMP/body" || fail "the diagram lacks node do"

# --- sequences: a frame runs (a still scene keeps the camera the page set; a path's frames
# move it: docs/time.md)
expect_code 200 -H "$H" -d "frame=3" "$B/api/frame"
grep -q '"frame":3,' "$TMP/body" || fail "state after frame=3: $(head -c 300 "$TMP/body")"
grep -q '"position":\[0,1,3.5' "$TMP/body" || fail "frame 3 of a still scene moved the camera"
expect_code 400 -H "$H" -d "frame=-1" "$B/api/frame"
expect_code 400 -H "$H" -d "frame=x" "$B/api/frame"
expect_code 200 -H "$H" -d "$cam&preview=0" "$B/api/camera"

# --- save as variant: beside the graph, then it runs from the command line
expect_code 200 -H "$H" -d "name=radius03" "$B/api/save"
[ -f "$TMP/graphs/radius03.graph" ] || fail "no variant beside the graph"
grep -q '^set do.radius = 0.3$' "$TMP/graphs/radius03.graph" || fail "variant: $(cat "$TMP/graphs/radius03.graph")"
expect_code 409 -H "$H" -d "name=radius03" "$B/api/save"
expect_code 400 -H "$H" -d "name=../../evil" "$B/api/save"
[ ! -e "$TMP/evil.graph" ] || fail "a variant was written outside the graph's folder"
"$BIN" run "$TMP/graphs/radius03.graph" "${common[@]}" --quiet --out "$TMP/variant" --show u.out ||
    fail "the saved variant does not run"
cmp -s "$TMP/variant/u.out.exr" "$TMP/cli/u.out.exr" || fail "the variant's u.out is not the session's"

# --- many clients at once: each answer whole, the state consistent afterwards
for i in $(seq 1 12); do
    curl -s -o "$TMP/par_state_$i" -w '%{http_code}\n' -H "$H" "$B/api/state" >>"$TMP/codes" &
    curl -s -o /dev/null -w '%{http_code}\n' -H "$H" -d "f.size=$((3 + 2 * (i % 2)))" "$B/api/set" >>"$TMP/codes" &
done
wait_children() { for j in $(jobs -p); do [ "$j" = "$pid" ] || wait "$j"; done; }
wait_children
[ "$(sort -u "$TMP/codes")" = 200 ] || fail "concurrent requests answered $(sort "$TMP/codes" | uniq -c)"
for i in $(seq 1 12); do
    python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$TMP/par_state_$i" ||
        fail "a concurrent state answer is not whole JSON"
done
kill -0 $pid || fail "the server died under concurrent requests"

# --- the file watcher: an edit reloads, an error shows at file:line:col, a fix clears it
gen=$(client state | python3 -c "import json,sys; print(json.load(sys.stdin)['generation'])")
sed -i 's/size=5,/size=7,/' "$G"
gen=$(client wait_gen "$gen" 30)
[ "$gen" != timeout ] || fail "an edit of the graph did not reload it"
expect_code 200 -H "$H" "$B/api/state"
cp "$G" "$TMP/good.graph"
sed -i 's/^f   = bilateral(/f   = bilateral(nosuch=1, /' "$G"
gen=$(client wait_gen "$gen" 30)
client state >"$TMP/state_error.json"
grep -q 'ssdo_realtime.graph:[0-9]*:[0-9]*: error:.*nosuch' "$TMP/state_error.json" ||
    fail "a broken graph's error is not shown at file:line:col: $(grep error "$TMP/state_error.json")"
expect_code 200 -H "$H" "$B/api/image?port=img.out" # the last good graph still serves
cp "$TMP/good.graph" "$G"
gen=$(client wait_gen "$gen" 30)
client state | grep -q '"error": null' || fail "the fixed graph still shows an error"

# --- SIGTERM: a clean end
view_stop_within 10000 TERM
finish test_view_http
