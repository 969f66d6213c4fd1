# accuracy_lib.sh - what test_accuracy.sh and test_accuracy_gi.sh share; source it after lib.sh.
# The values they check, their bounds and how to regenerate both: tests/fixtures/
# accuracy_expected.tsv. Two switches from the environment serve that regeneration:
# SSG_ACCURACY_SEED=N runs every `ssgraph run` with --seed N (the tables' noise: the check
# must still pass), SSG_ACCURACY_WRITE=1 rewrites the expected rows instead of checking them.
ACCURACY_EXPECTED=tests/fixtures/accuracy_expected.tsv

# The ssgraph that bench.py runs: $BIN, or a wrapper that adds --seed N to each run.
accuracy_bin() {
    if [ -z "${SSG_ACCURACY_SEED:-}" ]; then
        echo "$BIN"
        return
    fi
    printf '#!/bin/sh\n[ "$1" = run ] && exec "%s" "$@" --seed %s\nexec "%s" "$@"\n' \
        "$BIN" "$SSG_ACCURACY_SEED" "$BIN" > "$TMP/ssgraph_seed"
    chmod +x "$TMP/ssgraph_seed"
    echo "$TMP/ssgraph_seed"
}

# accuracy_values PART TABLE: each row's RMSE and FLIP against the expectations (or, with
# SSG_ACCURACY_WRITE=1, written into them).
accuracy_values() {
    if [ -n "${SSG_ACCURACY_WRITE:-}" ]; then
        python3 tests/accuracy_values.py write "$1" "$2" "$ACCURACY_EXPECTED" ||
            fail "could not write the $1 rows of $ACCURACY_EXPECTED"
        echo "wrote the $1 rows of $ACCURACY_EXPECTED"
        return
    fi
    local out
    if out=$(python3 tests/accuracy_values.py check "$1" "$2" "$ACCURACY_EXPECTED"); then
        echo "$out"
    else
        fail "the $1 table is not the expected one ($ACCURACY_EXPECTED):"$'\n'"$out"
    fi
}
