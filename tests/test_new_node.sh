#!/usr/bin/env bash
# test_new_node.sh - tools/new-node.sh on a scratch copy of the files it edits (SSG_ROOT):
# a bad name (not [a-z][a-z0-9_]*, too long, an existing node or folder, or the name of a
# test in tests/ or in a node's folder as test_NAME) is refused with a message naming it and nothing written; a good one gets its folder from the template with
# every placeholder replaced, one X(NAME) line at the end of nodes/nodes.def, and one row
# in README.md's node table, after its last row; a second run with that name is refused.
# (That the template's files compile and run is tests/CMakeLists.txt's test_node_template.)
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_new_node"
root=$TMP/repo
mkdir -p "$root/nodes"
cp nodes/nodes.def README.md "$root/"
mv "$root/nodes.def" "$root/nodes/"
mkdir "$root/nodes/gaussian" "$root/nodes/common" "$root/tests"
touch "$root/tests/test_contract.c" "$root/nodes/gaussian/test_gaussian_edges.c"
new_node() { SSG_ROOT=$root bash tools/new-node.sh "$@"; }
snapshot() { (cd "$root" && find . -type f | sort | xargs sha256sum); }

before=$(snapshot)
long=$(printf 'n%.0s' $(seq 41))
for bad in Foo 1node my-node "my node" "" _x gaussian common ssao contract gaussian_edges "$long"; do
    expect_exit 1 "error: .*(node name|already|would have its name)" new_node "$bad"
    [ "$(snapshot)" = "$before" ] || fail "refusing '$bad' changed files"
done
expect_exit 1 "usage" new_node --frobnicate x
expect_exit 0 "tools/new-node.sh --into DIR NAME" new_node --help
[ "$(snapshot)" = "$before" ] || fail "a bad option changed files"

expect_exit 0 "wrote nodes/my_node2/" new_node my_node2
dir=$root/nodes/my_node2
want="README.md my_node2.c my_node2.glsl my_node2.h my_node2_cpu.c my_node2_gl.c test_my_node2.c"
got=$(ls "$dir" 2>/dev/null | sort | tr '\n' ' ')
[ "$got" = "$want " ] || fail "nodes/my_node2 holds '$got', expected '$want'"
left=$(grep -rl '@name@\|@NAME@' "$dir")
[ -z "$left" ] || fail "placeholders left in: $left"
grep -q 'const struct ssg_node_desc ssg_node_my_node2 = {' "$dir/my_node2.c" ||
    fail "my_node2.c does not define ssg_node_my_node2"
grep -q '^#define SSG_MY_NODE2_PARAMS(P)' "$dir/my_node2.h" || fail "my_node2.h: no SSG_MY_NODE2_PARAMS"
[ "$(tail -n 1 "$root/nodes/nodes.def")" = "X(my_node2)" ] || fail "nodes.def does not end with X(my_node2)"
[ "$(grep -c '^X(my_node2)$' "$root/nodes/nodes.def")" = 1 ] || fail "X(my_node2) not once in nodes.def"
diff <(grep -v '^X(my_node2)$' "$root/nodes/nodes.def") nodes/nodes.def > /dev/null ||
    fail "nodes.def changed beyond the new line"

# The row: once, right after the row that was last, with the descriptor's summary.
last=$(grep '^| `' README.md | tail -n 1)
row=$(grep -A1 -F "$last" "$root/README.md" | tail -n 1)
case $row in
    '| `my_node2` | multiplies every channel of an image by `gain`'*' |') ;;
    *) fail "README.md: the row after the table's last is '$row'" ;;
esac
diff <(grep -v '^| `my_node2` |' "$root/README.md") README.md > /dev/null ||
    fail "README.md changed beyond the new row"

after=$(snapshot)
expect_exit 1 "nodes/my_node2 already exists" new_node my_node2
[ "$(snapshot)" = "$after" ] || fail "refusing an existing node changed files"
finish test_new_node
