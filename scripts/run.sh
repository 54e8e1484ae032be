#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, and runs the engine's main job headless.
# Output goes to out/ (see README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
mkdir -p out
GLOBE=build/release/engine/globe
"$GLOBE" render --at 20,10,2000000 --size 1280x720 --out out/render.png
"$GLOBE" render --at 20,10,2000000 --size 1280x720 --out out/render.exr
echo "main job done: see out/"
