#!/bin/sh
# globe from a portable bundle (scripts/gpu-bundle.sh): bin/globe runs under the bundle's own
# dynamic loader and glibc with lib/ searched first, so the host lends only its kernel and its
# Vulkan driver. Built-ins only: under `env -i` there is no PATH.
here=$(cd -P -- "${0%/*}" && pwd) || exit 1

export GLOBE_SHADER_DIR="$here/share/globe/shaders"
export GLOBE_ASSET_DIR="$here/share/globe/assets"
export PROJ_DATA="${PROJ_DATA:-$here/share/proj}"
export GDAL_DATA="${GDAL_DATA:-$here/share/gdal}"
# The bundled validation layer for --validate, beside any the host has.
export VK_ADD_LAYER_PATH="$here/share/vulkan/explicit_layer.d${VK_ADD_LAYER_PATH:+:$VK_ADD_LAYER_PATH}"

# A container's NVIDIA driver often sits outside the loader's default folders.
libraries="$here/lib"
nvidia=/usr/local/nvidia
if [ -f "$nvidia/share/vulkan/icd.d/nvidia_icd.json" ]; then
  export VK_ADD_DRIVER_FILES="$nvidia/share/vulkan/icd.d/nvidia_icd.json${VK_ADD_DRIVER_FILES:+:$VK_ADD_DRIVER_FILES}"
  for folder in "$nvidia/lib64" "$nvidia/lib"; do
    if [ -d "$folder" ]; then libraries="$libraries:$folder"; fi
  done
fi

exec "$here/lib/ld-linux-x86-64.so.2" --library-path "$libraries" --argv0 "$0" "$here/bin/globe" "$@"
