#!/usr/bin/env bash
# Sets up and builds HexEx (scripts/setup.sh), then runs the whole test suite with ctest:
# the GoogleTest unit and end-to-end tests, the install + find_package(HexEx) test and,
# when enabled, the documentation build. Exits non-zero if any test fails.
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$REPO_ROOT/build}"
export BUILD_DIR

bash "$REPO_ROOT/scripts/setup.sh"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j2
