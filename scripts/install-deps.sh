#!/usr/bin/env bash
# Installs every Debian package globe needs to build, run and test. Idempotent: only
# missing packages are installed. `--list` prints the list (one per line) and exits.
# tests/deps_test.sh checks that every library the binaries link and every tool the
# tests run comes from a package on this list.
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git dpkg
  # graphics: Vulkan loader/headers, lavapipe, validation layers, shader compiler, windowing
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools libglfw3-dev
  # maths and geodesy
  libglm-dev libgeographiclib-dev
  # real elevation sources (planet/sources): GDAL with PROJ; the USGS grids of assets/planets/earth-dem.toml
  # come from python-matplotlib-data; gdal-bin's tools and python3-gdal/python3-numpy for the commands
  # of docs/elevation-data.md
  libgdal-dev libproj-dev gdal-bin python3-gdal python3-numpy python-matplotlib-data
  # file formats and command line
  libopenexr-dev libstb-dev libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  # KML camera tours (XML); MP4 movies through FFmpeg's libraries (H.264 by libx264 inside libavcodec)
  libpugixml-dev libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  # overlay of the windowed viewer; vertex-cache order of the terrain grid
  libimgui-dev libmeshoptimizer-dev
  # rigid-body physics on collision meshes (its double-precision build, planet/physics)
  libbullet-dev
  # tests and benchmarks (libnoise is the benchmark's comparison peer)
  libgtest-dev libgmock-dev libbenchmark-dev libnoise-dev xvfb xauth
  # the formatting check of the test suite; readelf for the consumer check (binutils)
  clang-format binutils
  # globe bake: COG tiles through GDAL (gdalinfo checks them); GNU parallel runs shards (docs/bake.md);
  # CesiumJS (npm, tests/cesium) in headless Chromium reads a baked tileset
  libgdal-dev gdal-bin parallel nodejs chromium
  # the portable GPU bundle (scripts/gpu-bundle.sh): ldd (libc-bin) lists what it loads, xz packs it;
  # glvnd's libraries for NVIDIA's Vulkan driver; PROJ's and GDAL's data for real elevation sources
  libc-bin xz-utils libglvnd0 libglx0 proj-data gdal-data
  # NASA Blue Marble (earth.jpg): the Earth's colours the orbit view is compared with (globe compare)
  xplanet-images
)

if [[ "${1:-}" == "--list" ]]; then
  printf '%s\n' "${PACKAGES[@]}"
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The JavaScript client of the bake test (tests/cesium/package-lock.json), installed by npm ci when
# missing or older than the lock file.
CESIUM_DIR="$(cd "$(dirname "$0")/../tests/cesium" && pwd)"
# Debian's nodejs ships npm as a package of its own; NodeSource's nodejs (if preinstalled) carries it.
if ! command -v npm >/dev/null; then
  echo "install-deps: installing npm"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends npm
fi
if [[ ! -d "$CESIUM_DIR/node_modules/cesium" || "$CESIUM_DIR/package-lock.json" -nt "$CESIUM_DIR/node_modules/.package-lock.json" ]]; then
  echo "install-deps: npm ci in tests/cesium"
  (cd "$CESIUM_DIR" && npm ci --no-audit --no-fund --loglevel=error)
fi
