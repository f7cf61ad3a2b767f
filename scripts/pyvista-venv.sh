#!/bin/sh
# Makes (or completes) a venv at DIR with PyVista over Debian's VTK, as
# docs/python.md describes: /usr/bin/python3 -m venv --system-site-packages,
# then the pinned packages of scripts/pyvista-requirements.txt without their
# dependencies, and a check that no second VTK got in.
set -eu
[ $# -eq 1 ] || { echo "usage: scripts/pyvista-venv.sh DIR" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
dir=$1
[ -x "$dir/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$dir"
"$dir/bin/python" -m pip install --quiet --disable-pip-version-check --no-deps \
  -r "$here/scripts/pyvista-requirements.txt"
if "$dir/bin/python" -m pip show --quiet vtk >/dev/null 2>&1; then
  echo "error: $dir has pip's vtk, a second VTK: remove it (pip uninstall vtk)" >&2
  exit 1
fi
