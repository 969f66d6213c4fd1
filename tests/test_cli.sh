#!/usr/bin/env bash
# The ssgraph command line from the outside: results do not depend on the thread count,
# single nodes run on EXR files, and bad input gets a located message, a non-zero exit and no output file.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_cli"

# --- help, version, listing ---
expect_exit 0 "usage: ssgraph" "$BIN" --help
expect_exit 0 "usage: ssgraph" "$BIN" run --help
expect_exit 0 "^ssgraph [0-9]+\.[0-9]+" "$BIN" --version
expect_exit 2 "usage: ssgraph" "$BIN"
expect_exit 2 "unknown command 'frobnicate'" "$BIN" frobnicate
expect_exit 0 "ssao" "$BIN" nodes
expect_exit 0 "radius +float +default 0.5" "$BIN" describe ssao
expect_exit 1 "unknown node 'nope'" "$BIN" describe nope
expect_exit 2 "--size expects" "$BIN" run graphs/ssao.graph --size 12x
expect_exit 2 "unknown option '--frob'" "$BIN" run graphs/ssao.graph --frob 1

# --- the option table (cli/options.c): the usage text lists every option under the commands
# it applies to, and each other command refuses it, naming the option, the command and those
# commands, with the usage exit status ---
"$BIN" --help > "$TMP/help.txt"
for opt in $(grep -oE '\.name = "--[a-z-]+"' cli/options.c | grep -oE -- '--[a-z-]+'); do
    grep -qE -- "^  (-[a-z], )?$opt( |$)" "$TMP/help.txt" || fail "the usage text lacks $opt"
done
awk '/^options of /{ g = $0; sub(/^options of /, "", g); sub(/:$/, "", g); gsub(/,| and /, " ", g); next }
     /^$/ { g = "" } /^  -/ && g != "" { o = ($1 ~ /,$/) ? $2 : $1; print o "|" g }' \
    "$TMP/help.txt" > "$TMP/opts.txt"
[ "$(wc -l < "$TMP/opts.txt")" -ge 20 ] || fail "the usage text lists $(wc -l < "$TMP/opts.txt") options"
while IFS='|' read -r opt cmds; do
    for cmd in run check node bench compare; do
        case " $cmds " in *" $cmd "*) continue ;; esac
        expect_exit 2 "option '$opt' does not apply to '$cmd' \(it is an option of [a-z, ]+\)" \
            "$BIN" $cmd x "$opt" 1
    done
done < "$TMP/opts.txt"
expect_exit 2 "option '--json' does not apply to 'run' \(it is an option of compare\)" \
    "$BIN" run graphs/ssao.graph --json
expect_exit 2 "option '--frames' does not apply to 'check' \(it is an option of run and bench\)" \
    "$BIN" check graphs/ssao.graph --frames 2

# --- what `run` prints, column for column as scripts (bench/bench.py) read it: a `wrote
# PATH` line per file as it is written, then the timing table of one frame, the profile of
# several, the metrics; --quiet none of it; nothing on stderr ---
"$BIN" run graphs/ssao.graph --size 64x48 --out "$TMP/table" > "$TMP/table.txt" 2> "$TMP/table.err" \
    || fail "table run: $(tail -3 "$TMP/table.err")"
grep -qE '^node +type +on +ms +gpu ms +xfer ms  why$' "$TMP/table.txt" || fail "run lost its table's header"
for row in "g +gbuffer" "k +halton" "ao +ssao" "b +bilateral" "img +combine" "out +write"; do
    grep -qE "^$row +cpu +[0-9]+\.[0-9]{2} +- +-  (first run|sink)$" "$TMP/table.txt" \
        || fail "run's table lacks /$row/"
done
grep -qE '^total +[0-9]+\.[0-9]{2} +\(64x48, [0-9]+ threads, peak images [0-9]+\.[0-9] MB\)$' \
    "$TMP/table.txt" || fail "run's table lacks its total: $(cat "$TMP/table.txt")"
awk '/^node / { t = 1; next } t && !/^total/ && (length($0) < 70 || substr($0, 67, 4) !~ /^[-0-9]  [a-z]$/) { bad = 1 } END { exit bad }' "$TMP/table.txt" \
    || fail "a row of run's table is not 67 characters wide before its why: $(cat "$TMP/table.txt")"
[ -s "$TMP/table.err" ] && fail "run printed to stderr: $(head -3 "$TMP/table.err")"
"$BIN" run graphs/ssao.graph --size 64x48 --frames 3 --out "$TMP/prof" > "$TMP/prof.txt" \
    || fail "profile run"
grep -qE '^node +type +on +calls +avg ms +min ms +max ms +share +gpu ms +prepare ms +GB/s +GFLOP/s +bound +%bound  why$' "$TMP/prof.txt" \
    || fail "run --frames lost its profile's header"
grep -qE '^frame +3( +[0-9]+\.[0-9]{2}){3} +100\.0%   \(64x48, [0-9]+ threads, [0-9]+\.[0-9] fps; median frame [0-9]+\.[0-9]{2} ms, [0-9]+\.[0-9] fps\)$' \
    "$TMP/prof.txt" || fail "the profile lacks its frame row: $(cat "$TMP/prof.txt")"
grep -qE '^  ao +ssao +cpu +3( +[0-9]+\.[0-9]{2}){3} +[0-9]+\.[0-9]% +- +[0-9]+\.[0-9]{2} +[0-9]+\.[0-9]{2} +([0-9]+\.[0-9]{2}|-) +(memory|compute|-) +([0-9]+%|-)  first run, input k ran x2$' \
    "$TMP/prof.txt" || fail "the profile lacks the pass ao under the frame"
grep -qE '^out +write +cpu +1( +[0-9]+\.[0-9]{2}){3} +- +- +[0-9]+\.[0-9]{2} +[0-9]+\.[0-9]{2} +([0-9]+\.[0-9]{2}|-) +(memory|compute|-) +([0-9]+%|-)  sink$' "$TMP/prof.txt" \
    || fail "the profile lacks the sink out after the frame"
"$BIN" run graphs/ao_error.graph --size 48x32 --out "$TMP/metrics" > "$TMP/metrics.txt" \
    || fail "metrics run"
grep -qE '^metrics of +name +value$' "$TMP/metrics.txt" || fail "run lost its metrics' header"
for m in rmse mae psnr ssim; do
    grep -qE "^c_ssao +$m +[-+0-9.e]+$" "$TMP/metrics.txt" || fail "run's metrics lack c_ssao $m"
done
"$BIN" run graphs/ssao.graph --size 32x24 --out "$TMP/quiet" --quiet > "$TMP/quiet.txt" 2>&1 \
    || fail "quiet run"
[ -s "$TMP/quiet.txt" ] && fail "run --quiet printed: $(head -3 "$TMP/quiet.txt")"
for f in ssao.exr ssao.png; do
    grep -qx "wrote $TMP/table/$f" "$TMP/table.txt" || fail "run did not name $f"
done
[ "$(grep -c '^wrote ' "$TMP/table.txt")" -eq 2 ] || fail "run named other files than its two"

# --- a graph's scene line naming a missing file is reported at that line ---
printf 'scene "nosuch.scene"\nsize 64 48\ng = gbuffer()\nout = write(g.direct, "x")\n' \
    > "$TMP/noscene.graph"
expect_exit 1 "noscene.graph:1:7: error: cannot read the scene file '.*nosuch.scene'" \
    "$BIN" run "$TMP/noscene.graph" --out "$TMP/noscene"
[ ! -e "$TMP/noscene" ] || fail "a graph without its scene wrote $TMP/noscene"

# --- the node reference is generated from the descriptors and must be current ---
"$BIN" docs | diff -u docs/nodes.md - > "$TMP/docs.diff" \
    || fail "docs/nodes.md is stale: run '$BIN docs > docs/nodes.md' ($(head -c 300 "$TMP/docs.diff"))"
"$BIN" docs scenes | diff -u docs/scenes.md - > "$TMP/scenes.diff" \
    || fail "docs/scenes.md is stale: run '$BIN docs scenes > docs/scenes.md' ($(head -c 300 "$TMP/scenes.diff"))"
grep -q '^## mesh$' docs/scenes.md && grep -q '| `scale` |' docs/scenes.md \
    || fail "docs/scenes.md lacks the mesh entity's scale parameter"
expect_exit 2 "unknown reference 'bogus' \(expected nodes or scenes\)" "$BIN" docs bogus

# Every graph end to end (check, run, metrics over frames) is a ctest case of its own:
# tests/graphs/run.sh, registered per graph file in tests/CMakeLists.txt.

# --- ssao_unfiltered shows the unfiltered occlusion: its ao layer is ao_raw, no filter runs ---
"$BIN" run graphs/ssao_unfiltered.graph --size 64x40 --out "$TMP/unf" > "$TMP/unf.log" 2>&1 \
    || fail "ssao_unfiltered run: $(tail -3 "$TMP/unf.log")"
grep -q bilateral "$TMP/unf.log" && fail "ssao_unfiltered still runs the bilateral filter"
oiiotool "$TMP/unf/ssao_unfiltered.exr" --ch ao.Y -o "$TMP/unf_ao.exr" \
    && oiiotool "$TMP/unf/ssao_unfiltered.exr" --ch ao_raw.Y --chnames ao.Y -o "$TMP/unf_raw.exr" \
    && oiiotool "$TMP/unf_ao.exr" "$TMP/unf_raw.exr" --fail 0 --diff > /dev/null \
    || fail "ssao_unfiltered's ao layer is not the unfiltered ao_raw"

# --- determinism: same bytes with 1 and 2 threads, and across runs ---
"$BIN" run graphs/ssao.graph --size 160x90 --threads 1 --out "$TMP/t1" --quiet || fail "t1 run"
"$BIN" run graphs/ssao.graph --size 160x90 --threads 2 --out "$TMP/t2" --quiet || fail "t2 run"
"$BIN" run graphs/ssao.graph --size 160x90 --threads 2 --out "$TMP/t3" --quiet || fail "t3 run"
for f in ssao.exr ssao.png; do
    cmp -s "$TMP/t1/$f" "$TMP/t2/$f" || fail "$f differs between 1 and 2 threads"
    cmp -s "$TMP/t2/$f" "$TMP/t3/$f" || fail "$f differs between two identical runs"
done
"$BIN" run graphs/ssao.graph --size 160x90 --seed 7 --out "$TMP/s7" --quiet || fail "seed run"
cmp -s "$TMP/t1/ssao.exr" "$TMP/s7/ssao.exr" && fail "--seed 7 gave the same bytes as seed 1"

# --- EXR compression: uncompressed is larger but holds the same layers ---
"$BIN" run graphs/ssao.graph --size 160x90 --set out.compression=none --out "$TMP/raw" --quiet \
    || fail "compression=none run"
[ "$(stat -c %s "$TMP/raw/ssao.exr")" -gt "$(stat -c %s "$TMP/t1/ssao.exr")" ] \
    || fail "compression=none did not give a larger EXR than zip"
expect_exit 0 "wrote" "$BIN" node bilateral --in "in=$TMP/raw/ssao.exr:ao" \
    --in "depth=$TMP/raw/ssao.exr:depth" --out "$TMP/raw_node"

# --- overrides from the command line ---
"$BIN" run graphs/ssao.graph --size 64x40 --set out.name='"renamed"' --out "$TMP/ov" --quiet \
    || fail "override run"
[ -f "$TMP/ov/renamed.exr" ] || fail "--set out.name did not rename the output"
expect_exit 1 "<command line --set>:1:11: error: .*radius" \
    "$BIN" check graphs/ssao.graph --set ao.radius=abc
expect_exit 1 "unknown parameter or input 'radus'" \
    "$BIN" check graphs/ssao.graph --set ao.radus=1

# --- --lights and the graph's `lights` line relight the scene: same geometry, other light ---
"$BIN" run graphs/ssdo.graph --size 48x32 --out "$TMP/own" --quiet || fail "ssdo run"
"$BIN" run graphs/ssdo.graph --size 48x32 --lights examples/lights/sky.scene --out "$TMP/sky" \
    --quiet || fail "--lights run"
printf 'include "%s/graphs/ssdo.graph"\nlights "%s/examples/lights/sky.scene"\n' "$PWD" "$PWD" \
    > "$TMP/sky.graph"
"$BIN" run "$TMP/sky.graph" --size 48x32 --out "$TMP/skyline" --quiet || fail "lights line run"
cmp -s "$TMP/own/ssdo.exr" "$TMP/sky/ssdo.exr" && fail "--lights changed nothing"
# the pixels (the headers name each run's graph and lights file: README, "EXR metadata")
oiiotool "$TMP/sky/ssdo.exr" "$TMP/skyline/ssdo.exr" --fail 0 --diff > /dev/null \
    || fail "the lights line differs from --lights"
printf 'environment(color=[1, 1, 1])\nsphere(radius=1)\n' > "$TMP/bad.lights"
expect_exit 1 "bad.lights:2:1: error: a lights file holds only point_light" \
    "$BIN" check graphs/ssdo.graph --lights "$TMP/bad.lights"
expect_exit 1 "scene .*courtyard.scene' relit by '.*sun.scene' has no environment light" \
    "$BIN" run graphs/hybrid_ssdo.graph --size 32x24 --lights examples/lights/sun.scene \
    --out "$TMP/nolight"

# --- one node alone on EXR layers of a full run ---
src="$TMP/t1/ssao.exr"
expect_exit 0 "wrote .*samples.exr" "$BIN" node halton --set count=8 --out "$TMP/node"
expect_exit 0 "wrote .*out.exr" "$BIN" node ssao --in "position=$src:position" \
    --in "normal=$src:normal" --in "kernel=$TMP/node/samples.exr" --set radius=0.4 \
    --out "$TMP/node"
expect_exit 1 "needs input 'normal'" "$BIN" node ssao --in "position=$src:position" \
    --in "kernel=$TMP/node/samples.exr" --out "$TMP/node_missing"
expect_exit 1 "input 'normal' of node 'ssao' expects vector.*got 1 channels" "$BIN" node ssao \
    --in "position=$src:position" --in "normal=$src:depth" \
    --in "kernel=$TMP/node/samples.exr" --out "$TMP/node_channels"
[ -e "$TMP/node_missing" ] && fail "a failed node run created its output directory"

# --- bad input: located message, exit 1, nothing written ---
expect_exit 1 "cannot open" "$BIN" run "$TMP/does_not_exist.graph" --out "$TMP/none"
printf 'scene "%s/tests/fixtures/broken_gltf.scene"\ng = gbuffer()\nout = write(g.direct, "x")\n' \
    "$PWD" > "$TMP/broken.graph"
expect_exit 1 "broken_gltf\.scene:3:6: error: .*broken\.gltf: .*parse error" \
    "$BIN" run "$TMP/broken.graph" --out "$TMP/broken_out"
expect_exit 1 "broken_gltf\.scene:3:6: error: .*broken\.gltf" \
    "$BIN" check tests/fixtures/broken_gltf.scene
[ -e "$TMP/broken_out/x.exr" ] && fail "a failed run left x.exr behind"
expect_exit 1 "corrupt.exr.*error" "$BIN" node bilateral --in "in=tests/fixtures/corrupt.exr" \
    --in "depth=tests/fixtures/corrupt.exr" --out "$TMP/corrupt_out"
[ -e "$TMP/corrupt_out" ] && fail "a corrupt input still produced output"
# A bad environment image: not a lat-long probe (halton's 16 x 1 kernel), or not an image.
"$BIN" node halton --set count=16 --out "$TMP/notprobe" > /dev/null || fail "halton failed"
for img in "$TMP/notprobe/samples.exr" "$PWD/tests/fixtures/garbage.png"; do
    printf 'plane(center=[0, 0, 0], normal=[0, 1, 0], size=[1, 0, 1])\nenvironment(image="%s")\n' \
        "$img" > "$TMP/badenv.scene"
    printf 'scene "%s/badenv.scene"\ng = gbuffer()\nout = write(g.environment, "x")\n' \
        "$TMP" > "$TMP/badenv.graph"
    expect_exit 1 "$(basename "$img").*error: .*(lat-long light probe|cannot|not)" \
        "$BIN" run "$TMP/badenv.graph" --out "$TMP/badenv_out"
    [ -e "$TMP/badenv_out/x.exr" ] && fail "a bad environment image still produced output"
done
# A layer of another size than the main image is refused by check, before anything runs.
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\nd = downsample(depth=g.depth, position=g.position, normal=g.normal, albedo=g.albedo)\nout = write(g.direct, "x", half=d.depth)\n' \
    "$PWD" > "$TMP/half.graph"
expect_exit 1 "half.graph:4:33: error: input 'half' of node 'out' \(write\) is 640x360, but its first input 'g.direct' is 1280x720" \
    "$BIN" check "$TMP/half.graph"
# The a-trous filter's pass count is bounded (8 passes reach 510 px each side).
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\nf = atrous(g.depth, depth=g.depth, iterations=9)\nout = write(f.out, "x")\n' \
    "$PWD" > "$TMP/atrous.graph"
expect_exit 1 "atrous.graph:3:47: error: parameter 'iterations' of 'f' expects an integer in \[1, 8\] passes, got 9" \
    "$BIN" run "$TMP/atrous.graph" --out "$TMP/atrous_out"
[ -e "$TMP/atrous_out/x.exr" ] && fail "a refused atrous graph still wrote output"
printf 'g = gbuffer()\nout = write(g.direct, "x"\n' > "$TMP/syntax.graph"
expect_exit 1 "syntax.graph:3:1: error: expected '\)' to close the '\(' of line 2, column 12" \
    "$BIN" check "$TMP/syntax.graph"

# Hybrid AO: shadow maps of another light list, maps too large for memory, and a scene
# without an environment to make lights from.
cat > "$TMP/hybrid_bad.graph" <<EOF
scene "$PWD/examples/courtyard.scene"
g  = gbuffer()
a  = lightprobe(count=16)
b  = lightprobe(count=32)
sm = shadowmaps(b.lights, resolution=64)
pl = probe_light(g.position, g.normal, g.albedo, a.lights, shadowmaps=sm.maps)
out = write(pl.out, "x")
EOF
expect_exit 1 "hybrid_bad.graph:6:6: error: .*shadowmaps has 32 maps but lights has 16" \
    "$BIN" check "$TMP/hybrid_bad.graph"
sed -i 's/resolution=64/resolution=4096/; s/count=32/count=2048/' "$TMP/hybrid_bad.graph"
expect_exit 1 "hybrid_bad.graph:5:6: error: .*2048 maps of 4096 x 4096 need 128.0 GiB" \
    "$BIN" check "$TMP/hybrid_bad.graph"
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\nlp = lightprobe()\npl = probe_light(g.position, g.normal, g.albedo, lp.lights)\nout = write(pl.out, "x")\n' \
    "$PWD" > "$TMP/noenv.graph"
expect_exit 1 "lightprobe 'lp': scene .*cornell.scene' has no environment light" \
    "$BIN" run "$TMP/noenv.graph" --size 32x24 --out "$TMP/noenv_out"
[ -e "$TMP/noenv_out/x.exr" ] && fail "a run without an environment still produced output"

# --frames: a node runs in every frame where something it reads changes (here halton's
# samples turn, so ssao and what follows run N times; the G-buffer of a still camera runs
# once and is kept; the write runs in the last frame only), prepared once, and the profile
# lists each with its calls and why; --profile-json writes the same numbers. The
# samples move from frame to frame (halton, docs/time.md): the last frame's image is not
# the one-frame image, and is the same on 1 thread as on 2.
expect_exit 0 "^frame +3 " "$BIN" run graphs/ssao.graph --size 64x48 --frames 3 \
    --out "$TMP/frames3" --profile-json "$TMP/frames3/profile.json"
"$BIN" run graphs/ssao.graph --size 64x48 --out "$TMP/frames1" --quiet || fail "one frame run"
cmp -s "$TMP/frames1/ssao.exr" "$TMP/frames3/ssao.exr" && fail "--frames 3 kept frame 0's samples"
"$BIN" run graphs/ssao.graph --size 64x48 --frames 3 --threads 1 --out "$TMP/frames3t1" \
    --quiet || fail "--frames 3 --threads 1"
cmp -s "$TMP/frames3t1/ssao.exr" "$TMP/frames3/ssao.exr" \
    || fail "--frames 3 depends on the thread count"
# A still camera: the separable filter (its scratch image, node.h's ssg_node_scratch) reads
# nothing a frame changes, so it runs once and its image stands: the one-frame image.
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\nf = bilateral(g.direct, depth=g.depth, normal=g.normal, size=9, separable=true)\nout = write(f.out, "sep")\n' \
    "$PWD" > "$TMP/separable.graph"
for f in 1 3; do
    "$BIN" run "$TMP/separable.graph" --size 48x32 --frames $f --out "$TMP/sframes$f" \
        --quiet || fail "separable.graph --frames $f"
done
cmp -s "$TMP/sframes1/sep.exr" "$TMP/sframes3/sep.exr" || fail "--frames 3 changed separable.graph"
python3 - "$TMP/frames3/profile.json" <<'PY' || fail "profile.json is wrong"
import json, sys
p = json.load(open(sys.argv[1]))
names = [n["name"] for n in p["nodes"]]
assert p["frames"] == 3 and names == ["g", "k", "ao", "b", "img", "out"], names
passes = [n for n in p["nodes"] if n["name"] != "out"]
assert all(n["calls"] + n["kept"] == 3 and n["min_ms"] <= n["avg_ms"] <= n["max_ms"] for n in passes)
calls = {n["name"]: (n["calls"], n["why"]) for n in p["nodes"]}
assert calls["g"] == (1, "first run, kept x2"), calls  # a still camera: nothing g reads changes
assert calls["k"] == (3, "first run, new frame x2") and calls["ao"][0] == 3, calls
assert p["nodes"][-1]["calls"] == 1 and p["nodes"][-1]["share"] is None  # write: last frame
work = sum(n["calls"] * n["avg_ms"] for n in passes)  # the frames' time is the passes'
assert abs(work - 3 * p["frame"]["avg_ms"]) < 0.05 * 3 * p["frame"]["avg_ms"], work
PY
expect_exit 2 "--frames expects an integer" "$BIN" run graphs/ssao.graph --frames 0
expect_exit 1 "nope/p.json.*cannot write profile" "$BIN" run graphs/ssao.graph --size 32x24 \
    --out "$TMP/frames_bad" --profile-json "$TMP/nope/p.json" --quiet

# --stereo: both eyes through the same graph into one multi-view EXR (left the default
# view, right.* the other) and a PNG per eye, the pair's time (more in test_exr_meta.sh).
expect_exit 0 "stereo 60x64 per eye, ipd 0.2: left .* ms \+ right .* ms = .* ms per stereo frame" \
    "$BIN" run graphs/ssao.graph --stereo --ipd 0.2 --size 60x64 --out "$TMP/stereo"
"$BIN" run graphs/ssao.graph --size 60x64 --out "$TMP/mono" --quiet || fail "mono run failed"
for f in ssao.exr ssao_left.png ssao_right.png; do
    [ -f "$TMP/stereo/$f" ] || fail "--stereo wrote no $f"
done
for eye in "" :right; do
    "$BIN" compare "$TMP/stereo/ssao.exr$eye" "$TMP/mono/ssao.exr" --json | grep -q '"rmse":0,' \
        && fail "the ${eye:-left} eye sees the mono view"
done
"$BIN" compare "$TMP/stereo/ssao.exr" "$TMP/stereo/ssao.exr:right" --json | grep -q '"rmse":0,' \
    && fail "both eyes see the same"
expect_exit 2 "--ipd expects a positive distance" "$BIN" run graphs/ssao.graph --stereo --ipd 0
# A killed stereo run's eye folders (its pid gone) are removed by the next one; a live
# process's are left alone.
sh -c 'exit 0' & dead=$!; wait $dead
mkdir -p "$TMP/stereo/.stereo-left-$dead" "$TMP/stereo/.stereo-right-$$"
touch "$TMP/stereo/.stereo-left-$dead/ssao.exr"
"$BIN" run graphs/ssao.graph --stereo --size 20x24 --out "$TMP/stereo" --quiet > /dev/null \
    || fail "second stereo run failed"
[ -e "$TMP/stereo/.stereo-left-$dead" ] && fail "a killed stereo run's eye folder was left"
[ -d "$TMP/stereo/.stereo-right-$$" ] || fail "a live process's eye folder was removed"

# Outputs never replace a non-regular file: text outputs stream into a FIFO or a character
# device, images refuse one with the reason.
mkfifo "$TMP/fifo"
cat "$TMP/fifo" > "$TMP/fifo.got" & reader=$!
"$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/special" --quiet \
    --profile-json "$TMP/fifo" || fail "--profile-json into a FIFO failed"
wait $reader
[ -p "$TMP/fifo" ] || fail "--profile-json replaced a FIFO"
grep -q '"nodes"' "$TMP/fifo.got" || fail "--profile-json wrote nothing into the FIFO"
if [ "$(id -u)" -eq 0 ] && mknod "$TMP/null" c 1 3 2> /dev/null; then
    "$BIN" dot graphs/ssao.graph -o "$TMP/null" || fail "dot -o a character device failed"
    [ -c "$TMP/null" ] || fail "dot -o replaced a character device"
fi
mkdir -p "$TMP/special2/ssao.exr"
expect_exit 1 "ssao.exr: error: cannot write an output here: it is a directory" \
    "$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/special2" --quiet

finish test_cli
