#!/bin/sh
# One command from a fresh Debian 12 machine to every test: installs what is
# missing, builds, and runs the whole suite (unit, oracle, command line).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/install-deps.sh"
"$here/scripts/build.sh"
cd "$here/build"
exec ctest --output-on-failure -j"$(nproc)" "$@"
