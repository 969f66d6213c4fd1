#!/usr/bin/env bash
# Hostile input and hostile conditions, each a defect once found (issue 13): every case
# must end in a located message and a non-zero exit (or, for the conditions, in outputs
# that are either the previous complete files or the new ones), never a crash, a hang, an
# absurd allocation or a file written where it should not be. Fixtures live in
# tests/fixtures/hostile/; the rest is made here. Each command runs under `timeout`, so a
# hang fails the case instead of the suite.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_hostile"
H=tests/fixtures/hostile
T="timeout 60"

# --- text formats ---
# Nested brackets: a located syntax error, not a stack overflow.
expect_exit 1 "nested.graph:2:53: error: lists nested deeper than 16 levels" \
    $T "$BIN" check $H/nested.graph
# An include bomb (15 levels x 8 includes of the next): stopped early, with the chain.
expect_exit 1 "needs more than 1024 files read .*level00.graph -> .*level01.graph" \
    $T "$BIN" check $H/bomb/level00.graph
# More than 1024 set lines: none is dropped; the 1100th, out of range, is reported.
{
    printf 'scene "%s/examples/cornell.scene"\n' "$PWD"
    printf 'g = gbuffer()\nk = halton(count=8)\n'
    printf 'ao = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation)\n'
    printf 'out = write(ao.out, "x")\n'
    for i in $(seq 1 1099); do printf 'set ao.radius = 0.5\n'; done
    printf 'set ao.radius = -7\n'
} > "$TMP/sets.graph"
expect_exit 1 "sets.graph:1105:17: error: parameter 'radius' of 'ao' expects" \
    $T "$BIN" check "$TMP/sets.graph"
# Two write nodes with one name: refused with both places.
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\na = write(g.direct, "x")\nb = write(g.depth, "x")\n' \
    "$PWD" > "$TMP/twice.graph"
expect_exit 1 "twice.graph:4:5: error: node 'b' \(write\) writes 'x.exr', as node 'a' at .*twice.graph:3:5 does" \
    $T "$BIN" check "$TMP/twice.graph"
# ... but one writing only the EXR and one only the PNG of a name do not clash.
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\na = write(g.direct, "x", png=false)\nb = write(g.depth, "x", exr=false)\n' \
    "$PWD" > "$TMP/halves.graph"
expect_exit 0 "ok" $T "$BIN" check "$TMP/halves.graph"
# Checking is linear in the node count: a chain of 100,000 filters is checked in seconds
# (about 4 s in a release build; quadratic checking took 312 s, past the 120 s allowed).
awk -v cwd="$PWD" 'BEGIN {
    printf "size 8 8\nscene \"%s/examples/cornell.scene\"\ng = gbuffer()\nb0 = gaussian(g.depth)\n", cwd
    for (i = 1; i < 100000; i++) printf "b%d = gaussian(b%d.out)\n", i, i - 1
    print "out = write(b99999.out, \"x\")" }' > "$TMP/chain.graph"
expect_exit 0 "chain.graph: ok" timeout 120 "$BIN" check "$TMP/chain.graph"

# --- scenes: coordinates, sizes, special files ---
for z in 1e39 3e38 -3e38; do
    printf 'camera(position=[0, 1, %s], target=[0, 0, 0])\nplane()\n' $z > "$TMP/far.scene"
    expect_exit 1 "far.scene:1:24: error: parameter 'position' of 'camera' expects .*\[-1e\+09, 1e\+09\]" \
        $T "$BIN" run graphs/ssao.graph --scene "$TMP/far.scene" --size 32x24 --out "$TMP/far_out"
done
printf 'sphere(subdivisions=1024)\nsphere(subdivisions=1024)\nsphere(subdivisions=1024)\nsphere(subdivisions=1024)\nsphere(subdivisions=1024)\n' \
    > "$TMP/spheres.scene"
expect_exit 1 "spheres.scene:5:1: error: this shape has 4190208 triangles, which takes the scene past its limit" \
    $T "$BIN" check "$TMP/spheres.scene"
mkdir -p "$TMP/a-directory"
printf 'mesh(file="a-directory")\n' > "$TMP/dirmesh.scene"
expect_exit 1 "dirmesh.scene:1:11: error: .*not a regular file \(it is a directory\)" \
    $T "$BIN" check "$TMP/dirmesh.scene"
# Endless or blocking files where a file is read: /dev/zero and a FIFO with no writer.
mkfifo "$TMP/fifo.exr"
for f in /dev/zero "$TMP/fifo.exr"; do
    printf 'plane()\nenvironment(image="%s")\n' "$f" > "$TMP/env.scene"
    expect_exit 1 "not a regular file" $T "$BIN" check "$TMP/env.scene"
    printf 'material(albedo=[1, 1, 1], texture="%s")\nplane()\n' "$f" > "$TMP/tex.scene"
    expect_exit 1 "not a regular file" $T "$BIN" check "$TMP/tex.scene"
    printf 'mesh(file="%s")\n' "$f" > "$TMP/mesh.scene"
    expect_exit 1 "not a regular file" $T "$BIN" check "$TMP/mesh.scene"
    printf 'include "%s"\n' "$f" > "$TMP/inc.graph"
    expect_exit 1 "inc.graph:1:9: error: cannot read .*not a regular file" \
        $T "$BIN" check "$TMP/inc.graph"
    expect_exit 1 "not a regular file" $T "$BIN" node bilateral --in "in=$f" \
        --in "depth=$f" --out "$TMP/special_out"
    expect_exit 1 "not a regular file" $T "$BIN" check "$f"
done
[ -e "$TMP/special_out" ] && fail "a special input file still produced output"

# --- glTF ---
expect_exit 1 "overflow.scene:1:11: error: .*overflow.gltf: accessor 0 has 6148914691236517206 elements" \
    $T "$BIN" check $H/overflow.scene
expect_exit 1 "nan_vertex.scene:1:11: error: .*accessor 0 element 1 component 0 is NaN" \
    $T "$BIN" check $H/nan_vertex.scene
expect_exit 1 "devzero_buffer.scene:1:11: error: .*devzero_buffer.gltf: .*/dev/zero" \
    $T "$BIN" check $H/devzero_buffer.scene

# --- images: tiled EXR everywhere an image is read; non-finite textures refused ---
printf 'plane()\nenvironment(image="%s/%s/tiled_probe.exr")\n' "$PWD" $H > "$TMP/tiled_env.scene"
printf 'scene "%s/tiled_env.scene"\ng = gbuffer()\nout = write(g.environment, "x")\n' \
    "$TMP" > "$TMP/tiled_env.graph"
expect_exit 0 "total" $T "$BIN" run "$TMP/tiled_env.graph" --size 32x24 --out "$TMP/tiled_env"
printf 'material(albedo=[1, 1, 1], texture="%s/%s/tiled_probe.exr")\nplane()\n' "$PWD" $H \
    > "$TMP/tiled_tex.scene"
expect_exit 0 "ok" $T "$BIN" check "$TMP/tiled_tex.scene"
expect_exit 0 "wrote" $T "$BIN" node gaussian --in "in=tests/fixtures/images/tiled_layer.exr:depth" \
    --out "$TMP/tiled_node"
expect_exit 0 "rmse" $T "$BIN" compare tests/fixtures/images/tiled.exr \
    tests/fixtures/images/scanline.exr
# OpenEXR headers that claim more than the file holds (fuzz_image found a 1 KB file whose
# attribute claims 2 GB: seconds and gigabytes inside OpenEXR before it failed) are refused
# from their sizes alone.
for f in fuzz/corpus/image/exr_header_bomb_1.exr fuzz/corpus/image/exr_header_bomb_2.exr; do
    expect_exit 1 "$(basename $f): error: not a readable image: OpenEXR attribute .* claims [0-9]+ bytes, but the file has" \
        $T "$BIN" node gaussian --in "in=$f" --out "$TMP/bomb_out"
done
# Any format: a 23-byte file whose header declares 3921 x 14887 pixels (found by fuzz_image:
# 9 s and 1.3 GB before the decoder failed) is refused before the image is allocated.
expect_exit 1 "header_declares_gigabyte.img: error: not a readable image: its header declares 3921 x 14887 pixels" \
    $T "$BIN" node gaussian --in "in=fuzz/corpus/image/header_declares_gigabyte.img" --out "$TMP/bomb_out"
expect_exit 1 "truncated_8k.exr: error: not a readable image: OpenEXR header declares 512 chunks" \
    $T "$BIN" node gaussian --in "in=$H/truncated_8k.exr" --out "$TMP/bomb_out"
printf 'material(albedo=[1, 1, 1], texture="%s/%s/inf_texture.exr")\nplane()\n' "$PWD" $H \
    > "$TMP/inf_tex.scene"
expect_exit 1 "inf_texture.exr: error: pixel \(0, 0\) channel 0 is infinite" \
    $T "$BIN" check "$TMP/inf_tex.scene"

# --- outputs: links, full disks, signals ---
good="$TMP/good"
"$BIN" run graphs/ao_error.graph --size 48x32 --out "$good" --quiet > /dev/null 2>&1 \
    || fail "ao_error run failed"
# A symbolic link planted at an output or at the temporary names this process would try
# first is never written through: the victim keeps its bytes, the outputs are real files.
echo "precious" > "$TMP/victim"
out="$TMP/links"
mkdir -p "$out"
for f in metrics.json ao_error.exr ao_error.png profile.json; do
    ln -s "$TMP/victim" "$out/$f"
done
bash -c 'for n in 0 1 2 3 4 5; do for f in metrics.json ao_error.exr ao_error.png profile.json; do
             ext=${f##*.}; [ $ext = json ] && ext= || ext=.$ext
             ln -s "$1/victim" "$2/.$f.tmp-$$-$n$ext"; ln -s "$1/victim" "$2/$f.tmp-$$"; done; done
         exec "$3" run graphs/ao_error.graph --size 48x32 --out "$2" --profile-json "$2/profile.json" --frames 2' \
    _ "$TMP" "$out" "$BIN" > "$TMP/links.log" 2>&1 || fail "run with planted links failed: $(tail -3 "$TMP/links.log")"
[ "$(cat "$TMP/victim")" = "precious" ] || fail "a planted link was written through"
for f in metrics.json ao_error.exr ao_error.png profile.json; do
    [ -f "$out/$f" ] && [ ! -L "$out/$f" ] || fail "$f is not a regular file after the run"
done
"$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 --sweep k.count=4 --out "$TMP/benchlinks" \
    > /dev/null 2>&1 || fail "first bench failed"
for f in bench.csv bench.json bench.md; do rm -f "$TMP/benchlinks/$f"; ln -s "$TMP/victim" "$TMP/benchlinks/$f"; done
"$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 --sweep k.count=4 --out "$TMP/benchlinks" \
    > /dev/null 2>&1 || fail "bench over planted links failed"
[ "$(cat "$TMP/victim")" = "precious" ] || fail "bench wrote through a planted link"
# Plots too, in a folder whose name a shell would parse (gnuplot runs without a shell).
plots="$TMP/it's \$(plots)"
mkdir -p "$plots"
for f in bench_ms.dat bench_ms.gp bench_ms.png bench_ms.log bench_ms.png.tmp; do
    ln -s "$TMP/victim" "$plots/$f"
done
expect_exit 0 "2 cells, 0 failed" "$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 \
    --sweep k.count=4,8 --plot --out "$plots"
[ "$(cat "$TMP/victim")" = "precious" ] || fail "a plot was written through a planted link"
[ -f "$plots/bench_ms.png" ] && [ ! -L "$plots/bench_ms.png" ] || fail "no bench_ms.png drawn"

# A file size limit (RLIMIT_FSIZE; SIGXFSZ ignored, so writes fail with EFBIG): exit 1 with
# a message, the earlier outputs untouched, no temporary left.
before=$(cd "$good" && md5sum ao_error.exr ao_error.png metrics.json)
expect_exit 1 "cannot write.*(File too large|Failed OpenEXR write)" bash -c \
    'trap "" XFSZ; ulimit -f 16; exec "$1" run graphs/ao_error.graph --size 48x32 --set k.count=4 --out "$2"' \
    _ "$BIN" "$good"
[ "$(cd "$good" && md5sum ao_error.exr ao_error.png metrics.json)" = "$before" ] \
    || fail "a failed write changed the earlier outputs"
ls -A "$good" | grep -q tmp && fail "a failed write left a temporary: $(ls -A "$good")"
# A full file system (a small tmpfs, where this user may mount one): the PNG, written after
# the EXR fits, used to come out empty with exit 0.
small="$TMP/small"
mkdir -p "$small"
if mount -t tmpfs -o size=200k tmpfs "$small" 2> /dev/null; then
    "$BIN" run graphs/ssao.graph --size 96x64 --out "$small" --quiet > /dev/null 2>&1 \
        || fail "the first run on the tmpfs failed"
    before=$(cd "$small" && md5sum ssao.exr ssao.png)
    head -c 70000 /dev/zero > "$small/filler" 2> /dev/null
    expect_exit 1 "cannot write.*(No space left on device|Failed OpenEXR write)" \
        "$BIN" run graphs/ssao.graph --size 96x64 --set k.count=8 --out "$small"
    [ "$(cd "$small" && md5sum ssao.exr ssao.png)" = "$before" ] \
        || fail "a full disk changed the earlier outputs"
    ls -A "$small" | grep -q tmp && fail "a full disk left a temporary: $(ls -A "$small")"
    umount "$small"
else
    echo "test_hostile: cannot mount a tmpfs here; the full-disk case ran with RLIMIT_FSIZE only"
fi

# Signals during a large write (1280x720, uncompressed: ~66 MB): after SIGTERM or SIGINT no
# temporary remains; after SIGKILL the next write into the folder removes the leftover;
# every output is always a complete file, the previous one or the new one.
sig="$TMP/sig"
"$BIN" run graphs/ssao.graph --set out.compression=none --out "$sig" --quiet > /dev/null 2>&1 \
    || fail "the first large run failed"
"$BIN" run graphs/ssao.graph --set out.compression=none --set k.count=8 --out "$TMP/signew" \
    --quiet > /dev/null 2>&1 || fail "the reference large run failed"
allowed=$(cd "$sig" && md5sum ssao.exr ssao.png; cd "$TMP/signew" && md5sum ssao.exr ssao.png)
for s in TERM INT KILL; do
    "$BIN" run graphs/ssao.graph --set out.compression=none --set k.count=8 --out "$sig" \
        --quiet > /dev/null 2>&1 &
    pid=$!
    for _ in $(seq 1 3000); do
        ls -A "$sig" | grep -q '^\.ssao\.exr\.tmp-' && break
        sleep 0.01
    done
    kill -$s $pid 2> /dev/null
    wait $pid 2> /dev/null
    for f in ssao.exr ssao.png; do
        sum=$(cd "$sig" && md5sum $f)
        echo "$allowed" | grep -qF "$sum" || fail "after SIG$s, $f is neither the old nor the new file"
    done
    if [ $s != KILL ]; then
        ls -A "$sig" | grep -q tmp && fail "SIG$s left a temporary: $(ls -A "$sig")"
    fi
done
"$BIN" run graphs/ssao.graph --size 64x40 --out "$sig" --quiet > /dev/null 2>&1 || fail "rerun failed"
ls -A "$sig" | grep -q tmp && fail "the temporary of a killed run was not removed: $(ls -A "$sig")"

# --- write never leaves --out through a name from the graph ---
for name in '"../escape"' '"/etc/escape"' '"a/b"'; do
    expect_exit 1 "not a plain file name" $T "$BIN" check graphs/ssao.graph --set "out.name=$name"
done

# --- a value is one line: the rest of it is refused, never dropped or applied ---
expect_exit 1 "<command line --set>:1:14: error: a newline \(0x0a\)" \
    $T "$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/oneline" \
    --set 'ao.radius=0.3
include "/etc/passwd"'
[ -e "$TMP/oneline" ] && fail "a refused --set wrote $(ls -A "$TMP/oneline")"
expect_exit 1 "<command line --set>:1:3: error: a tab \(0x09\)" \
    $T "$BIN" check graphs/ssao.graph --set "ao$(printf '\t').radius=0.3"
# ... and a string's escaped newline, refused as a file name, is not echoed raw (it split
# the message over two lines)
out=$($T "$BIN" check graphs/ssao.graph --set 'out.name="a\nb"' 2>&1)
echo "$out" | grep -q "control character (0x0a at byte 1)" ||
    fail "an escaped newline in a name: $out"
[ "$(echo "$out" | wc -l)" -eq 1 ] || fail "the message about a newline in a name spans lines: $out"

finish test_hostile
