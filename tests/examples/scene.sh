#!/usr/bin/env bash
# One example scene (a ctest case per examples/*.scene, registered in tests/CMakeLists.txt):
# `check` loads it with its meshes, and graphs/ao_error.graph renders it at 64x48 with every
# AO method and the ray-traced reference, so a scene that stops loading or rendering, or
# whose camera sees nothing, fails here. Its comment (what it tests) must be there too.
set -u
scene=${1:?usage: scene.sh SCENE}
name=$(basename "$scene" .scene)
source "$(dirname "$0")/../lib.sh" "ssg_example_$name"

head -1 "$scene" | grep -q '^# ' || fail "$scene does not start with a comment saying what it tests"
expect_exit 0 "ok" "$BIN" check "$scene"
out="$TMP/out"
"$BIN" run graphs/ao_error.graph --scene "$scene" --size 64x48 --out "$out" --quiet \
    > "$TMP/run.log" 2>&1 || fail "$scene: ao_error.graph failed: $(tail -3 "$TMP/run.log")"
# Every compare node saw surface pixels and reported a finite error.
python3 - "$out/metrics.json" <<'PY' || fail "$scene: implausible metrics: $(cat "$out/metrics.json")"
import json, math, sys
m = json.load(open(sys.argv[1]))
ok = m and all(v["pixels"] > 64 and math.isfinite(v["rmse"]) and v["rmse"] < 0.5 for v in m.values())
sys.exit(0 if ok else 1)
PY
finish "example $name"
