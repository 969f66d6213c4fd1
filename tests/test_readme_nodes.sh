#!/usr/bin/env bash
# test_readme_nodes.sh - the README's node table names every registered node once, and no
# node that is not registered (`ssgraph nodes` reads the registry, nodes/nodes.def): a new
# node without its README row, or a row left behind by a removed one, fails here.
# tools/new-node.sh adds a new node's row (its descriptor's summary) with its registry line;
# the table stays written by hand so that a row can say more than the one-line summary.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_readme_nodes"
"$BIN" nodes | awk '{print $1}' | sort > "$TMP/registered" || fail "ssgraph nodes failed"
grep -o '^| `[a-z_0-9]*` |' README.md | sed 's/^| `//; s/` |$//' | sort > "$TMP/readme"
[ -s "$TMP/registered" ] || fail "ssgraph nodes listed nothing"
missing=$(comm -23 "$TMP/registered" "$TMP/readme" | tr '\n' ' ')
extra=$(comm -13 "$TMP/registered" "$TMP/readme" | tr '\n' ' ')
twice=$(uniq -d "$TMP/readme" | tr '\n' ' ')
[ -z "$missing" ] || fail "README.md's node table lacks: $missing"
[ -z "$extra" ] || fail "README.md's node table names nodes that are not registered: $extra"
[ -z "$twice" ] || fail "README.md's node table names these twice: $twice"
finish test_readme_nodes
