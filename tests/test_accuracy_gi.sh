#!/usr/bin/env bash
# `bench/bench.py --accuracy --part gi`, the GI half of docs/accuracy.md: at a tiny size and
# one run it still scores every GI pipeline on every example scene under each light of
# its own lights and each light of examples/lights (four rows a scene under the sun, six
# under its own lights, the sky and the probe: a finite rmse and flip, a signed bias, an ssim and
# the bounce's energy or -), one summary row a pipeline and light, and the frame times of
# ssdo.graph, gi.graph and hybrid_ssdo.graph; each per-scene row's rmse and flip are those of
# tests/fixtures/accuracy_expected.tsv within the seeds' noise (that file says how to
# regenerate it).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_accuracy_gi"
source "$(dirname "$0")/accuracy_lib.sh"
python3 bench/bench.py --accuracy --part gi --bin "$(accuracy_bin)" --runs 1 --size 48x36 --paths 16 > "$TMP/acc.md" \
    2> "$TMP/err" || fail "bench.py --accuracy --part gi failed: $(tail -3 "$TMP/err")"
scenes=$(grep -L -E '^[[:space:]]*(camera_key|orbit)\(' examples/*.scene | wc -l) # still cameras
grep -q '^# AO accuracy' "$TMP/acc.md" && fail "--part gi printed the AO table"
gi=$(grep -cE '^\| (own|sun|sky|courtyard) \| [a-z_]+ \| (none|ssao|ssdo|hybrid|hybrid_ssdo|gi) \| [0-9.]+ \| [0-9.]+ \| ([0-9.]+|-) \| [+-][0-9.]+ \| -?[0-9.]+ \| ([0-9.]+|-) \|$' "$TMP/acc.md")
[ "$gi" -eq $((22 * scenes)) ] || fail "expected $((22 * scenes)) GI rows, got $gi"
summary=$(grep -cE '^\| (own|sun|sky|courtyard) \| [a-z_]+ \(.*\) \| [0-9.]+ \| [0-9.]+ \| ([0-9.]+|-) \| [0-9.]+ \| [0-9.]+ \| [0-9]+ of '"$scenes"' \| ([0-9.]+|-) \|$' "$TMP/acc.md")
[ "$summary" -eq 22 ] || fail "expected 22 GI summary rows, got $summary"
bounce=$(grep -cE '^\| (own|sun|sky|courtyard) \| [a-z_]+ \| (ssdo|hybrid_ssdo|gi) \| .* \| [0-9.]+ \|$' "$TMP/acc.md")
[ "$bounce" -gt 0 ] || fail "no GI row has a bounce energy"
grep -qE 'ssdo.graph on the Cornell box [0-9.]+ ms, gi.graph on the Cornell box [0-9.]+ ms, hybrid_ssdo.graph on the courtyard [0-9.]+ ms' \
    "$TMP/acc.md" || fail "the GI table lacks its frame times"
accuracy_values gi "$TMP/acc.md"
finish test_accuracy_gi
