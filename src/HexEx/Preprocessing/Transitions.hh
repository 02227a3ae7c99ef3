#pragma once
/// @file Transitions.hh
/// @ingroup pipeline
/// Transition functions per halfface (paper 4.1.1) and singularity detection.

#include "../Core/DefaultInitAllocator.hh"
#include "../Core/Prefetch.hh"
#include "../Grid/GridTransform.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <cstdint>
#include <utility>
#include <vector>

namespace HexEx {

/// Compact per-halfface storage of grid transforms: one byte per halfface (the rotation
/// index, plus a flag if the translation is not zero) and the non-zero translations apart,
/// sparse while they are few and dense once they are many. Most faces of real maps have the
/// identity, so this takes about 1/16 of a GridTransform per halfface.
class HalffaceTransitions {
public:
    /// @p n halffaces, all with the identity.
    void reset(std::size_t n);
    /// Number of halffaces.
    std::size_t size() const { return code_.size(); }
    /// The transform of halfface @p h.
    GridTransform operator[](std::size_t h) const {
        const std::uint8_t c = code_[h];
        if (c == 0) return GridTransform();
        return GridTransform(Rotation(c & kRotationMask), (c & kTranslated) ? translation(h) : Vec3i(0, 0, 0));
    }
    /// The rotation of halfface @p h (operator[] without looking up the translation).
    Rotation rotation(std::size_t h) const { return Rotation(code_[h] & kRotationMask); }
    /// Asks the CPU to load the code of halfface @p h (and its translation, when dense) early.
    void prefetch(std::size_t h) const {
        prefetchKept(&code_[h]);
        if (!dense_.empty()) prefetchKept(&dense_[h]);
    }
    /// True if halfface @p h has the identity.
    bool is_identity(std::size_t h) const { return code_[h] == 0; }
    /// True if every halfface has the identity (a map with one chart): one pass over the
    /// one-byte codes.
    bool all_identity() const;
    /// Sets the transform of halfface @p h (not thread-safe; see set_rotation_only()).
    void set(std::size_t h, const GridTransform& g);
    /// Sets only the rotation of @p h, whose translation must be zero. Distinct halffaces
    /// may be set from different threads.
    void set_rotation_only(std::size_t h, Rotation r) { code_[h] = static_cast<std::uint8_t>(r.index()); }
    /// Adds translations of halffaces whose rotation is set (@p list in any order, each
    /// halfface once, none stored yet); used after a parallel set_rotation_only() pass.
    void add_translations(const std::vector<std::pair<int, Vec3i>>& list);
    /// add_translations() of the lists @p parts together (each halfface in one part at
    /// most), on @p threads threads where the translations are stored densely.
    void add_translations(const std::vector<std::vector<std::pair<int, Vec3i>>>& parts, int threads);

private:
    static constexpr std::uint8_t kRotationMask = 0x1F;
    static constexpr std::uint8_t kTranslated = 0x80;
    Vec3i translation(std::size_t h) const;
    std::vector<std::uint8_t> code_;                 // rotation index | kTranslated
    std::vector<std::pair<int, Vec3i>> sparse_;      // sorted by halfface, while dense_ is empty
    DefaultInitVector<Vec3i> dense_;                 // per halfface, once translations are many (zeroed in parallel)
};

/// Transitions of a parametrized tet mesh.
struct Transitions {
    /// Per halfface h = 4c+i: the map from the chart of cell c to the chart of the
    /// neighbour across h (identity on boundary halffaces).
    HalffaceTransitions halfface;
    /// Number of interior faces whose rotation could not be read from the parameters
    /// (degenerate face image) and was resolved from the neighbourhood.
    int n_ambiguous = 0;
    /// Of those, how many could not be resolved by edge consistency (best residual taken).
    int n_unresolved = 0;
    /// Interior faces with an outlier corner: two shared corners agree on the transition
    /// (within 0.05 grid units) and the third is more than 0.5 off (a corrupted corner
    /// parameter); fitted by consensus, to the two that agree.
    int n_inconsistent = 0;
};

/// Infers every interior halfface's transition from the corner parameters of the two
/// cells: the rotation that best maps the shared face's edge vectors, then the rounded
/// translation. When the three corners do not agree on one translation under that rotation
/// and one of them is an outlier (a corrupted corner), the transition is the one the other
/// two agree on (consensus), and the face is counted in Transitions::n_inconsistent. If @p given_rotations is non-null it holds a rotation index (0..23) per
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
