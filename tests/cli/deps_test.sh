#!/usr/bin/env bash
# Every package the build or the tests use must be installed by scripts/install-deps.sh, so a
# forgotten package fails here and not on a user's first run. Checks, through dpkg -S:
#  - each shared library the binaries link directly (ELF NEEDED, resolved by ldd),
#  - each file and tool the build found (paths in CMakeCache.txt) and each tool the tests run,
#  - the Vulkan driver (lavapipe) and validation-layer manifests.
# A file passes when its package is on the list or is a dependency (recursively) of a listed one.
# Usage: deps_test.sh SOURCE_DIR BINARY...
set -uo pipefail
SRC="$1"
shift
BUILD_DIR="$(dirname "$(dirname "$1")")"
mapfile -t LISTED < <("$SRC/scripts/install-deps.sh" --list)

# Closure of the listed packages under Depends/Pre-Depends (installed packages only), from one
# dpkg-query call over every installed package.
declare -A DEPENDS=()
while IFS=$'\t' read -r p deps; do
  DEPENDS[$p]="$deps"
done < <(dpkg-query -W -f='${Package}\t${Depends}, ${Pre-Depends}\n')
declare -A CLOSURE=()
queue=("${LISTED[@]}")
while ((${#queue[@]})); do
  p="${queue[0]}"
  queue=("${queue[@]:1}")
  p="${p%%:*}"
  [[ -n "${CLOSURE[$p]:-}" ]] && continue
  CLOSURE[$p]=1
  [[ -n "${DEPENDS[$p]+set}" ]] || continue
  while read -r d; do
    [[ -n "$d" ]] && queue+=("$d")
  done < <(echo "${DEPENDS[$p]}" | tr ',|' '\n\n' | sed -E 's/\(.*\)//; s/^ +//; s/ +$//; s/:any$//' | grep -v '^$')
done

failures=0
# Files to check, collected first (PATH and WHY, keyed by the resolved path: the binaries share most
# libraries), then looked up in one dpkg -S call: one call per file read dpkg's database each time
# and took 145 s of the suite under load.
declare -A WHY=() GIVEN=()
check_file() {  # check_file PATH WHY
  local real
  real=$(readlink -f "$1")
  [[ -n "${WHY[$real]:-}" ]] && return
  WHY[$real]="$2"
  GIVEN[$real]="$1"
}

# OWNERS[path]: "pkg1:arch, pkg2, ..." for each of the paths given that dpkg knows (a directory has
# many owners; diversion lines are skipped).
declare -A OWNERS=()
owners_of() {  # owners_of PATH...
  local line
  while IFS= read -r line; do
    [[ "$line" == diversion* || "$line" != *": /"* ]] && continue
    local path="/${line#*: /}"
    [[ -z "${OWNERS[$path]:-}" ]] && OWNERS[$path]="${line%%: /*}"
  done < <(dpkg -S "$@" 2>/dev/null)
}

# Each collected file passes when one of its owners is in the closure of the listed packages.
judge_files() {
  ((${#WHY[@]})) || return
  owners_of "${!WHY[@]}"
  local given=() real
  for real in "${!WHY[@]}"; do
    [[ -z "${OWNERS[$real]:-}" && "${GIVEN[$real]}" != "$real" ]] && given+=("${GIVEN[$real]}")
  done
  ((${#given[@]})) && owners_of "${given[@]}"
  for real in "${!WHY[@]}"; do
    local path="${GIVEN[$real]}" why="${WHY[$real]}" owners pkg owner covered=0
    owners="${OWNERS[$real]:-${OWNERS[$path]:-}}"
    pkg=$(echo "$owners" | cut -d: -f1 | cut -d, -f1)
    if [[ -z "$pkg" ]]; then
      case "$path" in /usr/local/* | /root/* | /opt/*) echo "FAIL: $why: $path is not from a Debian package"; failures=$((failures + 1)) ;; esac
      continue
    fi
    # A directory (/usr/include) belongs to every package with files in it: it is covered when any
    # of them is listed, so installing an unrelated -dev package elsewhere does not fail the check.
    for owner in ${owners//,/ }; do
      [[ -n "${CLOSURE[${owner%%:*}]:-}" ]] && covered=1
    done
    if ((covered == 0)) && [[ -z "${CLOSURE[$pkg]:-}" ]]; then
      echo "FAIL: $why: $path comes from Debian package '$pkg', which scripts/install-deps.sh does not install"
      failures=$((failures + 1))
    fi
  done
}

checked=0
for bin in "$@"; do
  while read -r lib path; do
    [[ "$path" == /* ]] && check_file "$path" "$(basename "$bin") links $lib" && checked=$((checked + 1))
  done < <(ldd "$bin" | awk '/=>/ {print $1, $3}')
done

# Files and tools found at configure time.
if [[ -f "$BUILD_DIR/CMakeCache.txt" ]]; then
  while read -r path; do
    [[ -e "$path" ]] && check_file "$path" "CMake found" && checked=$((checked + 1))
  done < <(grep -E '^[A-Za-z0-9_]+(_DIR|_LIBRARY|_LIBRARIES|_INCLUDE_DIR|_EXECUTABLE|_PROGRAM|_COMMAND)?:[A-Z]+=/usr/' \
             "$BUILD_DIR/CMakeCache.txt" | cut -d= -f2- | tr ';' '\n' | grep '^/usr/' | sort -u)
fi

# Tools the build and the tests run.
for tool in glslangValidator cmake ctest ninja c++ pkg-config Xvfb xauth bash dpkg clang-format readelf git gdalinfo node npm chromium parallel xz strip ldd tar; do
  p=$(command -v "$tool") || { echo "FAIL: tool $tool not found"; failures=$((failures + 1)); continue; }
  check_file "$p" "tool $tool"
  checked=$((checked + 1))
done

# Runtime manifests: the CPU Vulkan driver and the validation layer.
for f in /usr/share/vulkan/icd.d/lvp_icd.*.json /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json; do
  if [[ -e "$f" ]]; then check_file "$f" "Vulkan manifest"; else echo "FAIL: $f missing"; failures=$((failures + 1)); fi
  checked=$((checked + 1))
done

judge_files
echo "deps: checked $checked files, $failures not covered by scripts/install-deps.sh"
exit $((failures > 0))
