# Sourced first by the command-line test scripts that take GLOBE SOURCE_DIR WORKDIR: sets GLOBE, SRC
# and WORK (emptied), and `fail`, which counts into `failures` (the script exits with it).
GLOBE="$1"
SRC="$2"
WORK="$3"
rm -rf "$WORK" && mkdir -p "$WORK"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
