#!/usr/bin/env bash
# The GL backend from the command line: choosing it (--backend, the graph's `backend`
# line, a node's backend=), what a run reports (the `on` and `gpu ms` columns), and the
# errors: an unknown backend, GL asked of a CPU-only node, and a GL context that cannot be
# made (the message names the cause and suggests --backend cpu; nothing is written).
# Whole graphs on both backends: test_gl_graphs.sh.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_gl_cli"

g=graphs/ssao_gaussian.graph
expect_exit 0 "gb +gaussian +gl " "$BIN" run $g --size 64x48 --out "$TMP/a" --set gb.backend=gl
expect_exit 0 "GL: (OSMesa|EGL): " "$BIN" run $g --size 64x48 --out "$TMP/a" --set gb.backend=gl
expect_exit 0 "gb +gaussian +cpu " "$BIN" run $g --size 64x48 --out "$TMP/b"
# --backend cpu wins over a node's backend=gl (a user without GL runs any graph)
expect_exit 0 "gb +gaussian +cpu " "$BIN" run $g --size 64x48 --out "$TMP/b" \
    --set gb.backend=gl --backend cpu
# --backend gl: nodes without a GL side (write) stay on the CPU
expect_exit 0 "out +write +cpu " "$BIN" run $g --size 64x48 --out "$TMP/c" --backend gl
expect_exit 2 "--backend expects cpu or gl" "$BIN" run $g --backend vulkan

# the graph's own backend line, and its errors with file:line:column
printf 'include "%s/graphs/ssao_gaussian.graph"\nbackend gl\n' "$PWD" > "$TMP/gl.graph"
expect_exit 0 "gb +gaussian +gl " "$BIN" run "$TMP/gl.graph" --size 64x48 --out "$TMP/d"
printf 'include "%s/graphs/ssao_gaussian.graph"\nbackend metal\n' "$PWD" > "$TMP/bad.graph"
expect_exit 1 "bad.graph:2:9: error: 'backend' expects cpu or gl" "$BIN" check "$TMP/bad.graph"
printf 'include "%s/graphs/reference_ao.graph"\nset ref.backend = gl\n' "$PWD" > "$TMP/ref.graph"
expect_exit 1 "ref.graph:2:19: error: node 'ref' \(reference_ao\) has no GL implementation" \
    "$BIN" check "$TMP/ref.graph"
printf 'include "%s/graphs/ssao_gaussian.graph"\nset gb.backend = fast\n' "$PWD" > "$TMP/v.graph"
expect_exit 1 "v.graph:2:18: error: backend of node 'gb' must be cpu or gl" \
    "$BIN" check "$TMP/v.graph"

# no GL context: a clear cause, the hint, exit 1, and no output written
SSG_GL_PLATFORM=none expect_exit 1 \
    "GL backend unavailable: SSG_GL_PLATFORM is 'none'.*--backend cpu" \
    "$BIN" run $g --size 64x48 --out "$TMP/none" --backend gl
[ ! -e "$TMP/none" ] || fail "a run without GL wrote $TMP/none"

# the EGL path (Mesa's software device here, a GPU elsewhere) gives the OSMesa result
SSG_GL_PLATFORM=egl expect_exit 0 "GL: EGL: " "$BIN" run $g --size 64x48 --out "$TMP/egl" \
    --set gb.backend=gl
SSG_GL_PLATFORM=osmesa expect_exit 0 "GL: OSMesa: " "$BIN" run $g --size 64x48 \
    --out "$TMP/osm" --set gb.backend=gl
cmp -s "$TMP/egl/ssao_gaussian.exr" "$TMP/osm/ssao_gaussian.exr" \
    || fail "EGL and OSMesa runs differ"

# a single node on GL from the command line
"$BIN" run $g --size 64x48 --out "$TMP/e" > /dev/null
expect_exit 0 "wrote .*out.exr" "$BIN" node gaussian --in "in=$TMP/e/ssao_gaussian.exr:ao" \
    --backend gl --out "$TMP/node"
finish test_gl_cli
