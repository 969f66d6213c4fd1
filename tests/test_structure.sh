#!/usr/bin/env bash
# The structure issue 14 set up stays: core/ in its layers; no source file over 600 lines;
# every parameter table entry states its storage through a type-checked SSG_FIELD_* macro
# (never a bare .offset); no node fails on an image's shape at run time (check() and the
# executor's verification own shapes, core/graph/node.h); no node calls GL or includes
# core/gl's internals; shaders share code through #include of nodes/common/sampling.glsl
# rather than copies. Issue 43's two migrations stay
# done: a node's own tests live in its folder (nodes/<folder>/test_*.c, as the template's),
# never in tests/; a node's code includes only its own folder, nodes/common and core, never
# another node's folder (what two nodes share is nodes/common's).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_structure"

files() { if git rev-parse --git-dir > /dev/null 2>&1; then git ls-files "$@"; else
          find . -path ./build\* -prune -o -type f -print | sed 's|^\./||'; fi; }

layers=$(find core -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort | tr '\n' ' ')
[ "$layers" = "gl graph io lang scene " ] || fail "core/ layers are '$layers', expected gl graph io lang scene"
loose=$(find core -maxdepth 1 -type f ! -name ssgraph.h ! -name ssgraph_tools.h ! -name errors.def)
[ -z "$loose" ] || fail "files directly in core/ (put them in a layer): $loose"

long=$(files | grep -E '^(core|nodes|cli|tests|bench|fuzz|tools)/.*\.(c|h|cc|glsl|sh|py)$' |
       while read -r f; do n=$(wc -l < "$f"); [ "$n" -le 600 ] || echo "$f ($n lines)"; done)
[ -z "$long" ] || fail "source files over 600 lines: $long"

bare=$(files | grep -E '^(core|nodes)/.*\.(c|h)$' | xargs grep -n '\.offset *= *offsetof' |
       grep -v '^core/lang/params\.h:' | head -5)
[ -z "$bare" ] || fail "parameter tables with a bare .offset (use SSG_FIELD_*): $bare"

shape_fail=$(files | grep -E '^nodes/.*\.(c|h)$' |
             xargs grep -nE 'ssg_node_fail\(ctx, SSG_E_(SIZE|CHANNELS)' | head -5)
[ -z "$shape_fail" ] || fail "nodes failing on shapes at run time: $shape_fail"

# A node never calls GL (core/gl/gl.h): its GL side is gl.h's passes and gl_scene.h's scene
# and raster, which own the GL objects and share them over a run. The scene raster once lived
# in nodes/common with some 65 raw GL calls and an upload per node (issue 43).
node_sources=$(files | grep -E '^(nodes|tools/node-template)/.*\.(c|h|cc)$')
raw_gl=$(echo "$node_sources" | xargs grep -nE '\bgl[A-Z][A-Za-z0-9]*[[:space:]]*\(|\bGL_[A-Z0-9_]+' |
         head -5)
[ -z "$raw_gl" ] || fail "nodes calling GL directly (use core/gl/gl.h, gl/gl_scene.h): $raw_gl"
gl_inside=$(echo "$node_sources" | xargs grep -nE '#include "gl/' |
            grep -vE '#include "gl/(gl|gl_scene)\.h"' | head -5)
[ -z "$gl_inside" ] || fail "nodes including core/gl's internals (only gl/gl.h, gl/gl_scene.h): $gl_inside"

# Build and interpreter leftovers are never tracked (bench/__pycache__ crept back in twice).
leftovers=$(git ls-files 2>/dev/null | grep -E '(^|/)__pycache__/|\.py[co]$|(^|/)build[^/]*/' | head -5)
[ -z "$leftovers" ] || fail "generated files are tracked (git rm --cached them): $leftovers"

# misplaced_tests ROOT: "tests/FILE FOLDER" for each ROOT/tests/test_*.c named after one
# registered node (test_<node>.c, test_gl_<node>.c, either with _<what> after the name),
# FOLDER the node's (the one holding <node>.c: bounce's is nodes/ssdo).
misplaced_tests() {
    local root=$1 t base name def names m
    names=$(sed -n 's/^X(\(.*\))$/\1/p' "$root/nodes/nodes.def")
    for t in "$root"/tests/test_*.c; do
        [ -e "$t" ] || continue
        base=${t##*/} && base=${base%.c} && base=${base#test_} && base=${base#gl_}
        for name in $names; do
            case "$base" in "$name" | "$name"_*) ;; *) continue ;; esac
            def=nodes/$name/$name.c
            for m in "$root"/nodes/*/"$name".c; do [ -e "$m" ] && def=${m#"$root"/} && break; done
            echo "tests/${t##*/} ${def%/*}"
        done
    done
}

# cross_includes ROOT: "FILE INCLUDE" for each include in a node folder's code (its tests
# aside: a test may run other nodes to make its inputs) that reaches another node's folder:
# a C "folder/file" include naming a folder of nodes/ other than its own and common, or a
# shader's "file.glsl" (found by name among all shaders) that is neither in its own folder
# nor in nodes/common but in another node's.
cross_includes() {
    local root=$1 f inc dir to m
    while IFS=: read -r f inc; do
        case "$f" in */test_*.c) continue ;; esac
        inc=${inc#*\"} && inc=${inc%%\"*} && dir=${f%/*} && dir=${dir##*/} && to=
        if [[ $inc == */* ]]; then
            to=${inc%%/*}
            [ -d "$root/nodes/$to" ] || continue # a core layer
        elif [[ $f == *.glsl ]]; then
            [ -e "$root/nodes/$dir/$inc" ] && continue
            for m in "$root"/nodes/*/"$inc"; do
                [ -e "$m" ] && to=${m%/*} && to=${to##*/} && break
            done
            [ -n "$to" ] || continue # core/gl's
        else
            continue # a C file's own folder
        fi
        [ "$to" = common ] || [ "$to" = "$dir" ] || echo "$f $inc"
    done < <(cd "$root" && grep -H '^#include "' nodes/*/*.c nodes/*/*.h nodes/*/*.cc \
                                                nodes/*/*.glsl 2> /dev/null)
}

misplaced=$(misplaced_tests .)
[ -z "$misplaced" ] || fail "node tests in tests/ (move each into its node's folder with git mv: a node's own tests live there, as tools/node-template's; docs/adding-a-node.md):
$(echo "$misplaced" | sed 's|^\(.*\) \(.*\)$|  \1 -> \2/|')"
cross=$(cross_includes . | LC_ALL=C sort)
[ -z "$cross" ] || fail "includes from one node's folder into another's (a node includes only its own folder, nodes/common and core: move what both need into nodes/common):
$(echo "$cross" | sed 's|^\(.*\) \(.*\)$|  \1 includes "\2"|')"

# Both checks can fail: on a planted tree they name exactly the planted offenders.
plant=$TMP/planted
mkdir -p "$plant/nodes/alpha" "$plant/nodes/beta" "$plant/nodes/common" "$plant/tests"
printf 'X(alpha)\nX(beta)\nX(gamma)\n' > "$plant/nodes/nodes.def"
touch "$plant/nodes/beta/beta.h" "$plant/nodes/beta/beta.glsl" "$plant/nodes/beta/gamma.c" \
      "$plant/nodes/common/c.h" "$plant/nodes/common/c.glsl"
printf '#include "beta/beta.h"\n#include "common/c.h"\n#include "graph/node.h"\n' \
    > "$plant/nodes/alpha/alpha.c"
printf '#include "beta.glsl"\n#include "c.glsl"\n#include "common.glsl"\n' \
    > "$plant/nodes/alpha/alpha.glsl"
printf '#include "beta/beta.h"\n' > "$plant/nodes/alpha/test_alpha.c"
printf '#include "alpha/alpha.h"\n' > "$plant/nodes/common/c.c"
touch "$plant/tests/test_"{beta,gl_alpha_edges,gamma,graph,alphabet}.c
want="tests/test_beta.c nodes/beta
tests/test_gamma.c nodes/beta
tests/test_gl_alpha_edges.c nodes/alpha"
got=$(misplaced_tests "$plant")
[ "$got" = "$want" ] || fail "misplaced_tests on the planted tree gave '$got', expected '$want'"
want="nodes/alpha/alpha.c beta/beta.h
nodes/alpha/alpha.glsl beta.glsl
nodes/common/c.c alpha/alpha.h"
got=$(cross_includes "$plant" | LC_ALL=C sort)
[ "$got" = "$want" ] || fail "cross_includes on the planted tree gave '$got', expected '$want'"

for shader in nodes/ssao/ssao.glsl nodes/hbao/hbao.glsl nodes/ssdo/ssdo.glsl; do
    grep -q '^#include "sampling.glsl"' "$shader" || fail "$shader does not include sampling.glsl"
    grep -qE '^(float|vec3) (scene_depth|kernel_sample)\(' "$shader" &&
        fail "$shader defines its own copy of a sampling.glsl helper"
done
finish test_structure
