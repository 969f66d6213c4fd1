#!/usr/bin/env bash
# The atrium (examples/atrium.scene, issue 45) is the output of tools/make_atrium.py: the
# script run again writes the same glTF and buffer bytes and the same texture pixels, so
# the committed scene never drifts from its generator. And it is a scene as real ones come:
# `check` finds nothing in its glTF that ssgraph does not read (its alpha-masked leaves and
# banners, normal-mapped paving, emissive lanterns and spot lights all read), and counts its
# triangles and lights.
set -u
source "$(dirname "$0")/lib.sh" ssg_test_atrium

/usr/bin/python3 tools/make_atrium.py "$TMP/atrium" > "$TMP/make.log" 2>&1 ||
    fail "make_atrium.py failed: $(tail -3 "$TMP/make.log")"
for f in atrium.gltf atrium.bin; do
    cmp -s "$TMP/atrium/$f" "examples/atrium/$f" ||
        fail "examples/atrium/$f differs from what tools/make_atrium.py writes (run it again)"
done
/usr/bin/python3 - "$TMP/atrium" examples/atrium <<'PY' || fail "a texture differs from the script's"
import sys, numpy as np
from PIL import Image
for name in ("paving.png", "paving_normal.png", "leaf.png", "cloth.png"):
    a, b = (np.asarray(Image.open(d + "/" + name)) for d in sys.argv[1:3])
    if a.shape != b.shape or (a != b).any():
        sys.exit(name)
PY

out=$("$BIN" check examples/atrium.scene 2>&1) || fail "check failed: $out"
echo "$out" | grep -q "triangles: 267584" || fail "check does not count 267584 triangles: $out"
echo "$out" | grep -q "lights: 5 and an environment" || fail "the sun and 4 spots: $out"
[ "$(echo "$out" | grep -c "spot_light")" -eq 4 ] || fail "the file's four spot lights: $out"
echo "$out" | grep -qi "not read\|warning" && fail "something in the atrium goes unread: $out"
finish test_atrium
