#!/usr/bin/env python3
"""view_latency.py - how quickly `ssgraph view` answers what the page does (issue 31's
acceptance: a parameter change shows its image within 150 ms, a camera drag keeps at least
10 updates a second). Starts the viewer, then times over HTTP, as the page does them:
  set      POST /api/set of a new value, then GET /api/image of the shown port (the page's
           whole round trip), which nodes ran, and the round trip over the time the nodes
           that ran took themselves (issue 46's acceptance: a median of at most 1.5x)
  drag     POST /api/camera with preview=1 (an orbit step), then the preview image: the
           updates a second a drag keeps
  release  POST /api/camera with preview=0, then the full image
  metrics  GET /api/metrics of the shown port against itself, as A and B (the A/B view's
           numbers after each run)
Prints the median, minimum and maximum of each, in ms. Measures; asserts nothing.

  bench/view_latency.py [--bin build/ssgraph] [--graph graphs/ssdo_realtime.graph]
                        [--size 640x360] [--param do.radius] [--values 0.3,0.4,...]
                        [--port img.out] [--runs 21] [--every-node]

--every-node times, instead, a change of one number parameter of every node that has one
(its first float, else its first int: the value moved a tenth of its slider's range up and
back), --runs changes each, and prints each node's median round trip over the time of the
nodes that ran, and the median over the nodes.
"""
import argparse
import json
import math
import re
import statistics
import subprocess
import sys
import time
import urllib.error
import urllib.request


def start(args):
    proc = subprocess.Popen([args.bin, "view", args.graph, "--size", args.size, "--threads",
                             str(args.threads)], stdout=subprocess.PIPE, text=True)
    line = proc.stdout.readline()
    m = re.search(r"http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]+)", line)
    if not m:
        proc.kill()
        sys.exit("the viewer printed no URL: %r" % line)
    return proc, "http://127.0.0.1:%s" % m.group(1), m.group(2)


def request(base, token, path, body=None):
    req = urllib.request.Request(base + path, data=body.encode() if body else None,
                                 headers={"X-SSG-Token": token})
    with urllib.request.urlopen(req, timeout=120) as r:
        return r.read()


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return (time.perf_counter() - t0) * 1000.0, out


def report(name, times):
    print("%-8s median %7.1f ms   min %7.1f   max %7.1f   (%d runs)" %
          (name, statistics.median(times), min(times), max(times), len(times)))


def orbit(camera, angle):
    """The camera turned by angle (radians) about its target's vertical axis."""
    p, t = camera["position"], camera["target"]
    dx, dz = p[0] - t[0], p[2] - t[2]
    c, s = math.cos(angle), math.sin(angle)
    pos = [t[0] + c * dx - s * dz, p[1], t[2] + s * dx + c * dz]
    fmt = lambda v: ",".join("%.6g" % x for x in v)
    return "position=%s&target=%s&up=%s&fov=%g" % (fmt(pos), fmt(t), fmt(camera["up"]),
                                                  camera["fov_y"])


def nudged(p):
    """Two values of number parameter p a tenth of its slider's range apart, or None."""
    lo, hi = p.get("soft_min"), p.get("soft_max")
    if lo is None or hi is None or not hi > lo:
        return None
    v = float(p["value"])
    step = (hi - lo) / 10
    w = v + step if v + step <= hi else v - step
    if p["type"] == "int":
        v, w = int(round(v)), int(round(w))
        if v == w:
            w = v + 1 if v + 1 <= hi else v - 1
        return [str(v), str(w)]
    return ["%.6g" % v, "%.6g" % w]


def every_node(base, token, args):
    """Per node: the median round trip over the ran nodes' time for its first number
    parameter; returns the medians."""
    state = json.loads(request(base, token, "/api/state"))
    medians = []
    for node in state["nodes"]:
        nums = [p for kind in ("float", "int") for p in node["params"] if p["type"] == kind]
        values = next((v for v in map(nudged, nums) if v), None)
        if not values:
            continue
        param = next(p for p in nums if nudged(p) == values)["name"]
        ratios, own = [], []
        for i in range(args.runs + 1):
            body = "%s.%s=%s" % (node["name"], param, values[(i + 1) % 2])
            try:
                ms, answer = timed(lambda: request(base, token, "/api/set", body))
            except urllib.error.HTTPError as e:  # a value the node's checks refuse here
                print("%-28s refused: %s" % (body, json.loads(e.read())["error"][:120]))
                break
            ms2, _ = timed(lambda: request(base, token, "/api/image?port=" + args.port))
            took = sum(n["ms"] for n in json.loads(answer)["nodes"] if n["ran"])
            if i and took > 0:
                ratios.append((ms + ms2) / took)
                own.append(took)
        if ratios:
            medians.append(statistics.median(ratios))
            print("%-28s nodes that ran %7.1f ms   round trip / that %.2fx" %
                  ("%s.%s" % (node["name"], param), statistics.median(own), medians[-1]))
    print("median over %d nodes: %.2fx" % (len(medians), statistics.median(medians)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default="build/ssgraph")
    ap.add_argument("--graph", default="graphs/ssdo_realtime.graph")
    ap.add_argument("--size", default="640x360")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--param", default="do.radius")
    ap.add_argument("--values", default="0.3,0.4,0.5,0.6")
    ap.add_argument("--port", default="img.out")
    ap.add_argument("--runs", type=int, default=21)
    ap.add_argument("--every-node", action="store_true",
                    help="one number parameter of every node (see above)")
    args = ap.parse_args()
    proc, base, token = start(args)
    if args.every_node:
        try:
            print("%s at %s, %d threads, %s shown" % (args.graph, args.size, args.threads,
                                                      args.port))
            every_node(base, token, args)
        finally:
            proc.terminate()
            proc.wait()
        return
    try:
        values = args.values.split(",")
        sets, drags, releases, ran, ratios, own = [], [], [], set(), [], []
        for i in range(args.runs):
            body = "%s=%s" % (args.param, values[i % len(values)])
            ms, state = timed(lambda: request(base, token, "/api/set", body))
            ms2, _ = timed(lambda: request(base, token, "/api/image?port=" + args.port))
            sets.append(ms + ms2)
            nodes = [n for n in json.loads(state)["nodes"] if n["ran"]]
            ran.add(" ".join(n["name"] for n in nodes))
            own.append(sum(n["ms"] for n in nodes))
            if i and own[-1] > 0:  # the first set may re-make what the start left undone
                ratios.append((ms + ms2) / own[-1])
        camera = json.loads(request(base, token, "/api/state"))["camera"]
        for i in range(args.runs):
            body = orbit(camera, 0.02 * (i + 1)) + "&preview=1"
            ms, _ = timed(lambda: request(base, token, "/api/camera", body))
            ms2, _ = timed(lambda: request(base, token, "/api/image?preview=1&port=" + args.port))
            drags.append(ms + ms2)
        for i in range(max(3, args.runs // 4)):
            body = orbit(camera, -0.02 * (i + 1)) + "&preview=0"
            ms, _ = timed(lambda: request(base, token, "/api/camera", body))
            ms2, _ = timed(lambda: request(base, token, "/api/image?port=" + args.port))
            releases.append(ms + ms2)
        q = "/api/metrics?ref=%s&a=%s&b=%s" % (args.port, args.port, args.port)
        metrics = [timed(lambda: request(base, token, q))[0] for _ in range(max(3, args.runs // 4))]
    finally:
        proc.terminate()
        proc.wait()
    print("%s at %s, %d threads; %s changes, %s shown" % (args.graph, args.size, args.threads,
                                                        args.param, args.port))
    report("set", sets)
    print("         nodes that ran: %s" % " | ".join(sorted(ran)))
    print("         their own time: median %.1f ms; round trip / their time: median %.2fx "
          "(min %.2f, max %.2f)" % (statistics.median(own), statistics.median(ratios),
                                    min(ratios), max(ratios)))
    report("drag", drags)
    print("         %.1f updates a second (median)" % (1000.0 / statistics.median(drags)))
    report("release", releases)
    report("metrics", metrics)


if __name__ == "__main__":
    main()
