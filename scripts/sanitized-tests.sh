#!/usr/bin/env bash
# The C++ test suite under AddressSanitizer and UndefinedBehaviorSanitizer, in the one sanitized build
# the fuzz harnesses use (scripts/sanitized-build.sh, build-fuzz/): every CTest test without the `slow`
# label but the ones that check no C++ of whirl's (the docs build; the Python package, whose module an
# unsanitized python3 cannot load; the installed-tree consumer). A read out of bounds, a leak or undefined
# behaviour fails the test that hits it. The slow suites (97 s in the gcc build) ran over 20 min under
# ASan, past CTest's 25 min default timeout: run them with `bash scripts/sanitized-tests.sh -L slow`.
#
#   bash scripts/sanitized-tests.sh [CTEST ARGS...]     # default: the suite above, -j nproc
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
  nice -n 19 ctest --output-on-failure -j "$(nproc)" -LE 'docs|python|slow' -E '^install_consumer'
fi
echo "sanitized-tests.sh: tests under ASan + UBSan $(( $(date +%s) - start )) s"
