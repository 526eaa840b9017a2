"""Benchmark (not a test) of the Python module (issue 44, *Numbers*):

1. the cost of a call through the binding: a trivial bound attribute (argument conversion, call,
   result conversion) and the same through the Python wrapper;
2. Model.linearize of a 2-DOF model and of the NREL 5MW at 12 rpm (36 azimuths, multiblade average:
   whirl export's path, plus the second-order M, C, K at the equilibrium);
3. RSS growth over N linearizations in a loop (leaks), each result's arrays touched.

Usage: PYTHONPATH=build/python /usr/bin/python3 python/bench/overhead.py [N]
"""
import pathlib
import resource
import sys
import time

import whirl

ROOT = pathlib.Path(__file__).resolve().parents[2]


def rss_mb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def per_call(f, n):
    best = float("inf")
    for _ in range(5):
        t = time.perf_counter()
        for _ in range(n):
            f()
        best = min(best, (time.perf_counter() - t) / n)
    return best


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
    small = whirl.load(str(ROOT / "cases" / "landbased_2dof" / "landbased_2dof.yaml"))
    core = small._core
    print(f"trivial binding call (Model.name):      {1e6 * per_call(lambda: core.name, 100000):8.3f} us")
    print(f"Python wrapper property (Model.name):   {1e6 * per_call(lambda: small.name, 100000):8.3f} us")
    print(f"linearize, 2 DOFs (wrapper + C++):      {1e6 * per_call(small.linearize, 2000):8.1f} us")
    onshore = whirl.load(str(ROOT / "cases" / "nrel5mw" / "Main_Onshore.fst"))
    op = onshore.operating_point(rpm=12)
    print(f"linearize, NREL 5MW 12 rpm, 36 azimuths: {1e3 * per_call(lambda: onshore.linearize(op), 5):8.2f} ms")
    small.linearize()
    before = rss_mb()
    for k in range(n):
        lin = small.linearize()
        _ = lin.A  # a view: the result must be freed with it
    after = rss_mb()
    print(f"RSS over {n} linearizations (2 DOFs):    {before:.1f} -> {after:.1f} MB ({after - before:+.2f} MB)")


if __name__ == "__main__":
    main()
