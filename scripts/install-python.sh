#!/usr/bin/env bash
# Makes `import whirl` work with the build's package (build/python/whirl, built by scripts/build.sh
# when WHIRL_BUILD_PYTHON is on) for Debian's /usr/bin/python3 and for the first python3 on PATH when
# that is another interpreter (a pyenv, a venv): a file whirl.pth in each interpreter's site-packages
# naming build/python. An interpreter that then cannot import numpy (a pyenv without it) gets Debian's
# dist-packages (numpy, pandas from Debian) on its path too, when it is the same Python version
# (the compiled modules there are built for it). Each interpreter is checked with `import whirl`.
# Run by scripts/main.sh. Usage: bash scripts/install-python.sh [build folder]
set -euo pipefail
cd "$(dirname "$0")/.."
package_dir="$(cd "${1:-build}/python" 2>/dev/null && pwd)" || {
  echo "install-python: no ${1:-build}/python (configure with -DWHIRL_BUILD_PYTHON=ON)" >&2; exit 1; }
debian_dist=/usr/lib/python3/dist-packages

interpreters=()
[ -x /usr/bin/python3 ] && interpreters+=("$(/usr/bin/python3 -c 'import sys; print(sys.executable)')")
if command -v python3 >/dev/null 2>&1; then
  other="$(python3 -c 'import sys; print(sys.executable)' 2>/dev/null || true)"
  if [ -n "$other" ] && [ "$(realpath "$other")" != "$(realpath /usr/bin/python3 2>/dev/null || true)" ]; then
    interpreters+=("$other")
  fi
fi

status=0
for py in "${interpreters[@]}"; do
  site="$("$py" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
  lines="$package_dir"
  # An earlier run's whirl.pth may be what makes numpy importable: judge the interpreter without it.
  rm -f "$site/whirl.pth" "$("$py" -c 'import site; print(site.getusersitepackages())')/whirl.pth"
  if ! PYTHONPATH="$package_dir" "$py" -c 'import numpy' >/dev/null 2>&1; then
    version='import sys; print(sys.version_info[:2])'
    same_version=False
    [ -x /usr/bin/python3 ] && [ "$("$py" -c "$version")" = "$(/usr/bin/python3 -c "$version")" ] && same_version=True
    if [ -d "$debian_dist" ] && [ "$same_version" = True ]; then
      lines="$lines"$'\n'"$debian_dist"
    else
      echo "install-python: $py has no numpy and is not Debian's Python version: install numpy and pandas for it" >&2
    fi
  fi
  if ! { mkdir -p "$site" && printf '%s\n' "$lines" > "$site/whirl.pth"; } 2>/dev/null; then
    site="$("$py" -c 'import site; print(site.getusersitepackages())')"  # not writable: the user's site
    mkdir -p "$site" && printf '%s\n' "$lines" > "$site/whirl.pth"
  fi
  if "$py" -c 'import whirl' 2>/dev/null; then
    echo "install-python: $site/whirl.pth: 'import whirl' works with $py"
  else
    echo "install-python: 'import whirl' fails with $py:" >&2
    "$py" -c 'import whirl' || true
    status=1
  fi
done
exit $status
