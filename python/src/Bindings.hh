#pragma once
/// @file Bindings.hh
/// The groups of functions of the extension module hexex._core, one file each.

#include <nanobind/nanobind.h>

namespace HexExPython {

/// Tet maps: reading and writing `.hexex`/`.ovm`, generators, perturbation, statistics
/// (MapFunctions.cc).
void bindMapFunctions(nanobind::module_& m);

/// Hex meshes: reading, writing and validation (HexMeshFunctions.cc).
void bindHexMeshFunctions(nanobind::module_& m);

/// Untangling of hex meshes (UntangleFunctions.cc).
void bindUntangleFunctions(nanobind::module_& m);

/// Quality optimisation of hex meshes (OptimizeFunctions.cc).
void bindOptimizeFunctions(nanobind::module_& m);

} // namespace HexExPython
