#!/usr/bin/env bash
# One task of a sharded `ssgraph bench` job array: task I of N runs the sweep's cells whose
# index modulo N is I into $SSGRAPH_OUT/shard-I, with --threads $SLURM_CPUS_PER_TASK.
# submit-bench.sh submits it; by hand (to rerun shard 3 of 8 with the sweep's arguments):
#   SSGRAPH_BIN=$PWD/build/ssgraph SSGRAPH_SHARDS=8 SSGRAPH_OUT=$PWD/results/sweep \
#       sbatch --array=3 --cpus-per-task=4 --output=results/sweep/logs/shard-%a.out \
#       tools/slurm/bench-array.sh GRAPH --sweep ...
# Outside Slurm, SLURM_ARRAY_TASK_ID and SLURM_CPUS_PER_TASK may be set by hand.
#SBATCH --job-name=ssgraph-bench
#SBATCH --ntasks=1
set -euo pipefail

die() { echo "bench-array.sh: $*" >&2; exit 2; }

if [ $# -eq 0 ] || [ "$1" = -h ] || [ "$1" = --help ]; then
    cat <<EOF
usage: sbatch --array=0-(N-1) --cpus-per-task=C tools/slurm/bench-array.sh GRAPH [bench arguments...]
environment: SSGRAPH_SHARDS=N (required), SSGRAPH_OUT=DIR (required),
             SSGRAPH_BIN (default ./build/ssgraph); usually set by tools/slurm/submit-bench.sh
EOF
    [ $# -eq 0 ] && exit 2
    exit 0
fi

bin=${SSGRAPH_BIN:-./build/ssgraph}
shards=${SSGRAPH_SHARDS:-}
out=${SSGRAPH_OUT:-}
task=${SLURM_ARRAY_TASK_ID:-}
threads=${SLURM_CPUS_PER_TASK:-1}

[[ $shards =~ ^[1-9][0-9]*$ ]] ||
    die "SSGRAPH_SHARDS must be the shard count, a positive integer (it is '$shards')"
[ -n "$out" ] || die "SSGRAPH_OUT (the output folder) is not set"
[[ $task =~ ^[0-9]+$ ]] ||
    die "SLURM_ARRAY_TASK_ID is '${task}': submit with sbatch --array (or set it by hand)"
[ "$((10#$task))" -lt "$((10#$shards))" ] ||
    die "array task $task is not below the shard count $shards"
[[ $threads =~ ^[0-9]+$ ]] || die "SLURM_CPUS_PER_TASK is '$threads', not a count"
[ -x "$bin" ] || die "ssgraph program '$bin' not found or not executable on $(hostname)"

task=$((10#$task)); shards=$((10#$shards))
dir=$out/shard-$task
mkdir -p "$dir"
echo "bench-array.sh: shard $task/$shards on $(hostname), $threads threads, job ${SLURM_JOB_ID:-none}, into $dir"
start=$(date +%s)
status=0
"$bin" bench "$@" --shard "$task/$shards" --threads "$threads" --out "$dir" || status=$?
echo "bench-array.sh: shard $task/$shards exit $status after $(( $(date +%s) - start )) s"
exit "$status"
