#!/usr/bin/env bash
# Digests of every graph's output files, to prove a refactoring changed no byte:
#   tools/output_digest.sh BUILD_DIR DIGEST_FILE [SIZE...]
# runs each graph under graphs/ at each size (default 96x64 and 160x90) on the CPU and
# on the GL backend and writes one line per output file: graph size backend file sha256.
# Compare two digest files with diff; the same binary and inputs give the same bytes.
set -u
build=${1:?usage: output_digest.sh BUILD_DIR DIGEST_FILE [SIZE...]}
digest=${2:?usage: output_digest.sh BUILD_DIR DIGEST_FILE [SIZE...]}
shift 2
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(96x64 160x90)
bin="$build/ssgraph"
[ -x "$bin" ] || { echo "output_digest: no $bin (build first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: > "$digest.part"
for graph in graphs/*.graph graphs/*/*.graph; do
    for size in "${sizes[@]}"; do
        for backend in cpu gl; do
            out="$work/out"
            rm -rf "$out"
            if ! "$bin" run "$graph" --size "$size" --backend "$backend" --threads 2 \
                --quiet --out "$out" > "$work/log" 2>&1; then
                echo "$graph $size $backend FAILED $(tail -1 "$work/log")" >> "$digest.part"
                continue
            fi
            (cd "$out" && find . -type f \( -name '*.exr' -o -name 'metrics.json' \) | sort |
                while read -r f; do
                    echo "$graph $size $backend $f $(sha256sum "$f" | cut -d' ' -f1)"
                done) >> "$digest.part"
        done
    done
done
mv "$digest.part" "$digest"
echo "output_digest: $(wc -l < "$digest") files from $bin into $digest"
