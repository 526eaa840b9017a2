#!/usr/bin/env bash
# The include rule of docs/dev/architecture.md (*Layers*), checked against the graph CMake builds the
# layers by: cmake/layer-graph.cmake writes, from each layer target's links, the folders each source
# folder may include (build/layers/graph.txt), so the rule has one source, CMakeLists.txt.
# Prints every `#include "…"` of a layer folder that points outside what its target links, as
# file:line: includes X (folder a may not include folder b), and exits 1 if there is one; a source
# folder of no layer is an error too (give a new folder to whirl_layer(...) in CMakeLists.txt).
# Run by CTest (test `layers_include_rule`, label unit).
# Usage: bash scripts/check-layers.sh [repository root] [graph file, default <root>/build/layers/graph.txt]
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
graph=${2:-build/layers/graph.txt}
if [[ ! -f "$graph" ]]; then
  echo "check-layers.sh: $graph: no layer graph (configure the build first: cmake -S . -B build)" >&2
  exit 2
fi

declare -A visible=()
folders=()
while IFS= read -r line; do
  [[ -z "$line" || "$line" == \#* ]] && continue
  folder=${line%%:*}
  visible[$folder]=" ${line#*: } "
  folders+=("$folder")
done < "$graph"
# Longest folder first, so src/io/openfast/aerodyn/x.hpp maps to src/io/openfast, not to src/io.
mapfile -t folders < <(printf '%s\n' "${folders[@]}" | awk '{ print length, $0 }' | sort -rn | cut -d' ' -f2-)

folder_of() {
  local f
  for f in "${folders[@]}"; do
    if [[ "$1" == "$f"/* ]]; then
      echo "$f"
      return
    fi
  done
}

status=0
while IFS= read -r -d '' file; do
  from=$(folder_of "$file")
  if [[ -z "$from" ]]; then
    echo "$file: folder has no layer (add it to whirl_layer(...) in CMakeLists.txt)"
    status=1
    continue
  fi
  while IFS=: read -r line target; do
    [[ -z "$line" ]] && continue
    to=$(folder_of "$target")
    [[ -z "$to" ]] && continue  # a header outside the layers (tests/support) or a relative include
    if [[ "${visible[$from]}" != *" $to "* ]]; then
      echo "$file:$line: includes $target (folder $from may not include $to: its target does not link that layer)"
      status=1
    fi
  done < <(awk 'match($0, /^[ \t]*#[ \t]*include[ \t]*"[^"]*"/) {
                 s = substr($0, RSTART, RLENGTH); sub(/^[^"]*"/, "", s); sub(/"$/, "", s); print FNR ":" s }' "$file")
done < <(find src linearize modal python/src -type f \( -name '*.hpp' -o -name '*.hxx' -o -name '*.cpp' -o -name '*.h' \) -print0 | sort -z)
exit $status
