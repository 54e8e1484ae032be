# Sourced by the GUI tests after WORK is set: `fail`, the failure counter, and XVFB, the xvfb-run
# prefix. -a takes the first free display from a random start (-n), so concurrent runs (other build
# trees, other checkouts) rarely race for the same one; 24-bit like a desktop.
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

if ! command -v xvfb-run >/dev/null; then
  echo "FAIL: xvfb-run not found (scripts/install-deps.sh installs the xvfb package)"
  exit 1
fi
XVFB=(xvfb-run -a -n $((100 + RANDOM % 800)) -e "$WORK/xvfb.log" -s "-screen 0 1024x768x24 -nolisten tcp")
