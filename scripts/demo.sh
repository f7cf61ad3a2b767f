#!/bin/sh
# One command from a fresh Debian 12 machine to the main job: installs what
# is missing, builds, and runs `meshpaint demo` on the bundled bunny scan.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/install-deps.sh"
"$here/scripts/build.sh" >/dev/null
exec "$here/build/bin/meshpaint" demo "$@"
