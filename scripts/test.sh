#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every CTest test.
# Select a subset with ctest arguments, e.g. `bash scripts/test.sh -L unit` or `-LE slow`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
