#pragma once
/// @file HexEx.hh
/// @ingroup kernel
/// The one-call API: extract a hex mesh from a tet mesh with an integer-grid map.
/// HexEx::extractHexMesh() is declared by the pipeline's driver (Pipeline/Extractor.hh);
/// this header gathers it with the output types and the library version.

#include "Core/Version.hh"
#include "Extraction/ExtractionReport.hh"
#include "Mesh/HexArcs.hh"
#include "Mesh/HexProvenance.hh"
#include "Mesh/HexMesh.hh"
#include "Mesh/ParametrizedTetMesh.hh"
#include "Pipeline/Extractor.hh"
