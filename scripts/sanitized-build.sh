#!/usr/bin/env bash
# The one sanitized build (clang, ASan + UBSan, libFuzzer's coverage instrumentation) that serves both
# the fuzz harnesses (scripts/fuzz.sh) and the test suite under the sanitizers
# (scripts/sanitized-tests.sh): configures SANITIZED_BUILD_DIR (default build-fuzz) once, with the
# tests, then builds the targets named.
#
#   bash scripts/sanitized-build.sh TARGET...
#
# Runs under `nice -n 19` with SANITIZED_BUILD_JOBS (default 2) jobs; the log is <dir>.log.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${SANITIZED_BUILD_DIR:-build-fuzz}
bash scripts/install-deps.sh clang libclang-rt-14-dev > /dev/null
launcher=()
# ccache keys on paths relative to the folder above the repository (as scripts/build.sh), so a fresh
# clone (CI) reuses the objects of an earlier build on the same machine.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$PWD")}"
# The objects carry -gline-tables-only: without NOHASHDIR ccache keys on the build folder, so every
# worktree or clone would recompile the whole clang build (15 min on 2 cores).
export CCACHE_NOHASHDIR=1
# The coverage ignore list is named by its absolute path, which base-folder rewriting leaves alone:
# the flag stays out of the hash, the list's MD5 enters it as a definition (CMakeLists.txt).
export CCACHE_IGNOREOPTIONS="-fsanitize-coverage-ignorelist=*"
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
if [ ! -f "$out/CMakeCache.txt" ]; then
  nice -n 19 cmake -S . -B "$out" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DWHIRL_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only" \
    -DWHIRL_BUILD_TESTS=ON -DWHIRL_BUILD_BENCH=OFF "${launcher[@]}" > "$out.log" 2>&1 || { cat "$out.log"; exit 2; }
fi
start=$(date +%s)
if ! nice -n 19 cmake --build "$out" -j "${SANITIZED_BUILD_JOBS:-2}" --target "$@" >> "$out.log" 2>&1; then
  tail -n 30 "$out.log"; echo "sanitized-build.sh: build failed (log: $out.log)" >&2; exit 2
fi
echo "sanitized-build.sh: $* built in $(( $(date +%s) - start )) s"
