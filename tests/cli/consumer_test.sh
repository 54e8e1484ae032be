#!/usr/bin/env bash
# Installs this build into a temporary prefix, then configures, builds and runs tests/consumer against
# it with find_package(globe COMPONENTS ...): the exported package works, a headless user links no GLFW or
# ImGui, a user of the planet component alone links no GDAL, Vulkan, Bullet or FFmpeg, and one of the gdal
# component reads real data.
set -euo pipefail
BUILD=$1 SRC=$2 WORK=$3
rm -rf "$WORK"; mkdir -p "$WORK"
fail() { echo "FAIL: $*" >&2; exit 1; }
cmake --install "$BUILD" --prefix "$WORK/prefix" >"$WORK/install.log" || fail "cmake --install (see $WORK/install.log)"
[ -f "$WORK/prefix/share/globe/shaders/terrain.vert.spv" ] || fail "no SPIR-V installed"
[ -f "$WORK/prefix/share/globe/assets/planets/earthlike.toml" ] || fail "no assets installed"
# One include root, globe/, holding the public headers alone, each project include under globe/ too.
[ "$(ls "$WORK/prefix/include")" = "globe" ] || fail "the include tree holds more than globe/: $(ls "$WORK/prefix/include")"
if grep -rnE '#include "(planet|engine|shaders)/' "$WORK/prefix/include"; then fail "an installed header includes outside globe/"; fi
for private in engine/viewer/viewer_state.h engine/render/terrain_pipelines.h planet/physics/grid_mesh_shape.h; do
  [ ! -e "$WORK/prefix/include/globe/$private" ] || fail "the private header $private is installed"
done
# One consumer per component set (tests/consumer/CMakeLists.txt).
build_consumer() {  # build_consumer SET
  cmake -S "$SRC/tests/consumer" -B "$WORK/$1" -G Ninja -DCMAKE_PREFIX_PATH="$WORK/prefix" -DCONSUMER="$1" \
    >"$WORK/$1-configure.log" 2>&1 || { cat "$WORK/$1-configure.log"; fail "find_package(globe COMPONENTS $1)"; }
  cmake --build "$WORK/$1" >"$WORK/$1-build.log" 2>&1 || { cat "$WORK/$1-build.log"; fail "building the $1 consumer"; }
}
build_consumer render
"$WORK/render/consumer" || fail "the render consumer did not run"
if readelf -d "$WORK/render/consumer" | grep NEEDED | grep -Ei 'libglfw|imgui|libX11'; then fail "a headless consumer links GLFW/ImGui/X11"; fi
build_consumer headers
build_consumer planet
"$WORK/planet/consumer" "$WORK/prefix/share/globe/assets/planets/earthlike.toml" || fail "the planet consumer did not run"
if readelf -d "$WORK/planet/consumer" | grep NEEDED | grep -Ei 'libgdal|libvulkan|libBullet|libav|libglfw|imgui|libX11|OpenEXR'; then
  fail "a consumer of the planet component links GDAL, Vulkan, Bullet, FFmpeg, OpenEXR or a window library"
fi
# Without GDAL a planet with real sources is refused by name, and read once the gdal component installs it.
dem="$WORK/prefix/share/globe/assets/planets/earth-dem.toml"
if "$WORK/planet/consumer" "$dem" 2>"$WORK/planet-dem.err"; then fail "the planet consumer read a DEM planet without a reader"; fi
grep -q "installed no reader" "$WORK/planet-dem.err" || fail "the planet consumer's refusal: $(cat "$WORK/planet-dem.err")"
build_consumer gdal
"$WORK/gdal/consumer" "$dem" || fail "the gdal consumer did not read $dem"
# The installed program finds its shaders and assets beside itself (no build path compiled in).
mv "$WORK/prefix" "$WORK/moved"
"$WORK/moved/bin/globe" planet check >/dev/null || fail "the installed globe does not find its default planet"
"$WORK/moved/bin/globe" render --size 32x32 --out "$WORK/frame.png" >/dev/null || fail "the installed globe does not render"
echo "consumer: ok"
