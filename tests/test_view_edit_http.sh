#!/usr/bin/env bash
# `ssgraph view`'s graph editor over HTTP (POST /api/edit, /api/edit/save, /api/edit/discard,
# GET /api/types; docs/viewer-api.md, "Editing the graph"):
# - add a node, rewire an input, remove a node: each answered with the new state;
# - refused edits (a type mismatch, an unknown node type, a cycle, removing a node another
#   reads, a syntax error) answer 400 with the graph file's file:line:column at the line of
#   the edited text, and leave the session's graph as it was;
# - a positional argument is replaced where it stands, a missing one added to the call;
# - a change of the file on disk is not loaded while there are edits (the state says so);
# - save as NAME: `ssgraph check NAME.graph` loads the page's nodes and outputs, the page's
#   parameter change is written into the call, and the saved text differs from the
#   original only in the edited lines (plus the server's command line at its end);
# - discard drops the edits and loads the file from disk.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_edit_http"
source "$(dirname "$0")/view_lib.sh"
ROOT=$(pwd)
D=$TMP/graphs
mkdir -p "$D"
G=$D/edit.graph
cat >"$G" <<'EOF'
# a graph to edit
seed 1

g   = gbuffer()
k   = halton(count=8, bases=[2, 3])
ao  = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation, radius=0.5)
b   = bilateral(ao.out, depth=g.depth, normal=g.normal, size=5)   # smooths the AO
img = combine(direct=g.direct, albedo=g.albedo, ambient_occlusion=b.out, ambient=0.6)
out = write(img.out, "edit")
EOF
cp "$G" "$TMP/original.graph"
view_start "$TMP/view.log" "$G" --scene "$ROOT/examples/cornell.scene" --size 48x27 \
    --threads 2 --out "$TMP/out" || { fail "no URL printed"; finish test_view_edit_http; }

edit() { expect_code "$1" -H "$H" --data-binary "$2" "$B/api/edit"; }
# state_nodes: the node names of the answer in $TMP/body, one line
nodes_of() { python3 -c 'import json,sys; print(" ".join(n["name"] for n in json.load(open(sys.argv[1]))["nodes"]))' "$1"; }
from_of() { # FILE NODE PORT: where the input reads from
    python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); n=[n for n in s["nodes"] if n["name"]==sys.argv[2]][0]; print([i["from"] for i in n["inputs"] if i["port"]==sys.argv[3]][0])' "$@"
}

# --- the types a page may add
expect_code 200 -H "$H" "$B/api/types"
python3 - "$TMP/body" <<'EOF' || fail "/api/types lacks bilateral's ports: $(head -c 300 "$TMP/body")"
import json, sys
t = {x["name"]: x for x in json.load(open(sys.argv[1]))["types"]}
b = t["bilateral"]
assert [i["port"] for i in b["inputs"]][:1] == ["in"], b
assert all(i["types"] for i in b["inputs"]) and b["outputs"][0]["types"], b
EOF

# --- add, rewire, remove
edit 200 'b2 = bilateral(ao.out, depth=g.depth, normal=g.normal, size=3)'
[ "$(nodes_of "$TMP/body")" = "g k ao b img out b2" ] || fail "after add: $(nodes_of "$TMP/body")"
edit 200 'set img.ambient_occlusion = b2.out'
[ "$(from_of "$TMP/body" img ambient_occlusion)" = b2.out ] || fail "the rewire did not take"
edit 200 'remove b'
[ "$(nodes_of "$TMP/body")" = "g k ao img out b2" ] || fail "after remove: $(nodes_of "$TMP/body")"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); assert s["edited"] and s["unsaved_edits"] == 3, s["unsaved_edits"]' "$TMP/body" ||
    fail "the state does not count the edits"

# --- refused edits: the graph file's messages at the edited text's line; nothing changes
# refused CODE EDIT PATTERN: answered CODE, the error matches PATTERN (grep -E)
refused() {
    edit 400 "$1"
    grep -Eq -- "$2" "$TMP/body" || fail "'$1' refused without /$2/: $(head -c 400 "$TMP/body")"
}
GE=${G//\//\\/}
refused 'set img.albedo = k.samples' "$GE:7:39: error: input .albedo. .*kernel"       # a kernel into a colour
refused 'x = nosuchnode(g.depth)' "$GE:10:5: error: unknown node 'nosuchnode'"
refused 'set b2.in = img.out' "$GE:[0-9]+:[0-9]+: error: the graph has a cycle"
refused 'remove g' "$GE:6:12: error: cannot remove node 'g': node 'ao' reads it"
refused 'remove nobody' "<edit>:1:8: error: no node 'nobody'"
refused 'set img.ambient_occlusion = ' "<edit>:1:29: error: expected a value"
expect_code 200 -H "$H" "$B/api/state"
[ "$(nodes_of "$TMP/body")" = "g k ao img out b2" ] || fail "a refused edit changed the graph"
[ "$(from_of "$TMP/body" img ambient_occlusion)" = b2.out ] || fail "a refused edit rewired"
cmp -s "$G" "$TMP/original.graph" || fail "an edit wrote the graph file on disk"

# --- a positional argument replaced where it stands; an argument the call lacks added to it
edit 200 'set b2.in = g.depth'
[ "$(from_of "$TMP/body" b2 in)" = g.depth ] || fail "the positional rewire did not take"
edit 200 'set b2.separable = true'

# --- a parameter changed in the page is saved into the call
expect_code 200 -H "$H" -d "b2.size=7" "$B/api/set"

# --- a change on disk is not loaded over the edits
gen=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["generation"])' "$TMP/body")
sed -i 's/radius=0.5/radius=0.25/' "$G"
for _ in $(seq 1 50); do
    [ "$(code -H "$H" "$B/api/state?since=$gen")" = 200 ] && break
    sleep 0.2
done
grep -q 'changed on disk while the page holds edits' "$TMP/body" ||
    fail "the file's change was not reported: $(head -c 300 "$TMP/body")"
[ "$(nodes_of "$TMP/body")" = "g k ao img out b2" ] || fail "the change on disk replaced the edits"
cp "$TMP/original.graph" "$G"

# --- save as: `ssgraph check` loads what the page shows
expect_code 200 -H "$H" "$B/api/state"
cp "$TMP/body" "$TMP/edited_state.json"
expect_code 200 -H "$H" -d "name=edited" "$B/api/edit/save"
S=$D/edited.graph
[ -f "$S" ] || fail "no $S"
expect_code 409 -H "$H" -d "name=edited" "$B/api/edit/save" # never replaced
/usr/bin/python3 tests/view_edit_check.py "$BIN" "$S" "$TMP/edited_state.json" >"$TMP/compare.txt" ||
    fail "the saved graph is not the page's: $(cat "$TMP/compare.txt")"
# only the edited lines differ, then the command line's statements follow
diff "$TMP/original.graph" "$S" >"$TMP/diff.txt"
want_diff="7,8c7
< b   = bilateral(ao.out, depth=g.depth, normal=g.normal, size=5)   # smooths the AO
< img = combine(direct=g.direct, albedo=g.albedo, ambient_occlusion=b.out, ambient=0.6)
---
> img = combine(direct=g.direct, albedo=g.albedo, ambient_occlusion=b2.out, ambient=0.6)
9a9,13
> b2 = bilateral(g.depth, depth=g.depth, normal=g.normal, size=7, separable=true)
> 
> # The command line \`ssgraph view\` was started with:
> scene \"$ROOT/examples/cornell.scene\"
> size 48 27"
[ "$(cat "$TMP/diff.txt")" = "$want_diff" ] || fail "the saved text differs elsewhere: $(cat "$TMP/diff.txt")"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); assert s["unsaved_edits"] == 0' \
    <(curl -s -H "$H" "$B/api/state") || fail "the save left the edits counted as unsaved"

# --- discard: the file from disk again
expect_code 200 -H "$H" -d "" "$B/api/edit/discard"
[ "$(nodes_of "$TMP/body")" = "g k ao b img out" ] || fail "discard: $(nodes_of "$TMP/body")"
expect_code 400 -H "$H" -d "name=again" "$B/api/edit/save" # nothing to save
kill $pid
finish test_view_edit_http
