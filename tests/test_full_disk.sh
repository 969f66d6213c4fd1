#!/usr/bin/env bash
# test_full_disk.sh - an EXR write that fails on a full disk (issue 42, item 4a): OpenEXR
# reports the failed write to our error handler with its context lock held, and the handler
# asked OpenEXR for its user data, which takes that lock again: `run`, `node` and
# `bench --reference` never returned. Each must end in the OS's reason, exit 1 (bench goes
# on without its cache, with a warning), with no temporary left and no output replaced.
# The full disk is a file size limit (RLIMIT_FSIZE with SIGXFSZ ignored: a write past it
# fails with EFBIG, "File too large"), which works anywhere, and, where this user may mount
# one (root on CI), a small tmpfs that really fills ("No space left on device"). Each
# command runs under `timeout`, and ctest's TIMEOUT bounds the whole: a hang fails.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_full_disk"
T="timeout 30"
export SSGRAPH_CACHE="$TMP/cache"

# limited KIB CMD...: CMD with files limited to KIB KiB, SIGXFSZ ignored.
limited() {
    $T bash -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$@"
}
# no_temporary DIR WHAT: fails when DIR holds a temporary of ours.
no_temporary() {
    ! ls -A "$1" 2> /dev/null | grep -q '\.tmp-' || fail "$2 left a temporary: $(ls -A "$1")"
}

# An input for `node`, and the outputs a failed run must leave as they were.
"$BIN" run graphs/ssao.graph --size 192x128 --set out.compression=none --out "$TMP/run" -q \
    > /dev/null || fail "the unlimited run failed"
before=$(md5sum "$TMP/run/ssao.exr")

# run: the EXR (uncompressed, no PNG) fails in its header (a limit of 0: nothing can be
# written; the header is written under OpenEXR's lock, where the handler deadlocked), and in
# its chunks, past the header.
for kib in 0 16; do
    expect_exit 1 "ssao.exr: error: cannot write image: File too large" limited $kib "$BIN" \
        run graphs/ssao.graph --size 192x128 --set out.compression=none --set out.png=false \
        --set k.count=8 --out "$TMP/run"
    [ "$(md5sum "$TMP/run/ssao.exr")" = "$before" ] || fail "a failed write changed ssao.exr"
    no_temporary "$TMP/run" "run"
done

# node: its output EXR.
expect_exit 1 "out.exr: error: cannot write image: File too large" limited 0 "$BIN" node \
    gaussian --in "in=$TMP/run/ssao.exr:ao" --set sigma=2 -o "$TMP/node/out.exr"
[ -e "$TMP/node/out.exr" ] && fail "node left a failed output"
no_temporary "$TMP/node" "node"

# bench --reference: the reference's cache entry cannot be written: the bench goes on
# without it, with a warning, and then fails on its own tables, naming why.
# (Its output through a pipe: a file would be limited too.)
log=$(limited 0 "$BIN" bench graphs/ao_error.graph --size 40x28 --frames 1 --sweep k.count=4 \
    --reference ref.out --image aob.out --out "$TMP/bench" 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "bench --reference on a full disk exited $rc: $log"
echo "$log" | grep -q "warning: the reference was not cached .*File too large" \
    || fail "bench --reference did not say why its cache was not written: $log"
echo "$log" | grep -q "bench.csv: error: .*File too large" \
    || fail "bench --reference did not say why bench.csv was not written: $log"
ls "$TMP/cache/references" 2> /dev/null | grep -q '\.key$' && fail "a failed cache kept a key"
no_temporary "$TMP/cache/references" "bench --reference"
no_temporary "$TMP/bench" "bench --reference"

# A real full file system, where a tmpfs can be mounted (root): the OS's own reason.
small="$TMP/small"
mkdir -p "$small"
if mount -t tmpfs -o size=256k tmpfs "$small" 2> /dev/null; then
    head -c 1M /dev/zero > "$small/filler" 2> /dev/null # fills it
    expect_exit 1 "ssao.exr: error: cannot write image: No space left on device" $T "$BIN" \
        run graphs/ssao.graph --size 192x128 --set out.compression=none --set out.png=false \
        --out "$small" -q
    no_temporary "$small" "run on a full tmpfs"
    expect_exit 1 "out.exr: error: cannot write image: No space left on device" $T "$BIN" \
        node gaussian --in "in=$TMP/run/ssao.exr:ao" --set sigma=2 -o "$small/out.exr"
    no_temporary "$small" "node on a full tmpfs"
    umount "$small"
else
    echo "test_full_disk: skipped the tmpfs case: this user cannot mount one (the file" \
         "size limit cases ran)"
fi

finish test_full_disk
