#!/usr/bin/env bash
# Configures and builds whirl (Release) into build/. Used by main.sh and test.sh.
# WHIRL_WERROR=ON in the environment makes warnings errors (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# ccache keys on paths relative to the repository root, so clones and worktrees share cached objects.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$PWD")}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DWHIRL_WERROR="${WHIRL_WERROR:-OFF}" > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)" 2>&1 | tail -n 3
