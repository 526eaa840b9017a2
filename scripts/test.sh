#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every CTest test — first the gate (every
# test without the `slow` label: unit, CLI, docs build, layer and format checks, Python), then the slow
# ones, each with its time. Select a subset with ctest arguments instead, e.g. `bash scripts/test.sh -L
# unit` or `-LE slow`.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/build.sh
cd build
if [ $# -gt 0 ]; then
  ctest --output-on-failure -j "$(nproc)" "$@"
  exit 0
fi
gate=$(date +%s)
ctest --output-on-failure -j "$(nproc)" -LE slow
echo "test.sh: gate (build $(( gate - start )) s, tests without the slow label $(( $(date +%s) - gate )) s) passed"
slow=$(date +%s)
ctest --output-on-failure -j "$(nproc)" -L slow
echo "test.sh: slow tests $(( $(date +%s) - slow )) s; all $(( $(date +%s) - start )) s"
