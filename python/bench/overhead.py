"""Benchmark (not a test) of the Python module (issue 44, *Numbers*; docs/dev/performance.md):

1. the overhead of the Python call over the C++ library for one NREL 5MW linearization: the wall time
   of ``Model.linearize(op)`` seen from Python minus the library's own time of the same call
   (``LinearModel.compute_seconds``, timed in C++ around exportSweep and linearize with the GIL
   released), so the computation's own scatter does not enter: what is left is argument conversion,
   the GIL release and re-acquisition, the result objects and the Python wrapper (freeing the result
   is left out of the timed call: a C++ caller frees its result too);
2. the cost of a trivial bound attribute, directly and through the wrapper;
3. a 23-wind-speed aeroelastic Campbell diagram (NREL 5MW, Main_Aero.fst, 3 … 25 m/s, 36 azimuths)
   from Python against ``whirl campbell --wind 3:1:25`` (process start, reading, writing the CSV/JSON
   files without the plot), best of 3 each, wall and CPU time (the CPU time is the steadier figure
   on a shared machine);
4. memory: RSS before and after N linearizations of the NREL 5MW in a loop (N = 10,000 by default),
   each result's arrays touched and dropped: growth means a leak (target < 10 MB).

Usage: PYTHONPATH=build/python /usr/bin/python3 python/bench/overhead.py [N]
"""
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import whirl

ROOT = pathlib.Path(__file__).resolve().parents[2]


def rss_mb() -> float:
    """Resident set size of this process [MB] (Linux /proc)."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    raise RuntimeError("no VmRSS in /proc/self/status")


def per_call(f, n: int) -> float:
    """Best of 5 runs of n calls, seconds per call."""
    best = float("inf")
    for _ in range(5):
        t = time.perf_counter()
        for _ in range(n):
            f()
        best = min(best, (time.perf_counter() - t) / n)
    return best


def costs(f, child: bool = False):
    """(wall, CPU) time of one call of f [s]; CPU of this process, or of its finished children
    (a subprocess): on a shared machine the CPU time is the steadier of the two."""
    who = resource.RUSAGE_CHILDREN if child else resource.RUSAGE_SELF

    def cpu():
        r = resource.getrusage(who)
        return r.ru_utime + r.ru_stime
    t, c = time.perf_counter(), cpu()
    f()
    return time.perf_counter() - t, cpu() - c


def overhead(model, op, azimuths: int, n: int):
    """(median library time, median and minimum overhead) of n calls of model.linearize [s]."""
    library, extra = [], []
    for _ in range(n):
        t = time.perf_counter()
        lin = model.linearize(op, azimuths=azimuths)
        wall = time.perf_counter() - t
        library.append(lin.compute_seconds)
        extra.append(wall - lin.compute_seconds)
        del lin  # freeing the result outside the timed call (C++ pays for it too)
    return statistics.median(library), statistics.median(extra), min(extra)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
    onshore = whirl.load(str(ROOT / "cases" / "nrel5mw" / "Main_Onshore.fst"))
    core = onshore._core
    print(f"trivial binding call (Model.name):        {1e6 * per_call(lambda: core.name, 100000):8.3f} us")
    print(f"Python wrapper property (Model.name):     {1e6 * per_call(lambda: onshore.name, 100000):8.3f} us")
    for rpm, azimuths in ((0, 1), (12, 36)):
        op = onshore.operating_point(rpm=rpm)
        onshore.linearize(op, azimuths=azimuths)  # warm-up
        lib, median, least = overhead(onshore, op, azimuths, 200 if azimuths == 1 else 40)
        print(f"NREL 5MW linearize, {rpm:2d} rpm, {azimuths:2d} azimuths: library {1e3 * lib:7.3f} ms, "
              f"Python call overhead {1e6 * median:6.1f} us (median), {1e6 * least:6.1f} us (min)")

    aero_deck = str(ROOT / "cases" / "nrel5mw" / "Main_Aero.fst")
    binary = os.environ.get("WHIRL_BINARY", str(ROOT / "build" / "whirl"))
    aero = whirl.load(aero_deck)
    py_wall, py_cpu = min(costs(lambda: aero.campbell(wind=range(3, 26), azimuths=36)) for _ in range(3))
    with tempfile.TemporaryDirectory() as out:
        cli = [binary, "campbell", aero_deck, "--wind", "3:1:25", "--azimuths", "36", "--no-plot", "--out", out]
        cli_wall, cli_cpu = min(costs(lambda: subprocess.run(cli, check=True, capture_output=True), child=True)
                                for _ in range(3))
    print(f"Campbell, 23 wind speeds, 36 azimuths: Python {py_wall:.3f} s wall, {py_cpu:.3f} s CPU; "
          f"CLI {cli_wall:.3f} s wall, {cli_cpu:.3f} s CPU (CPU {100 * (py_cpu / cli_cpu - 1):+.1f} %)")

    op = onshore.operating_point(rpm=0)
    for _ in range(100):  # allocator pools and caches settle first
        onshore.linearize(op, azimuths=1).A.sum()
    before = rss_mb()
    t = time.perf_counter()
    for k in range(n):
        lin = onshore.linearize(op, azimuths=1)
        _ = lin.A.sum() + lin.M.sum()  # views of the C++ result: freed with it
        if k == n // 2:
            half = rss_mb()
    after = rss_mb()
    print(f"RSS over {n} NREL 5MW linearizations ({time.perf_counter() - t:.1f} s): {before:.1f} -> {half:.1f} "
          f"(half way) -> {after:.1f} MB ({after - before:+.2f} MB)")


if __name__ == "__main__":
    main()
