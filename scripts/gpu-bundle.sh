#!/usr/bin/env bash
# Builds a headless globe (render, bench, trade, ...; no window, no MP4) and packs it, with its
# shaders, assets, the Khronos validation layer and every shared library it loads, its own glibc
# and dynamic loader included, into one archive that runs on a bare x86-64 Linux machine with a
# Vulkan driver (docs/benchmark.md, "A GPU machine").
#
#   scripts/gpu-bundle.sh [--out FILE.tar.xz]      (default build/bundle/globe-bundle.tar.xz)
#
# The archive unpacks to globe-bundle/; run globe-bundle/globe as the program. Its launcher starts
# bin/globe through the bundled loader with lib/ as the only library path before the system's, so
# nothing of the host but the kernel and the GPU driver is used. The archive must stay under
# 64 MiB (what a device machine's working tree may carry); the script fails above that.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/bundle/globe-bundle.tar.xz
while (($#)); do
  case "$1" in
    --out) out="${2:?--out needs a file}"; shift 2 ;;
    *) echo "gpu-bundle: unknown argument '$1' (usage: scripts/gpu-bundle.sh [--out FILE.tar.xz])" >&2; exit 2 ;;
  esac
done
readonly limit_bytes=$((64 * 1024 * 1024))

cmake --preset bundle >/dev/null
cmake --build --preset bundle

# Packing takes a minute: an archive newer than everything it holds of the repository is kept.
inputs=(build/bundle/bin/globe build/bundle/share/globe/shaders assets scripts/gpu-bundle.sh
        scripts/gpu-bundle-launcher.sh scripts/gpu-bench.sh)
if [[ -f "$out" && -z "$(find -L "${inputs[@]}" -newer "$out" -print -quit)" ]]; then
  echo "gpu-bundle: $out is up to date ($(($(stat -c %s "$out") / 1048576)) MiB)"
  exit 0
fi

stage=$(mktemp -d "${TMPDIR:-/tmp}/globe-bundle.XXXXXX")
trap 'rm -rf "$stage"' EXIT
root="$stage/globe-bundle"
mkdir -p "$root/bin" "$root/lib" "$root/share/globe" "$root/share/vulkan/explicit_layer.d" "$root/share/proj"

# The program, stripped (the debug symbols are the build's; the bundle is for running).
strip -o "$root/bin/globe" build/bundle/bin/globe
cp -rL build/bundle/share/globe/shaders "$root/share/globe/shaders"
cp -rL assets "$root/share/globe/assets"

# The validation layer, for the short validated run of scripts/gpu-bench.sh: its manifest names the
# library by file name alone, so the loader finds it in lib/.
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
cp "$layer_json" "$root/share/vulkan/explicit_layer.d/"
layer_lib=/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so
# NVIDIA's Vulkan driver (libGLX_nvidia) needs glvnd's dispatch library, which a bare machine may lack.
extra_libs=("$layer_lib" /usr/lib/x86_64-linux-gnu/libGLdispatch.so.0 /usr/lib/x86_64-linux-gnu/libGLX.so.0)

# Every library the program and the extras load, by the name the loader asks for; the dynamic
# loader itself too (ld.so lists it as an absolute path).
for binary in "$root/bin/globe" "${extra_libs[@]}"; do
  ldd "$binary" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3} $1 ~ /^\/.*ld-linux/ {print $1, $1}'
done | sort -u | while read -r name path; do
  cp -L "$path" "$root/lib/$(basename "$name")"
done
for lib in "${extra_libs[@]}"; do cp -L "$lib" "$root/lib/$(basename "$lib")"; done
# The whole of glibc's run time, not only what globe links: a driver that needs libdl or librt must
# get them from the same glibc as the rest of the process.
for lib in libc.so.6 libm.so.6 libmvec.so.1 libdl.so.2 libpthread.so.0 librt.so.1 libresolv.so.2 libutil.so.1 libanl.so.1; do
  cp -L "/lib/x86_64-linux-gnu/$lib" "$root/lib/$lib"
done
if ! ls "$root"/lib/ld-linux-*.so.* >/dev/null 2>&1; then
  echo "gpu-bundle: ldd named no dynamic loader for build/bundle/bin/globe" >&2
  exit 1
fi

# PROJ's database and GDAL's data: planets with real elevation sources in other CRSs need them.
cp /usr/share/proj/proj.db "$root/share/proj/"
cp -r /usr/share/gdal "$root/share/gdal"
cp scripts/gpu-bundle-launcher.sh "$root/globe"
chmod +x "$root/globe"
cp scripts/gpu-bench.sh "$root/gpu-bench.sh"

mkdir -p "$(dirname "$out")"
tmp="$out.tmp$$"
tar -C "$stage" --owner=0 --group=0 --numeric-owner -cf - globe-bundle | xz -T0 -6 >"$tmp"
size=$(stat -c %s "$tmp")
if ((size > limit_bytes)); then
  rm -f "$tmp"
  echo "gpu-bundle: the archive is $((size / 1048576)) MiB, over the 64 MiB a device machine may carry" >&2
  exit 1
fi
mv "$tmp" "$out"
echo "gpu-bundle: $out ($((size / 1048576)) MiB, $(ls "$root/lib" | wc -l) libraries, $(du -sm "$root" | cut -f1) MiB unpacked)"
