#!/usr/bin/env bash
# Executes the example notebooks (examples/*.ipynb) with the built Python module, as a user would run
# them: jupyter nbconvert --execute, every cell, an error in any cell fails. The executed copies go to
# BUILD/examples/; with --markdown DIR they are also converted to Markdown (with their figures) into
# DIR, which is how the documentation site shows them (scripts/docs.sh).
#   bash scripts/run-notebooks.sh [BUILD_DIR] [--markdown DIR]
# Debian packages: jupyter-nbconvert python3-ipykernel (scripts/install-deps.sh). Debian's Python
# (/usr/bin/python3) runs nbconvert and, through ipykernel's own kernel, the notebooks.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
markdown=""
if [ "${2:-}" = "--markdown" ]; then markdown="$(realpath -m "$3")"; fi
py=/usr/bin/python3
[ -d "$build/python/whirl" ] || { echo "run-notebooks: no $build/python/whirl (build the target whirl_python)" >&2; exit 1; }
out="$build/examples"
mkdir -p "$out" "$build/jupyter-runtime"
export PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}"
export WHIRL_SOURCE_DIR="$root"
export JUPYTER_RUNTIME_DIR="$build/jupyter-runtime" IPYTHONDIR="$build/jupyter-runtime/ipython"
export PYDEVD_DISABLE_FILE_VALIDATION=1 MPLBACKEND=module://matplotlib_inline.backend_inline
notebooks=("$root"/examples/*.ipynb)
"$py" -m nbconvert --log-level=WARN --to notebook --execute --ExecutePreprocessor.timeout=300 \
  --output-dir "$out" "${notebooks[@]}"
if [ -n "$markdown" ]; then
  mkdir -p "$markdown"
  "$py" -m nbconvert --log-level=WARN --to markdown --output-dir "$markdown" "$out"/*.ipynb
fi
echo "run-notebooks: ${#notebooks[@]} notebooks executed into $out${markdown:+, Markdown in $markdown}"
