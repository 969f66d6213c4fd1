#!/usr/bin/env bash
# `bench.py --gallery` (bench/gallery.py) end to end, small: one scene under its own lights
# and the sky, a few paths: the references are rendered once and then come from the cache
# (a second run renders none and writes the same Markdown), every GI and AO pipeline gets a
# row, a picture and crops, the truth's own error is stated, and a stale cache key (another
# path count) renders again.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_gallery"
export SSGRAPH_CACHE=$TMP/cache
for m in numpy PIL OpenImageIO matplotlib; do
    /usr/bin/python3 -c "import $m" 2> /dev/null ||
        fail "Python module $m is missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
done
[ "$fails" -eq 0 ] || finish test_gallery

gallery() { # PATHS NAME LIGHTS [PIPELINES]
    /usr/bin/python3 bench/bench.py --gallery --bin "$BIN" --scenes cornell --lights "$3" \
        --size 48x27 --paths "$1" --rays 8 --self-error --gallery-out "$TMP/$2/gallery.md" \
        ${4:+--pipelines "$4"}
}
gallery 8 first own,sky > "$TMP/first.log" 2>&1 || fail "gallery failed: $(tail -5 "$TMP/first.log")"
md=$TMP/first/gallery.md
[ -s "$md" ] || fail "no $md"
for p in gi ssdo ssdo_realtime ssilvb gi_temporal hybrid hybrid_ssdo ssao hbao gtao; do
    grep -q "^| $p | " "$md" || fail "no summary row for $p"
done
# hybrids only where the lighting has an environment (the Cornell box's own has none)
grep -q "^| hybrid_ssdo | own" "$md" && fail "hybrid_ssdo scored without an environment"
grep -q "^| hybrid_ssdo | sky | 1 |" "$md" || fail "hybrid_ssdo under the sky is missing"
grep -Eq "^\| cornell_own \| [0-9.]+ \|" "$md" || fail "the truth's own error is missing"
for pic in cornell_own_gi cornell_sky_gi cornell_ao cornell_sky_gi_hybrid_ssdo_crop; do
    f=$TMP/first/images/gallery/$pic.jpg
    [ "$(head -c 3 "$f" | od -An -tx1 | tr -d ' ')" = ffd8ff ] || fail "$pic.jpg is not a JPEG"
    grep -q "images/gallery/$pic.jpg" "$md" || fail "$md does not show $pic.jpg"
done
keys=$(ls "$SSGRAPH_CACHE/gallery"/*.key | wc -l)
[ "$keys" -eq 7 ] || fail "expected 7 cached references (2 lightings x 3 + AO), got $keys"

# again (three of the pipelines, to keep the test short): every reference from the cache,
# the same rows
before=$(stat -c %Y "$SSGRAPH_CACHE"/gallery/*.exr | sort | tr '\n' ' ')
gallery 8 second own,sky gi,hybrid_ssdo,ssao > "$TMP/second.log" 2>&1 ||
    fail "second gallery failed"
after=$(stat -c %Y "$SSGRAPH_CACHE"/gallery/*.exr | sort | tr '\n' ' ')
[ "$before" = "$after" ] || fail "the second run rendered references again"
rows() { grep -E "^\| (gi|hybrid_ssdo|ssao|cornell_[a-z]+) \|" "$1"; }
[ "$(rows "$TMP/second/gallery.md" | wc -l)" -eq 6 ] || fail "the second run lacks rows"
diff <(rows "$TMP/first/gallery.md") <(rows "$TMP/second/gallery.md") > /dev/null ||
    fail "the second run's rows differ from the first's"
grep -q "^| ssdo |" "$TMP/second/gallery.md" && fail "--pipelines did not leave ssdo out"
# another path count is another key (the AO reference's stays)
gallery 12 third own gi > "$TMP/third.log" 2>&1 || fail "third gallery failed"
keys=$(ls "$SSGRAPH_CACHE/gallery"/*.key | wc -l)
[ "$keys" -eq 10 ] || fail "another path count should add 3 references, have $keys keys"
finish test_gallery
