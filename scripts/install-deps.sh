#!/usr/bin/env bash
# Installs the Debian 12 packages whirl needs, only those missing. Idempotent; needs root (or sudo).
# Extra package names as arguments are installed too (scripts/fuzz.sh: clang libclang-rt-14-dev).
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libeigen3-dev liblapacke-dev liblapack-dev libblas-dev
  libpetsc-real-dev libslepc-real-dev libopenmpi-dev openmpi-bin
  gnuplot-nox libyaml-cpp-dev libcli11-dev libfmt-dev libmatio-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libsundials-dev  # IDA, the time integrator of whirl simulate
  ccache  # compiler cache: rebuilds on the same machine (CI, sessions) reuse objects
  clang-format git  # the style check of the tree (scripts/check-format.sh)
  python3-scipy  # the .mat export test loads the file with scipy.io.loadmat (skipped without it)
  python3-sphinx python3-myst-parser python3-breathe doxygen  # the documentation site: scripts/docs.sh
  # the Python module (python/, docs/user/python.md): pybind11, and what its package and tests use
  pybind11-dev python3-dev python3-pybind11 python3-numpy python3-pandas python3-pytest python3-xarray
  python3-matplotlib python3-yaml
  jupyter-nbconvert python3-ipykernel  # the example notebooks, executed by the tests and the docs (run-notebooks.sh)
  libjs-d3 libjs-three  # inlined into the interactive Campbell report (campbell --html, whirl report)
  chromium chromium-driver python3-selenium  # the report's test in headless Chromium (skipped without them)
  "$@"
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo_cmd apt-get update -qq
$sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
