#!/bin/sh
# Installs the Debian packages in scripts/packages.txt that are missing, and
# fetches the scans into data/scans/. Idempotent: with everything in place it
# only checks, in well under a second.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
packages=$(grep -v '^#' "$here/scripts/packages.txt" | tr '\n' ' ')

missing=""
for p in $packages; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  case "$status" in *"install ok installed"*) ;; *) missing="$missing $p" ;; esac
done

if [ -n "$missing" ]; then
  echo "installing:$missing" >&2
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

"$here/scripts/fetch-scans.sh"
