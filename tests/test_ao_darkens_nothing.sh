#!/usr/bin/env bash
# combine warns at its definition when its ambient_occlusion darkens nothing: AO darkens the
# environment, ambient and irradiance terms, and with none of them lit the image is the same
# without it (issue 46: gi_error.graph's ssao row equalled no occlusion on the Cornell box
# under its own light, without a word). Under a sky, or with an ambient, no warning.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_ao_darkens_nothing"

warn="gi_error.graph:[0-9]+:[0-9]+: warning: node 'ssao_img' \(combine\): its ambient_occlusion darkens nothing"
expect_exit 0 "$warn.*--lights examples/lights/sky.scene" "$BIN" check graphs/gi_error.graph
out=$("$BIN" check graphs/gi_error.graph --lights examples/lights/sky.scene 2>&1)
echo "$out" | grep -q "darkens nothing" && fail "a warning under the sky: $out"
out=$("$BIN" check graphs/ssao.graph 2>&1) # its combine has an ambient term
echo "$out" | grep -q "darkens nothing" && fail "a warning with an ambient term: $out"
# the run says it too, and still runs
expect_exit 0 "$warn" "$BIN" run graphs/gi_error.graph --size 32x24 --set ref.samples=1 \
    --out "$TMP/out" -q
finish test_ao_darkens_nothing
