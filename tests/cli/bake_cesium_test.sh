#!/usr/bin/env bash
# CesiumJS in headless Chromium reads a baked quantized-mesh tileset (tests/cesium/bake_cesium_test.mjs).
# Skips (exit 77) only when chromium is absent; scripts/install-deps.sh installs it and runs `npm ci`
# in tests/cesium. Usage: bake_cesium_test.sh GLOBE SOURCE_DIR WORK_DIR
set -euo pipefail
GLOBE="$1"
SRC="$2"
WORK="$3"
if ! command -v chromium >/dev/null; then
  echo "SKIP: chromium is not installed (scripts/install-deps.sh installs it)"
  exit 77
fi
if [[ ! -d "$SRC/tests/cesium/node_modules/cesium" ]]; then
  echo "FAIL: tests/cesium/node_modules is missing: run scripts/install-deps.sh (npm ci in tests/cesium)"
  exit 1
fi
node "$SRC/tests/cesium/bake_cesium_test.mjs" "$GLOBE" "$SRC/assets/planets/earthlike.toml" "$WORK"
