#!/usr/bin/env bash
# bench/artefact_crops.py, the before/after crops of docs/gallery.md's artefact list, small:
# one artefact with this build as both "before" and "after" gives a JPEG of three panels
# (truth, before, after: three times the window's width at --scale) and a Markdown line
# whose before and after numbers are equal (the same binary and graphs give the same bytes).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_artefact_crops"
export SSGRAPH_CACHE=$TMP/cache
for m in numpy PIL OpenImageIO; do
    /usr/bin/python3 -c "import $m" 2> /dev/null ||
        fail "Python module $m is missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
done
[ "$fails" -eq 0 ] || finish test_artefact_crops

/usr/bin/python3 bench/artefact_crops.py --bin "$BIN" --before "$BIN" --before-graphs graphs \
    --size 64x36 --paths 4 --scale 3 --only cornell_box_shadows --out "$TMP/crops" \
    > "$TMP/log" 2>&1 || fail "artefact_crops failed: $(tail -5 "$TMP/log")"
line=$(grep '^- the tall box' "$TMP/log")
[ -n "$line" ] || fail "no Markdown line: $(cat "$TMP/log")"
before=$(echo "$line" | grep -o 'before rmse [0-9.]*, [0-9.]*x')
after=$(echo "$line" | grep -o 'after rmse [0-9.]*, [0-9.]*x')
[ -n "$before" ] && [ "${before#before }" = "${after#after }" ] ||
    fail "before and after differ for the same binary: $line"
/usr/bin/python3 - "$TMP/crops/cornell_box_shadows.jpg" <<'PY' || fail "the crop JPEG is wrong"
import sys
from PIL import Image
im = Image.open(sys.argv[1])
assert im.format == "JPEG", im.format
# the window (0.15..0.5 of 64, 0.3..0.8 of 36) is 22 x 18 px; three panels at 3x
assert im.size == (3 * 22 * 3, 18 * 3), im.size
PY
expect_exit 2 "needs --before-graphs" /usr/bin/python3 bench/artefact_crops.py --bin "$BIN" \
    --before "$BIN" --only none --out "$TMP/none"
finish test_artefact_crops
