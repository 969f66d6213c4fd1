#!/usr/bin/env bash
# test_public_api.sh - the command line stands on the public interface alone, and the
# shared library exports exactly that interface (issue 31):
#   1. no file of cli/ includes a header of ours but core/ssgraph.h and cli/'s own (system
#      headers in <...> are free);
#   2. every function core/ssgraph.h declares carries SSG_API (one without it would be
#      hidden in libssgraph.so, and a user's program could not link it);
#   3. the dynamic symbols libssgraph.so defines are exactly the SSG_API functions (the
#      difference is printed both ways), and the ssgraph executable links that library, so
#      a function the CLI needs that is not exported fails its build;
#   4. each check finds a planted violation (a check that cannot fail proves nothing).
set -u
. "$(dirname "$0")/lib.sh" test_public_api
BUILD=$(cd "$(dirname "$BIN")" && pwd)
SO="$BUILD/libssgraph.so"

# Prints "FILE:LINE: #include ..." for each include of a header in quotes that is neither
# ssgraph.h nor a file of the same folder.
foreign_includes() {
    local dir=$1 f line name target root
    root=$(realpath "$dir")
    find "$dir" -type f | sort | while IFS= read -r f; do
        grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$f" | while IFS= read -r line; do
            name=$(printf '%s\n' "$line" | sed -E 's/^[0-9]+:[^"]*"([^"]*)".*/\1/')
            [ "$name" = ssgraph.h ] && continue
            # cli's own headers, beside the file or in a folder of cli/ (view/view.h,
            # ../options.h), never one that leads out of cli/
            target=$(realpath -m "$(dirname "$f")/$name")
            [ -f "$target" ] && case "$target" in "$root"/*) continue ;; esac
            target=$(realpath -m "$root/$name")
            [ -f "$target" ] && case "$target" in "$root"/*) continue ;; esac
            echo "$f:$line"
        done
    done
}

# The functions a header declares with SSG_API, one a line, sorted.
api_functions() {
    sed -nE 's/^SSG_API [^(]*[ *](ssg_[a-z0-9_]+)\(.*/\1/p' "$@" | sort -u
}

# Prints each function declaration of a header that lacks SSG_API (static inline ones are
# the header's own, typedefs are types).
unmarked_functions() {
    grep -nE '^(const |unsigned |void|int|double|float|size_t|enum |struct )[^;{]*\bssg_[a-z0-9_]+\(' "$1" |
        grep -vE '^[0-9]+:(static|typedef)'
}

# The symbols a shared library defines for others, one a line, sorted.
exported() {
    nm -D --defined-only "$1" | awk '{print $NF}' | sort -u
}

# 1. cli/ includes
bad=$(foreign_includes cli)
[ -z "$bad" ] || fail "cli/ includes headers outside core/ssgraph.h:
$bad"

# 2. every declared function is SSG_API
# (the interface is core/ssgraph.h and the ssgraph_tools.h it includes)
bad=$(unmarked_functions core/ssgraph.h; unmarked_functions core/ssgraph_tools.h)
[ -z "$bad" ] || fail "core/ssgraph.h or ssgraph_tools.h declares functions without SSG_API:
$bad"
api_functions core/ssgraph.h core/ssgraph_tools.h >"$TMP/api.txt"
[ "$(wc -l <"$TMP/api.txt")" -ge 40 ] ||
    fail "found only $(wc -l <"$TMP/api.txt") SSG_API functions in core/ssgraph.h: the pattern broke"

# 3. the export list
if [ -f "$SO" ]; then
    exported "$SO" >"$TMP/exported.txt"
    if ! cmp -s "$TMP/api.txt" "$TMP/exported.txt"; then
        fail "libssgraph.so exports other than the SSG_API functions of core/ssgraph.h:
exported, not SSG_API: $(comm -13 "$TMP/api.txt" "$TMP/exported.txt" | tr '\n' ' ')
SSG_API, not exported: $(comm -23 "$TMP/api.txt" "$TMP/exported.txt" | tr '\n' ' ')"
    fi
    readelf -d "$BIN" | grep -q 'NEEDED.*\[libssgraph\.so' ||
        fail "$BIN does not link libssgraph.so: its use of the public API is not checked"
else
    echo "note: no $SO (SSGRAPH_BUILD_SHARED=OFF): the export list is not checked"
fi

# 4. the checks catch what they are for
mkdir -p "$TMP/cli"
printf '#include <stdio.h>\n#include "ssgraph.h"\n#include "own.h"\n' >"$TMP/cli/ok.c"
: >"$TMP/cli/own.h"
printf '#include "own.h"\n #  include "lang/files.h"\n' >"$TMP/cli/bad.c"
printf '#include "missing.h"\n' >"$TMP/cli/bad2.c"
mkdir -p "$TMP/cli/sub" && : >"$TMP/outside.h"
printf '#include "../own.h"\n#include "../../outside.h"\n' >"$TMP/cli/sub/nested.c"
planted=$(foreign_includes "$TMP/cli")
[ "$(echo "$planted" | grep -c .)" -eq 3 ] && echo "$planted" | grep -q 'bad.c:2:' &&
    echo "$planted" | grep -q 'bad2.c:1:' && echo "$planted" | grep -q 'nested.c:2:' ||
    fail "the include check missed or over-reported planted includes: $planted"
printf 'SSG_API int ssg_a(void);\nSSG_API struct ssg_image *ssg_b(int x,\n    int y);\n%s\n%s\n' \
    'enum ssg_err ssg_c(int x);' 'static inline int ssg_d(void) { return 0; }' >"$TMP/h.h"
[ "$(api_functions "$TMP/h.h" | tr '\n' ' ')" = "ssg_a ssg_b " ] ||
    fail "api_functions read $(api_functions "$TMP/h.h" | tr '\n' ' ') from a planted header"
[ "$(unmarked_functions "$TMP/h.h" | cut -d: -f1)" = 4 ] ||
    fail "unmarked_functions found '$(unmarked_functions "$TMP/h.h")', not line 4"
if [ -f "$BUILD/libssgraph.a" ]; then
    # the static library's members define the internal functions the .so must not export
    nm --defined-only "$BUILD/libssgraph.a" 2>/dev/null | grep -q ' T ssg_graph_build$' ||
        fail "libssgraph.a lacks ssg_graph_build: the planted comparison has nothing to find"
    exported "$SO" 2>/dev/null | grep -qx ssg_graph_build &&
        fail "libssgraph.so exports the internal ssg_graph_build"
fi
finish test_public_api
