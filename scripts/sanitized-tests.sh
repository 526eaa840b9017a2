#!/usr/bin/env bash
# The C++ test suite under AddressSanitizer and UndefinedBehaviorSanitizer, in the one sanitized build
# the fuzz harnesses use (scripts/sanitized-build.sh, build-fuzz/): every CTest test but the ones that
# check no C++ of whirl's (the docs build, the Python package, whose module an unsanitized python3 cannot
# load, and the installed-tree consumer, which would compile a consumer under the sanitizers). A read
# out of bounds, a leak or undefined behaviour fails the test that hits it.
#
#   bash scripts/sanitized-tests.sh [CTEST ARGS...]     # default: the whole suite above, -j nproc
set -euo pipefail
cd "$(dirname "$0")/.."
out=${SANITIZED_BUILD_DIR:-build-fuzz}
SANITIZED_BUILD_DIR=$out bash scripts/sanitized-build.sh whirl whirl_unit_tests whirl_validation_tests whirl_cli_tests
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
cd "$out"
start=$(date +%s)
if [ $# -gt 0 ]; then
  nice -n 19 ctest --output-on-failure -j "$(nproc)" "$@"
else
  nice -n 19 ctest --output-on-failure -j "$(nproc)" -LE 'docs|python' -E '^install_consumer'
fi
echo "sanitized-tests.sh: tests under ASan + UBSan $(( $(date +%s) - start )) s"
