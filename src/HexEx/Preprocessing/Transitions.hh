#pragma once
/// @file Transitions.hh
/// Transition functions per halfface (paper 4.1.1) and singularity detection.

#include "../Grid/GridTransform.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <vector>

namespace HexEx {

/// Transitions of a parametrized tet mesh.
struct Transitions {
    /// Per halfface h = 4c+i: the map from the chart of cell c to the chart of the
    /// neighbour across h (identity on boundary halffaces).
    std::vector<GridTransform> halfface;
    /// Number of interior faces whose rotation could not be read from the parameters
    /// (degenerate face image) and was resolved from the neighbourhood.
    int n_ambiguous = 0;
    /// Of those, how many could not be resolved by edge consistency (best residual taken).
    int n_unresolved = 0;
};

/// Infers every interior halfface's transition from the corner parameters of the two
/// cells: the rotation that best maps the shared face's edge vectors, then the rounded
/// translation. If @p given_rotations is non-null it holds a rotation index (0..23) per
/// halfface that is used instead of inferring one (the paper's assumption). @p threads
/// parallelizes the per-face fits; the result does not depend on it.
Transitions computeTransitions(const TetMesh& mesh, const CornerParams& params,
                               const std::vector<int>* given_rotations = nullptr, int threads = 1);

/// A singular edge: the accumulated transition around it is not the identity.
struct SingularEdge {
    EdgeHandle edge;        ///< the edge
    int valence = 0;        ///< number of quarter turns of parametric angle around it (4 = regular)
    Rotation holonomy;      ///< accumulated rotation around the edge
};

/// Singular edges and vertices.
struct Singularities {
    std::vector<SingularEdge> edges;          ///< interior singular edges, by edge index
    std::vector<VertexHandle> vertices;       ///< vertices incident to a number of singular edges other than 0 or 2
    std::vector<char> is_singular_vertex;     ///< per vertex: lies on a singular edge
};

/// Finds the interior edges whose holonomy (composition of transitions around the edge) is
/// not the identity, with their valence computed from the parametric dihedral angles.
/// @p threads parallelizes over edges; the result does not depend on it.
Singularities findSingularities(const TetMesh& mesh, const CornerParams& params, const Transitions& tr,
                                int threads = 1);

/// The halfface of cell @p c that contains edge (@p a, @p b) and leads to cell @p next, or invalid.
HalfFaceHandle halffaceTowards(const TetMesh& mesh, CellHandle c, CellHandle next);

} // namespace HexEx
