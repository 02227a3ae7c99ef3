#!/usr/bin/env bash
# Installs the build dependencies (Debian/Ubuntu, only when something is missing) and
# configures + builds HexEx in Release mode into <repo>/build.
# Idempotent: a second run skips apt and only rebuilds what changed.
#
# Two profiles (HEXEX_PROFILE):
#   tool  - what the library and the `hexex` tool need (compiler, CMake, CGAL, Eigen, OpenMesh,
#           pugixml, zlib), and builds only the `hexex` target (and its library). Used by
#           scripts/run-example.sh so a first result needs no test or documentation packages.
#   full  - (default) adds GoogleTest, Doxygen, xz, Python with numpy/meshio/venv (the test
#           suite, the documentation test and the Python package tests) and builds every target.
#
# Environment: BUILD_DIR (default <repo>/build), BUILD_TYPE (default Release),
#              HEXEX_PROFILE (tool|full, default full), HEXEX_SKIP_APT=1 to never touch apt,
#              CMAKE_ARGS for extra configure flags, HEXEX_WITH_OVM=1 to build OpenVolumeMesh
#              for the adapter tests (see below).
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$REPO_ROOT/build}"
BUILD_TYPE="${BUILD_TYPE:-Release}"
PROFILE="${HEXEX_PROFILE:-full}"

TOOL_PACKAGES=(cmake ninja-build g++ ccache libcgal-dev libeigen3-dev libopenmesh-dev
               libpugixml-dev zlib1g-dev)
TEST_PACKAGES=(libgtest-dev doxygen xz-utils python3 python3-numpy python3-meshio python3-venv python3-dev)

case "$PROFILE" in
    tool) PACKAGES=("${TOOL_PACKAGES[@]}")
          CONFIGURE_ARGS=(-DHEXEX_BUILD_TESTS=OFF -DHEXEX_BUILD_BENCHMARKS=OFF)
          BUILD_TARGETS=(--target hexex) ;;
    full) PACKAGES=("${TOOL_PACKAGES[@]}" "${TEST_PACKAGES[@]}")
          CONFIGURE_ARGS=(-DHEXEX_BUILD_TESTS=ON -DHEXEX_BUILD_BENCHMARKS=ON)
          BUILD_TARGETS=() ;;
    *) echo "setup: HEXEX_PROFILE must be 'tool' or 'full', not '$PROFILE'" >&2; exit 2 ;;
esac

missing_packages() {
    local p status
    for p in "${PACKAGES[@]}"; do
        status="$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)"
        [[ "$status" == "install ok installed" ]] || echo "$p"
    done
}

if [[ "${HEXEX_SKIP_APT:-0}" != 1 ]] && command -v dpkg-query >/dev/null 2>&1; then
    mapfile -t missing < <(missing_packages)
    if (( ${#missing[@]} > 0 )); then
        echo "setup: installing ${missing[*]}"
        SUDO=()
        if [[ "$(id -u)" != 0 ]]; then
            command -v sudo >/dev/null 2>&1 || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
            SUDO=(sudo)
        fi
        export DEBIAN_FRONTEND=noninteractive
        "${SUDO[@]}" apt-get update -q
        "${SUDO[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
    else
        echo "setup: all $PROFILE-profile dependencies are installed"
    fi
fi

# OpenVolumeMesh for the adapter tests (HexEx/Adapters/OpenVolumeMesh.hh): with
# HEXEX_WITH_OVM=1 (set by run-tests.sh) it is built once from ../shared/anchors/openvolumemesh
# into a cache directory (scripts/build-openvolumemesh.sh) and passed to the configure.
if [[ "${HEXEX_WITH_OVM:-0}" == 1 ]]; then
    OVM_PREFIX="$(bash "$REPO_ROOT/scripts/build-openvolumemesh.sh" | tail -n 1)" ||
        { echo "setup: building OpenVolumeMesh failed; its adapter tests will be skipped" >&2; OVM_PREFIX=""; }
    if [[ -n "$OVM_PREFIX" ]]; then CMAKE_ARGS="${CMAKE_ARGS:-} -DCMAKE_PREFIX_PATH=$OVM_PREFIX"; fi
fi

GENERATOR_ARGS=()
# Keep the generator and launcher of an existing build tree. New trees use Ninja, and ccache
# so that the Python package's build (scripts/run-python-tests.sh, which compiles the library
# again in its own tree with the same flags) takes the library's objects from the cache.
if [[ ! -f "$BUILD_DIR/CMakeCache.txt" ]]; then
    command -v ninja >/dev/null 2>&1 && GENERATOR_ARGS+=(-G Ninja)
    command -v ccache >/dev/null 2>&1 && GENERATOR_ARGS+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# shellcheck disable=SC2086  # CMAKE_ARGS is a list of flags
cmake -S "$REPO_ROOT" -B "$BUILD_DIR" "${GENERATOR_ARGS[@]}" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" \
    "${CONFIGURE_ARGS[@]}" ${CMAKE_ARGS:-}
cmake --build "$BUILD_DIR" --parallel "$(nproc 2>/dev/null || echo 2)" "${BUILD_TARGETS[@]}"
echo "setup: built $BUILD_TYPE ($PROFILE profile) into $BUILD_DIR"
