#!/usr/bin/env bash
# test_run_watch.sh - `ssgraph run --watch` (cli/watch.h): it runs, then runs again when the
# graph (a parameter) or its scene changes, saying which file changed; a broken graph prints
# its error at file:line:col and the watcher keeps waiting; fixed, it runs again; SIGTERM
# ends it with exit 0 and no temporary file left, also when it comes during a run. Every
# wait polls with a deadline, so a watcher that misbehaves fails the test, never hangs it.
set -u
. "$(dirname "$0")/lib.sh" test_run_watch

W=$TMP/graph OUT=$TMP/out LOG=$TMP/stdout ERR=$TMP/stderr
mkdir -p "$W"
cp examples/cornell.scene "$W/"
sed 's|^scene .*|scene "cornell.scene"|' graphs/ssao.graph >"$W/ao.graph"
grep -q 'radius=0.5)' "$W/ao.graph" || fail "graphs/ssao.graph no longer has ssao's radius=0.5"

PID=
trap '[ -n "$PID" ] && kill -9 "$PID" 2>/dev/null' EXIT

# start ARGS...: the watcher in the background, its output in $LOG and $ERR.
start() {
    : >"$LOG"; : >"$ERR"
    "$BIN" run "$W/ao.graph" --threads 2 --out "$OUT" --watch "$@" >"$LOG" 2>"$ERR" &
    PID=$!
}

# wait_for PATTERN FILE: until FILE has a line matching PATTERN (grep -E); 1 after 20 s or
# when the watcher has ended.
wait_for() {
    local deadline=$((SECONDS + 20))
    until grep -Eq -- "$1" "$2" 2>/dev/null; do
        kill -0 "$PID" 2>/dev/null || return 1
        [ "$SECONDS" -lt "$deadline" ] || return 1
        sleep 0.05
    done
}

# expect_line PATTERN FILE WHAT: wait_for, or fail showing what the watcher printed and
# end the test (each later step would only wait out its own deadline).
expect_line() {
    wait_for "$1" "$2" && return
    fail "$3: no line /$1/ in $2 within 20 s. stdout: $(cat "$LOG") stderr: $(cat "$ERR")"
    kill -9 "$PID" 2>/dev/null
    finish test_run_watch
}

# stop_watcher: SIGTERM, then its exit status must be 0 (waited for with a deadline).
stop_watcher() {
    kill -TERM "$PID"
    local deadline=$((SECONDS + 20))
    while kill -0 "$PID" 2>/dev/null && [ "$SECONDS" -lt "$deadline" ]; do sleep 0.05; done
    if kill -0 "$PID" 2>/dev/null; then
        fail "$1: the watcher did not end within 20 s of SIGTERM"
        kill -9 "$PID"
    fi
    wait "$PID"
    local rc=$?
    [ "$rc" -eq 0 ] || fail "$1: SIGTERM ended the watcher with status $rc, expected 0"
    PID=
    local left
    left=$(find "$TMP" -name '*.tmp-*')
    [ -z "$left" ] || fail "$1: temporary files left: $left"
}

digest() { sha256sum "$OUT/ssao.exr" 2>/dev/null | cut -d' ' -f1; }

# edit SED-EXPRESSION FILE: in place, through a new file renamed over it (as editors save).
edit() { sed "$1" "$2" >"$2.new" && mv "$2.new" "$2"; }

start --size 32x24 --quiet --set k.count=8
expect_line '^watch: run 1 done' "$LOG" "first run"
first=$(digest)
[ -n "$first" ] || fail "the first run wrote no $OUT/ssao.exr"

# a parameter changes: the run's line names the graph, and the image differs
edit 's/radius=0.5)/radius=0.9)/' "$W/ao.graph"
expect_line "^watch: .*ao\.graph changed" "$LOG" "parameter edit"
expect_line '^watch: run 2 done' "$LOG" "run after the parameter edit"
second=$(digest)
[ -n "$second" ] && [ "$second" != "$first" ] ||
    fail "the EXR did not change with the radius ($first -> $second)"

# broken: the error at file:line:col, and the watcher waits on
edit 's/radius=0.9)/radus=0.9)/' "$W/ao.graph"
expect_line '^watch: run 3 failed' "$LOG" "broken graph"
grep -Eq "ao\.graph:[0-9]+:[0-9]+: error: .*radus" "$ERR" ||
    fail "the broken graph's error lacks file:line:col: $(cat "$ERR")"
kill -0 "$PID" 2>/dev/null || fail "the watcher ended after a failed reload"
[ "$(digest)" = "$second" ] || fail "the failed reload changed the EXR"

# fixed: it runs again, with the new radius
edit 's/radus=0.9)/radius=0.7)/' "$W/ao.graph"
expect_line '^watch: run 4 done' "$LOG" "fixed graph"
fourth=$(digest)
[ -n "$fourth" ] && [ "$fourth" != "$second" ] || fail "the fixed graph's EXR is unchanged"
# each reload keeps the command line's overrides: the bytes of a fresh run with them
"$BIN" run "$W/ao.graph" --threads 2 --out "$TMP/fresh" --size 32x24 --quiet --set k.count=8 ||
    fail "a fresh run of the fixed graph failed"
cmp -s "$OUT/ssao.exr" "$TMP/fresh/ssao.exr" || fail "the watcher's EXR differs from a fresh run's"

# the scene file is watched too (an edit in place, same size: the mtime tells)
sed -i 's/^# /#./' "$W/cornell.scene"
expect_line "^watch: .*cornell\.scene changed" "$LOG" "scene edit"
expect_line '^watch: run 5 done' "$LOG" "run after the scene edit"
stop_watcher "between runs"

# SIGTERM while a run is (most likely) under way: still 0 and no temporaries
start --size 480x270
expect_line '^watch: run 1 done' "$LOG" "second watcher's first run"
edit 's/radius=0.7)/radius=0.6)/' "$W/ao.graph"
expect_line "changed: running again" "$LOG" "second watcher's edit"
stop_watcher "during a run"

finish test_run_watch
