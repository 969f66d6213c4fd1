#!/usr/bin/env bash
# The structure issue 14 set up stays: core/ in its layers; no source file over 600 lines;
# every parameter table entry states its storage through a type-checked SSG_FIELD_* macro
# (never a bare .offset); no node fails on an image's shape at run time (check() and the
# executor's verification own shapes, core/graph/node.h); no node calls GL or includes
# core/gl's internals; shaders share code through #include of nodes/common/sampling.glsl
# rather than copies.
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

for shader in nodes/ssao/ssao.glsl nodes/hbao/hbao.glsl nodes/ssdo/ssdo.glsl; do
    grep -q '^#include "sampling.glsl"' "$shader" || fail "$shader does not include sampling.glsl"
    grep -qE '^(float|vec3) (scene_depth|kernel_sample)\(' "$shader" &&
        fail "$shader defines its own copy of a sampling.glsl helper"
done
finish test_structure
