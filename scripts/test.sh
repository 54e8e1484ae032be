#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds (warnings are errors) and packs the GPU
# bundle (scripts/gpu-bundle.sh), runs ctest.
# Vulkan validation is on in every GPU test; any message fails the test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset ci >/dev/null
cmake --build --preset ci
# The portable bundle's own build (headless, no FFmpeg) and archive, which cli.gpu_bundle checks.
scripts/gpu-bundle.sh
ctest --preset ci -j2 "$@"
