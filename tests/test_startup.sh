#!/usr/bin/env bash
# Start-up (issue 17, item 6; issue 28, item 7): the ssgraph binary links none of the heavy
# libraries, so that `nodes` and `check` start in a few ms; EXR and PNG are read and written
# by the library itself (OpenEXRCore, libpng), so a run that writes its EXR and PNG never
# opens OpenImageIO; the module libssgraph_oiio.so comes only for another format (here an
# HDR light probe), and then its loading is a line of its own in the run's table and in
# --profile-json, not part of a node's time. A missing module is a clear error on the file
# that needed it, with a non-zero exit and no output left behind. Last, the order of the
# write node's renames: the PNG before the EXR (docs/exr.md), seen with strace where it runs.
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

# Writing the EXR and the PNG (and reading them back) needs no module at all, and opens none.
out=$(env SSGRAPH_MODULE_DIR="$TMP/empty" LD_DEBUG=files "$BIN" run graphs/ssao.graph \
      --size 64x48 --out "$TMP/out" 2>&1) || fail "a run without the module failed: $out"
[ -s "$TMP/out/ssao.exr" ] && [ -s "$TMP/out/ssao.png" ] || fail "no ssao.exr/png: $out"
grep -q 'file=[^ ]*libssgraph_oiio.so' <<<"$out" && fail "writing EXR and PNG opened the module"
grep -q 'file=[^ ]*libOpenImageIO' <<<"$out" && fail "writing EXR and PNG loaded OpenImageIO"
grep -Eq '^load ' <<<"$out" && fail "a run that loaded nothing printed a load line: $out"
expect_exit 0 "rmse" env SSGRAPH_MODULE_DIR="$TMP/empty" "$BIN" compare "$TMP/out/ssao.exr" \
    "$TMP/out/ssao.png" --json

# A light probe in a format only OpenImageIO reads (Radiance HDR).
command -v oiiotool > /dev/null || { fail "oiiotool not found (openimageio-tools)"; finish test_startup; }
oiiotool examples/probes/courtyard.exr --resize 64x32 -o "$TMP/probe.hdr" || fail "oiiotool hdr"
printf 'environment(image="probe.hdr", intensity=1)\n' > "$TMP/lights.scene"
run_hdr() { # run_hdr OUT [ARGS]: ssao.graph lit by the HDR probe
    local dir=$1; shift
    "$BIN" run graphs/ssao.graph --size 64x48 --lights "$TMP/lights.scene" --out "$TMP/$dir" "$@"
}

# Without the module: a located error, exit 1, nothing written.
expect_exit 1 "probe.hdr: error: cannot load ssgraph's OpenImageIO module libssgraph_oiio.so" \
    env SSGRAPH_MODULE_DIR="$TMP/empty" "$BIN" run graphs/ssao.graph --size 64x48 \
    --lights "$TMP/lights.scene" --out "$TMP/none"
if ls -A "$TMP/none" 2>/dev/null | grep -q .; then
    fail "a run without the module left files: $(ls -A "$TMP/none")"
fi

# With it (found next to the binary or in the build tree): the load on its own line, after
# the nodes and before the total, and in the profile's JSON.
out=$(run_hdr hdr --profile-json "$TMP/hdr.json" 2>&1) || fail "the HDR run failed: $out"
[ -s "$TMP/hdr/ssao.exr" ] || fail "no ssao.exr written with the module found"
grep -Eq '^load +OpenImageIO module +[0-9]+\.[0-9]+$' <<<"$out" || fail "no load line: $out"
tail -n 2 <<<"$out" | head -n 1 | grep -q '^load ' || fail "the load line is not last but total: $out"
python3 - "$TMP/hdr.json" <<'PY' || fail "profile.json lacks the load: $(cat "$TMP/hdr.json")"
import json, sys
p = json.load(open(sys.argv[1]))
loads = p["loads"]
assert [l["what"] for l in loads] == ["OpenImageIO module"], loads
assert loads[0]["ms"] > 0, loads
PY

# The commit order of the write node: the PNG renamed first, the EXR last.
if command -v strace > /dev/null && strace -o /dev/null true 2>/dev/null; then
    # LeakSanitizer cannot run under a tracer: off for this run of a sanitizer build
    ASAN_OPTIONS=detect_leaks=0 strace -f -o "$TMP/strace.log" \
        -e trace=rename,renameat,renameat2 "$BIN" run \
        graphs/ssao.graph --size 64x48 --out "$TMP/order" > /dev/null 2>&1 || fail "strace run"
    order=$(grep -oE '"[^"]*/ssao\.(exr|png)"\)' "$TMP/strace.log" | sed 's/.*\.\(exr\|png\).*/\1/' | tr '\n' ' ')
    [ "$order" = "png exr " ] || fail "renames in the order '$order', expected 'png exr '"
else
    echo "test_startup: strace unavailable, the rename order is not checked here" >&2
fi

finish test_startup
