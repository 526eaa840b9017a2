#!/usr/bin/env bash
# Executes the example notebooks (examples/*.ipynb) with the built Python module, as a user would run
# them: jupyter nbconvert --execute, every cell, an error in any cell fails. The executed copies go to
# OUT (default BUILD/examples); with --markdown DIR they are also converted to Markdown (with their
# figures) into DIR, which is how the documentation site shows them (scripts/docs.sh). Callers that
# may run at once (CTest runs the docs and python tests in parallel) give different OUT folders.
#   bash scripts/run-notebooks.sh [BUILD_DIR] [--out OUT] [--markdown DIR]
# Debian packages: jupyter-nbconvert python3-ipykernel (scripts/install-deps.sh). Debian's Python
# (/usr/bin/python3) runs nbconvert and, through ipykernel's own kernel, the notebooks.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
[ $# -gt 0 ] && shift
out="$build/examples"
markdown=""
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$(realpath -m "$2")"; shift 2 ;;
    --markdown) markdown="$(realpath -m "$2")"; shift 2 ;;
    *) echo "run-notebooks: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
py=/usr/bin/python3
[ -d "$build/python/whirl" ] || { echo "run-notebooks: no $build/python/whirl (build the target whirl_python)" >&2; exit 1; }
mkdir -p "$out/jupyter-runtime"
export PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}"
export WHIRL_SOURCE_DIR="$root"
export JUPYTER_RUNTIME_DIR="$out/jupyter-runtime" IPYTHONDIR="$out/jupyter-runtime/ipython"
export PYDEVD_DISABLE_FILE_VALIDATION=1 MPLBACKEND=module://matplotlib_inline.backend_inline
notebooks=("$root"/examples/*.ipynb)
"$py" -m nbconvert --log-level=WARN --to notebook --execute --ExecutePreprocessor.timeout=300 \
  --output-dir "$out" "${notebooks[@]}"
if [ -n "$markdown" ]; then
  mkdir -p "$markdown"
  rm -rf "$markdown"/*.md "$markdown"/*_files  # pages of notebooks since renamed go too
  "$py" -m nbconvert --log-level=WARN --to markdown --output-dir "$markdown" "$out"/*.ipynb
fi
echo "run-notebooks: ${#notebooks[@]} notebooks executed into $out${markdown:+, Markdown in $markdown}"
