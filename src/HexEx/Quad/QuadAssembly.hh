#pragma once
/// @file QuadAssembly.hh
/// @ingroup quad
/// Quad mesh assembly in 2D: vertices are the <alpha_1, alpha_2> orbits of the final map,
/// faces its <alpha_0, alpha_1> orbits.

#include "QuadGMapValidator.hh"
#include "QuadMesh.hh"
#include "TriangleDarts.hh"

namespace HexEx {

/// Counts of the assembly.
struct QuadAssemblyStats {
    long quads = 0;           ///< faces with 8 darts and 4 distinct vertices
    long polygons = 0;        ///< other faces with at least 3 distinct vertices
    long dropped_faces = 0;   ///< faces with fewer than 3 distinct vertices
    long boundary_edges = 0;  ///< edge orbits with a free alpha_2
};

/// Builds @p out from the map with links @p links (every dart alive) whose dart k is @p darts[k] (same indexing) and its
/// orbit @p labels. Vertex positions: the point of the vertex orbit's smallest dart,
/// mapped from its triangle's parameter image to 3D by barycentric coordinates. Faces are
/// numbered by their smallest dart and oriented counter-clockwise in parameter space.
/// Runs on @p threads threads; the result does not depend on their number.
QuadAssemblyStats assembleQuadMesh(const QuadLinks& links, const TriDartVector& darts, const QuadOrbitLabels& labels,
                                   const ParametrizedTriMesh& mesh, const TriParams& params, QuadMesh& out,
                                   int threads = 1);

} // namespace HexEx
