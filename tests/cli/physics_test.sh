#!/usr/bin/env bash
# globe physics end to end (docs/physics.md): bad values are one line and write nothing; a small run
# writes bodies.csv (the issue's columns, one row per body, every body at rest on the ground),
# summary.json and a rendered frame. Usage: physics_test.sh GLOBE SOURCE_DIR WORKDIR
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_common.sh"

# expect_bad PATTERN ARGS...: exit 2, one stderr line matching PATTERN, no output directory.
expect_bad() {
  local pattern="$1"
  shift
  "$GLOBE" physics --out "$WORK/bad" "$@" >"$WORK/stdout" 2>"$WORK/stderr"
  local got=$?
  if [[ $got -ne 2 ]]; then fail "'$*' exited $got, expected 2"; cat "$WORK/stderr"; return; fi
  if [[ $(wc -l <"$WORK/stderr") -ne 1 ]] || ! grep -qE "^globe: error: .*$pattern" "$WORK/stderr"; then
    fail "'$*' stderr is not one line matching '$pattern':"; cat "$WORK/stderr"; return
  fi
  if [[ -e "$WORK/bad" ]]; then fail "'$*' wrote $WORK/bad"; rm -rf "$WORK/bad"; return; fi
  echo "ok: $* -> $(cat "$WORK/stderr")"
}

expect_bad "--bodies" --bodies 0
expect_bad "--bodies" --bodies 100001
expect_bad "--seconds" --seconds 0
expect_bad "--seconds" --seconds nan
expect_bad "--level" --level 0
expect_bad "--level" --level 30
expect_bad "--radius" --radius -1
expect_bad "--shape" --shape cube
expect_bad "--grid" --grid 24
expect_bad "--budget" --budget 0
expect_bad "--render" --render "$WORK/frame.txt"
expect_bad "--out" --out /nonexistent/dir/out
expect_bad "no-such.toml" --planet "$WORK/no-such.toml"
expect_bad "--seed" --seed -3
# Sized before the run (issue 40 item 12: both ran for minutes with no output).
expect_bad "--radius: 10000 m at level 24 reaches about .* collision meshes around each body" --level 24 --radius 10000
expect_bad "--budget: 100000 scattered bodies need about .* MiB\\), more than the pool's 256 MiB: raise --budget" \
  --bodies 100000
printf 'name = "heavy"\nradius_m = 1000000.0\nsurface_gravity_m_s2 = -1\n[[layers]]\nname = "a"\noctaves = 1\nwavelength_m = 1e5\namplitude_m = 10\n' >"$WORK/bad_gravity.toml"
expect_bad "bad_gravity.toml:3:.*surface_gravity_m_s2" --planet "$WORK/bad_gravity.toml"

OUT="$WORK/run"
if ! "$GLOBE" physics --bodies 6 --seconds 12 --grid 16 --radius 8 --seed 3 --out "$OUT" --render "$WORK/frame.png" \
    >"$WORK/run.log" 2>&1; then
  fail "the small run failed:"; cat "$WORK/run.log"
else
  header=$(head -1 "$OUT/bodies.csv")
  want="id,lat_deg,lon_deg,shape,size_m,start_height_m,rest_height_above_exact_surface_m,speed_m_s,contact_nodes"
  [[ "$header" == "$want" ]] || fail "bodies.csv header is '$header'"
  [[ $(wc -l <"$OUT/bodies.csv") -eq 7 ]] || fail "bodies.csv has $(wc -l <"$OUT/bodies.csv") lines, want 7"
  # Every body touches a mesh, rests within 3 m of the exact surface (the level's mesh error) and is still.
  awk -F, 'NR > 1 && ($9 < 1 || $7 < -3 || $7 > 3 || $8 >= 0.05) { print "FAIL: body " $0; bad = 1 } END { exit bad }' \
    "$OUT/bodies.csv" || failures=$((failures + 1))
  for key in steps ms_per_step_p50 ms_per_step_p99 nodes_generated_sync nodes_generated_async collision_pool_mib; do
    grep -q "\"$key\"" "$OUT/summary.json" || fail "summary.json lacks $key"
  done
  grep -q '"steps": 1440,' "$OUT/summary.json" || fail "12 s are 1440 steps of 1/120 s"
  [[ -s "$WORK/frame.png" ]] || fail "no rendered frame"
  # The frame looks at a body on land, not at bare sea over the ones on the sea floor.
  grep -qE '^[1-9][0-9]* bodies in view' "$WORK/run.log" || fail "no body in the rendered frame: $(grep 'in view' "$WORK/run.log")"
  ls -A "$OUT" | grep -q '\.tmp' && fail "a temporary file was left in $OUT"
  echo "ok: run -> $(tail -1 "$WORK/run.log")"
fi

# A crowd: 1000 mixed bodies dropped into one valley land on each other and on the ground; none may
# end below the exact surface by more than the level's mesh error (a crowd once pushed a capsule
# through the ground when continuous collision was off, which the scattered drops did not show).
if ! "$GLOBE" physics --bodies 1000 --clustered --shape mixed --seconds 4 --seed 1 --out "$WORK/crowd" \
    >"$WORK/crowd.log" 2>&1; then
  fail "the crowd run failed:"; cat "$WORK/crowd.log"
else
  awk -F, 'NR > 1 && $7 < -3 { print "FAIL: crowd body below the surface: " $0; bad = 1 } END { exit bad }' \
    "$WORK/crowd/bodies.csv" || failures=$((failures + 1))
  echo "ok: crowd -> $(tail -1 "$WORK/crowd.log")"
fi

if ((failures)); then
  echo "$failures failure(s)"
  exit 1
fi
echo "physics: all checks passed"
