#!/bin/sh
# One command from a fresh Debian 12 machine to every test: installs what is
# missing, builds, and runs the whole suite (unit, oracle, command line);
# then the same suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (MESHPAINT_SKIP_SANITIZE=1 skips that second pass); then each libFuzzer
# target for 30 s from a fixed seed, so that a clean tree gives the same run
# each time (MESHPAINT_SKIP_FUZZ=1 skips it; scripts/fuzz.sh alone explores).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/install-deps.sh"
"$here/scripts/build.sh"
(cd "$here/build" && ctest --output-on-failure -j"$(nproc)" "$@")
if [ "${MESHPAINT_SKIP_SANITIZE:-0}" != 1 ]; then
  MESHPAINT_BUILD_DIR="$here/build-asan" "$here/scripts/build.sh" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMESHPAINT_SANITIZE=ON
  # Leak checking is off: the OpenCL ICD loader and PoCL keep allocations
  # until exit by design.
  (cd "$here/build-asan" && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j"$(nproc)" "$@")
fi
if [ "${MESHPAINT_SKIP_FUZZ:-0}" != 1 ]; then
  MESHPAINT_FUZZ_SEED=${MESHPAINT_FUZZ_SEED:-1} "$here/scripts/fuzz.sh" 30
fi
