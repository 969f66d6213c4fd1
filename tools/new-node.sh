#!/usr/bin/env bash
# new-node.sh - writes a new node from the template in tools/node-template/: the folder
# nodes/NAME/ (header with its port and parameter rows, descriptor, CPU kernel, GL pass,
# shader, README.md with the method text, and test_NAME.c, a unit test on an analytic case
# plus CPU/GL parity), the registry line X(NAME) at the end of nodes/nodes.def, and the
# node's row in README.md's node table (tests/test_readme_nodes.sh holds that table to the
# registry). With --build DIR it then builds DIR and regenerates docs/nodes.md from the
# built binary (tests/test_cli.sh fails on a stale one). docs/adding-a-node.md walks
# through what comes next.
#
#   tools/new-node.sh [--build DIR] NAME   a node in this repository
#   tools/new-node.sh --into DIR NAME      only the folder, as DIR/NAME/ (the build's
#                                          template check, tests/CMakeLists.txt)
#   tools/new-node.sh --help               this text
#
# NAME is [a-z][a-z0-9_]*, at most 40 characters, no node or folder in nodes/ yet, and no
# test's name in tests/ or a node's folder (test_NAME). A refused name writes nothing.
# SSG_ROOT, when set, is the repository to write into (tests/test_new_node.sh runs the
# script on a scratch copy).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
template=$here/node-template
root=${SSG_ROOT:-$(dirname "$here")}

die() { echo "new-node.sh: error: $*" >&2; exit 1; }
usage() { die "usage: tools/new-node.sh [--build DIR | --into DIR] NAME"; }

case ${1:-} in -h | --help) sed -n '2,/^set /{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac
build="" into=""
while [ $# -gt 1 ]; do
    case $1 in
        --build) build=$2; shift 2 ;;
        --into) into=$2; shift 2 ;;
        *) usage ;;
    esac
done
[ $# -eq 1 ] || usage
name=$1

# The name becomes a folder, a C identifier (ssg_node_NAME) and a word of the graph files.
[[ $name =~ ^[a-z][a-z0-9_]*$ ]] ||
    die "node name '$name' must be a lowercase letter then lowercase letters, digits or '_' ([a-z][a-z0-9_]*)"
[ ${#name} -le 40 ] || die "node name '$name' is longer than 40 characters"

# The folder from the template: every @name@ becomes NAME, every @NAME@ NAME in capitals,
# and a file named after NAME (NAME.h, test_NAME.c) is named after the node.
instantiate() {
    local dir=$1 upper
    upper=$(printf '%s' "$name" | tr '[:lower:]' '[:upper:]')
    mkdir -p "$dir"
    for f in "$template"/*; do
        local base
        base=$(basename "$f")
        sed -e "s/@name@/$name/g" -e "s/@NAME@/$upper/g" "$f" > "$dir/${base//NAME/$name}"
    done
}

if [ -n "$into" ]; then
    rm -rf "${into:?}/$name.tmp"
    instantiate "$into/$name.tmp"
    rm -rf "${into:?}/$name"
    mv "$into/$name.tmp" "$into/$name"
    exit 0
fi

def=$root/nodes/nodes.def readme=$root/README.md
[ -f "$def" ] && [ -f "$readme" ] || die "no nodes/nodes.def and README.md under $root"
[ ! -e "$root/nodes/$name" ] || die "nodes/$name already exists (pick another name)"
grep -q "^X($name)\$" "$def" && die "node '$name' is already registered in nodes/nodes.def"
grep -q "^| \`$name\` |" "$readme" && die "README.md's node table already has a row '$name'"
for t in "$root/tests/test_$name.c" "$root/tests/test_$name.sh" "$root"/nodes/*/"test_$name.c"; do
    [ ! -e "$t" ] || die "${t#"$root"/} exists: the node's test_$name would have its name"
done

# The README row is the descriptor's .summary (the string literals after `.summary =` in
# the template's NAME.c, joined), after the table's last row: edit both when the method
# changes.
summary=$(awk '/\.summary =/ {s = 1} s {print} s && /",$/ {exit}' "$template/NAME.c" |
          grep -o '"[^"]*"' | tr -d '"\n')
[ -n "$summary" ] || die "no .summary in $template/NAME.c"
table_end=$(awk '/^\| node \| what it does \|$/ {t = 1} t && /^\| `/ {last = NR}
                 t && !/^\|/ {exit} END {print last + 0}' "$readme")
[ "$table_end" -gt 0 ] || die "README.md has no node table ('| node | what it does |')"

# Everything is checked: write the folder, then the two registry lines.
instantiate "$root/nodes/$name"
[ -z "$(tail -c 1 "$def")" ] || echo >> "$def"
echo "X($name)" >> "$def"
awk -v n="$table_end" -v row="| \`$name\` | $summary |" '{print} NR == n {print row}' \
    "$readme" > "$readme.tmp" && mv "$readme.tmp" "$readme"
echo "new-node.sh: wrote nodes/$name/ ($(ls "$root/nodes/$name" | tr '\n' ' ')), X($name) in nodes/nodes.def, its row in README.md"

if [ -n "$build" ]; then
    log=$(cmake --build "$build" -j"$(nproc)" 2>&1) ||
        { echo "$log" | tail -n 40 >&2; die "building $build failed (its last lines above)"; }
    "$build/ssgraph" docs > "$root/docs/nodes.md.tmp" && mv "$root/docs/nodes.md.tmp" "$root/docs/nodes.md"
    echo "new-node.sh: built $build and regenerated docs/nodes.md"
else
    echo "new-node.sh: now build, then regenerate docs/nodes.md: ./build/ssgraph docs > docs/nodes.md"
fi
