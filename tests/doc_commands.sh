#!/usr/bin/env bash
# doc_commands.sh DOC NAME - the examples of a Markdown document are true
# (tests/test_doc_readme.sh and test_doc_tutorial.sh run it on README.md and docs/tutorial.md):
#   - a fenced block whose info string names a file (```graph file=docs/tutorial/first.graph)
#     shows that file exactly as it is in the repository;
#   - every command of a ```sh block that starts with ./build/ssgraph (a trailing \ joins
#     the next line) runs as written and exits 0. It runs in a scratch folder that holds the
#     repository's docs, examples, graphs and tools and a build/ssgraph that is the build
#     under test, so what it writes (out/...) stays there.
set -u
DOC=$1
. "$(dirname "$0")/lib.sh" "$2"
SRC=$(pwd)
mkdir -p "$TMP/run/build"
for d in docs examples graphs tools; do ln -s "$SRC/$d" "$TMP/run/$d"; done
ln -s "$BIN" "$TMP/run/build/ssgraph"

# Shown files: compare each with the repository's copy.
python3 - "$DOC" "$TMP/shown" <<'PY'
import os, re, sys
doc, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
text = open(doc).read()
for i, m in enumerate(re.finditer(r"^```[^\n]*\bfile=(\S+)\n(.*?)^```$", text, re.M | re.S)):
    with open(os.path.join(out, "%d" % i), "w") as f:
        f.write(m.group(1) + "\n" + m.group(2))
PY
shown=0
for f in "$TMP"/shown/*; do
    [ -e "$f" ] || continue
    shown=$((shown + 1))
    path=$(head -1 "$f")
    tail -n +2 "$f" | diff -u "$path" - > "$TMP/shown.diff" ||
        fail "$DOC shows $path differently from the file: $(head -c 600 "$TMP/shown.diff")"
done

# Commands: one a line after joining continuations, in document order.
python3 - "$DOC" > "$TMP/commands" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
for block in re.findall(r"^```sh\n(.*?)^```$", text, re.M | re.S):
    for command in block.replace("\\\n", " ").splitlines():
        command = command.strip()
        if command.startswith("./build/ssgraph"):
            print(" ".join(command.split()))
PY
ran=0
while IFS= read -r command; do
    ran=$((ran + 1))
    if ! (cd "$TMP/run" && bash -c "$command") > "$TMP/command.log" 2>&1; then
        fail "$DOC: '$command' failed: $(tail -c 800 "$TMP/command.log")"
    fi
done < "$TMP/commands"
[ "$ran" -gt 0 ] || fail "$DOC has no ./build/ssgraph command in a sh block"
echo "$DOC: $shown shown files, $ran commands"
finish "$2"
