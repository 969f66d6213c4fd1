#!/usr/bin/env bash
# `bench/bench.py --accuracy`, the command that makes docs/accuracy.md: at a tiny size and
# one run it still scores every AO method on every example scene (six rows a scene, with a
# finite rmse, a flip, a signed bias and an ssim) and times the three shipped graphs; each row's
# rmse and flip are those of tests/fixtures/accuracy_expected.tsv within the seeds' noise (a
# changed default or metric fails here; that file says how to regenerate it). Its GI tables
# are test_accuracy_gi.sh (two cases, so each stays short on a busy machine).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_accuracy"
source "$(dirname "$0")/accuracy_lib.sh"
python3 bench/bench.py --accuracy --part ao --bin "$(accuracy_bin)" --runs 1 --size 48x36 --rays 64 > "$TMP/acc.md" 2> "$TMP/err" ||
    fail "bench.py --accuracy failed: $(tail -3 "$TMP/err")"
scenes=$(grep -L -E '^[[:space:]]*(camera_key|orbit)\(' examples/*.scene | wc -l) # still cameras
rows=$(grep -cE '^\| [a-z_]+ \| (ssao|hbao|gtao)( \+ bilateral)? \| [0-9.]+ \| [0-9.]+ \| [+-][0-9.]+ \| -?[0-9.]+ \| ([0-9.]+|-) \|$' "$TMP/acc.md")
[ "$rows" -eq $((6 * scenes)) ] || fail "expected $((6 * scenes)) rows, got $rows: $(head -20 "$TMP/acc.md")"
timed=$(grep -cE '\+ bilateral \| .* \| [0-9.]+ \|$' "$TMP/acc.md")
[ "$timed" -eq $((3 * scenes)) ] || fail "expected $((3 * scenes)) timed rows, got $timed"
grep -q "^# GI accuracy" "$TMP/acc.md" && fail "--part ao printed the GI tables"
accuracy_values ao "$TMP/acc.md"
finish test_accuracy
