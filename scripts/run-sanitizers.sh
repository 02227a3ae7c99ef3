#!/usr/bin/env bash
# Builds HexEx in Debug mode with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DHEXEX_SANITIZE=ON) into <repo>/build-asan and runs the whole test suite under it.
# Any sanitizer report makes the affected test fail.
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${ASAN_BUILD_DIR:-$REPO_ROOT/build-asan}"
export BUILD_TYPE=Debug
export CMAKE_ARGS="-DHEXEX_SANITIZE=ON ${CMAKE_ARGS:-}"
# OpenVolumeMesh from ../shared (when present), so the adapter tests run under the sanitizers too.
export HEXEX_WITH_OVM="${HEXEX_WITH_OVM:-1}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
# Suppressions cover third-party code only (OpenVolumeMesh; see the file).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$REPO_ROOT/scripts/ubsan-suppressions.txt}"

bash "$REPO_ROOT/scripts/setup.sh"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j2
