#pragma once
/// @file QuadEx.hh
/// @ingroup quad
/// The 2D (quad) API in one include: extractQuadMesh() on the built-in types
/// (Quad/QuadExtraction.hh) and for any kernel through traits, with the OpenMesh and
/// plain-array specializations (Quad/QuadTraits.hh).

#include "Quad/QuadExtraction.hh"
#include "Quad/QuadTraits.hh"
