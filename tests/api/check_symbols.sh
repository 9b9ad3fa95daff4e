#!/usr/bin/env bash
# The symbols libdymesh_c.so exports are exactly the checked-in list (api/exported_symbols.txt):
# a new or lost dm_ name, or a leaked C++ symbol, fails. Args: the library, the list.
set -euo pipefail
actual="$(nm -D --defined-only "$1" | awk '{print $3}' | sed 's/@@.*//' | grep -v '^DYMESH_C_' | sort)"
expected="$(sort "$2")"
if [ "$actual" != "$expected" ]; then
  diff <(echo "$expected") <(echo "$actual") || true
  echo "exported symbols differ from $2 (< expected, > actual)"
  exit 1
fi
soname="$(readelf -d "$1" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')"
[ "$soname" = "libdymesh_c.so.1" ] || { echo "SONAME is '$soname', expected libdymesh_c.so.1"; exit 1; }
echo "$(echo "$actual" | wc -l) symbols, SONAME $soname"
