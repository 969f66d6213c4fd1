#!/usr/bin/env bash
# End-to-end test of the Slurm scripts on one machine, by hand, as root on Debian (not part of
# ctest: it installs packages and runs daemons). It installs slurm-wlm and munge with apt-get
# if they are missing, starts munged, slurmctld and slurmd in the foreground of background jobs
# with a single-node configuration for this machine in a scratch folder (the system's
# /etc/slurm and /etc/munge stay untouched), submits a 2x2x2 sweep as 4 shards plus the merge
# with submit-bench.sh, waits, and checks that the merged table equals an unsharded run's (rows,
# swept values, status, metrics; timings aside). It then removes one shard, checks that the
# merge refuses and names it, reruns that shard alone with --only and checks the merge again.
# The daemons are stopped on exit, whatever happens; the scratch folder is removed on success.
#
#   SSGRAPH_BIN   the ssgraph program (default ./build/ssgraph)
#   SSGRAPH_SLURM_TIMEOUT  seconds to wait for the jobs of one submission (default 600)
#   SSGRAPH_SLURM_KEEP=1   keep the scratch folder (configuration, logs, tables)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/../.."
repo=$(pwd)
bin=${SSGRAPH_BIN:-./build/ssgraph}
timeout=${SSGRAPH_SLURM_TIMEOUT:-600}
graph=graphs/ao_error.graph
sweep=(--size 64x48 --frames 1 --sweep "k.count=4,8" --sweep "ao.radius=0.25,0.5" --sweep "ao.bias=0.01,0.02")
shards=4

t_start=$(date +%s)
t_stage=$t_start
say() { echo "test-local.sh: $*"; }
die() { echo "test-local.sh: FAIL: $*" >&2; exit 1; }
stage_done() {
    local now; now=$(date +%s)
    say "stage '$1' took $((now - t_stage)) s"
    t_stage=$now
}

[ "$(id -u)" = 0 ] || die "run as root (it installs slurm-wlm and starts daemons)"
[ -x "$bin" ] || die "ssgraph program '$bin' not found: build it or set SSGRAPH_BIN"
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
help=$("$bin" help bench 2>&1 || true)
grep -q -- --shard <<< "$help" || die "$bin has no 'bench --shard' (rebuild it from this tree)"
command -v python3 > /dev/null || die "python3 is needed to compare the tables"
for d in slurmctld slurmd munged; do
    if pgrep -x "$d" > /dev/null; then
        die "a $d is already running (pid $(pgrep -x "$d" | tr '\n' ' ')): stop it first"
    fi
done

# --- install -------------------------------------------------------------------------------
if ! command -v slurmctld > /dev/null || ! command -v slurmd > /dev/null ||
   ! command -v sbatch > /dev/null || ! command -v munged > /dev/null; then
    command -v apt-get > /dev/null || die "apt-get not found: this test wants Debian"
    say "installing slurm-wlm and munge with apt-get"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q
    apt-get install -y -q --no-install-recommends slurm-wlm munge
else
    say "slurm-wlm and munge already installed"
fi
say "slurm-wlm $(dpkg-query -W -f '${Version}' slurm-wlm 2> /dev/null || echo '?'), $(munged --version 2>&1 | head -1)"
stage_done install

# --- configure -----------------------------------------------------------------------------
scratch=$(mktemp -d "${TMPDIR:-/tmp}/ssgraph-slurm.XXXXXX")
chmod 755 "$scratch"          # munged wants every folder above its socket searchable
mkdir -m 755 "$scratch/run"
mkdir -m 700 "$scratch/munge" "$scratch/state"
mkdir -p "$scratch/state/ctld" "$scratch/state/d" "$scratch/log"
pids=()
ok=0

cleanup() {
    local rc=$?
    set +e
    if [ -n "${SLURM_CONF:-}" ] && [ -f "${SLURM_CONF}" ] && command -v scancel > /dev/null; then
        for j in ${jobs_to_cancel:-}; do scancel "$j" 2> /dev/null; done
    fi
    local i
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
        kill "${pids[i]}" 2> /dev/null && wait "${pids[i]}" 2> /dev/null
    done
    [ ${#pids[@]} -gt 0 ] && say "stopped slurmd, slurmctld and munged"
    if [ "$ok" = 1 ] && [ "${SSGRAPH_SLURM_KEEP:-0}" != 1 ]; then
        rm -rf "$scratch"
    else
        say "scratch folder kept: $scratch (configuration, daemon logs in log/, tables in out/)"
        if [ "$ok" != 1 ]; then
            for f in "$scratch"/log/*.log "$scratch"/out/logs/*.out; do
                [ -f "$f" ] || continue
                echo "--- $f (last 20 lines)"; tail -n 20 "$f"
            done
        fi
    fi
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

dd if=/dev/urandom of="$scratch/munge/munge.key" bs=1024 count=1 2> /dev/null
chmod 600 "$scratch/munge/munge.key"
sock=$scratch/run/munge.socket

host=$(hostname -s)
cpus=$(nproc)
mem_mb=$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)
export SLURM_CONF=$scratch/slurm.conf
cat > "$SLURM_CONF" <<EOF
# Single-node Slurm for tools/slurm/test-local.sh: $cpus CPUs (nproc), ${mem_mb} MB (90% of MemTotal)
ClusterName=ssgraph-local
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
SlurmctldPort=6817
SlurmdPort=6818
StateSaveLocation=$scratch/state/ctld
SlurmdSpoolDir=$scratch/state/d
SlurmctldPidFile=$scratch/run/slurmctld.pid
SlurmdPidFile=$scratch/run/slurmd.pid
SlurmctldLogFile=$scratch/log/slurmctld.log
SlurmdLogFile=$scratch/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
MinJobAge=3600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
say "wrote $SLURM_CONF: node $host, $cpus CPUs, $mem_mb MB, partition local"
stage_done configure

# --- start the daemons ---------------------------------------------------------------------
munged -F --socket="$sock" --key-file="$scratch/munge/munge.key" \
    --pid-file="$scratch/run/munged.pid" --seed-file="$scratch/munge/munged.seed" \
    > "$scratch/log/munged.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$sock" ] && break; sleep 0.1; done
munge -n -S "$sock" | unmunge -S "$sock" > /dev/null || die "munged does not answer on $sock"
say "munged up (pid ${pids[0]})"
slurmctld -D -f "$SLURM_CONF" > "$scratch/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" > "$scratch/log/slurmd.out" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 60); do
    state=$(sinfo -h -n "$host" -o %T 2> /dev/null || true)
    case $state in idle*|mixed*|allocated*) break ;; esac
    for p in "${pids[@]}"; do kill -0 "$p" 2> /dev/null || die "a daemon exited (see the logs below)"; done
    sleep 1
done
case $state in idle*|mixed*|allocated*) ;; *) die "node $host is '${state:-unknown}' after 60 s" ;; esac
say "slurmctld (pid ${pids[1]}) and slurmd (pid ${pids[2]}) up; node $host is $state"
stage_done daemons

# --- the reference: the same sweep unsharded -----------------------------------------------
plot=()
command -v gnuplot > /dev/null && plot=(--plot)
say "unsharded: ssgraph bench $graph ${sweep[*]} ${plot[*]} --threads 1"
"$bin" bench "$graph" "${sweep[@]}" "${plot[@]}" --threads 1 --out "$scratch/unsharded" -q ||
    die "the unsharded bench failed"
stage_done unsharded

# --- submit, wait --------------------------------------------------------------------------
out=$scratch/out
wait_jobs() {    # job ids...: wait until none is queued or running, then print their states
    local deadline=$(( $(date +%s) + timeout )) ids
    ids=$(IFS=,; echo "$*")
    while [ -n "$(squeue -h -j "$ids" -o %i 2> /dev/null)" ]; do
        [ "$(date +%s)" -lt "$deadline" ] || die "jobs $ids still queued after $timeout s:
$(squeue -j "$ids")"
        sleep 1
    done
    local j
    for j in "$@"; do
        scontrol -o show job "$j" | tr ' ' '\n' | awk -F= -v j="$j" '
            $1 == "JobId" { id = $2 } $1 == "ArrayJobId" { id = $2 } $1 == "ArrayTaskId" { id = id "_" $2 }
            $1 == "JobState" { st = $2 } $1 == "ExitCode" { print "  job " id ": " st " exit " $2 }'
    done
}
read_jobs() {    # the job ids submit-bench.sh wrote to OUT/jobs
    array=$(sed -n 's/^array=//p' "$out/jobs")
    merge=$(sed -n 's/^merge=//p' "$out/jobs")
    if [ -z "$array" ] || [ -z "$merge" ]; then die "no job ids in $out/jobs"; fi
}
all_completed() {    # job ids...: every job (and array task) COMPLETED
    local j info
    for j in "$@"; do
        info=$(scontrol -o show job "$j") || return 1
        [ -n "$info" ] || return 1
        if grep -v -q 'JobState=COMPLETED' <<< "$info"; then return 1; fi
    done
}

say "submitting: tools/slurm/submit-bench.sh -n $shards -c 1 -t 00:10:00 -o $out -- $graph ${sweep[*]} ${plot[*]}"
SSGRAPH_BIN=$bin tools/slurm/submit-bench.sh -n "$shards" -c 1 -t 00:10:00 -o "$out" -- \
    "$graph" "${sweep[@]}" "${plot[@]}"
read_jobs
jobs_to_cancel="$array $merge"
stage_done submit

say "waiting for array job $array and merge job $merge (squeue, at most $timeout s)"
wait_jobs "$array" "$merge"
all_completed "$array" "$merge" || die "a job did not complete"
stage_done "shards and merge on Slurm"

# --- check ---------------------------------------------------------------------------------
compare() {    # unsharded merged: same rows, values, status, metrics; timings aside
    python3 - "$1" "$2" <<'EOF'
import csv, json, os, sys
a, b = sys.argv[1], sys.argv[2]
timing = ("frame_avg_ms", "frame_median_ms", "frame_min_ms", "frame_max_ms", "node_ms",
          "node_median_ms", "node_min_ms", "node_max_ms")
def rows(d):
    with open(os.path.join(d, "bench.csv"), newline="") as f:
        r = list(csv.reader(f))
    keep = [i for i, h in enumerate(r[0]) if h not in timing]
    return [[row[i] for i in keep] for row in r]
def cells(d):
    with open(os.path.join(d, "bench.json")) as f:
        j = json.load(f)
    return j, [{k: v for k, v in c.items() if k not in timing} for c in j["cells"]]
ra, rb = rows(a), rows(b)
if ra[0] != rb[0]:
    sys.exit("bench.csv headers differ:\n  %s\n  %s" % (ra[0], rb[0]))
if len(ra) != len(rb):
    sys.exit("bench.csv: %d rows unsharded, %d merged" % (len(ra) - 1, len(rb) - 1))
for x, y in zip(ra[1:], rb[1:]):
    if x != y:
        sys.exit("bench.csv rows differ (timings aside):\n  unsharded %s\n  merged    %s" % (x, y))
ja, ca = cells(a)
jb, cb = cells(b)
if ca != cb:
    sys.exit("bench.json cells differ (timings aside)")
if ja.get("sweeps") != jb.get("sweeps"):
    sys.exit("bench.json sweeps differ: %s / %s" % (ja.get("sweeps"), jb.get("sweeps")))
statuses = sorted(set(r[ra[0].index("status")] for r in ra[1:]))
nmetrics = sum(len(c.get("metrics", {})) for c in ca)
print("  %d rows, columns %s; status %s; %d metric values equal" %
      (len(ra) - 1, ",".join(ra[0]), "/".join(statuses), nmetrics))
EOF
}
check_merged() {
    local f
    for f in bench.csv bench.json bench.md; do
        [ -s "$out/merged/$f" ] || die "merged/$f missing"
    done
    for f in "$scratch"/unsharded/*.png; do
        [ -e "$f" ] || continue
        [ -s "$out/merged/$(basename "$f")" ] || die "merged/$(basename "$f") missing (the unsharded run has it)"
    done
    compare "$scratch/unsharded" "$out/merged" || die "merged differs from unsharded"
    say "merged equals unsharded: $(cd "$out/merged" && echo *)"
}
for i in $(seq 0 $((shards - 1))); do
    say "shard $i: $(( $(wc -l < "$out/shard-$i/bench.csv") - 1 )) rows"
done
check_merged
stage_done check

# --- a lost shard: the merge refuses, rerun it alone, merge again ---------------------------
say "removing shard-2: the merge must refuse and name it"
rm -rf "$out/shard-2" "$out/merged"
if SSGRAPH_BIN=$bin SSGRAPH_SHARDS=$shards SSGRAPH_OUT=$out tools/slurm/bench-merge.sh \
        > "$scratch/log/merge-missing.txt" 2>&1; then
    die "the merge of 3 shards out of 4 succeeded"
fi
sed 's/^/  | /' "$scratch/log/merge-missing.txt"
grep -q -e 'shard-2' -e "shard 2/$shards" "$scratch/log/merge-missing.txt" ||
    die "the merge's error does not name shard 2"
[ ! -e "$out/merged/bench.csv" ] || die "the refused merge wrote merged/bench.csv"
say "rerunning shard 2 alone: submit-bench.sh --only 2"
SSGRAPH_BIN=$bin tools/slurm/submit-bench.sh -n "$shards" -c 1 -t 00:10:00 -o "$out" --only 2 -- \
    "$graph" "${sweep[@]}" "${plot[@]}"
read_jobs
jobs_to_cancel="$array $merge"
wait_jobs "$array" "$merge"
all_completed "$array" "$merge" || die "a job of the rerun did not complete"
check_merged
stage_done "rerun one shard"

ok=1
say "PASS in $(( $(date +%s) - t_start )) s (repository $repo)"
