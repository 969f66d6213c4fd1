# lib.sh - what the shell tests share; source it after `set -u`. Sets BIN (the ssgraph
# executable, from SSG_BIN) and TMP (an emptied scratch directory, from SSG_TMP, else the
# folder named $1 in $TMPDIR or /tmp), counts failures, and `finish NAME` exits with the verdict.
BIN=${SSG_BIN:?SSG_BIN must point at the ssgraph executable}
TMP=${SSG_TMP:-${TMPDIR:-/tmp}/$1}
rm -rf "$TMP" && mkdir -p "$TMP"
fails=0

fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
# expect_exit CODE PATTERN CMD...: runs CMD, checks its exit status and that stderr+stdout
# match PATTERN (grep -E).
expect_exit() {
    local code=$1 pattern=$2; shift 2
    local out rc
    out=$("$@" 2>&1); rc=$?
    [ "$rc" -eq "$code" ] || fail "'$*' exited $rc, expected $code. Output: $out"
    echo "$out" | grep -Eq -- "$pattern" || fail "'$*' output lacks /$pattern/: $out"
}

finish() {
    if [ "$fails" -ne 0 ]; then
        echo "$1: $fails failure(s)" >&2
        exit 1
    fi
    echo "$1: all passed"
}
