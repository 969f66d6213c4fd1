"""No leak over 1000 runs, and what the bindings claim about threads."""
import threading

import numpy as np

import ssgraph


def rss_kib() -> int:
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def test_no_leak_over_1000_runs(repo):
    with ssgraph.load(repo / "graphs/ssao.graph", size=(32, 24)) as g:
        for i in range(200):  # warm up: allocator pools, first-touch pages
            g.set("ao.radius", 0.2 + 0.001 * i).run().output("b.out")
        before = rss_kib()
        for i in range(1000):
            g.set("ao.radius", 0.3 + 0.0001 * i)
            g.run().output("b.out")
            g.output("g.normal")
        grown = rss_kib() - before
    # 1000 runs, each handing out 4 images of 32x24: a leak of one image a run would be
    # 3 MiB and over; what is left is the allocator's noise (and the graph keeping each set
    # line, tens of bytes a set)
    assert grown < 1024, "RSS grew by %d KiB over 1000 runs" % grown


def test_threads_take_turns_with_right_results(repo):
    """Two threads running two graphs at once get the results of running them one after
    the other (the library's calls take turns; the GIL is free meanwhile)."""
    radii = [0.2, 0.6]
    alone = []
    for r in radii:
        with ssgraph.load(repo / "graphs/ssao.graph", size=(40, 30),
                          sets={"ao.radius": r}) as g:
            alone.append(g.run().output("b.out"))
    results = [None, None]
    ticks = []

    def work(i):
        with ssgraph.load(repo / "graphs/ssao.graph", size=(40, 30),
                          sets={"ao.radius": radii[i]}) as g:
            for _ in range(5):
                results[i] = g.run().output("b.out")
                g.set("b.size", 7).set("b.size", 9)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    while any(t.is_alive() for t in threads):  # Python keeps running during the runs
        ticks.append(1)
        threads[0].join(0.001)
    for t in threads:
        t.join()
    for i in range(2):
        assert np.array_equal(results[i], alone[i])
    assert len(ticks) > 1
