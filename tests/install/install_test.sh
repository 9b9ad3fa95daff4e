#!/usr/bin/env bash
# cmake --install into a fresh prefix, then configure, build and run the consumer projects against it
# (C++: find_package + dymesh::core dymesh::accel; C: dymesh::c and pkg-config). Args: build dir, source dir.
set -euo pipefail
build="$1"
source="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
for consumer in "$source"/tests/install/*_consumer; do
  name="$(basename "$consumer")"
  cmake -S "$consumer" -B "$work/$name" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/$name.log"
  cmake --build "$work/$name" -j2 >> "$work/$name.log"
  "$work/$name/consumer"
done
# the C ABI through pkg-config, as a Makefile host would use it
libdir="$(dirname "$(find "$work/prefix" -name dymesh.pc)")"
export PKG_CONFIG_PATH="$libdir"
cc -std=c99 -o "$work/pkg_consumer" "$source/tests/install/c_consumer/main.c" $(pkg-config --cflags --libs dymesh)
LD_LIBRARY_PATH="$(pkg-config --variable=libdir dymesh)" "$work/pkg_consumer"
# the Python module from the prefix's Python path
if [ -n "$(find "$work/prefix" -name 'dymesh.cpython-*.so')" ]; then
  PYTHONPATH="$(dirname "$(find "$work/prefix" -name 'dymesh.cpython-*.so')")" /usr/bin/python3 \
    "$source/tests/install/python_example.py" "$source/data/scenarios/barrier_frontal.json"
fi
