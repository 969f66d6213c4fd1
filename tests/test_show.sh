#!/usr/bin/env bash
# `ssgraph run --show`, `ssgraph layers` and `ssgraph extract` (cli/show.c, cli/layers.c):
# a shown port is the very pixels a write node writes of it (EXR exactly, PNG byte for
# byte), the graph's own files are unchanged by --show, on CPU and GL; layers lists the
# write node's layers with their channels; extract round-trips a layer exactly; bad input
# gets a clear message, a non-zero exit and no file.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_show"
g=graphs/ssao.graph
run=(--size 64x48 --threads 2 --quiet)

# same_pixels A B: the two single-layer EXRs hold the same floats (oiiotool, independent of
# ssgraph's reader).
same_pixels() {
    oiiotool "$1" "$2" --fail 0 --failpercent 0 --diff > "$TMP/diff.txt" 2>&1 \
        || fail "$1 and $2 differ: $(tail -3 "$TMP/diff.txt")"
}
# layer FILE CHANNELS OUT: those channels of FILE renamed to Y / R,G,B, as a one-layer EXR.
layer() {
    local names=Y
    case "$2" in *,*,*) names=R,G,B ;; esac
    oiiotool "$1" --ch "$2" --chnames "$names" -d float -o "$3" || fail "oiiotool --ch $2 of $1"
}

for backend in cpu gl; do
    out=$TMP/$backend
    "$BIN" run $g "${run[@]}" --backend $backend --out "$out/plain" || fail "$backend: plain run"
    "$BIN" run $g "${run[@]}" --backend $backend --out "$out" \
        --show ao.out,b.out,g.normal,img.out || fail "$backend: --show run"
    # the graph ran as always: its own files, byte for byte
    for f in ssao.exr ssao.png; do
        cmp -s "$out/plain/$f" "$out/$f" || fail "$backend: --show changed the graph's $f"
    done
    # each shown port is what the write node wrote of it
    for pair in ao.out:ao_raw.Y b.out:ao.Y g.normal:normal.X,normal.Y,normal.Z \
        img.out:R,G,B; do
        port=${pair%%:*} channels=${pair#*:}
        [ -f "$out/$port.exr" ] && [ -f "$out/$port.png" ] || fail "$backend: no $port files"
        layer "$out/ssao.exr" "$channels" "$TMP/want.exr"
        same_pixels "$out/$port.exr" "$TMP/want.exr"
    done
    # the PNG preview is the write node's: the main image's is ssao.png itself
    cmp -s "$out/img.out.png" "$out/ssao.png" || fail "$backend: img.out.png is not ssao.png"
    oiiotool --info "$out/ao.out.png" | grep -q "64 x  *48, 1 channel" \
        || fail "$backend: ao.out.png is not one grey channel: $(oiiotool --info "$out/ao.out.png")"
    oiiotool --info "$out/g.normal.png" | grep -q "64 x  *48, 3 channel" \
        || fail "$backend: g.normal.png is not colour"
done

# a guard band is cropped as the write node crops it
"$BIN" run $g "${run[@]}" --guard 6 --out "$TMP/guard" --show g.depth || fail "guard run"
layer "$TMP/guard/ssao.exr" Z "$TMP/want_z.exr"
same_pixels "$TMP/guard/g.depth.exr" "$TMP/want_z.exr"

# `wrote` lines name the shown files after the graph's, before the table
"$BIN" run $g --size 64x48 --out "$TMP/log" --show ao.out > "$TMP/log.txt" || fail "log run"
grep -n '^wrote \|^node ' "$TMP/log.txt" | cut -d: -f2- | tr '\n' '|' > "$TMP/order.txt"
grep -qx "wrote $TMP/log/ssao.exr|wrote $TMP/log/ssao.png|wrote $TMP/log/ao.out.exr|wrote $TMP/log/ao.out.png|node .*|" \
    "$TMP/order.txt" || fail "run --show printed: $(cat "$TMP/order.txt")"

# --- layers: every layer of the write node, its channels as the file names them ---
exr=$TMP/cpu/ssao.exr
"$BIN" layers "$exr" > "$TMP/layers.txt" || fail "layers: $(cat "$TMP/layers.txt")"
grep -qx "$exr: 8 layers" "$TMP/layers.txt" || fail "layers' header: $(head -1 "$TMP/layers.txt")"
for row in "\(unnamed\) +R,G,B" "depth +Z" "ao +ao\.Y" "ao_raw +ao_raw\.Y" \
    "normal +normal\.X,normal\.Y,normal\.Z" "position +position\.X,position\.Y,position\.Z" \
    "albedo +albedo\.R,albedo\.G,albedo\.B" "direct +direct\.R,direct\.G,direct\.B"; do
    grep -qE "^$row +64x48 +min [-0-9.e+]+ +max [-0-9.e+]+ +mean [-0-9.e+]+$" "$TMP/layers.txt" \
        || fail "layers lacks /$row/: $(cat "$TMP/layers.txt")"
done
# its numbers are the layer's: the mean as compare reads it, a normal's range within [-1, 1]
mean=$("$BIN" compare "$exr:ao" "$exr:ao" | awk '$1 == "mean" { printf "%.6g", $2 }')
grep -qE "^ao +ao\.Y +64x48 .* mean $mean$" "$TMP/layers.txt" \
    || fail "layers' ao mean is not $mean: $(grep '^ao ' "$TMP/layers.txt")"
awk '$1 == "normal" { exit !($5 >= -1 && $5 < 0 && $7 > 0 && $7 <= 1) }' "$TMP/layers.txt" \
    || fail "layers' normal range: $(grep '^normal ' "$TMP/layers.txt")"
expect_exit 0 "^.*ao.out.png: 1 layer" "$BIN" layers "$TMP/cpu/ao.out.png"

# --- extract: a layer exactly, by its name or its channel's; one channel alone ---
expect_exit 0 "^wrote $TMP/ao.exr$" "$BIN" extract "$exr" ao -o "$TMP/ao.exr"
layer "$exr" ao.Y "$TMP/want_ao.exr"
same_pixels "$TMP/ao.exr" "$TMP/want_ao.exr"
"$BIN" extract "$exr" ao.Y -o "$TMP/ao_y.exr" > /dev/null || fail "extract ao.Y"
cmp -s "$TMP/ao.exr" "$TMP/ao_y.exr" || fail "extract ao.Y differs from extract ao"
"$BIN" extract "$exr" normal.Y -o "$TMP/ny.exr" > /dev/null || fail "extract normal.Y"
layer "$exr" normal.Y "$TMP/want_ny.exr"
same_pixels "$TMP/ny.exr" "$TMP/want_ny.exr"
"$BIN" extract "$exr" '(unnamed)' -o "$TMP/main.png" > /dev/null || fail "extract (unnamed)"
cmp -s "$TMP/main.png" "$TMP/cpu/ssao.png" || fail "the main layer's PNG is not the write node's"
"$BIN" extract "$exr" ao -o "$TMP/ao.png" > /dev/null || fail "extract ao -o PNG"
oiiotool --info "$TMP/ao.png" | grep -q "1 channel" || fail "ao.png is not grey"
"$BIN" extract "$exr" ao --tonemap clamp -o "$TMP/ao_clamp.png" > /dev/null \
    || fail "extract --tonemap clamp"
cmp -s "$TMP/ao.png" "$TMP/ao_clamp.png" && fail "--tonemap clamp made the aces PNG"
# an extracted EXR reads back as the same layer: extract of the extract
"$BIN" extract "$TMP/ao.exr" Y -o "$TMP/ao2.exr" > /dev/null || fail "extract of an extract"
cmp -s "$TMP/ao.exr" "$TMP/ao2.exr" || fail "extract does not round-trip its own file"

# --- bad input: a message, a non-zero exit, no file (and no temporary) ---
mkdir -p "$TMP/bad"
expect_exit 1 "nosuch.exr: error: cannot read image" "$BIN" layers "$TMP/nosuch.exr"
expect_exit 1 "nosuch.exr: error: cannot read image" \
    "$BIN" extract "$TMP/nosuch.exr" ao -o "$TMP/bad/x.png"
expect_exit 1 "no layer 'occlusion' \(layers in the file: \(unnamed\), depth, .*ao_raw" \
    "$BIN" extract "$exr" occlusion -o "$TMP/bad/x.exr"
expect_exit 1 "error: " "$BIN" extract "$exr" ao -o "$TMP/nodir/x.exr"
expect_exit 2 "extract writes -o OUT.png or OUT.exr, got '.*x.tif'" \
    "$BIN" extract "$exr" ao -o "$TMP/bad/x.tif"
expect_exit 2 "extract writes -o OUT.png or OUT.exr, got 'no -o'" "$BIN" extract "$exr" ao
expect_exit 2 "extract expects FILE LAYER" "$BIN" extract "$exr"
expect_exit 1 "<output>:1:4: error: node 'ao' \(ssao\) has no output 'nope' \(expected one of: out\)" \
    "$BIN" run $g --size 64x48 --out "$TMP/bad/run" --show ao.nope
expect_exit 1 "no node named 'zz'" "$BIN" run $g --size 64x48 --out "$TMP/bad/run" --show zz.out
expect_exit 2 "--show expects NODE.PORT\[,NODE.PORT...\], got 'ao'" \
    "$BIN" run $g --out "$TMP/bad/run" --show ao
expect_exit 2 "--show expects NODE.PORT\[,NODE.PORT...\], got '../x.out'" \
    "$BIN" run $g --out "$TMP/bad/run" --show ao.out,../x.out
expect_exit 2 "--show names 'ao.out' twice" "$BIN" run $g --out "$TMP/bad/run" --show ao.out,ao.out
expect_exit 2 "not with --stereo" "$BIN" run $g --out "$TMP/bad/run" --show ao.out --stereo
expect_exit 2 "--tonemap and --exposure are the PNGs' of --show" \
    "$BIN" run $g --out "$TMP/bad/run" --tonemap clamp
expect_exit 2 "--tonemap expects clamp, reinhard or aces, got 'filmic'" \
    "$BIN" extract "$exr" ao -o "$TMP/bad/x.png" --tonemap filmic
[ -z "$(ls -A "$TMP/bad")" ] || fail "bad input left files: $(ls -A "$TMP/bad")"
[ ! -e "$TMP/nodir" ] || fail "extract made the missing folder $TMP/nodir"

finish test_show
