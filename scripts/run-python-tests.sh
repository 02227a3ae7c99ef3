#!/usr/bin/env bash
# Builds and installs the Python package (python/) into a virtual environment and runs its
# pytest suite (python/tests). Called by scripts/run-tests.sh after ctest; exits non-zero
# if the build or any test fails.
#
# Why a virtual environment: it works the same with any python3 on PATH (a pyenv CPython, or
# Debian's /usr/bin/python3, whose pip refuses system-wide installs under PEP 668), it
# never changes the user's interpreter, and the pinned versions of
# python/requirements-test.txt (build backend, nanobind, numpy, meshio, matplotlib, pytest)
# come from PyPI. The package is built without build isolation into a persistent CMake tree
# ($BUILD_DIR/python), so a second run only rebuilds what changed.
#
# Environment: BUILD_DIR (default <repo>/build), PYTHON (default python3: the interpreter
# the environment is made from), HEXEX_PYTHON_VENV (default $BUILD_DIR/python-venv).
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$REPO_ROOT/build}"
PYTHON="${PYTHON:-python3}"
VENV="${HEXEX_PYTHON_VENV:-$BUILD_DIR/python-venv}"

if [[ ! -x "$VENV/bin/python" ]]; then
    echo "python-tests: creating the virtual environment $VENV with $(command -v "$PYTHON")"
    "$PYTHON" -m venv "$VENV"
fi
VPY="$VENV/bin/python"
"$VPY" -m pip install --quiet --disable-pip-version-check -r "$REPO_ROOT/python/requirements-test.txt"

# Build with two jobs (the C++ library is compiled again for the module); reuse ccache if present.
BUILD_ARGS=(-C "build-dir=$BUILD_DIR/python")
if command -v ccache >/dev/null 2>&1; then
    BUILD_ARGS+=(-C "cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache")
fi
echo "python-tests: building and installing the hexex package (python/)"
CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}" \
    "$VPY" -m pip install --quiet --disable-pip-version-check --no-build-isolation "${BUILD_ARGS[@]}" "$REPO_ROOT/python"
"$VPY" -c "import hexex; print('python-tests: hexex', hexex.__version__, 'from', hexex.__file__)"

# The suite compares with the CLI of the C++ build.
export HEXEX_CLI="${HEXEX_CLI:-$BUILD_DIR/src/Tools/hexex/hexex}"
cd "$REPO_ROOT/python"
"$VENV/bin/pytest" -q tests
