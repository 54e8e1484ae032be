#!/usr/bin/env bash
# Soak test (docs/reliability.md, "Soak"): a long random flight through `globe bench`, headless and
# budgeted, with validation on; samples the process's resident memory while it flies and checks
# that the payload pool stays within its budget, resident memory grows at most 5 % after warm-up,
# and no validation message appears (the bench fails on any).
#
#   scripts/soak.sh GLOBE OUT_DIR [FRAMES] [SEED] [VRAM_MIB]
#
# FRAMES (default 20000) frames at 60 Hz of path time, 320x180; the path is random but fixed by SEED:
# a keyframe every 4 s, heights log-uniform from 30 m to 300 km, headings and pitches at random,
# each hop a few times the height, so the flight keeps asking for new terrain and the pool evicts.
set -euo pipefail
GLOBE=$1
OUT=$2
FRAMES=${3:-20000}
SEED=${4:-21}
VRAM_MIB=${5:-64}
mkdir -p "$OUT"
PATH_FILE="$OUT/soak.path"
awk -v seed="$SEED" -v frames="$FRAMES" 'BEGIN {
  srand(seed); pi = atan2(0, -1)
  duration = (frames - 0.5) / 60.0; step = 4.0
  lat = 20; lon = -100
  print "# Random soak flight, seed " seed
  print "t_s lat_deg lon_deg height_m heading_deg pitch_deg roll_deg"
  for (t = 0; t < duration + step; t += step) {
    if (t > duration) t = duration
    h = exp(log(30) + rand() * (log(300000) - log(30)))
    hop_deg = h * (1 + 4 * rand()) / 111000.0        # a few heights per keyframe, in degrees
    dir = 2 * pi * rand()
    lat += hop_deg * cos(dir); lon += hop_deg * sin(dir)
    if (lat > 80) lat = 160 - lat; if (lat < -80) lat = -160 - lat
    printf "%.3f %.6f %.6f %.1f %.1f %.1f 0\n", t, lat, lon, h, 360 * rand(), -5 - 60 * rand()
    if (t >= duration) break
  }
}' > "$PATH_FILE"

RSS="$OUT/rss.csv"
echo "elapsed_s,rss_kib" > "$RSS"
start=$(date +%s)
MESA_SHADER_CACHE_DISABLE=true "$GLOBE" bench --path "$PATH_FILE" --rate 60 --size 320x180 --keyframes "" \
  --vram-mib "$VRAM_MIB" --validate --out "$OUT/bench" > "$OUT/bench.log" 2>&1 &
pid=$!
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  [ -n "$rss" ] && echo "$(( $(date +%s) - start )),$rss" >> "$RSS"
  sleep 5
done
status=0
wait "$pid" || status=$?
cat "$OUT/bench.log" | tail -3
if [ "$status" -ne 0 ]; then echo "FAIL: globe bench exited $status"; exit 1; fi

# Warm-up: the first 20 % of the samples (start-up, the pool filling to its budget). Growth: the
# highest sample after it over the last sample of the warm-up.
awk -F, -v budget="$VRAM_MIB" -v csv="$OUT/bench/frames.csv" '
  NR > 1 { rss[n++] = $2 }
  END {
    if (n < 5) { print "FAIL: too few RSS samples (" n ")"; exit 1 }
    w = int(n * 0.2); base = rss[w]; peak = base
    for (i = w; i < n; ++i) if (rss[i] > peak) peak = rss[i]
    growth = 100.0 * (peak - base) / base
    while ((getline line < csv) > 0) {
      split(line, f, ",")
      if (f[1] == "frame") { for (k in f) col[f[k]] = k; continue }
      frames++; if (f[col["resident_mib"]] > maxres) maxres = f[col["resident_mib"]]
      if (f[col["gen_in_flight"]] > maxq) maxq = f[col["gen_in_flight"]]; evicted += f[col["evicted"]]
    }
    printf "frames %d rss_after_warmup_mib %.1f rss_peak_mib %.1f growth_pct %.2f resident_mib_max %.1f (budget %d) in_flight_max %d evicted %d\n",
           frames, base / 1024, peak / 1024, growth, maxres, budget, maxq, evicted
    if (growth > 5) { print "FAIL: resident memory grew more than 5 % after warm-up"; exit 1 }
    if (maxres > budget) { print "FAIL: payload pool above its budget"; exit 1 }
  }' "$RSS"
