#!/usr/bin/env bash
# Quick start 1: set up, build, and run the demo scenario (car into rigid barrier).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
scenario="${1:-data/scenarios/barrier_frontal.json}"
./build/cli/dymesh run "$scenario" --out out/demo
