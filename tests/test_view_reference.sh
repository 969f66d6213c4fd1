#!/usr/bin/env bash
# `ssgraph view`'s reference files and FLIP map over HTTP (docs/viewer-api.md):
# - --reference FILE opens an EXR that `ssgraph run --show img.out --out` wrote: the state
#   names it file:PATH, GET /api/image serves its pixels, its metrics against img.out are
#   RMSE 0 / SSIM 1;
# - POST /api/reference refuses what is not an EXR at the frame's size, each with its
#   reason, and never waits on a FIFO or reads a directory; the file open before stays;
# - GET /api/flip is the compare node's FLIP map: one channel in [0, 1], 0 for a port
#   against itself, and its mean is the flip metric `ssgraph compare` prints for the same
#   two images; a bad port is a 400;
# - `ssgraph view --reference` of a missing file exits 1 with the reason.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_reference"
source "$(dirname "$0")/view_lib.sh"
ROOT=$(pwd)
G=graphs/ssdo_realtime.graph
common=(--size 96x54 --threads 2)
"$BIN" run $G "${common[@]}" -q --show img.out,g.direct --out "$TMP/cli" > "$TMP/cli.log" 2>&1 ||
    fail "ssgraph run --show: $(cat "$TMP/cli.log")"
"$BIN" run $G --size 48x27 --threads 2 -q --show img.out --out "$TMP/small" > "$TMP/cli.log" 2>&1 ||
    fail "ssgraph run --size 48x27: $(cat "$TMP/cli.log")"
REF=$TMP/cli/img.out.exr

if "$BIN" view $G "${common[@]}" --reference "$TMP/missing.exr" > "$TMP/missing.log" 2>&1; then
    fail "ssgraph view --reference of a missing file started"
fi
grep -q "missing.exr: No such file" "$TMP/missing.log" ||
    fail "--reference of a missing file says: $(cat "$TMP/missing.log")"

view_start "$TMP/view.log" $G "${common[@]}" --reference "$REF" || {
    fail "no URL printed"; finish test_view_reference; }
client() { python3 "$ROOT/tests/view_client.py" "$B" "$token" "$@"; }
enc() { python3 -c 'import sys, urllib.parse; print(urllib.parse.quote(sys.argv[1], safe=""))' "$1"; }

[ "$(client state reference_file)" = "file:$REF" ] ||
    fail "the state's reference_file is '$(client state reference_file)', not file:$REF"
client dump "file:$REF" "$TMP/ref.pfm" || fail "GET /api/image of the file"
oiiotool "$TMP/ref.pfm" "$REF" --fail 0 --failpercent 0 --diff > "$TMP/diff.txt" 2>&1 ||
    fail "the file's image is not the file: $(tail -3 "$TMP/diff.txt")"
expect_code 200 -H "$H" "$B/api/metrics?ref=$(enc "file:$REF")&a=img.out&b=$(enc "file:$REF")"
grep -q '"a":{"rmse":0,"ssim":1},"b":{"rmse":0,"ssim":1}' "$TMP/body" ||
    fail "img.out and the file against the file: $(cat "$TMP/body")"
expect_code 404 -H "$H" "$B/api/image?port=$(enc "file:$TMP/cli/g.direct.exr")"

# --- what POST /api/reference refuses, and why
echo "not an image" > "$TMP/notes.txt"
echo "garbage" > "$TMP/broken.exr"
mkfifo "$TMP/fifo.exr"
mkdir "$TMP/folder.exr"
check_refused() { # CODE PATH TEXT
    expect_code "$1" -H "$H" --data-binary "path=$2" "$B/api/reference"
    grep -q "$3" "$TMP/body" || fail "POST /api/reference path=$2 says $(cat "$TMP/body"), not '$3'"
}
check_refused 404 "$TMP/missing.exr" "No such file"
check_refused 400 "$TMP/notes.txt" "must be an OpenEXR file"
check_refused 400 "$TMP/broken.exr" "not an OpenEXR file"
check_refused 404 "$TMP/fifo.exr" "not a regular file"
check_refused 404 "$TMP/folder.exr" "not a regular file"
check_refused 400 "$TMP/small/img.out.exr" "is 48x27, the graph's frame is 96x54"
check_refused 400 "" "expected path=FILE.exr"
expect_code 400 -H "$H" --data-binary "file=$REF" "$B/api/reference"
[ "$(client state reference_file)" = "file:$REF" ] || fail "a refused file replaced the open one"
expect_code 200 -H "$H" --data-binary "path=$TMP/cli/g.direct.exr" "$B/api/reference"
grep -q "\"reference_file\":\"file:$TMP/cli/g.direct.exr\"" "$TMP/body" ||
    fail "the answer to an opened file does not name it: $(head -c 300 "$TMP/body")"
expect_code 404 -H "$H" "$B/api/image?port=$(enc "file:$REF")"

# --- the FLIP map
flip_stats() { # A B: "W H C min mean max" of GET /api/flip
    curl -s -H "$H" "$B/api/flip?a=$(enc "$1")&b=$(enc "$2")" | python3 -c '
import array, struct, sys
d = sys.stdin.buffer.read()
assert d[:4] == b"SSGI", d[:200]
w, h, c, _ = struct.unpack("<4I", d[4:20])
a = array.array("f"); a.frombytes(d[20:])
print(w, h, c, min(a), sum(a) / len(a), max(a))'
}
read -r w h c lo mean hi <<< "$(flip_stats img.out g.direct)"
[ "$w $h $c" = "96 54 1" ] || fail "/api/flip is ${w}x${h}x$c, expected 96x54x1"
python3 -c "import sys; lo, hi = $lo, $hi; sys.exit(0 if 0 <= lo <= hi <= 1 and hi > 0 else 1)" ||
    fail "the FLIP map of img.out against g.direct spans [$lo, $hi]"
want=$("$BIN" compare "$TMP/cli/img.out.exr" "$TMP/cli/g.direct.exr" --json |
    python3 -c 'import json, sys; print(json.load(sys.stdin)["flip"])')
python3 -c "import sys; sys.exit(0 if abs($mean - $want) <= 1e-6 else 1)" ||
    fail "the FLIP map's mean is $mean, ssgraph compare's flip $want"
read -r w h c lo mean hi <<< "$(flip_stats img.out img.out)"
[ "$hi" = "0.0" ] || fail "the FLIP map of img.out against itself reaches $hi"
read -r w h c lo mean hi <<< "$(flip_stats img.out "file:$TMP/cli/g.direct.exr")"
python3 -c "import sys; sys.exit(0 if abs($mean - $want) <= 1e-6 else 1)" ||
    fail "the FLIP map against the file g.direct.exr has the mean $mean, not $want"
expect_code 400 -H "$H" "$B/api/flip?a=img.out&b=nosuch.port"
expect_code 400 -H "$H" "$B/api/flip?a=img.out"

view_stop_within 10000 TERM
finish test_view_reference
