#!/usr/bin/env bash
# The house style (.clang-format) on every line changed since the baseline below: `git clang-format
# --diff` lists what clang-format would change in those lines; any change fails (the tree is not
# reformatted at once — it would collide with every open branch — so the rule applies to lines as they
# are written; docs/dev/conventions.md). Format yours with `git clang-format <baseline>` (or on staged
# changes, `git clang-format`). Needs git, a git checkout, and clang-format (Debian's clang-format).
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
baseline=810ceb5bf3afc68a9490fa7d2455fb1f9063c185
if ! command -v git-clang-format >/dev/null || ! git rev-parse --verify -q "$baseline^{commit}" >/dev/null; then
  echo "check-format: skipped (no git-clang-format, or no git history with $baseline)"
  exit 0
fi
out=$(git clang-format --diff "$baseline" -- '*.cpp' '*.hpp' '*.hxx' 2>&1) || true
if [ -z "$out" ] || echo "$out" | grep -q -e "^no modified files to format" -e "did not modify any files"; then
  echo "check-format: the lines changed since ${baseline:0:10} follow .clang-format"
  exit 0
fi
echo "$out"
echo "check-format: the lines above differ from .clang-format: run git clang-format $baseline" >&2
exit 1
