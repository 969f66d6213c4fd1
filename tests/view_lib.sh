# view_lib.sh - what the tests of `ssgraph view` over HTTP share; source it after lib.sh.
# view_start LOG ARGS...: starts `ssgraph view ARGS...` in the background (output in LOG),
# waits for its URL and sets pid, port, token, B (http://127.0.0.1:PORT) and H (the token
# header); an EXIT trap kills it. Returns 1 (with LOG shown) when no URL was printed.
view_start() {
    local log=$1; shift
    "$BIN" view "$@" >"$log" 2>&1 &
    pid=$!
    trap 'kill $pid 2>/dev/null' EXIT
    local url=
    for _ in $(seq 1 300); do # the load may take a while on a busy machine
        url=$(grep -o 'http://127.0.0.1:[0-9]*/?token=[0-9a-f]*' "$log")
        [ -n "$url" ] || ! kill -0 $pid 2>/dev/null && break
        sleep 0.2
    done
    [ -n "$url" ] || { cat "$log"; return 1; }
    port=${url#http://127.0.0.1:}; port=${port%%/*}
    token=${url##*token=}
    B=http://127.0.0.1:$port
    H="X-SSG-Token: $token"
}

# view_start_ao SIZE: view_start on a scratch copy of graphs/reference_ao.graph at SIZE with
# 4 rays a pixel (cheap; ref.rays=65536 makes a run of seconds); ends the test when no URL
# came. ROOT is the source folder.
view_start_ao() {
    mkdir -p "$TMP/graphs"
    cp graphs/reference_ao.graph "$TMP/graphs/"
    view_start "$TMP/view.log" "$TMP/graphs/reference_ao.graph" --scene "$ROOT/examples/cornell.scene" \
        --size "$1" --threads 2 --set ref.rays=4 --out "$TMP/out" || {
        fail "no URL printed"; finish "$(basename "$0" .sh)"; }
}

# code ARGS...: the HTTP status of a curl request (its body in $TMP/body; 000 when no answer
# came within 60 s: a blocked server fails its test rather than hanging it)
code() { curl -s --max-time 60 -o "$TMP/body" -w '%{http_code}' "$@"; }
expect_code() {
    local want=$1; shift
    local got; got=$(code "$@")
    [ "$got" = "$want" ] || fail "curl $* answered $got, expected $want: $(head -c 300 "$TMP/body")"
}

# view_stop_within MS SIGNAL: sends SIGNAL and checks that the server ends within MS
# milliseconds with status 0; sets stop_ms to the milliseconds it took. MS tells an end
# from none (callers give 10 s: a busy machine must not fail it); the time is printed.
view_stop_within() {
    local limit=$1 sig=$2 t0 took rc
    t0=$(date +%s%N)
    kill -"$sig" $pid
    while kill -0 $pid 2>/dev/null && [ $((($(date +%s%N) - t0) / 1000000)) -le $((limit + 1000)) ]; do
        sleep 0.02
    done
    took=$((($(date +%s%N) - t0) / 1000000))
    if kill -0 $pid 2>/dev/null; then
        fail "the server was still running $took ms after SIG$sig"
        kill -KILL $pid
    fi
    wait $pid; rc=$?
    trap - EXIT
    [ "$rc" -eq 0 ] || fail "SIG$sig ended the server with status $rc"
    [ "$took" -le "$limit" ] || fail "SIG$sig took $took ms to end the server (at most $limit)"
    stop_ms=$took
}

# browser_tools_check: fails (once per missing tool) unless Debian's chromium, chromedriver,
# python3 and python3-selenium are there, as the browser tests need them.
browser_tools_check() {
    for tool in /usr/bin/chromium /usr/bin/chromedriver /usr/bin/python3; do
        [ -x "$tool" ] || fail "$tool is missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
    done
    /usr/bin/python3 -c 'import selenium' 2> /dev/null ||
        fail "python3-selenium is missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
}
