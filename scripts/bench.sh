#!/usr/bin/env bash
# Set up, build, and run the benchmark suite; JSON to out/bench.json (figures: bench/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
mkdir -p out
./build/bench/dymesh_bench --benchmark_out=out/bench.json --benchmark_out_format=json --benchmark_min_time=0.3 "$@"
