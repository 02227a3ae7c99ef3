#!/usr/bin/env bash
# Sets up and builds HexEx (scripts/setup.sh), then runs the whole test suite with ctest:
# the GoogleTest unit and end-to-end tests, the install + find_package(HexEx) test and,
# when enabled, the documentation build; then builds the Python package into a virtual
# environment and runs its pytest suite (scripts/run-python-tests.sh). Exits non-zero if
# any test fails. HEXEX_SKIP_PYTHON=1 skips the Python part.
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$REPO_ROOT/build}"
export BUILD_DIR
export HEXEX_PROFILE=full
# Build OpenVolumeMesh from ../shared (when present) so the OpenVolumeMesh adapter tests run.
export HEXEX_WITH_OVM="${HEXEX_WITH_OVM:-1}"

bash "$REPO_ROOT/scripts/setup.sh"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j2
if [[ "${HEXEX_SKIP_PYTHON:-0}" != 1 ]]; then
    bash "$REPO_ROOT/scripts/run-python-tests.sh"
fi
