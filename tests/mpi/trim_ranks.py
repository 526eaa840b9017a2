#!/usr/bin/env python3
"""A command whose --wind trim is spread over MPI ranks (linearize/trim_schedule.cpp), run on one process
and on 2 ranks: the table TABLE must have the same rows in the same order (every text column equal:
wind speed, mode name, region) and every number equal to the trim's tolerance.

Why not byte-identical: on 2 ranks the second block of wind speeds starts its trim cold instead of from
its neighbour's balance (docs/user/mpi.md), so it lands on the same balance within the trim's tolerance
(TrimOptions::tolerance = 1e-9 of the rated torque) but not on the same bits. The rotor speed, pitch,
loads and frequencies follow the balance to about 1e-9 relative (measured: 1e-9 at most on the NREL
5-MW, cases/nrel5mw/Main_Aero.fst); RTOL leaves a factor 100 for their sensitivity to the torque.

Usage: trim_ranks.py MPIEXEC OUT TABLE WHIRL ARGS...   (OUT: a scratch folder; --out is added)
"""
import csv
import os
import shutil
import subprocess
import sys

RTOL = 1e-7
ATOL = 1e-10  # for values that are zero in one run (pitch below rated, a damping crossing zero)


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stdout}\n{p.stderr}")
    return p.stdout


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare(one, two):
    """The problems between the rows of two tables; none when they agree."""
    if len(one) != len(two):
        return [f"{len(one)} rows on one process, {len(two)} on 2 ranks"]
    problems = []
    for r, (a, b) in enumerate(zip(one, two)):
        if len(a) != len(b):
            problems.append(f"row {r}: {len(a)} columns against {len(b)}")
            continue
        for c, (x, y) in enumerate(zip(a, b)):
            fx, fy = number(x), number(y)
            if fx is None or fy is None:
                if x != y:
                    problems.append(f"row {r} column {c}: {x!r} against {y!r}")
            elif abs(fx - fy) > RTOL * max(abs(fx), abs(fy)) + ATOL:
                problems.append(f"row {r} column {c}: {x} against {y}")
    return problems


def main():
    mpiexec, out, table, whirl, *args = sys.argv[1:]
    shutil.rmtree(out, ignore_errors=True)
    run([whirl, *args, "--out", os.path.join(out, "one")])
    log = run([mpiexec, "-n", "2", "--oversubscribe", whirl, *args, "--out", os.path.join(out, "two")])
    if "on 2 MPI ranks" not in log:
        sys.exit(f"the 2-rank run did not run on 2 ranks:\n{log}")
    rows = [list(csv.reader(open(os.path.join(out, d, table)))) for d in ("one", "two")]
    if len(rows[0]) < 3:
        sys.exit(f"{table}: expected a header and rows, found {len(rows[0])} lines")
    problems = compare(*rows)
    if problems:
        sys.exit(f"{table} differs between 1 and 2 ranks:\n" + "\n".join(problems[:20]))
    print(f"{table}: {len(rows[0]) - 1} rows equal on 1 and 2 ranks within {RTOL:g} relative")


if __name__ == "__main__":
    main()
