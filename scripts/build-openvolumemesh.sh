#!/usr/bin/env bash
# Builds and installs OpenVolumeMesh 3.4.1 from ../shared/anchors/openvolumemesh/ (next to
# the repository) into a cache directory, for the OpenVolumeMesh adapter's tests.
# Skipped when the install is already there. Prints the install prefix on the last line
# of stdout; prints nothing and exits 0 when the sources are not available.
#
# Environment: HEXEX_OVM_PREFIX (default ${XDG_CACHE_HOME:-$HOME/.cache}/hexex-deps/ovm-3.4.1).
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ARCHIVE="$REPO_ROOT/../shared/anchors/openvolumemesh/OpenVolumeMesh-3.4.1.tar.xz"
PREFIX="${HEXEX_OVM_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/hexex-deps/ovm-3.4.1}"

if [[ -f "$PREFIX/.hexex-installed" ]]; then
    echo "$PREFIX"
    exit 0
fi
if [[ ! -f "$ARCHIVE" ]]; then
    echo "build-openvolumemesh: $ARCHIVE not found; the OpenVolumeMesh adapter tests will be skipped" >&2
    exit 0
fi

WORK="$(mktemp -d "${TMPDIR:-/tmp}/hexex-ovm.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
echo "build-openvolumemesh: building OpenVolumeMesh 3.4.1 into $PREFIX (a few minutes)" >&2
tar -xJf "$ARCHIVE" -C "$WORK"
GEN=()
command -v ninja >/dev/null 2>&1 && GEN=(-G Ninja)
cmake -S "$WORK/OpenVolumeMesh-3.4.1" -B "$WORK/build" "${GEN[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DOVM_ENABLE_UNITTESTS=OFF -DOVM_ENABLE_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX="$PREFIX" >&2
cmake --build "$WORK/build" --parallel "$(nproc 2>/dev/null || echo 2)" >&2
cmake --install "$WORK/build" >&2
touch "$PREFIX/.hexex-installed"
echo "$PREFIX"
