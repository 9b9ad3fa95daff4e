#!/usr/bin/env bash
# Makes docs/report.png, the README's picture of the demo report: its title, first pulse plots and
# crush section as headless Chromium draws them (a copy of the report with the other parts hidden).
# Needs a build (scripts/setup.sh; or DYMESH=path/to/dymesh) and Debian's chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"${DYMESH:-./build/cli/dymesh}" run data/scenarios/barrier_frontal.json --out "$work/out" --quiet
# hide the tables, the later pulse plots and the trajectories in a copy
hide='p.meta, #summary, #table-summary, #table-overall, #pulse + .figures > figure:nth-of-type(n+3),'
hide+=' #trajectories, #trajectories + figure, p.note { display: none; }'
sed "s|</head>|<style>$hide</style></head>|" "$work/out/report.html" > "$work/shot.html"
mkdir -p "$work/profile" docs
chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --hide-scrollbars --user-data-dir="$work/profile" \
  --window-size=1280,1400 --screenshot="$PWD/docs/report.png" "file://$work/shot.html" 2>/dev/null
ls -l docs/report.png
