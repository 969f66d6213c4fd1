#!/usr/bin/env bash
# `ssgraph compare` and the compare node in a graph, from the outside: identical files score
# rmse 0 and ssim 1 (psnr null) in one line of JSON, different layers score a real error,
# a mask restricts the pixels, bad input (missing file, shape mismatch, bad options) exits
# non-zero with a message naming the problem, and `ssgraph run` writes compare's metrics to
# out/metrics.json.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_compare_cli"

# Images to compare: the layers of one small SSAO run (ao = filtered, ao_raw = unfiltered).
"$BIN" run graphs/ssao.graph --size 64x48 --out "$TMP/run" --quiet || fail "ssao run"
src="$TMP/run/ssao.exr"

# --- identical images: exactly one line of JSON ---
out=$("$BIN" compare "$src:ao" "$src:ao" --json) || fail "identical compare exited $?"
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "--json printed more than one line: $out"
echo "$out" | grep -Eq '^\{"rmse":0,"mae":0,"bias":0,"psnr":null,"ssim":1,"pixels":3072,"mean":([0-9.]+),"reference_mean":\1,"flip":0\}$' \
    || fail "identical images: unexpected JSON $out"
out=$("$BIN" compare "$src" "$src" --json) || fail "identical colour compare exited $?"
echo "$out" | grep -q '"rmse":0,.*"ssim":1,' || fail "identical colour images: $out"

# --- different images: a real, finite error; the table form ---
out=$("$BIN" compare "$src:ao_raw" "$src:ao" --json) || fail "different compare exited $?"
echo "$out" | grep -Eq '^\{"rmse":0\.[0-9]+(e-[0-9]+)?,"mae":0\.[0-9]+(e-[0-9]+)?,"bias":-?0\.[0-9]+(e-[0-9]+)?,"psnr":[0-9.]+,"ssim":0\.[0-9]+,"pixels":3072,"mean":[0-9.]+,"reference_mean":[0-9.]+,"flip":0\.[0-9]+(e-[0-9]+)?\}$' \
    || fail "different images: unexpected JSON $out"
expect_exit 0 "^rmse +0\.[0-9]+" "$BIN" compare "$src:ao_raw" "$src:ao"
expect_exit 0 "psnr +inf" "$BIN" compare "$src:ao" "$src:ao"
# a higher peak raises PSNR by 20 log10(2) = 6.02 dB
p1=$("$BIN" compare "$src:ao_raw" "$src:ao" --json | sed 's/.*"psnr":\([0-9.]*\).*/\1/')
p2=$("$BIN" compare "$src:ao_raw" "$src:ao" --json --peak 2 | sed 's/.*"psnr":\([0-9.]*\).*/\1/')
awk -v a="$p1" -v b="$p2" 'BEGIN { d = b - a - 6.0206; exit !(d < 1e-3 && d > -1e-3) }' \
    || fail "--peak 2 should add 6.02 dB to PSNR: $p1 -> $p2"

# --- a mask restricts the pixels (depth > 0.5: the surfaces, not the background) ---
out=$("$BIN" compare "$src:ao_raw" "$src:ao" --mask "$src:depth" --json) || fail "mask run"
n=$(echo "$out" | sed 's/.*"pixels":\([0-9]*\).*/\1/')
[ "$n" -gt 0 ] && [ "$n" -lt 3072 ] || fail "--mask did not restrict the pixels: $out"

# --- --depth turns on the structure measure: identical images have d = 0 everywhere ---
out=$("$BIN" compare "$src:ao" "$src:ao" --mask "$src:depth" --depth "$src:depth" --json) \
    || fail "--depth compare exited $?"
echo "$out" | grep -Eq '"structure_pp":(0|null),"structure_rms":(0|null),"structure_pixels":[0-9]+,' \
    || fail "--depth: no structure measure in $out"
expect_exit 1 "missing.exr" "$BIN" compare "$src:ao" "$src:ao" --depth "$TMP/missing.exr"

# --- errors: clear message, exit 1 (bad input) or 2 (bad command line) ---
expect_exit 1 "$TMP/missing.exr" "$BIN" compare "$TMP/missing.exr" "$src:ao"
expect_exit 1 "$TMP/missing.exr" "$BIN" compare "$src:ao" "$TMP/missing.exr" --json
printf 'not an image' > "$TMP/corrupt.exr"
expect_exit 1 "corrupt.exr" "$BIN" compare "$TMP/corrupt.exr" "$src:ao"
expect_exit 1 "same type" "$BIN" compare "$src" "$src:ao"
"$BIN" run graphs/ssao.graph --size 32x24 --out "$TMP/small" --quiet || fail "small run"
expect_exit 1 "same size: a is 64x48, b is 32x24" "$BIN" compare "$src:ao" "$TMP/small/ssao.exr:ao"
expect_exit 1 "mask" "$BIN" compare "$src:ao" "$src:ao" --mask "$TMP/small/ssao.exr:depth"
expect_exit 2 "two image files" "$BIN" compare "$src:ao"
expect_exit 2 "unexpected argument" "$BIN" compare "$src:ao" "$src:ao" "$src:ao"
expect_exit 2 "--peak expects" "$BIN" compare "$src:ao" "$src:ao" --peak 0
expect_exit 2 "needs a value" "$BIN" compare "$src:ao" "$src:ao" --mask
expect_exit 2 "unknown option '--frob'" "$BIN" compare "$src:ao" "$src:ao" --frob

# --- in a graph: metrics printed after the timings and written to metrics.json ---
cat > "$TMP/cmp.graph" <<EOF
scene "$PWD/examples/cornell.scene"
size 48 32
g = gbuffer()
same = compare(g.depth, g.depth)
half = compare(g.depth, g.normal)
EOF
expect_exit 1 "same type" "$BIN" check "$TMP/cmp.graph"
cat > "$TMP/cmp.graph" <<EOF
scene "$PWD/examples/cornell.scene"
size 48 32
g = gbuffer()
same = compare(g.depth, g.depth, mask=g.depth)
albedo = compare(g.albedo, g.direct)
EOF
expect_exit 0 "same +ssim +1" "$BIN" run "$TMP/cmp.graph" --out "$TMP/graph"
json="$TMP/graph/metrics.json"
[ -f "$json" ] || fail "run did not write $json"
tr -d ' \n' < "$json" | grep -q '"same":{"rmse":0,"mae":0,"bias":0,"psnr":null,"ssim":1,"pixels":[0-9]*,"mean":[0-9.e-]*,"reference_mean":[0-9.e-]*,"flip":0}' \
    || fail "metrics.json lacks the identical comparison: $(cat "$json")"
tr -d ' \n' < "$json" | grep -q '"albedo":{"rmse":0\.[0-9]*' \
    || fail "metrics.json lacks the albedo comparison: $(cat "$json")"

finish test_compare_cli
