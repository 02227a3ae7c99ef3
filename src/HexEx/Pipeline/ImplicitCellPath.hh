#pragma once
/// @file ImplicitCellPath.hh
/// @ingroup pipeline
/// The implicit-cell fast path, in one place: unit cells inside one large proper tet are
/// built from the grid without darts (ExtractionOptions::implicit_cells). This file decides
/// when the path is used, which tet faces may carry implicit-cell corners, how explicit
/// darts refer to implicit cells (occurrence ids) and builds the implicit cells for the
/// assembly (ImplicitCells).

#include "../Core/DefaultInitAllocator.hh"
#include "../Extraction/ConnectionTracing.hh"
#include "../Postprocessing/HexMeshAssembly.hh"

#include <vector>

namespace HexEx {

/// True if the fast path is used: requested and no tet is flipped (otherwise a fold could
/// annihilate darts of an implicit cell).
inline bool useImplicitCells(bool requested, long flipped_tets) { return requested && flipped_tets == 0; }

/// Per tet: bit j set if grid points on face j may be corners of implicit cells (the face
/// is on the boundary or shared with a proper tet, where vertices are joined across).
std::vector<FaceMask> implicitCellFaces(const TetMesh& mesh, const std::vector<TetSoS>& tets);

/// Per surviving dart (new index): the occurrence id of its implicit alpha_3 partner, or
/// -1. Reads the traced links @p alpha before they are compacted; @p new_index maps old
/// dart indices to new ones (-1 for removed darts).
DefaultInitVector<int> implicitAlpha3Occurrences(const std::vector<DartLinks>& alpha, const std::vector<char>& alive,
                                           const std::vector<int>& new_index, int n_alive, int threads);

/// Per surviving dart (new index): the occurrence id of its own grid point, or -1; empty
/// if @p darts has no occurrences.
DefaultInitVector<int> implicitDartOccurrences(const DartSet& darts, const std::vector<char>& alive,
                                         const std::vector<int>& new_index, int n_alive, int threads);

/// Fills the implicit cells of @p darts into @p out: n_occurrences, cells (8 corner
/// occurrences in VTK order, in the sequential order for any thread count), boundary_quads,
/// joined_occurrences and position. The position function refers to @p mesh, @p tets and
/// @p darts: they must outlive @p out's use.
void buildImplicitCells(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets,
                        const DartSet& darts, int threads, ImplicitCells& out);

} // namespace HexEx
