#!/usr/bin/env bash
# `ssgraph view`'s "save as variant" (cli/view/variant.c) from outside:
# - the variant carries the server's --scene (relative to where it was started), --size and
#   --seed as statements, quotes the graph's file name (here a"b.graph) the way the lexer
#   reads it, and runs from another folder without them to the session's pixels;
# - a name that exists in any form (a FIFO, a dangling link, a mode-000 file, a directory)
#   is refused at once, never opened, replaced or written through, and the server keeps
#   answering; a name is checked on every character (sub/../../evil, a bad last one);
# - the 257th changed parameter is refused before it is applied, and the saved variant has
#   the 256 others;
# - a value with a newline (`ref.max_distance=0.3\ninclude "/etc/passwd"`) is refused (the
#   core's check, ssg_line_check), and no saved variant has a line of it (variant.c's).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_save"
source "$(dirname "$0")/view_lib.sh"
ROOT=$(pwd)
D=$TMP/graphs
mkdir -p "$D/sub"
# No scene and no size of its own: only the server's --scene and --size make it load. 29
# halton nodes nobody reads give 261 parameters to change.
G=$D/'a"b.graph'
{
    echo 'seed 1'
    echo 'g = gbuffer()'
    echo 'ref = reference_ao(g.position, g.normal, rays=4, max_distance=0.5)'
    echo 'out = write(ref.out, "ao")'
    for i in $(seq 1 29); do echo "k$i = halton(count=4)"; done
} >"$G"
common=(--scene examples/cornell.scene --size 48x27 --seed 7 --threads 2)
view_start "$TMP/view.log" "$G" "${common[@]}" --set ref.rays=8 --out "$TMP/out" || {
    fail "no URL printed"; finish test_view_save; }
post_save() { expect_code "$1" --max-time 20 -H "$H" -d "name=$2" "$B/api/save"; }

# --- the variant carries the command line and runs without it, from elsewhere
expect_code 200 -H "$H" -d "ref.max_distance=0.4" "$B/api/set"
post_save 200 v1
V=$D/v1.graph
for line in 'include "a\"b.graph"' "scene \"$ROOT/examples/cornell.scene\"" 'size 48 27' \
    'seed 7' 'set ref.rays = 8' 'set ref.max_distance = 0.4'; do
    grep -qxF "$line" "$V" || fail "the variant lacks the line '$line': $(cat "$V")"
done
"$BIN" run "$G" "${common[@]}" --quiet --set ref.rays=8 --set ref.max_distance=0.4 \
    --out "$TMP/cli" || fail "the CLI run with the server's options"
(cd "$TMP" && "$BIN" run "$V" --threads 2 --quiet --out "$TMP/variant") ||
    fail "the variant does not run from another folder without the server's options"
# same_pixels A B: the images' pixels are equal (their metadata names their graph files)
same_pixels() { oiiotool "$1" "$2" --fail 0 --failpercent 0 --diff >"$TMP/diff.txt" 2>&1; }
same_pixels "$TMP/variant/ao.exr" "$TMP/cli/ao.exr" ||
    fail "the variant's image is not the session's: $(tail -3 "$TMP/diff.txt")"
"$BIN" run "$G" "${common[@]:0:4}" --threads 2 --quiet --set ref.rays=8 \
    --set ref.max_distance=0.4 --out "$TMP/seed1" || fail "the CLI run with the graph's seed"
same_pixels "$TMP/seed1/ao.exr" "$TMP/cli/ao.exr" && fail "the seed changes nothing: the check above is void"

# --- names that exist in any form: refused at once, nothing replaced or written through
mkfifo "$D/fifo.graph"
ln -s "$TMP/nowhere" "$D/dangling.graph"
echo keep >"$D/locked.graph" && chmod 000 "$D/locked.graph"
mkdir "$D/dir.graph"
for name in v1 fifo dangling locked dir; do
    post_save 409 $name
    grep -q 'exists already' "$TMP/body" || fail "save as $name: $(cat "$TMP/body")"
done
[ -p "$D/fifo.graph" ] || fail "the FIFO was replaced"
[ -L "$D/dangling.graph" ] && [ ! -e "$TMP/nowhere" ] || fail "the dangling link was written through or replaced"
chmod 600 "$D/locked.graph"
[ "$(cat "$D/locked.graph")" = keep ] || fail "the mode-000 file was overwritten"
expect_code 200 --max-time 20 -H "$H" "$B/api/state" # the lock is free
ls "$D" | grep -q 'tmp' && fail "a temporary was left: $(ls "$D")"

# --- every character of a name is checked
for name in "sub/../../evil" "sub%2F..%2F..%2Fevil" "evil/" "evil." "e vil" ""; do
    post_save 400 "$name"
done
# a NUL in a body would cut it where the routes read it as text: refused whole, so neither the
# name after it nor a set line after it goes unchecked
printf 'name=ok\0/../../evil' > "$TMP/nul_name"
expect_code 400 --max-time 20 -H "$H" --data-binary @"$TMP/nul_name" "$B/api/save"
printf 'ref.max_distance=0.35\0\ninclude "/etc/passwd"' > "$TMP/nul_set"
expect_code 400 --max-time 20 -H "$H" --data-binary @"$TMP/nul_set" "$B/api/set"
[ ! -e "$D/ok.graph" ] || fail "a body cut at its NUL saved ok.graph"
[ ! -e "$TMP/evil.graph" ] && [ ! -e "$D/evil.graph" ] && [ ! -e "$D/evil..graph" ] ||
    fail "a variant was written under a refused name: $(ls "$TMP" "$D")"

# --- the 257th change is refused before it is applied; the variant holds the 256 others
python3 - "$B" "$token" >"$TMP/sets.txt" <<'PY' || fail "the 256 changes: $(tail -3 "$TMP/sets.txt")"
import sys, urllib.request, urllib.error
base, token = sys.argv[1], sys.argv[2]
values = {"count": "4", "offset": "1", "period": "0", "mapping": "cosine", "falloff": "2",
          "min_scale": "0.1", "pattern": "4", "rotations": "tile", "bases": "[2, 3]"}
keys = [f"k{i}.{p}" for i in range(1, 30) for p in values]
def post(body):
    req = urllib.request.Request(base + "/api/set", data=body.encode(),
                                 headers={"X-SSG-Token": token})
    try:
        with urllib.request.urlopen(req, timeout=20) as r:
            return r.status
    except urllib.error.HTTPError as e:
        return e.code
# 2 changes so far (ref.max_distance, and ref.rays from the command line is not one)
for k in keys[:255]:
    code = post(f"{k}={values[k.split('.')[1]]}")
    if code != 200:
        print(f"{k}: {code}")
        sys.exit(1)
print(post("k29.falloff=3"), post("k1.count=5"))
PY
[ "$(tail -1 "$TMP/sets.txt")" = "400 200" ] ||
    fail "the 257th change answered '$(tail -1 "$TMP/sets.txt")', expected 400 (and 200 for a key already changed)"
python3 "$ROOT/tests/view_client.py" "$B" "$token" param k29 falloff >"$TMP/falloff" &&
    [ "$(cat "$TMP/falloff")" = 2 ] || fail "the refused 257th change was applied: k29.falloff = $(cat "$TMP/falloff")"
post_save 200 v256
[ "$(grep -c '^set ' "$D/v256.graph")" = 257 ] ||
    fail "the variant has $(grep -c '^set ' "$D/v256.graph") set lines, not 257 (256 and ref.rays)"
grep -q 'k29.falloff' "$D/v256.graph" && fail "the refused change is in the variant"

# --- a newline in a value: refused, and no variant gets a line of it
expect_code 400 -H "$H" --data-binary $'ref.max_distance=0.3\ninclude "/etc/passwd"' "$B/api/set"
code -H "$H" -d "name=nl" "$B/api/save" >/dev/null
grep -q '/etc/passwd' "$D/nl.graph" 2>/dev/null && fail "a value's newline became a line: $(cat "$D/nl.graph")"

view_stop_within 10000 TERM
finish test_view_save
