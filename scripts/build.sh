#!/bin/sh
# Configures (once) and builds meshpaint in build/ (Release).
# MESHPAINT_BUILD_DIR and extra cmake arguments (e.g. -DMESHPAINT_SANITIZE=ON)
# select another build.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${MESHPAINT_BUILD_DIR:-"$here/build"}
if [ ! -f "$build/CMakeCache.txt" ] || [ $# -gt 0 ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
fi
cmake --build "$build" -j"$(nproc)"
