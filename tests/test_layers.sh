#!/usr/bin/env bash
# test_layers.sh - core/'s layers include only downwards: lang (the language, diagnostics,
# files) below scene, scene below graph (nodes, images, the executor), graph below gl and io
# (the GL backend and the image files). A header that reaches up a layer (scene including
# graph/node.h for M_PI, graph including the GL runtime's header) makes the layers one
# include cycle; this test names the file and the include that does it.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_layers"
allowed() { # the layers a file of layer $1 may include
    case "$1" in
        lang) echo "lang" ;;
        scene) echo "lang scene" ;;
        graph) echo "lang scene graph" ;;
        gl | io) echo "lang scene graph $1" ;;
        *) echo "" ;;
    esac
}
for dir in core/*/; do
    layer=$(basename "$dir")
    ok=$(allowed "$layer")
    [ -n "$ok" ] || fail "core/$layer is not a known layer: add it to tests/test_layers.sh"
    for f in "$dir"*.c "$dir"*.h "$dir"*.cc; do
        [ -e "$f" ] || continue
        while IFS= read -r inc; do
            to=${inc%%/*}
            case " $ok " in
                *" $to "*) ;;
                *) fail "$f includes \"$inc\": layer $layer may include only: $ok" ;;
            esac
        done < <(sed -n 's/^#include "\([a-z_]*\/[a-z_0-9.]*\)".*/\1/p' "$f")
    done
done
finish test_layers
