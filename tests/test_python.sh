#!/usr/bin/env bash
# The Python package (python/, docs/python.md) as a user installs it: a virtual environment
# that sees Debian's packages (python3 -m venv --system-site-packages), the documented
# `pip install --no-build-isolation ./python` against this build's libssgraph.so (offline:
# nothing is downloaded), the README's one-line check from the repository root, then the
# pytest suite (python/tests): numpy round trips, the CLI's bytes, every kind of bad input,
# 1000 runs without growth, threads. The package is built from a copy of python/, so a
# build folder left there by another install is never reused.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_python"

build=$(cd "$(dirname "$BIN")" && pwd)
for m in numpy cffi setuptools wheel pytest; do
    /usr/bin/python3 -c "import $m" 2> /dev/null ||
        fail "python3-$m is missing: install the packages in tools/debian-packages-test.txt (tools/install-deps.sh --test)"
done
[ -e "$build/libssgraph.so" ] || fail "no libssgraph.so in $build (SSGRAPH_BUILD_SHARED=OFF?)"
[ "$fails" -eq 0 ] || finish test_python

# A sanitizer build's library needs its runtime loaded before Python's own allocations:
# preload it, and leave Python's own never-freed objects out of the leak report.
if ldd "$build/libssgraph.so" | grep -q libasan; then
    export LD_PRELOAD=$(gcc -print-file-name=libasan.so)
    # no quarantine: freed blocks are reused at once, so RSS shows growth, not ASan's cache
    export ASAN_OPTIONS=detect_leaks=0:intercept_tls_get_addr=0:quarantine_size_mb=0:thread_local_quarantine_size_kb=0
fi

cp -r python "$TMP/src"
rm -rf "$TMP/src/build" "$TMP/src"/*.egg-info
/usr/bin/python3 -m venv --system-site-packages "$TMP/venv" || fail "python3 -m venv failed"
SSGRAPH_BUILD_DIR=$build "$TMP/venv/bin/pip" install --no-build-isolation --no-index \
    "$TMP/src" > "$TMP/pip.log" 2>&1 || { cat "$TMP/pip.log"; fail "pip install failed"; }
[ "$fails" -eq 0 ] || finish test_python

# A Python without wheel and cffi (here Debian's with its site-packages off, as a pyenv
# or conda build would be) stops the build with what is missing and the way out, not with
# "invalid command 'bdist_wheel'" (issue 46)
out=$(cd "$TMP/src" && /usr/bin/python3 -S setup.py --version 2>&1)
echo "$out" | grep -q "needs wheel and cffi, which /usr/bin/python3" &&
    echo "$out" | grep -q "tools/install-deps.sh --test" ||
    fail "setup.py without wheel and cffi said: $out"

# The README's check, as written there, from the repository root
out=$("$TMP/venv/bin/python3" -c "import ssgraph; g = ssgraph.load('graphs/ssao.graph'); \
g.set('ao.radius', 0.25); a = g.run().output('b.out'); print(a.shape, a.dtype)" 2>&1)
[ "$out" = "(720, 1280) float32" ] || fail "the README's one-liner printed: $out"
# the package's version is the library's
want=$(sed -n 's/^#define SSG_VERSION "\(.*\)"/\1/p' core/ssgraph.h)
have=$("$TMP/venv/bin/python3" -c "import ssgraph; print(ssgraph.__version__)" 2>&1)
[ "$have" = "$want" ] || fail "ssgraph.__version__ is $have, core/ssgraph.h says $want"
# help() shows the docstrings and the module needs no LD_LIBRARY_PATH
doc=$(env -u LD_LIBRARY_PATH "$TMP/venv/bin/python3" -c "import ssgraph; help(ssgraph.Graph.run)" 2>&1)
echo "$doc" | grep -q "GIL is" || fail "help(ssgraph.Graph.run) lacks its docstring: $doc"

cd "$TMP" && SSG_BIN=$BIN "$TMP/venv/bin/python3" -m pytest -q -p no:cacheprovider \
    "$OLDPWD/python/tests" || fail "pytest python/tests"
finish test_python
