#!/usr/bin/env bash
# Times a 200-point NREL 5MW Campbell sweep on 1 and on 2 MPI ranks and prints the speed-up.
# Usage: bash scripts/bench-mpi.sh [RANKS (default 2)] [RPM range (default 0.06:0.06:12, 200 points)]
# Both runs write their tables (no plot) under a temporary folder and are checked identical.
set -euo pipefail
cd "$(dirname "$0")/.."
ranks=${1:-2}
rpm=${2:-0.06:0.06:12}
whirl=${WHIRL:-build/whirl}
case=cases/nrel5mw/Main_Onshore.fst
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# One machine: shared-memory transport only. Without these OpenMPI probes its network transports
# (ofi, openib, tcp, ucx) in MPI_Init, which doubles its start-up (~0.45 s → ~0.25 s here).
# A value already set in the environment wins.
export OMPI_MCA_pml=${OMPI_MCA_pml:-ob1} OMPI_MCA_btl=${OMPI_MCA_btl:-self,vader}
now() { date +%s.%N; }
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
tp=$(now)
"$whirl" campbell "$case" --rpm "$rpm" --no-plot --out "$out/plain" > "$out/plain.log" 2>&1
t0=$(now)
mpirun -n 1 "$whirl" campbell "$case" --rpm "$rpm" --no-plot --out "$out/one" > "$out/one.log" 2>&1
t1=$(now)
mpirun -n "$ranks" --oversubscribe "$whirl" campbell "$case" --rpm "$rpm" --no-plot --out "$out/many" > "$out/many.log" 2>&1
t2=$(now)
s1=$(tail -n 1 "$out/one.log")
s2=$(tail -n 1 "$out/many.log")
echo "$s1"
echo "$s2"
cmp "$out/one/campbell.csv" "$out/many/campbell.csv" && cmp "$out/plain/campbell.csv" "$out/many/campbell.csv" &&
  echo "campbell.csv identical without mpirun, on 1 and on $ranks ranks"
# whirl's own figure: the sweep, tracking and output, after MPI/PETSc start-up.
sweep1=$(sed -E 's/.* ([0-9.]+) s.*/\1/' <<< "$s1")
sweep2=$(sed -E 's/.* ([0-9.]+) s.*/\1/' <<< "$s2")
awk -v p="$tp" -v a="$t0" -v b="$t1" -v c="$t2" -v n="$ranks" -v s1="$sweep1" -v s2="$sweep2" 'BEGIN {
  printf "wall clock, no mpirun (one process, no MPI at all): %.2f s; %d ranks vs it: %.2fx\n", a - p, n, (a - p) / (c - b)
  printf "wall clock (mpirun, MPI start-up included): 1 rank %.2f s, %d ranks %.2f s, speed-up %.2fx\n", b - a, n, c - b, (b - a) / (c - b)
  printf "sweep (whirl timer, after start-up):         1 rank %.2f s, %d ranks %.2f s, speed-up %.2fx\n", s1, n, s2, s1 / s2 }'
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
