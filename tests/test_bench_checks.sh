#!/usr/bin/env bash
# test_bench_checks.sh - bench's names and outputs checked before any work (issue 42, item
# 5): `--merge A B --out A` would replace shard A's files; a misspelt --error metric was
# accepted; `--time nonode` was refused after the first cell, leaving its files; `run
# --profile-json DIR` failed after the images were written; two --scene with --plot ended
# in "nothing to plot" (the scenes, file names, were the plot's x axis). Each refusal
# names what is wrong and writes nothing.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_bench_checks"
T="timeout 60"
SWEEP=(graphs/ssao.graph --size 32x24 --frames 1 --sweep k.count=4,8)

# --merge into one of its shards: refused (by the folder itself, however spelt), the shard
# untouched.
$T "$BIN" bench "${SWEEP[@]}" --shard 0/2 -q --out "$TMP/a" || fail "shard 0 failed"
$T "$BIN" bench "${SWEEP[@]}" --shard 1/2 -q --out "$TMP/b" || fail "shard 1 failed"
before=$(md5sum "$TMP/a/bench.json")
for out in "$TMP/a" "$TMP/b/../a" "$TMP/link"; do
    ln -sfn "$TMP/a" "$TMP/link"
    expect_exit 1 "--out .* is the shard folder .*/a: the joined tables would replace" \
        $T "$BIN" bench --merge "$TMP/a" "$TMP/b" --out "$out"
done
[ "$(md5sum "$TMP/a/bench.json")" = "$before" ] || fail "--merge --out A changed shard A"
expect_exit 0 "merged 2 shards: 2 cells" $T "$BIN" bench --merge "$TMP/a" "$TMP/b" \
    --out "$TMP/merged"
# --merge runs nothing: an option it would ignore (a misspelt --error among them) is refused,
# and nothing is written.
for opt in "--error c_ssao.rmsee" "--time ao" "--frames 3" "--size 8x8" "--set ao.radius=1" \
           "--reference ref.out" "--seed 3" "--scene examples/cornell.scene" "--threads 1"; do
    expect_exit 2 "it takes no ${opt%% *} \(only --out, --plot" \
        $T "$BIN" bench --merge "$TMP/a" "$TMP/b" $opt --out "$TMP/ignored"
done
[ -e "$TMP/ignored" ] && fail "a refused --merge wrote its --out"

# --error: a metric the node does not report, and a node that reports none or is none.
expect_exit 2 "--error 'c_ssao\.rsme': node 'c_ssao' \(compare\) reports no metric 'rsme' \(expected one of: rmse, mae, bias, psnr, ssim" \
    $T "$BIN" bench graphs/ao_error.graph --size 32x24 --frames 1 --sweep k.count=4 \
    --error c_ssao.rsme --out "$TMP/error1"
expect_exit 2 "--error 'ao\.rmse': expected NODE\.METRIC, NODE a node of .* that reports metrics \(one of: c_ssao, c_hbao" \
    $T "$BIN" bench graphs/ao_error.graph --size 32x24 --frames 1 --sweep k.count=4 \
    --error ao.rmse --out "$TMP/error2"
expect_exit 2 "--error 'rmse': expected NODE\.METRIC, .*none does: add a compare node" \
    $T "$BIN" bench "${SWEEP[@]}" --error rmse --out "$TMP/error3"
for d in error1 error2 error3; do [ -e "$TMP/$d" ] && fail "a refused --error wrote $d"; done
# bench_reference's metrics with --reference are a compare's.
expect_exit 2 "node 'bench_reference' \(compare\) reports no metric 'rmsd'" $T "$BIN" bench \
    graphs/ao_error.graph --size 32x24 --frames 1 --sweep k.count=4 --reference ref.out \
    --image aob.out --error bench_reference.rmsd --out "$TMP/error4"
[ -e "$TMP/error4" ] && fail "a refused --error wrote error4"

# --time nonode: refused before the first cell, with the graph's nodes, nothing written.
expect_exit 2 "--time 'nonode' is not a node of graphs/ssao.graph \(expected one of: g, k, ao, b, img, out\)" \
    $T "$BIN" bench "${SWEEP[@]}" --time nonode --out "$TMP/time"
[ -e "$TMP/time" ] && fail "a refused --time wrote $(ls -R "$TMP/time")"

# --profile-json DIR: refused before the run writes its images.
mkdir -p "$TMP/profile_dir"
expect_exit 1 "profile_dir: error: cannot write an output here: it is a directory" \
    $T "$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/profiled" -q \
    --profile-json "$TMP/profile_dir"
[ -e "$TMP/profiled" ] && fail "a refused --profile-json let the run write $(ls "$TMP/profiled")"
# ... and into a folder that does not exist: refused before the run too.
expect_exit 1 "nope/p.json: error: cannot write profile: its folder .*No such file" \
    $T "$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/profiled" -q \
    --profile-json "$TMP/nope/p.json"
[ -e "$TMP/profiled" ] && fail "a refused --profile-json let the run write $(ls "$TMP/profiled")"
# the --out folder itself, not made yet: it would be a folder when the profile is written
expect_exit 1 "--profile-json .*/newout/ names the --out folder itself" $T "$BIN" run \
    graphs/ssao.graph --size 32x24 -q --out "$TMP/newout" --profile-json "$TMP/newout/"
[ -e "$TMP/newout" ] && fail "a refused --profile-json let the run write $(ls "$TMP/newout")"
# ... but one in an --out the run makes is fine.
$T "$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/made/" -q \
    --profile-json "$TMP/made/p.json" && [ -s "$TMP/made/p.json" ] \
    || fail "--profile-json into a new --out failed"

# Two --scene with --plot: the first --sweep is the x axis, each scene a series.
if command -v gnuplot > /dev/null; then
    expect_exit 0 "wrote .*/plot/bench_ms.png" $T "$BIN" bench "${SWEEP[@]}" \
        --scene examples/cornell.scene --scene examples/gap.scene --plot --out "$TMP/plot"
    grep -q "scene=examples/gap.scene" "$TMP/plot/bench_ms.dat" \
        || fail "the scenes are not the plot's series: $(cat "$TMP/plot/bench_ms.dat")"
else
    echo "test_bench_checks: skipped the --plot case: gnuplot is not installed"
fi

finish test_bench_checks
