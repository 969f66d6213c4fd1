#!/usr/bin/env bash
# bench/readme_figure.py, the README's first picture: on a made-up EXR whose answer is known
# (a truth of 0.1 everywhere, gi.graph 5x too bright in one block and 1/5 in another) the
# ratio panel is red in the first block, blue in the second (nearly full: the dark floor),
# white elsewhere and black off the surfaces,
# and both crops land on those blocks; then once end to end on gi_error.graph, small.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_readme_figure"
for m in numpy PIL OpenImageIO; do
    /usr/bin/python3 -c "import $m" 2> /dev/null ||
        fail "Python module $m is missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
done
[ "$fails" -eq 0 ] || finish test_readme_figure

/usr/bin/python3 - "$TMP/known.exr" <<'EOF' || fail "could not write the known EXR"
import sys
import numpy as np
import OpenImageIO as oiio
h, w = 96, 128
truth = np.full((h, w, 3), 0.1, np.float32)
gi = truth.copy()
gi[40:64, 8:40] *= 5     # 5x brighter: red
gi[56:88, 80:120] /= 5   # 5x darker: blue
depth = np.ones((h, w, 1), np.float32)
depth[:, :4] = 0         # a background strip: black
names = ["R", "G", "B", "gi.R", "gi.G", "gi.B", "ssdo.R", "ssdo.G", "ssdo.B", "Z"]
spec = oiio.ImageSpec(w, h, len(names), oiio.FLOAT)
spec.channelnames = tuple(names)
out = oiio.ImageOutput.create(sys.argv[1])
out.open(sys.argv[1], spec)
out.write_image(np.concatenate([truth, gi, truth, depth], axis=2))
out.close()
EOF

/usr/bin/python3 bench/readme_figure.py --exr "$TMP/known.exr" --blur 0 --out "$TMP/known.png" \
    > "$TMP/known.log" 2>&1 || fail "readme_figure failed: $(tail -3 "$TMP/known.log")"
# the red block exactly; the blue one is larger than a window: any window inside it
grep -Eq "crops at \(y, x, h, w\) \(40, 8, 24, 32\) and \((5[6-9]|6[0-4]), (8[0-8]), 24, 32\)" \
    "$TMP/known.log" ||
    fail "the crops are not on the two wrong blocks: $(cat "$TMP/known.log")"
/usr/bin/python3 - "$TMP/known.png" <<'EOF' || fail "the ratio panel's colours are wrong"
import sys
import numpy as np
from PIL import Image
fig = np.asarray(Image.open(sys.argv[1]).convert("RGB")).astype(int)
assert fig.shape[1] == 256, fig.shape          # two 128-wide panels a row
ratio = fig[96:192, 128:256]                   # row 2, right: gi.graph / truth
def near(px, rgb):
    return all(abs(a - b) <= 1 for a, b in zip(px, rgb))
def expected(ratio):
    """The diverging map by hand: t = log5 of the ratio with the dark floor of 2 % of the
    truth's median (0.1), red (0.70, 0.05, 0.10) at t = 1, blue (0.10, 0.20, 0.70) at -1."""
    floor = 0.002
    t = np.log((0.1 * ratio + floor) / (0.1 + floor)) / np.log(5)
    end = (0.70, 0.05, 0.10) if t > 0 else (0.10, 0.20, 0.70)
    return [int((1 + abs(t) * (e - 1)) * 255 + 0.5) for e in end]
assert near(ratio[50, 20], expected(5)), (ratio[50, 20], expected(5))      # 5x: red
assert near(ratio[70, 100], expected(0.2)), (ratio[70, 100], expected(0.2))  # 1/5x: blue
assert near(ratio[90, 60], (255, 255, 255)), ratio[90, 60]  # right: white
assert near(ratio[50, 1], (0, 0, 0)), ratio[50, 1]          # no surface: black
EOF

/usr/bin/python3 bench/readme_figure.py --bin "$BIN" --size 64x48 --paths 4 \
    --out "$TMP/small.png" > "$TMP/small.log" 2>&1 ||
    fail "readme_figure on gi_error.graph failed: $(tail -3 "$TMP/small.log")"
[ "$(head -c 4 "$TMP/small.png" | od -An -tx1 | tr -d ' ')" = 89504e47 ] ||
    fail "no PNG written from gi_error.graph"
ls "$TMP"/*.part.png > /dev/null 2>&1 && fail "a partial PNG was left behind"
finish test_readme_figure
