#!/usr/bin/env bash
# Installs this build into a temporary prefix, then configures, builds and runs tests/consumer against
# it with find_package(globe): the exported package works, and a headless user links no GLFW or ImGui.
set -euo pipefail
BUILD=$1 SRC=$2 WORK=$3
rm -rf "$WORK"; mkdir -p "$WORK"
fail() { echo "FAIL: $*" >&2; exit 1; }
cmake --install "$BUILD" --prefix "$WORK/prefix" >"$WORK/install.log" || fail "cmake --install (see $WORK/install.log)"
[ -f "$WORK/prefix/share/globe/shaders/terrain.vert.spv" ] || fail "no SPIR-V installed"
[ -f "$WORK/prefix/share/globe/assets/planets/earthlike.toml" ] || fail "no assets installed"
cmake -S "$SRC/tests/consumer" -B "$WORK/build" -G Ninja -DCMAKE_PREFIX_PATH="$WORK/prefix" \
  >"$WORK/configure.log" 2>&1 || { cat "$WORK/configure.log"; fail "find_package(globe)"; }
cmake --build "$WORK/build" >"$WORK/build.log" 2>&1 || { cat "$WORK/build.log"; fail "building the consumer"; }
"$WORK/build/consumer" || fail "the consumer did not run"
if readelf -d "$WORK/build/consumer" | grep NEEDED | grep -Ei 'libglfw|imgui|libX11'; then fail "a headless consumer links GLFW/ImGui/X11"; fi
# The installed program finds its shaders and assets beside itself (no build path compiled in).
mv "$WORK/prefix" "$WORK/moved"
"$WORK/moved/bin/globe" planet check >/dev/null || fail "the installed globe does not find its default planet"
"$WORK/moved/bin/globe" render --size 32x32 --out "$WORK/frame.png" >/dev/null || fail "the installed globe does not render"
echo "consumer: ok"
