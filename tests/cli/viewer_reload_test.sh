#!/usr/bin/env bash
# Live reload of `globe view --planet FILE` under a virtual X server (docs/viewer.md): the viewer runs a
# script with a still camera while this test rewrites the planet file at the script's WAIT RELOAD
# points: first a valid planet with another seed (the image must change), then the same with every
# land cover class in another colour and the first seed (against the first planet's image: the
# [[land_cover]] section is reloaded, the image must change),
# then an invalid one (the errors go to stderr as file:line:column, the image must stay the last good
# planet's). Vulkan
# validation is on, so any message (including objects leaked when the old terrain and its payload
# pool are destroyed) fails the run; the exit must be clean.
# Usage: viewer_reload_test.sh GLOBE SCREENSHOT_CHECK SCRIPT PLANET WORKDIR
set -uo pipefail
GLOBE="$1"
CHECK="$2"
SCRIPT="$3"
PLANET="$4"
WORK="$5"
rm -rf "$WORK" && mkdir -p "$WORK"
source "$(dirname "$0")/xvfb_common.sh"

cp "$PLANET" "$WORK/planet.toml"
"${XVFB[@]}" "$GLOBE" view --validate --planet "$WORK/planet.toml" --frames 130 --script "$SCRIPT" --size 320x240 \
  --screenshot-dir "$WORK" >"$WORK/stdout" 2>"$WORK/stderr" &
viewer=$!

# wait_for N: until the viewer has printed its N-th "waiting for the planet file" line.
wait_for() {
  for _ in $(seq 1 1200); do
    [[ $(grep -c "waiting for the planet file" "$WORK/stdout") -ge $1 ]] && return 0
    kill -0 "$viewer" 2>/dev/null || return 1
    sleep 0.05
  done
  return 1
}
# An editor's save: write a temporary, rename it over the file.
save() { cat >"$WORK/planet.toml.tmp" && mv "$WORK/planet.toml.tmp" "$WORK/planet.toml"; }

if wait_for 1; then
  sed 's/^seed = .*/seed = 4242/' "$WORK/planet.toml" | save
else
  fail "the viewer never waited for the first reload"
fi
if wait_for 2; then
  # The first planet's seed again (its continent in view), every `colour = ` line changed: the
  # classes' (the ramp's too, which a planet with land cover does not use).
  sed -e "s/^seed = .*/$(grep '^seed = ' "$PLANET")/" -e 's/^colour = .*/colour = [0.8, 0.1, 0.8]/' "$WORK/planet.toml" | save
else
  fail "the viewer never waited for the land cover reload"
fi
if wait_for 3; then
  # Two errors: every one is reported, not just the first.
  # Both in one save: an append after the rename would race the viewer's reload.
  { sed -e 's/^seed = .*/seed = 7/' -e '0,/^gain = .*/s//gain = -2.0/' "$WORK/planet.toml"
    printf 'no_such_key = 1\n'; } | save
else
  fail "the viewer never waited for the second reload"
fi
wait "$viewer"
code=$?
cat "$WORK/stdout"
if [[ $code -ne 0 ]]; then fail "globe view exited $code"; cat "$WORK/stderr"; cat "$WORK/xvfb.log" 2>/dev/null; fi
if grep -qi "validation" "$WORK/stderr"; then fail "validation messages:"; cat "$WORK/stderr"; fi
grep -q "viewed 130 frames" "$WORK/stdout" || fail "did not report 130 frames"
grep -q "^planet reloaded: .*planet.toml (frame 42)" "$WORK/stdout" || fail "no reload at frame 42"
grep -q "^planet reloaded: .*planet.toml (frame 87)" "$WORK/stdout" || fail "no land cover reload at frame 87"
grep -q "^planet reload failed: .*planet.toml (frame 112)" "$WORK/stdout" || fail "no failed reload at frame 112"
for f in 40 85 110 125; do
  grep -q "^screenshot .*globe-frame$(printf %06d $f).png (converged)" "$WORK/stdout" || fail "frame $f was not a converged screenshot"
done
# The errors: once each on stderr, with file, line and column.
echo "--- stderr:"; cat "$WORK/stderr"
grep -qE "^globe: error: .*planet\.toml:[0-9]+:[0-9]+: .*gain" "$WORK/stderr" || fail "no file:line:column error for gain"
grep -qE "^globe: error: .*planet\.toml:[0-9]+:[0-9]+: .*no_such_key" "$WORK/stderr" || fail "no error for the unknown key"
[[ $(grep -c "no_such_key" "$WORK/stderr") -eq 1 ]] || fail "the unknown key was not reported exactly once"
# The images: a new planet changes the picture, an invalid file does not.
"$CHECK" differ "$WORK/globe-frame000040.png" "$WORK/globe-frame000085.png" || fail "the reload did not change the image"
"$CHECK" differ "$WORK/globe-frame000040.png" "$WORK/globe-frame000110.png" || fail "the land cover reload did not change the image"
"$CHECK" same "$WORK/globe-frame000110.png" "$WORK/globe-frame000125.png" || fail "the invalid file changed the image"

echo "viewer reload: $failures failure(s)"
exit $((failures > 0))
