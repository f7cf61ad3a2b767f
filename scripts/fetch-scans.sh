#!/bin/sh
# Puts the real scans this project tests and benchmarks on into data/scans/,
# taken from Debian's libcgal-demo package (see data/README.md). Idempotent:
# does nothing when every scan is already there.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
dest="$here/data/scans"
scans="bunny00.off refined_elephant.off armadillo.off ChineseDragon-10kv.off femur.off lion-head.off"

missing=0
for s in $scans; do [ -s "$dest/$s" ] || missing=1; done
[ "$missing" = 0 ] && exit 0

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "fetching scans from Debian's libcgal-demo into data/scans/" >&2
(cd "$work" && apt-get download libcgal-demo >/dev/null 2>&1) ||
  { echo "error: apt-get download libcgal-demo failed (is apt reachable?)" >&2; exit 1; }
dpkg -x "$work"/libcgal-demo_*.deb "$work/pkg"
mkdir -p "$dest"
members=""
for s in $scans; do members="$members data/meshes/$s"; done
# shellcheck disable=SC2086
tar -xzf "$work/pkg/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" $members
for s in $scans; do mv "$work/data/meshes/$s" "$dest/$s"; done
