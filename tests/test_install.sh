#!/usr/bin/env bash
# test_install.sh - the installed tree is usable as a user would use it:
#   `cmake --install` of this build into a scratch prefix, then
#   1. a C program built with pkg-config (shared library) runs a graph through the public API,
#      and so does the tutorial's example (docs/tutorial/hello.c);
#   2. the same program built by a CMake project with find_package(ssgraph), against
#      ssgraph::ssgraph (shared) and ssgraph::ssgraph_static, runs it too;
#   3. the installed command line renders an installed graph without the OpenImageIO
#      module, finds that module in the installed tree (not the build tree), and
#      `ssgraph.pc` and the headers are where the docs say.
# In a sanitizer build the programs get the same -fsanitize flags (SSG_SANITIZE_FLAGS).
set -u
. "$(dirname "$0")/lib.sh" test_install
BUILD=$(cd "$(dirname "$BIN")" && pwd)
SRC=$(pwd)
PREFIX="$TMP/prefix"
FLAGS=${SSG_SANITIZE_FLAGS:-}
CC=${CC:-cc}

cmake --install "$BUILD" --prefix "$PREFIX" >"$TMP/install.log" 2>&1 ||
    { fail "cmake --install failed: $(tail -5 "$TMP/install.log")"; finish test_install; }
LIBDIR=$(dirname "$(find "$PREFIX" -name ssgraph.pc | head -1)")/..
for f in bin/ssgraph include/ssgraph/ssgraph.h include/ssgraph/ssgraph_tools.h include/ssgraph/errors.def \
         share/ssgraph/graphs/ssao.graph share/ssgraph/examples/cornell.scene; do
    [ -e "$PREFIX/$f" ] || fail "the install lacks $f"
done
for f in libssgraph.a libssgraph.so ssgraph/libssgraph_oiio.so cmake/ssgraph/ssgraphConfig.cmake \
         cmake/ssgraph/ssgraphConfigVersion.cmake; do
    [ -e "$LIBDIR/$f" ] || fail "the install lacks lib/$f"
done
GRAPH="$PREFIX/share/ssgraph/graphs/ssao.graph"

# 1. pkg-config, shared library (the user's program finds it through the rpath that
#    ssgraph.pc's Libs set, with no LD_LIBRARY_PATH, wherever the prefix is)
export PKG_CONFIG_PATH="$LIBDIR/pkgconfig"
if ! pc=$(pkg-config --cflags --libs ssgraph 2>&1); then
    fail "pkg-config does not know ssgraph: $pc"
elif ! $CC -std=c11 $FLAGS "$SRC/tests/install/consumer.c" -o "$TMP/consumer_pc" $pc -lm \
        >"$TMP/pc.log" 2>&1; then
    fail "building against pkg-config's flags ($pc) failed: $(cat "$TMP/pc.log")"
else
    expect_exit 0 "consumer: ok" env -u LD_LIBRARY_PATH "$TMP/consumer_pc" "$GRAPH"
fi
# the tutorial's library example (docs/tutorial/hello.c), built as the tutorial says
if $CC -std=c11 $FLAGS "$SRC/docs/tutorial/hello.c" -o "$TMP/hello" $pc >"$TMP/hello.log" 2>&1; then
    expect_exit 0 "^320x180, mean ambient occlusion 0\.[0-9]+$" \
        env -u LD_LIBRARY_PATH "$TMP/hello" "$SRC/docs/tutorial/first.graph"
else
    fail "docs/tutorial/hello.c did not build as the tutorial says: $(cat "$TMP/hello.log")"
fi
# the tutorial's live-graph example: a sweep where only ao and what follows run again
if $CC -std=c11 $FLAGS "$SRC/docs/tutorial/sweep_live.c" -o "$TMP/sweep_live" $pc \
        >"$TMP/sweep.log" 2>&1; then
    pushd "$TMP" >/dev/null # it writes out/sweep where it runs
    expect_exit 0 "^radius 1     mean ambient occlusion 0\.[0-9]+ \(3 of 5 nodes ran\)$" \
        env -u LD_LIBRARY_PATH "$TMP/sweep_live" "$SRC/docs/tutorial/first.graph"
    popd >/dev/null
else
    fail "docs/tutorial/sweep_live.c did not build as the tutorial says: $(cat "$TMP/sweep.log")"
fi
pkg-config --modversion ssgraph | grep -qx "$(sed -n 's/^#define SSG_VERSION "\(.*\)"/\1/p' \
    "$SRC/core/ssgraph.h")" || fail "ssgraph.pc's version is not the header's"

# 2. find_package, both variants
if ! cmake -S "$SRC/tests/install" -B "$TMP/consumer" -DCMAKE_PREFIX_PATH="$PREFIX" \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_FLAGS="$FLAGS" -DCMAKE_EXE_LINKER_FLAGS="$FLAGS" \
        >"$TMP/cmake.log" 2>&1 ||
   ! cmake --build "$TMP/consumer" -j2 >>"$TMP/cmake.log" 2>&1; then
    fail "the find_package(ssgraph) project did not build: $(tail -20 "$TMP/cmake.log")"
else
    expect_exit 0 "consumer: ok" env -u LD_LIBRARY_PATH "$TMP/consumer/consumer_shared" "$GRAPH"
    expect_exit 0 "consumer: ok" "$TMP/consumer/consumer_static" "$GRAPH"
    ldd "$TMP/consumer/consumer_static" | grep -q libssgraph &&
        fail "consumer_static links libssgraph dynamically"
fi

# 3. the installed command line: it renders an installed graph (EXR and PNG need no
#    OpenImageIO, so that run loads no module), and it finds its OpenImageIO module in the
#    installed tree, not the build tree (--version opens it)
unset SSGRAPH_MODULE_DIR
out=$(LD_DEBUG=files "$PREFIX/bin/ssgraph" run "$GRAPH" --size 48x32 --out "$TMP/cli" 2>&1)
[ -s "$TMP/cli/ssao.exr" ] || fail "the installed ssgraph wrote no out/ssao.exr: $out"
echo "$out" | grep -q 'file=[^ ]*libssgraph_oiio.so' &&
    fail "writing EXR and PNG loaded the OpenImageIO module"
loaded=$("$PREFIX/bin/ssgraph" --version | sed -n 's/^openimageio module: //p')
case "$loaded" in
    "$PREFIX"/*) ;;
    *) fail "the installed ssgraph loaded its module from '$loaded', not from $PREFIX" ;;
esac
finish test_install
