#!/usr/bin/env bash
# Installs what the tool needs and builds only the `hexex` target (scripts/setup.sh, profile
# "tool": no test, documentation or Python packages), then extracts the hex mesh of a bundled
# example (Examples/data/sphere.hexex) with the hexex tool and prints the report.
# Output: $OUT_DIR (default /tmp/hexex-example)/sphere.vtu and sphere-report.json.
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$REPO_ROOT/build}"
OUT_DIR="${OUT_DIR:-/tmp/hexex-example}"
INPUT="$REPO_ROOT/Examples/data/sphere.hexex"
export BUILD_DIR
export HEXEX_PROFILE="${HEXEX_PROFILE:-tool}"

bash "$REPO_ROOT/scripts/setup.sh"

HEXEX="$BUILD_DIR/src/Tools/hexex/hexex"
mkdir -p "$OUT_DIR"
OUT="$OUT_DIR/sphere.vtu"
REPORT="$OUT_DIR/sphere-report.json"
ERR="$OUT_DIR/stderr.txt"

echo "+ hexex extract $INPUT -o $OUT --report $REPORT"
# run_hexex ARGS...: runs the tool, shows its stderr and keeps a copy in $ERR; sets $status.
run_hexex() {
    set +e
    "$HEXEX" "$@" 2>"$ERR"
    status=$?
    set -e
    cat "$ERR" >&2
}

run_hexex extract "$INPUT" -o "$OUT" --report "$REPORT"

case "$status" in
    0) echo "Wrote $OUT and $REPORT" ;;
    3) echo "Wrote $OUT and $REPORT (output is not all-hex, see the report)" ;;
    *) echo "hexex extract failed with status $status" >&2 ; exit "$status" ;;
esac
[[ -f "$REPORT" ]] && cat "$REPORT"
echo
echo "Output: $OUT (hex mesh), $REPORT (report)."
echo "Look at it: paraview $OUT   (or: $HEXEX validate $OUT)"
exit "$status"
