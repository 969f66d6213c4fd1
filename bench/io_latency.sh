#!/usr/bin/env bash
# io_latency.sh - how long a small run takes end to end, and how long the write node takes on
# a full frame (issue 28, item 7), for one ssgraph binary or two (before and after: their runs
# interleaved, so a load that comes and goes on the machine hits both alike). Prints the
# median and the minimum of each, the ratio of the medians, and the CPU seconds (user + sys)
# of the small run, which another process's load moves less than the wall clock. Measures;
# asserts nothing.
#
#   bench/io_latency.sh [-n RUNS] BIN [BIN_BEFORE]
#
#   small  `ssgraph run graphs/ssao.graph --size 160x90`, wall ms of the whole process
#   write  the `write` node's ms in the table of `ssgraph run graphs/ssao.graph` (1280x720,
#          18 channels: R,G,B, Z, ao, ao_raw, normal, position, albedo, direct)
#   probe  the same 1280x720 run lit by examples/lights/courtyard.scene: its probe is a DWAB
#          EXR, which only OpenImageIO reads, so both binaries load the module before the
#          run and the write node's ms is the writing alone, before as after
#   load   the one-off library loads the run's table lists (none when EXR and PNG are
#          built in)
# Each binary finds its OpenImageIO module next to itself. With -DSSGRAPH_BUILD_BENCH=ON the
# build also has io_micro (bench/io_micro.c: each EXR compression and the PNG alone).
set -u
runs=9
if [ "${1:-}" = "-n" ]; then runs=$2; shift 2; fi
bins=("$@")
[ ${#bins[@]} -ge 1 ] || { echo "usage: $0 [-n RUNS] BIN [BIN_BEFORE]" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now_ms() { date +%s%N | awk '{printf "%.3f", $1 / 1e6}'; }

# one_run K KIND: one run of binary K; appends "wall_ms cpu_s write_ms" to $work/K.KIND
one_run() {
    local k=$1 kind=$2 bin=${bins[$1]} t0 t1 size=()
    [ "$kind" = small ] && size=(--size 160x90)
    [ "$kind" = probe ] && size=(--lights examples/lights/courtyard.scene)
    t0=$(now_ms)
    /usr/bin/time -f "%U %S" -o "$work/time" "$bin" run graphs/ssao.graph "${size[@]}" \
        --out "$work/out$k" > "$work/log" 2>&1 || { echo "run failed: $(tail -3 "$work/log")" >&2; exit 1; }
    t1=$(now_ms)
    local cpu write load
    cpu=$(awk '{print $1 + $2}' "$work/time")
    write=$(awk '$2 == "write" {print $4}' "$work/log")
    load=$(awk '$1 == "load" {s += $NF} END {print s + 0}' "$work/log")
    echo "$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}') $cpu $write $load" >> "$work/$k.$kind"
}

for kind in small full probe; do
    n=$runs
    [ "$kind" != small ] && n=$(( (runs + 1) / 2 ))
    for ((i = 0; i < n; i++)); do
        for k in "${!bins[@]}"; do one_run "$k" "$kind"; done
    done
done

python3 - "$work" "${#bins[@]}" "${bins[@]}" <<'PY'
import statistics, sys
work, count, bins = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def col(k, kind, i):
    return [float(l.split()[i]) for l in open(f"{work}/{k}.{kind}")]
rows = [("small run, wall ms", "small", 0), ("small run, cpu s", "small", 1),
        ("small run, write ms", "small", 2), ("small run, load ms", "small", 3),
        ("1280x720, write ms", "full", 2), ("1280x720, load ms", "full", 3),
        ("probe-lit, write ms", "probe", 2), ("probe-lit, load ms", "probe", 3)]
names = ["after" if count > 1 and k == 0 else "before" if k == 1 else "binary"
         for k in range(count)]
print(f"{'':22}" + "".join(f"{n + ' median':>16}{'min':>10}" for n in names) +
      ("   before/after" if count > 1 else ""))
for label, kind, i in rows:
    med = [statistics.median(col(k, kind, i)) for k in range(count)]
    low = [min(col(k, kind, i)) for k in range(count)]
    line = f"{label:22}" + "".join(f"{m:16.3f}{l:10.3f}" for m, l in zip(med, low))
    if count > 1 and med[0] > 0 and med[1] > 0:
        line += f"   {med[1] / med[0]:8.2f}x"
    print(line)
print(f"({len(col(0, 'small', 0))} small runs and {len(col(0, 'full', 0))} full ones each; "
      + "; ".join(f"{n}: {b}" for n, b in zip(names, bins)) + ")")
PY
