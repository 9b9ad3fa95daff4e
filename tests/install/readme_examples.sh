#!/usr/bin/env bash
# The README's library examples are the ones the install test compiles and runs: each example file
# appears in README.md verbatim. Args: source dir.
set -euo pipefail
source="$1"
for example in tests/install/cpp_consumer/main.cpp tests/install/c_consumer/main.c tests/install/python_example.py; do
  python3 - "$source/README.md" "$source/$example" <<'PY'
import sys
readme, example = (open(p, encoding="utf-8").read() for p in sys.argv[1:3])
if example.strip() not in readme:
    sys.exit(f"README.md does not contain {sys.argv[2]} verbatim: update the 'Use as a library' section")
PY
done
echo "README examples match"
