#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, and replays the default benchmark flight
# (assets/paths/flyover.path on assets/planets/earthlike.toml) headless. The report is written to
# out/bench/report.html (see docs/benchmark.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
mkdir -p out
build/release/bin/globe bench --planet assets/planets/earthlike.toml --path assets/paths/flyover.path \
  --out out/bench --mode budgeted "$@"
echo "main job done: open out/bench/report.html"
