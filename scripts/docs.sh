#!/usr/bin/env bash
# Builds the documentation site: Doxygen XML of the public headers, then Sphinx (MyST Markdown +
# Breathe) into BUILD/docs/html, every warning an error. Then checks every local link of README.md,
# CONTRIBUTING.md, CHANGELOG.md and the pages (scripts/check-doc-links.py).
#   bash scripts/docs.sh [BUILD_DIR]     (default build/; the HTML is in BUILD_DIR/docs/html)
# Debian packages: python3-sphinx python3-myst-parser python3-breathe doxygen, jupyter-nbconvert
# python3-ipykernel (scripts/install-deps.sh).
# Uses Debian's Python (/usr/bin/python3) explicitly: a python3 earlier on PATH may lack Sphinx.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
out="$build/docs"
py=/usr/bin/python3
rm -rf "$out/doxygen" "$out/html" "$out/doctrees" "$out/notebooks"
mkdir -p "$out/doxygen"
(cd "$root" && WHIRL_DOXYGEN_OUT="$out/doxygen" doxygen docs/Doxyfile)
# The example notebooks, executed with the built module and converted to Markdown pages with their
# figures (docs/user/examples/, not in git), and the Python API reference read from the built module's
# docstrings (sphinx.ext.autodoc imports build/python/whirl): both need the target whirl_python built.
bash "$root/scripts/run-notebooks.sh" "$build" --out "$out/notebooks" --markdown "$root/docs/user/examples" >/dev/null
PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}" WHIRL_DOXYGEN_XML="$out/doxygen/xml" "$py" -m sphinx -q -W --keep-going -b html \
  -d "$out/doctrees" "$root/docs" "$out/html"
"$py" "$root/scripts/check-doc-links.py" "$root"
echo "docs: $out/html/index.html"
