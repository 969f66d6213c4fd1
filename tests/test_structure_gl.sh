#!/usr/bin/env bash
# How a node's GL side binds what its shaders read (core/gl/gl.h, issue 43 item 4):
# parameters by the table (#pragma ssg_params), prepare()'s constants by the descriptor's
# `uniforms` rows (#pragma ssg_consts), ports by ssg_gl_ports. A uniform bound by hand in
# nodes/*/*_gl.c (ssg_gl_int, ssg_gl_input, ...) is refused unless it is listed below with
# the reason no table can hold it, and never when it names a row of its node's tables; a
# listed binding that is gone must leave the list too, so the list stays the truth.
# And each GLSL helper function is defined once across the node shaders: a second copy
# goes into nodes/common/*.glsl (as its C twin lives in nodes/common/*.h).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_structure_gl"

# file, the name it binds by hand, and why no table holds it.
allowed=$(cat <<'EOF'
nodes/bilateral/bilateral_gl.c "src" each pass's source: in, or the scratch image of the pass before
nodes/bilateral/bilateral_gl.c "src2" each pass's in2, or its scratch image
nodes/bilateral/bilateral_gl.c "dst" each pass's destination: a scratch image, out for the last
nodes/bilateral/bilateral_gl.c "dst2" likewise for in2's
nodes/bilateral/bilateral_gl.c "reach" the pass's half-widths (separable: a row, then a column)
nodes/bilateral/bilateral_gl.c "step" the pass's tap spacing (atrous: 1, 2, 4, ...)
nodes/bilateral/bilateral_gl.c "depth" a port of a multi-pass node (ssg_gl_ports would bind in and out, which passes replace)
nodes/bilateral/bilateral_gl.c "normal" likewise, and read only with normal_power > 0 as well as connected
nodes/gaussian/gaussian_gl.c "src" each axis's source: in, then the scratch image
nodes/gaussian/gaussian_gl.c "dst" each axis's destination: the scratch image, then out
nodes/gaussian/gaussian_gl.c "axis" the pass's axis
nodes/gaussian/gaussian_gl.c "layer" the dispatch's channel (a loop index)
nodes/temporal/temporal_gl.c "reset" ctx->history_reset of this run, in no table
nodes/taau/taau_gl.c "reset" ctx->history_reset of this run, in no table
nodes/probe_light/probe_light_gl.c "lights" the frames pass: the node's second shader (one consts table serves the light pass)
nodes/probe_light/probe_light_gl.c "frames" the scratch image the frames pass writes and the light pass reads
nodes/probe_light/probe_light_gl.c "rot" the frames pass (second shader), as "lights"
nodes/probe_light/probe_light_gl.c "eye" the frames pass (second shader), as "lights"
nodes/probe_light/probe_light_gl.c "centre" the frames pass: the bounding sphere, shared with the CPU's shadow frames
nodes/probe_light/probe_light_gl.c "radius" the frames pass: likewise
nodes/probe_light/probe_light_gl.c "frame_res" the frames pass (second shader), as "lights"
nodes/shadowmaps/shadowmaps_gl.c "lights" a raster pass: its outputs are drawn layers, not image bindings (ssg_gl_ports)
nodes/shadowmaps/shadowmaps_gl.c "centre" the scene's bounding sphere, taken at run time (shadowmaps has no prepare())
nodes/shadowmaps/shadowmaps_gl.c "radius" likewise
nodes/common/horizon_gl.c "invf" the three horizon nodes' shared setup: a member of three consts structs, bound in this one place (horizon.h)
nodes/common/horizon_gl.c "proj" likewise
nodes/complexity/complexity_gl.c "nd" a grid's scratch image of mean normals and depths, written by its means pass, read by its weight pass
nodes/complexity/complexity_gl.c "pt" a grid's scratch image of mean points, likewise
nodes/complexity/complexity_gl.c "weight" a grid's scratch image of cell weights, read by the count pass as t<r>
nodes/complexity/complexity_gl.c "side" the cell side of the grid this means pass is for (one pass a grid: a loop value)
nodes/complexity/complexity_gl.c names[r] the grids' weight images (scratch), t0 to t3
nodes/gbuffer/gbuffer_gl.c "ids" the visibility buffer (scratch): the raster pass writes it, the shading pass reads it, the peel redraws it for the back pass
nodes/gbuffer/gbuffer_gl.c "first" the first layer's depth, the shading pass's output read by the peel, back and motion passes
nodes/gtao/gtao_gl.c "noise_shift" this frame's turn of the slices (ssg_gtao_frame_of, from ctx->frame_index): in no table
nodes/gtao/gtao_gl.c "slice_cos" this frame's slice directions (ssg_gtao_frame_of): a per-frame array, in no table
nodes/gtao/gtao_gl.c "slice_sin" likewise
nodes/hbao/hbao_gl.c "dir_cos" the consts' flexible tail (consts_size_of), one a direction: an array no fixed row holds
nodes/hbao/hbao_gl.c "dir_rank" likewise
nodes/hbao/hbao_gl.c "dir_sin" likewise
nodes/rsm/rsm_gl.c "cells" the scratch image of the slots: the cells pass writes it, the list pass reads it
nodes/rsm/rsm_gl.c "list" the scratch image of the non-empty slots and their CDF, between the passes
nodes/rsm/rsm_gl.c "state" the list walk's scratch (count, sum) carried between its dispatches
nodes/rsm/rsm_gl.c "count" that scratch read by the picks and the gather (the VPL count)
nodes/rsm/rsm_gl.c "pick" the scratch image of the draws the picks pass makes, read by the gather
nodes/rsm/rsm_gl.c "acc" the gather's scratch sums between the dispatches of an exact run
nodes/rsm/rsm_gl.c "row0" the list walk's dispatch: its first row (a loop value)
nodes/rsm/rsm_gl.c "vpl0" the exact gather's dispatch: its first VPL (a loop value)
nodes/rsm/rsm_gl.c "vpls" the exact gather's dispatch: how many VPLs (a loop value)
nodes/rsm/rsm_gl.c "first" the exact gather's dispatch: the first (a loop value)
nodes/rsm/rsm_gl.c "last" the exact gather's dispatch: the last (a loop value)
nodes/ssilvb/ssilvb_gl.c "noise_off" this frame's noise offsets (ssg_ssilvb_frame_of, from ctx->frame_index): in no table
nodes/ssilvb/ssilvb_gl.c "slice_cos" this frame's slice directions (ssg_ssilvb_frame_of): a per-frame array
nodes/ssilvb/ssilvb_gl.c "slice_sin" likewise
nodes/ssilvb/ssilvb_gl.c "turn_cos" a float array of the consts (rows hold scalars, vectors and matrices, not arrays)
nodes/ssilvb/ssilvb_gl.c "turn_sin" likewise
EOF
)

# Every hand binding as `file name`, the name as written (a literal or an expression).
bindings=$(git ls-files 'nodes/*/*_gl.c' 2>/dev/null | sort | while read -r f; do
    grep -oE 'ssg_gl_(int|ivec2|float|vec2|vec3|vec4|floats|ints|input|output|projection)\([^,]+, *[^,)]+' "$f" |
        sed -E 's/^[^,]+, *//' | sort -u | sed "s|^|$f |"
done)
listed=$(echo "$allowed" | awk '{print $1, $2}' | sort -u)
new=$(comm -23 <(echo "$bindings" | sort -u) <(echo "$listed"))
[ -z "$new" ] || fail "uniforms bound by hand (bind them from the tables: #pragma ssg_params, a
\`uniforms\` row and #pragma ssg_consts, or ssg_gl_ports; or list them in this test with the
reason no table holds them):
$new"
gone=$(comm -13 <(echo "$bindings" | sort -u) <(echo "$listed"))
[ -z "$gone" ] || fail "listed hand bindings that are gone (remove them from the list): $gone"

# A hand binding never names a row of its node's tables: that row is bound already (as
# p_<field> or <field>), and a second binding under its own name would be a copy; nor a
# parameter under its plain name (the old form, p_<field> is the table's).
while read -r f name; do
    [ -n "$f" ] || continue
    dir=$(dirname "$f")
    rows=$(cat "$dir"/*.h 2>/dev/null | grep -oE '\b[PU]\([A-Z0-9]+, *[a-z_0-9]+' |
           sed -E 's/^P\([A-Z0-9]+, */p_/; s/^U\([A-Z0-9]+, *//')
    plain=$(echo "$rows" | sed 's/^p_//')
    bare=${name//\"/}
    if echo "$rows" | grep -qx "$bare"; then
        fail "$f binds \"$bare\" by hand, a row of its node's tables (bound by the pass)"
    elif echo "$plain" | grep -qx "$bare" && echo "$rows" | grep -qx "p_$bare"; then
        fail "$f binds parameter \"$bare\" by hand: read it as p_$bare (#pragma ssg_params)"
    fi
done <<< "$bindings"

# A row's or port's .gl_in names shader files of the tree (a renamed shader would leave its
# rows unchecked there): every name in a .gl_in string, or in a macro one is made of.
gl_in=$(git ls-files 'nodes/*/*.h' 'nodes/*/*.c' 2>/dev/null | xargs cat |
        grep -oE '(gl_in = |#define SSG_[A-Z_]*_GL_[A-Z_]+ )"[^"]*"' | sed -E 's/^[^"]*"//; s/"$//' |
        tr ' ' '\n' | grep -v '^$' | sort -u)
[ -n "$gl_in" ] || fail "no .gl_in names found (the pattern above no longer matches)"
for s in $gl_in; do
    git ls-files "nodes/*/$s" | grep -q . || fail ".gl_in names $s, which is no shader file"
done

# GLSL helpers once: a function (return type, name, parameter types) defined in two node
# shaders is a copy; it belongs in nodes/common/*.glsl, #include'd by both (as
# joint_weights.glsl serves bilateral and upsample). main() is each shader's own; the
# signatures below are known and wait for the change named.
known=$(cat <<'EOF'
void setup_pixel(ivec2) gtao and ssilvb: two functions of one name, each its own turn and jitter (the shared setup is horizon.glsl's ssg_horizon_pixel)
void store_background(ivec2) gbuffer and ssdo: two different functions of one name
EOF
)
defs=$(git ls-files 'nodes/*/*.glsl' 2>/dev/null | while read -r f; do
    awk -v f="$f" '
        /^(precise )?(float|vec[234]|ivec[234]|int|uint|bool|void) [a-z_A-Z0-9]+\(/ {
            head = $0; sub(/\(.*/, "", head); args = $0; sub(/^[^(]*\(/, "", args)
            sub(/\).*/, "", args); n = split(args, a, ","); sig = ""
            for (i = 1; i <= n; i++) {   # a parameter: its words but the last
                k = split(a[i], w, " "); t = ""
                for (m = 1; m < k; m++) if (w[m] !~ /^(in|out|inout|const|precise)$/) t = t w[m]
                sig = sig (i > 1 ? "," : "") t
            }
            if (head !~ / main$/) print head "(" sig ")\t" f }' "$f"
done)
# (one shader's variants, #ifdef'd, may each define it: counted once a file)
twice=$(echo "$defs" | sort -u | awk -F'\t' '{n[$1]++; at[$1] = at[$1] " " $2}
                                   END {for (s in n) if (n[s] > 1) print s "\t" at[s]}' |
        while IFS=$'\t' read -r sig at; do
            echo "$known" | grep -qF "$sig " || echo "$sig:$at"; done)
[ -z "$twice" ] || fail "GLSL functions defined in more than one shader (move one copy into
nodes/common/*.glsl and #include it): $twice"
stale=$(echo "$known" | while read -r ret rest; do sig="$ret ${rest%%)*})"
        n=$(echo "$defs" | sort -u | cut -f1 | grep -cxF "$sig"); [ "$n" -ge 2 ] || echo "$sig"; done)
[ -z "$stale" ] || fail "signatures listed as known copies that are no longer twice: $stale"
finish test_structure_gl
