#!/usr/bin/env bash
# The GPU benchmark (docs/benchmark.md, "A GPU machine"): on the machine's best Vulkan device
# (a discrete GPU when there is one; GLOBE_DEVICE=NAME forces another), replays the default flyover
# at 1920x1080 with each preset, a still camera, `exact` with a 128-cell grid at depth 20 like the
# primary source (budgeted and converged), `trade --quick`, and one short run with the validation
# layer, cold shader caches throughout. Each run's report goes to OUT/<step>/; OUT/summary.txt holds
# the device and every run's one-line result. Sized for well under 10 minutes on a GPU.
#
#   gpu-bench.sh [--out DIR] [--globe PROGRAM] [--quick] [--steps a,b,...]
#
# PROGRAM defaults to the bundle's launcher beside this script (globe-bundle/globe), else
# build/release/bin/globe. --quick: 320x180 at 10 frames per path second (a smoke test that runs on
# lavapipe in a minute or two). Steps: validate, flyover, still, exact128, trade (default: all).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=out/gpu-bench
globe=""
size=1920x1080
validate_size=640x360
rate=60
steps=validate,flyover,still,exact128,trade
while (($#)); do
  case "$1" in
    --out) out="${2:?--out needs a directory}"; shift 2 ;;
    --globe) globe="${2:?--globe needs a program}"; shift 2 ;;
    --quick) size=320x180; validate_size=320x180; rate=10; shift ;;
    --steps) steps="${2:?--steps needs a list}"; shift 2 ;;
    *) echo "gpu-bench: unknown argument '$1' (usage: gpu-bench.sh [--out DIR] [--globe PROGRAM] [--quick] [--steps LIST])" >&2
       exit 2 ;;
  esac
done
if [[ -z "$globe" ]]; then
  if [[ -x "$here/globe" ]]; then globe="$here/globe"; else globe="$here/../build/release/bin/globe"; fi
fi
if [[ ! -x "$globe" ]]; then
  echo "gpu-bench: $globe: no globe program there (build one, or give --globe)" >&2
  exit 2
fi
for step in ${steps//,/ }; do
  case "$step" in validate | flyover | still | exact128 | trade) ;;
    *) echo "gpu-bench: --steps: unknown step '$step' (validate, flyover, still, exact128, trade)" >&2; exit 2 ;;
  esac
done
mkdir -p "$out" || exit 1
summary="$out/summary.txt"
failures=0

# Cold caches, as a user's first run: Mesa's and NVIDIA's shader disk caches off.
export MESA_SHADER_CACHE_DISABLE=true __GL_SHADER_DISK_CACHE=0

{
  echo "gpu-bench $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -n), $size at $rate frames per path second"
  echo "load: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"
  if command -v nvidia-smi >/dev/null; then
    nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv,noheader 2>&1 | sed 's/^/nvidia-smi: /'
  fi
} | tee "$summary"

# One run: its output in OUT/NAME.log, its device and result lines in the summary.
run() {
  local name="$1"
  shift
  local start=$SECONDS
  echo "== $name: globe $*" | tee -a "$summary"
  if "$globe" "$@" >"$out/$name.log" 2>&1; then
    grep -E '^(device: |bench: |first frame |globe trade: |truth ray )' "$out/$name.log" | sed 's/^/   /' | tee -a "$summary"
    echo "   ($((SECONDS - start)) s)" | tee -a "$summary"
  else
    echo "   FAILED (exit $?): $(tail -1 "$out/$name.log")" | tee -a "$summary"
    failures=$((failures + 1))
  fi
}

# The camera paths: the bundle's copy beside this script, else the repository's.
assets="$here/share/globe/assets"
[[ -d "$assets" ]] || assets="$here/../assets"
flyover=(--path "$assets/paths/flyover.path")
still=(--path "$assets/paths/still.path" --keyframes 0,5,10)

for step in ${steps//,/ }; do
  case "$step" in
    validate)
      run validate bench --validate "${still[@]}" --size "$validate_size" --rate 10 --out "$out/validate" ;;
    flyover)
      for quality in fast balanced exact; do
        run "flyover-$quality" bench "${flyover[@]}" --quality "$quality" --size "$size" --rate "$rate" \
          --out "$out/flyover-$quality"
      done ;;
    still)
      for quality in balanced exact; do
        run "still-$quality" bench "${still[@]}" --quality "$quality" --size "$size" --rate "$rate" \
          --out "$out/still-$quality"
      done ;;
    exact128)
      for mode in budgeted converged; do
        run "exact128-$mode" bench "${flyover[@]}" --quality exact --grid 128 --mode "$mode" --size "$size" \
          --rate "$rate" --out "$out/exact128-$mode"
      done ;;
    trade)
      run trade trade --quick --out "$out/trade" ;;
  esac
done

echo "gpu-bench: $failures failed; summary in $summary" | tee -a "$summary"
((failures == 0))
