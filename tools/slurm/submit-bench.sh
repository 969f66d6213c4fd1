#!/usr/bin/env bash
# Submits a sharded `ssgraph bench` sweep to Slurm: a job array of N tasks (bench-array.sh),
# task I running `ssgraph bench ... --shard I/N`, and a merge job (bench-merge.sh) that starts
# when every task has succeeded and writes OUT/merged. See docs/cluster.md.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

usage() {
    cat <<EOF
usage: $(basename "$0") [options] -- GRAPH [ssgraph bench arguments...]

Submits GRAPH's sweep as a Slurm job array of N shards plus a dependent merge job.
Each option also reads the environment variable in brackets; the option wins.

  -n, --shards N       number of shards (array tasks 0..N-1)   [SSGRAPH_SHARDS, default 4]
  -o, --out DIR        output folder on a shared file system:
                       DIR/shard-I per task, DIR/merged, DIR/logs [SSGRAPH_OUT, default out/slurm-bench]
  -c, --cpus N         CPUs per task, passed on as --threads     [SSGRAPH_CPUS, default 4]
  -p, --partition P    partition                                 [SSGRAPH_PARTITION, default: the cluster's]
  -t, --time T         time limit per task (sbatch --time)       [SSGRAPH_TIME, default 01:00:00]
      --mem M          memory per task (sbatch --mem), e.g. 8G   [SSGRAPH_MEM, default: the cluster's]
  -b, --bin PATH       the ssgraph program, on the shared file system
                                                                 [SSGRAPH_BIN, default ./build/ssgraph]
      --only LIST      submit only these array indices (sbatch --array syntax: 3 or 1,5 or 2-4),
                       to rerun failed shards into an existing DIR; the merge job runs again after them
      --merge-after ok|any
                       start the merge after every task succeeded (ok, default) or after every
                       task ended (any: tasks whose cells failed exit 1, yet wrote their tables)
                                                                 [SSGRAPH_MERGE_AFTER]
      --no-merge       submit the array only
      --sbatch ARG     one more sbatch argument for every job (repeatable), e.g. --sbatch=--account=abc
      --dry-run        print the sbatch commands instead of running them
  -h, --help           this message

The bench arguments are passed to every task unchanged, except --plot, which goes to the
merge. --out, --shard and --threads are set per task and may not be given. Relative paths
(GRAPH, --scene, DIR, the program) are resolved from the current folder, which is also each
job's working folder: submit from a folder every node sees.

Example, 8 shards of 4 CPUs:
  $(basename "$0") -n 8 -c 4 -o results/sweep -- graphs/ao_error.graph \\
      --sweep k.count=8,16,32 --sweep ao.radius=0.25,0.5 --size 800x600 --plot
EOF
}

die() { echo "submit-bench.sh: $*" >&2; exit 2; }

orig=("$@")
shards=${SSGRAPH_SHARDS:-4}
out=${SSGRAPH_OUT:-out/slurm-bench}
cpus=${SSGRAPH_CPUS:-4}
partition=${SSGRAPH_PARTITION:-}
timelimit=${SSGRAPH_TIME:-01:00:00}
mem=${SSGRAPH_MEM:-}
bin=${SSGRAPH_BIN:-./build/ssgraph}
merge_after=${SSGRAPH_MERGE_AFTER:-ok}
only=""
merge=1
dry=0
extra=()

need_value() { [ $# -ge 2 ] || die "$1 needs a value (see --help)"; }
while [ $# -gt 0 ]; do
    case $1 in
        -h|--help) usage; exit 0 ;;
        -n|--shards) need_value "$@"; shards=$2; shift 2 ;;
        --shards=*) shards=${1#*=}; shift ;;
        -o|--out) need_value "$@"; out=$2; shift 2 ;;
        --out=*) out=${1#*=}; shift ;;
        -c|--cpus) need_value "$@"; cpus=$2; shift 2 ;;
        --cpus=*) cpus=${1#*=}; shift ;;
        -p|--partition) need_value "$@"; partition=$2; shift 2 ;;
        --partition=*) partition=${1#*=}; shift ;;
        -t|--time) need_value "$@"; timelimit=$2; shift 2 ;;
        --time=*) timelimit=${1#*=}; shift ;;
        --mem) need_value "$@"; mem=$2; shift 2 ;;
        --mem=*) mem=${1#*=}; shift ;;
        -b|--bin) need_value "$@"; bin=$2; shift 2 ;;
        --bin=*) bin=${1#*=}; shift ;;
        --only) need_value "$@"; only=$2; shift 2 ;;
        --only=*) only=${1#*=}; shift ;;
        --merge-after) need_value "$@"; merge_after=$2; shift 2 ;;
        --merge-after=*) merge_after=${1#*=}; shift ;;
        --no-merge) merge=0; shift ;;
        --sbatch) need_value "$@"; extra+=("$2"); shift 2 ;;
        --sbatch=*) extra+=("${1#*=}"); shift ;;
        --dry-run) dry=1; shift ;;
        --) shift; break ;;
        -*) die "unknown option '$1' (bench arguments go after --; see --help)" ;;
        *) break ;;
    esac
done

[ $# -ge 1 ] || { usage >&2; die "no GRAPH given (after --)"; }

is_count() { [[ $1 =~ ^[0-9]+$ ]] && [ "$((10#$1))" -ge 1 ]; }
is_count "$shards" || die "the shard count must be a positive integer, not '$shards'"
is_count "$cpus" || die "CPUs per task must be a positive integer, not '$cpus'"
shards=$((10#$shards)); cpus=$((10#$cpus))
case $merge_after in ok|any) ;; *) die "--merge-after takes ok or any, not '$merge_after'" ;; esac
if [ -n "$only" ]; then
    [[ $only =~ ^[0-9]+(-[0-9]+)?(,[0-9]+(-[0-9]+)?)*$ ]] ||
        die "--only takes array indices like 3, 1,5 or 2-4, not '$only'"
    for n in $(tr ',-' '  ' <<< "$only"); do
        [ "$((10#$n))" -lt "$shards" ] || die "--only: shard $n is not below the shard count $shards"
    done
fi

# Bench arguments: --plot moves to the merge; the per-task options are refused.
plot=()
args=()
for a in "$@"; do
    case $a in
        --plot) plot=(--plot) ;;
        --out|--out=*|-o|--shard|--shard=*|--threads|--threads=*|--merge|--merge=*)
            die "'$a' is set by the Slurm scripts; leave it out of the bench arguments" ;;
        *) args+=("$a") ;;
    esac
done
[ -f "${args[0]}" ] || die "graph '${args[0]}' not found (relative to $(pwd))"

command -v sbatch > /dev/null || [ "$dry" = 1 ] ||
    die "sbatch not found: run this on a Slurm login node (or with --dry-run)"
[ -x "$bin" ] || die "ssgraph program '$bin' not found or not executable (set --bin or SSGRAPH_BIN)"

# Absolute paths: the jobs start in this folder, but the scripts are copied by Slurm.
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
mkdir -p "$out/logs"
out=$(cd "$out" && pwd)

if [ -z "$only" ]; then
    for d in "$out"/shard-*; do
        [ -e "$d" ] || continue
        die "$out already holds shards ($d): choose another --out, remove them, or rerun some with --only"
    done
    array="0-$((shards - 1))"
else
    array=$only
fi

common=("${extra[@]}")
[ -n "$partition" ] && common+=("--partition=$partition")
[ -n "$timelimit" ] && common+=("--time=$timelimit")
[ -n "$mem" ] && common+=("--mem=$mem")
export SSGRAPH_BIN="$bin" SSGRAPH_SHARDS="$shards" SSGRAPH_OUT="$out"

run_sbatch() {
    if [ "$dry" = 1 ]; then
        printf '%q ' sbatch "$@" >&2; echo >&2
        echo "DRYRUN$RANDOM"
    else
        sbatch "$@"
    fi
}

array_job=$(run_sbatch --parsable --export=ALL --job-name=ssgraph-bench \
    --array="$array" --cpus-per-task="$cpus" --ntasks=1 \
    --output="$out/logs/shard-%a.out" "${common[@]}" \
    "$here/bench-array.sh" "${args[@]}")
array_job=${array_job%%;*}
echo "submitted shards $array of $shards: job $array_job -> $out/shard-I (logs in $out/logs)"
# The job ids (for scripts) and the command (to rerun a shard: the same with --only K).
if [ "$dry" = 0 ]; then
    echo "array=$array_job" > "$out/jobs"
    {
        printf '# %s: array job %s\n' "$(date -u '+%Y-%m-%d %H:%M:%S UTC')" "$array_job"
        printf '%q ' SSGRAPH_BIN="$bin" "$here/submit-bench.sh" "${orig[@]}"
        echo
    } >> "$out/submit.log"
fi

if [ "$merge" = 1 ]; then
    merge_job=$(run_sbatch --parsable --export=ALL --job-name=ssgraph-merge \
        --dependency="after$merge_after:$array_job" --kill-on-invalid-dep=yes \
        --cpus-per-task=1 --ntasks=1 --output="$out/logs/merge.out" "${common[@]}" \
        "$here/bench-merge.sh" "${plot[@]}")
    merge_job=${merge_job%%;*}
    echo "submitted merge: job $merge_job after$merge_after:$array_job -> $out/merged"
    [ "$dry" = 1 ] || echo "merge=$merge_job" >> "$out/jobs"
fi
