#!/usr/bin/env bash
# The include rule of docs/dev/architecture.md (*Layers*): a file includes only files of its own layer
# or of a lower one, and folders of one rank (aerodynamics and the MPI map; FE and equations; OpenFAST
# and .lin readers) do not include each other.
# Prints every `#include "…"` that breaks the rule as file:line: includes X (layer a -> b) and exits
# 1 if there is one; a source folder with no layer is an error too (give a new folder its layer here
# and in CMakeLists.txt). Run by CTest (test `layers_include_rule`, label unit).
# Usage: bash scripts/check-layers.sh [repository root]
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"

# folder -> layer rank × 10 (docs/dev/architecture.md, table *Layers*); within a layer the folders are
# ranked by their own targets' links: layer 0 base < aerodynamics, MPI map < model types < shapes; the
# readers of layer 2 text < OpenFAST, .lin < YAML cases
layer_of() {
  case "$1" in
    src/base/*) echo 0 ;;
    src/aero/*|src/parallel/*) echo 2 ;;
    src/model/*) echo 4 ;;
    src/shapes/*) echo 6 ;;
    src/fem/*|src/dynamics/*) echo 10 ;;
    src/io/text/*) echo 20 ;;
    src/io/openfast/*|src/io/lin/*) echo 21 ;;
    src/io/case/*) echo 22 ;;
    src/turbine/*) echo 30 ;;
    linearize/*) echo 40 ;;
    modal/*) echo 50 ;;
    src/writers/*) echo 60 ;;
    src/cli/*) echo 70 ;;
    python/src/*) echo 80 ;;
    *) echo "" ;;
  esac
}
# folders of one rank that must not include each other
peers() {
  case "$1" in
    src/fem/*) echo fem ;;
    src/dynamics/*) echo dynamics ;;
    src/aero/*) echo aerodynamics ;;
    src/parallel/*) echo "MPI/thread map" ;;
    src/io/openfast/*) echo "OpenFAST readers" ;;
    src/io/lin/*) echo ".lin readers" ;;
    *) echo "" ;;
  esac
}

status=0
while IFS= read -r -d '' file; do
  from=$(layer_of "$file")
  if [[ -z "$from" ]]; then
    echo "$file: folder has no layer (add it to scripts/check-layers.sh and CMakeLists.txt)"
    status=1
    continue
  fi
  while IFS=: read -r line target; do
    [[ -z "$line" ]] && continue
    to=$(layer_of "$target")
    [[ -z "$to" ]] && continue  # a header outside the layers (none today) or a relative include
    if (( to > from )); then
      echo "$file:$line: includes $target (rank $from -> $to, upward)"
      status=1
    elif (( to == from )) && [[ -n "$(peers "$file")" && -n "$(peers "$target")" && "$(peers "$file")" != "$(peers "$target")" ]]; then
      echo "$file:$line: includes $target (folders of one layer: $(peers "$file") -> $(peers "$target"))"
      status=1
    fi
  done < <(awk 'match($0, /^[ \t]*#[ \t]*include[ \t]*"[^"]*"/) {
                 s = substr($0, RSTART, RLENGTH); sub(/^[^"]*"/, "", s); sub(/"$/, "", s); print FNR ":" s }' "$file")
done < <(find src linearize modal python/src -type f \( -name '*.hpp' -o -name '*.hxx' -o -name '*.cpp' -o -name '*.h' \) -print0 | sort -z)
exit $status
