#!/usr/bin/env bash
# Start-up (issue 17, item 6): the ssgraph binary links none of the heavy libraries, so that
# `nodes` and `check` start in a few ms; OpenImageIO comes from the module libssgraph_oiio.so
# on the first image read or written, OSMesa on the first GL node. A missing module is a
# clear error on the file being written, with a non-zero exit and no output left behind.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_startup"

# Linked libraries: a regression here costs every start about half a second.
linked=$(ldd "$BIN")
for heavy in libOpenImageIO libOSMesa libLLVM libopencv libavcodec; do
    if grep -q "$heavy" <<<"$linked"; then
        fail "ssgraph links $heavy at start-up (load it lazily)"
    fi
done

# What needs no image file runs without the module.
mkdir -p "$TMP/empty"
expect_exit 0 "" env SSGRAPH_MODULE_DIR="$TMP/empty" "$BIN" nodes
expect_exit 0 "" env SSGRAPH_MODULE_DIR="$TMP/empty" "$BIN" check graphs/ssao.graph

# A run that writes needs it: a located error, exit 1, nothing written.
expect_exit 1 "ssao.exr: error: cannot load ssgraph's OpenImageIO module libssgraph_oiio.so" \
    env SSGRAPH_MODULE_DIR="$TMP/empty" "$BIN" run graphs/ssao.graph --size 64x48 \
    --out "$TMP/out"
if ls -A "$TMP/out" 2>/dev/null | grep -q .; then
    fail "a run without the module left files: $(ls -A "$TMP/out")"
fi

# The same run finds the module by itself (next to the binary or in the build tree).
expect_exit 0 "" "$BIN" run graphs/ssao.graph --size 64x48 --out "$TMP/out"
[ -s "$TMP/out/ssao.exr" ] || fail "no ssao.exr written with the module found"

finish test_startup
