#!/usr/bin/env bash
# Sweep of maps built from the published hex meshes in ../shared/data/hexmeshes with heavy
# folds (SharedHexMeshes.DISABLED_FullSweep): one line per case (hexes, polyhedra, report
# and written-mesh verdicts, annihilation order kept, broken cells, extraction seconds,
# the from-hex check) and the count of cases that give the source mesh back.
#
# Usage: scripts/fold-sweep.sh [BUILD_DIR]          (default BUILD_DIR: <repo>/build)
# Environment (defaults: the standard sweep, a = 0.6,0.7,0.8, seeds 1-4, both meshes):
#   A="1.0,1.2,1.5"       amplitudes (grid units)
#   SEEDS="1-40"          seeds: numbers and ranges, comma-separated
#   MESHES="pig,cfpc16"   which meshes
# Run from the repository root (the test reads ../shared relative to it). Skips cleanly
# without the shared data.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
cd "$ROOT"
[[ -n ${A:-} ]] && export HEXEX_SWEEP_A=$A
[[ -n ${SEEDS:-} ]] && export HEXEX_SWEEP_SEEDS=$SEEDS
[[ -n ${MESHES:-} ]] && export HEXEX_SWEEP_MESHES=$MESHES
exec "$BUILD/src/Unittests/unittests" --gtest_also_run_disabled_tests --gtest_filter='SharedHexMeshes.DISABLED_FullSweep'
