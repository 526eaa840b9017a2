#!/usr/bin/env bash
# What `whirl modes DECK` does with each public OpenFAST deck: a Markdown table on stdout, one row per
# primary file (runs, or the first line of the refusal), then the count of decks that run.
#
#   bash scripts/deck-table.sh [DECKS_DIR] [WHIRL] > docs/decks-table.md
#
# DECKS_DIR defaults to ../shared/data/decks (the collection described in its README.md); WHIRL to
# build/whirl. The offshore certification tests Test19–25 (HydroDyn, SubDyn, moorings) are left out.
set -uo pipefail
cd "$(dirname "$0")/.."
decks=${1:-../shared/data/decks}
whirl=${2:-build/whirl}
[ -d "$decks" ] || { echo "deck-table.sh: no folder $decks" >&2; exit 2; }
[ -x "$whirl" ] || { echo "deck-table.sh: no executable $whirl (build it first)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "| deck | \`whirl modes DECK\` |"
echo "|---|---|"
runs=0
total=0
while IFS= read -r fst; do
  rel=${fst#"$decks"/}
  case "$rel" in certtest/Test19* | certtest/Test2[0-5]*) continue ;; esac
  total=$((total + 1))
  if timeout 600 "$whirl" modes "$fst" > "$tmp/out" 2> "$tmp/err"; then
    runs=$((runs + 1))
    echo "| $rel | runs ($(grep -c . "$tmp/out") lines of modes) |"
  else
    code=$?
    # The message names files by their path under DECKS_DIR; cut that prefix and escape table pipes.
    reason=$(head -n 1 "$tmp/err" | sed -e "s|$decks/||g" -e 's/|/\\|/g')
    [ "$code" -eq 124 ] && reason="timed out after 600 s"
    echo "| $rel | refused (exit $code): $reason |"
  fi
done < <(find "$decks" -name '*.fst' | LC_ALL=C sort)
echo
echo "$runs of $total decks run."
