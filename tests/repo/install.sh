#!/usr/bin/env bash
# `cmake --install build --prefix P` installs the executable, the libraries with their public
# headers and the standard profiles; the installed binary runs and prints its version.
set -euo pipefail
src=$1; build=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/p" >/dev/null
for f in bin/mhcontact lib/libmhcontact_core.a lib/libmhcontact_io.a include/mhcontact/contact/ellipse/hertz.hpp \
         include/mhcontact/profile/read.hpp share/mhcontact/profiles/S1002.csv; do
  [ -e "$tmp/p/$f" ] || { echo "install: $f missing"; exit 1; }
done
"$tmp/p/bin/mhcontact" --version | grep -q '^mhcontact [0-9]' || { echo "install: --version"; exit 1; }
echo "install: OK"
