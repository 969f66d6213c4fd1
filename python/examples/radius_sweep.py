#!/usr/bin/env python3
"""radius_sweep.py - the tutorial of docs/python.md: how far SSAO and HBAO are from
path-traced truth as their radius changes, on one loaded graph.

    python3 python/examples/radius_sweep.py --size 320x180 --plot sweep.png

graphs/ao_error.graph computes reference_ao (1024 rays a pixel) and compares every AO
method with it. It is loaded once; each radius is a `set` and a `run`, which runs only the
AO nodes, their filters and the compare nodes again: the G-buffer and the reference (most
of the time) are computed once. The truth counts occluders within max_distance 0.5; the
screen-space methods' error is lowest a little beyond that radius (0.55-0.65 on this box).
"""
import argparse
import time

import ssgraph


def sweep(graph_path, size, radii, rays):
    """[(radius, ssao_rmse, hbao_rmse)] over the radii, and the seconds it took."""
    rows = []
    start = time.perf_counter()
    with ssgraph.load(graph_path, size=size, sets={"ref.rays": rays}) as g:
        for r in radii:
            g.set("ao.radius", r).set("h.radius", r)
            m = g.run().metrics
            rows.append((r, m["c_ssao_filtered.rmse"], m["c_hbao_filtered.rmse"]))
    return rows, time.perf_counter() - start


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")  # no display needed
    import matplotlib.pyplot as plt
    radii, ssao, hbao = zip(*rows)
    fig, ax = plt.subplots(figsize=(6, 3.5), dpi=100)
    ax.plot(radii, ssao, "o-", label="ssao (filtered)")
    ax.plot(radii, hbao, "s-", label="hbao (filtered)")
    ax.axvline(0.5, color="gray", linestyle=":", label="reference max_distance")
    ax.set_xlabel("radius (scene units)")
    ax.set_ylabel("RMSE against reference_ao")
    ax.set_title("Cornell box: AO error over the radius")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--graph", default="graphs/ao_error.graph")
    p.add_argument("--size", default="320x180", help="WxH")
    p.add_argument("--count", type=int, default=20, help="radii from 0.1 to 1.0")
    p.add_argument("--rays", type=int, default=256, help="reference_ao rays a pixel")
    p.add_argument("--plot", help="write the plot here (PNG)")
    a = p.parse_args()
    radii = [0.1 + 0.9 * i / max(1, a.count - 1) for i in range(a.count)]
    rows, seconds = sweep(a.graph, a.size, radii, a.rays)
    print("radius  ssao_rmse  hbao_rmse")
    for r, s, h in rows:
        print("%6.3f  %9.5f  %9.5f" % (r, s, h))
    best = min(rows, key=lambda row: row[1])
    print("lowest ssao error at radius %.3f; %d runs in %.2f s" % (best[0], len(rows), seconds))
    if a.plot:
        plot(rows, a.plot)
        print("wrote", a.plot)


if __name__ == "__main__":
    main()
