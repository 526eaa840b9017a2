#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, ASan + UBSan) into build-fuzz/ and runs each for
# SECONDS (default 45) from its seed corpus (scripts/fuzz-seeds.sh: cases/, tests/data/, fuzz/seeds/).
#
#   bash scripts/fuzz.sh [SECONDS] [HARNESS...]     # default: every harness, one after the other
#   bash scripts/fuzz.sh --short                    # .ci/run: every harness for 20 s
#
# Per harness it prints executions, new findings (crash, timeout = a hang over 5 s, out-of-memory
# over 2 GB, leak) and libFuzzer's exit status; it exits non-zero when any harness found something,
# naming the reproducer (build-fuzz/findings/<harness>/crash-…). Re-run one with
#   build-fuzz/fuzz/<harness> build-fuzz/findings/<harness>/crash-…
# The corpus each run grows is kept in build-fuzz/corpus/<harness> for the next run.
# Everything runs under `nice -n 19`; the build uses FUZZ_BUILD_JOBS (default 2) jobs.
# FUZZ_RUNS=N also stops each harness after N executions. FUZZ_TIMEOUT=S counts an input as a hang
# after S seconds instead of 5: libFuzzer measures wall-clock time, and a niced campaign beside
# compiler jobs can stall that long on an input that runs in under a second on its own.
# The build is the one sanitized build of scripts/sanitized-build.sh (which also serves the test suite:
# scripts/sanitized-tests.sh); FUZZ_BUILD_DIR=DIR uses another folder configured with -DWHIRL_FUZZ=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-45}
if [ "$seconds" = --short ]; then seconds=20; fi
shift || true
out=${FUZZ_BUILD_DIR:-build-fuzz}
all=(fuzz_case_yaml fuzz_openfast_parse fuzz_fst fuzz_elastodyn fuzz_servodyn fuzz_ed_tower fuzz_ed_blade fuzz_lin
     fuzz_schedule fuzz_compare fuzz_tracking fuzz_aerodyn fuzz_ad_blade fuzz_airfoil fuzz_inflowwind fuzz_servodyn_aero
     fuzz_read_aerodyn fuzz_read_ad_blade fuzz_read_airfoil fuzz_read_inflowwind fuzz_read_servodyn fuzz_subdyn fuzz_read_beamdyn
     fuzz_read_case_yaml fuzz_read_fst fuzz_read_elastodyn fuzz_read_ed_tower fuzz_read_ed_blade
     fuzz_read_aerodyn14 fuzz_read_airfoil14 fuzz_read_wamit_ss fuzz_read_map fuzz_read_moordyn
     fuzz_read_hydrodyn fuzz_read_seastate fuzz_read_discon fuzz_rotor_performance
     fuzz_cli fuzz_study fuzz_simulate fuzz_writers)
harnesses=("${all[@]}")
if [ $# -gt 0 ]; then harnesses=("$@"); fi

SANITIZED_BUILD_DIR=$out SANITIZED_BUILD_JOBS=${FUZZ_BUILD_JOBS:-2} bash scripts/sanitized-build.sh "${harnesses[@]}"
bash scripts/fuzz-seeds.sh "$out/seeds" > /dev/null

# The harnesses' sandboxes (fuzz/fuzz_support.hpp, under TMPDIR) on tmpfs where there is one: the
# output writers fsync every file they commit, and on a disk busy with builds one fsync took over 5 s,
# which libFuzzer counts as a hang (the same input ran in 0.9 s on its own).
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
# Leaks are findings; OpenMPI is never started by the harnesses (no PETSc), so nothing to suppress.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
printf '%-16s %12s %10s %6s  %s\n' harness executions "exec/s" exit findings
for h in "${harnesses[@]}"; do
  corpus=$out/corpus/$h findings=$out/findings/$h log=$out/logs/$h.log
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  before=$(ls "$findings" | wc -l)
  # The tokenizer's seeds include 57 kB BeamDyn files: mutating those runs at a tenth of the speed.
  extra=()
  if [ "$h" = fuzz_openfast_parse ]; then extra=(-max_len=6000); fi
  set +e
  nice -n 19 "$out/fuzz/$h" "$corpus" "$out/seeds/$h" -max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-5}" -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$findings/" ${FUZZ_RUNS:+-runs=$FUZZ_RUNS} "${extra[@]}" > "$log" 2>&1
  rc=$?
  set -e
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  new=$(( $(ls "$findings" | wc -l) - before ))
  printf '%-16s %12s %10s %6s  %s\n' "$h" "${execs:-?}" "${rate:-?}" "$rc" "$new"
  if [ "$rc" -ne 0 ] || [ "$new" -ne 0 ]; then
    status=1
    grep -m 3 -E 'ERROR: |FINDING|runtime error|SUMMARY' "$log" | sed 's/^/    /' || true
    ls -t "$findings" | head -n 3 | sed "s|^|    reproducer: $findings/|"
    echo "    log: $log"
  fi
done
exit $status
