#!/usr/bin/env bash
# The merge job of a sharded `ssgraph bench`: merges $SSGRAPH_OUT/shard-0 .. shard-(N-1) into
# $SSGRAPH_OUT/merged. `ssgraph bench --merge` refuses (exit 1, nothing written) unless the
# shards come from one sweep and cover every cell once, and names the missing or foreign shard.
# submit-bench.sh submits it after the array; by hand: sbatch tools/slurm/bench-merge.sh [--plot]
# with SSGRAPH_BIN, SSGRAPH_SHARDS and SSGRAPH_OUT set, or run it directly without Slurm.
#SBATCH --job-name=ssgraph-merge
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail

die() { echo "bench-merge.sh: $*" >&2; exit 2; }

if [ "${1:-}" = -h ] || [ "${1:-}" = --help ]; then
    cat <<EOF
usage: [sbatch] tools/slurm/bench-merge.sh [--plot] [more ssgraph bench --merge options]
environment: SSGRAPH_SHARDS=N (required), SSGRAPH_OUT=DIR (required),
             SSGRAPH_BIN (default ./build/ssgraph)
EOF
    exit 0
fi

bin=${SSGRAPH_BIN:-./build/ssgraph}
shards=${SSGRAPH_SHARDS:-}
out=${SSGRAPH_OUT:-}
[[ $shards =~ ^[1-9][0-9]*$ ]] ||
    die "SSGRAPH_SHARDS must be the shard count, a positive integer (it is '$shards')"
[ -n "$out" ] || die "SSGRAPH_OUT (the output folder) is not set"
[ -x "$bin" ] || die "ssgraph program '$bin' not found or not executable on $(hostname)"

# Every shard by name, present or not, so that a missing one is named by the merge.
dirs=()
for ((i = 0; i < 10#$shards; i++)); do dirs+=("$out/shard-$i"); done
echo "bench-merge.sh: merging ${#dirs[@]} shards of $out into $out/merged"
exec "$bin" bench --merge "${dirs[@]}" --out "$out/merged" "$@"
