#pragma once
/// @file LocalVertexCheck.hh
/// @ingroup pipeline
/// Finds vertices that the links of an uncompacted dart array (during the annihilation)
/// merge: two quads with the same four vertices, or a quad with a repeated vertex. Each
/// cell can be a valid hex and each vertex link a sphere while alpha_3 links crossed around
/// an edge join two vertices of the source into one (Documentation/algorithm.md,
/// "Retries in other orders"); the assembled mesh then has a quad in three hexes.

#include <array>
#include <vector>

namespace HexEx {

/// Counts the quads at the vertices of the alive darts in @p seeds that repeat a vertex or
/// have the same four vertices as another quad of a different face.
///
/// Vertices are <alpha_1, alpha_2, alpha_3> orbits of alive darts, quads
/// <alpha_0, alpha_1, alpha_3> orbits; both are followed only over alive partners (free
/// and unconnected links are skipped). Every quad with a dart at one of the seeds'
/// vertices is looked at, so that two quads merged through a vertex of a seed are both
/// seen. In a valid hex mesh the count is 0. Time and memory in proportion to the darts of
/// those vertices and quads (plus one int per dart of @p alpha for the labels).
long countMergedVertexQuads(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& seeds);

} // namespace HexEx
