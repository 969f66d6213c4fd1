#!/usr/bin/env bash
# EXR metadata, depth as Z, stereo as one multi-view EXR, and `node` taking its camera from
# an input file (README, "EXR metadata"):
#  1. A run's EXR carries software, the graph, the --set list, the seed, the frame, the
#     camera and OpenEXR's worldToCamera/worldToNDC, as oiiotool reads them.
#  2. The layer `depth` is the bare channel Z, read back as `:depth`; an old file's depth.Y
#     still reads; the main image stays R,G,B.
#  3. --stereo writes one EXR with views left (default) and right (right.R, ao.right.Y,
#     right.Z, the right eye's camera as ssgraph:right:*) and a PNG per eye, nothing else.
#  4. `node` on an ssgraph EXR uses its fov (40, not the default 45); --fov still wins; a
#     foreign file (metadata erased) keeps the default.
#  5. Every compression the write node offers (written by OpenEXRCore, docs/exr.md) reads in
#     OpenImageIO as that compression, with the same pixels as zip.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_exr_meta"

info() { # oiiotool's listing of a file, made once (each oiiotool start costs)
    [ -f "$1.info" ] || oiiotool --info -v "$1" > "$1.info" 2>&1
    cat "$1.info"
}
has() { # has FILE PATTERN: oiiotool's listing of FILE matches PATTERN (grep -E)
    info "$1" | grep -Eq -- "$2" || fail "$1 lacks /$2/: $(info "$1")"
}
rmse() { "$BIN" compare "$1" "$2" --json | sed -n 's/.*"rmse":\([^,]*\),.*/\1/p'; }

# --- 1. the metadata of a run ---
f="$TMP/m/ssao.exr"
"$BIN" run graphs/ssao.graph --size 48x32 --seed 5 --set ao.radius=0.3 --out "$TMP/m" --quiet \
    > "$TMP/log" 2>&1 || fail "run: $(tail -3 "$TMP/log")"
version=$("$BIN" --version | head -1 | awk '{print $2}')
has "$f" "software: \"ssgraph $version\""
has "$f" 'ssgraph:graph: "graphs/ssao.graph"'
has "$f" 'ssgraph:overrides: "ao.radius=0.3"'
has "$f" 'ssgraph:seed: "5"'
has "$f" 'ssgraph:frame_size: 48, 32'
has "$f" 'ssgraph:guard: 0'
has "$f" 'ssgraph:fov: 40$'
has "$f" 'ssgraph:camera_position: 0, 1, 3.9$'
has "$f" 'ssgraph:camera_target: 0, 1, 0$'
has "$f" 'ssgraph:scene: ".*cornell.scene"'
# OpenEXR's camera space looks down +z: the scene's origin is 3.9 in front of the camera
has "$f" 'worldToCamera: 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, -1, 3.9, 1$'
# worldToNDC takes the point looked at, (0, 1, 0), to the frame's centre (0.5, 0.5)
python3 - "$(info "$f" | sed -n 's/.*worldToNDC: //p')" <<'PY' || fail "worldToNDC is wrong"
import sys
m = [float(v) for v in sys.argv[1].split(",")]
p = [0, 1, 0, 1]
x, y, _, w = (sum(p[r] * m[4 * r + c] for r in range(4)) for c in range(4))
assert abs(x / w - 0.5) < 1e-5 and abs(y / w - 0.5) < 1e-5, (x / w, y / w)
PY

# --- 2. depth as Z ---
has "$f" 'channel list: R, G, B, Z, '
info "$f" | grep -q 'depth\.' && fail "$f still has a depth.* channel"
oiiotool "$f" --ch Z -o "$TMP/z.exr" && oiiotool "$f" --ch R,G,B -o "$TMP/rgb.exr" \
    || fail "oiiotool cannot split $f"
[ "$(rmse "$TMP/z.exr" "$f:depth")" = 0 ] || fail ":depth does not read the Z channel"
[ "$(rmse "$TMP/rgb.exr" "$f")" = 0 ] || fail "the main image is not R,G,B"
oiiotool "$f" --ch Z --chnames depth.Y -o "$TMP/old.exr" || fail "oiiotool depth.Y"
[ "$(rmse "$TMP/old.exr:depth" "$f:depth")" = 0 ] || fail "an old depth.Y file no longer reads"

# --- 3. stereo: one multi-view EXR and two previews ---
s="$TMP/st"
"$BIN" run graphs/ssao.graph --stereo --ipd 0.2 --size 40x32 --out "$s" --quiet \
    > "$TMP/log" 2>&1 || fail "stereo run: $(tail -3 "$TMP/log")"
[ "$(ls -A "$s" | tr '\n' ' ')" = "ssao.exr ssao_left.png ssao_right.png " ] \
    || fail "--stereo wrote $(ls -A "$s" | tr '\n' ' ')"
has "$s/ssao.exr" 'multiView: "left", "right"'
has "$s/ssao.exr" 'channel list: R, G, B, Z, .*ao\.right\.Y.*right\.R, right\.G, right\.B, right\.Z$'
has "$s/ssao.exr" 'ssgraph:camera_position: -0.1, 1, 3.9$'
has "$s/ssao.exr" 'ssgraph:right:camera_position: 0.1, 1, 3.9$'
has "$s/ssao.exr" 'ssgraph:right:worldToCamera: '
[ "$(rmse "$s/ssao.exr:right" "$s/ssao.exr")" != 0 ] || fail "both views are the same"
[ "$(rmse "$s/ssao.exr:depth.right" "$s/ssao.exr:depth")" != 0 ] \
    || fail "the right view's depth is the left one's"
[ "$(rmse "$s/ssao.exr:ao.right" "$s/ssao.exr:ao")" != 0 ] || fail "ao.right = ao"

# --- 4. node takes the fov from the file ---
"$BIN" node halton --set count=8 --out "$TMP/k" > /dev/null || fail "halton"
ao() { # ao OUT FILE [ARGS]: ssao on FILE's position and normal
    local out=$1 file=$2; shift 2
    "$BIN" node ssao --in "position=$file:position" --in "normal=$file:normal" \
        --in "kernel=$TMP/k/samples.exr" --set radius=0.4 "$@" --out "$TMP/$out" > /dev/null \
        || fail "node ssao $out"
}
ao own "$f"
ao fov40 "$f" --fov 40
ao fov45 "$f" --fov 45
[ "$(rmse "$TMP/own/out.exr" "$TMP/fov40/out.exr")" = 0 ] || fail "node ignored the file's fov 40"
[ "$(rmse "$TMP/own/out.exr" "$TMP/fov45/out.exr")" != 0 ] || fail "fov 40 and 45 give one result"
ao win "$f" --fov 45
[ "$(rmse "$TMP/win/out.exr" "$TMP/fov45/out.exr")" = 0 ] || fail "--fov 45 did not win"
oiiotool "$f" --eraseattrib "ssgraph:.*" -o "$TMP/foreign.exr" || fail "oiiotool erase"
info "$TMP/foreign.exr" | grep -q 'ssgraph:fov' && fail "the foreign file kept ssgraph:fov"
ao foreign "$TMP/foreign.exr"
[ "$(rmse "$TMP/foreign/out.exr" "$TMP/fov45/out.exr")" = 0 ] \
    || fail "a foreign file without --fov no longer gets the default fov"

# --- 5. every compression, as OpenImageIO reads it ---
for c in zip none rle piz; do
    "$BIN" run graphs/ssao.graph --size 40x37 --set out.compression=$c --out "$TMP/c_$c" \
        --quiet > "$TMP/log" 2>&1 || fail "compression=$c: $(tail -3 "$TMP/log")"
    has "$TMP/c_$c/ssao.exr" "compression: \"$c\""
    [ $c = zip ] || oiiotool --diff "$TMP/c_zip/ssao.exr" "$TMP/c_$c/ssao.exr" > "$TMP/diff" 2>&1 \
        || fail "compression=$c differs from zip in OpenImageIO: $(tail -3 "$TMP/diff")"
done

finish test_exr_meta
