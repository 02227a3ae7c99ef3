#pragma once
/// @file CgalLinearCellComplexT_impl.hh
/// Template bodies of the CGAL Linear_cell_complex adapter's one-call overloads of
/// extractHexMesh() (declared in CgalLinearCellComplex.hh, which includes this file): the tets
/// are read straight into the built-in kernel, extracted, the copy freed, and the result
/// written into the user's LCC.

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../HexExTraits.hh"
#include "../Preprocessing/SingularityGraph.hh"
#include "../Preprocessing/Transitions.hh"

#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace HexEx {
namespace detail {

/// The dart of the face opposite corner @p i in the tet with corner darts @p c
/// (lccTetCornerDarts()): the face of c[0] is opposite corner 3, the faces across its
/// edges from corners 0, 1 and 2 are opposite corners 2, 0 and 1.
template <class LCC>
typename LCC::Dart_const_handle lccFaceOpposite(const LCC& lcc, const std::array<typename LCC::Dart_const_handle, 4>& c,
                                                int i) {
    switch (i) {
    case 3: return c[0];
    case 2: return lcc.beta(c[0], 2);
    case 0: return lcc.beta(c[1], 2);
    default: return lcc.beta(c[2], 2);
    }
}

/// A mark of a CGAL combinatorial map, released (every dart unmarked first) when the
/// object goes out of scope, exceptions included.
template <class LCC>
struct LccMark {
    /// Reserves a mark of @p lcc (marks are mutable in CGAL: a const map can be marked).
    explicit LccMark(const LCC& lcc) : map(lcc), id(lcc.get_new_mark()) {}
    /// Unmarks every dart and frees the mark.
    ~LccMark() {
        map.unmark_all(id);
        map.free_mark(id);
    }
    /// Not copyable: the mark is freed once.
    LccMark(const LccMark&) = delete;
    /// Not copyable: the mark is freed once.
    LccMark& operator=(const LccMark&) = delete;

    const LCC& map;                   ///< the marked map
    typename LCC::size_type id;       ///< the mark
};

/// Copies the tets of @p lcc into the built-in kernel (the order of LccTetMesh) with the
/// parameters given by @p param (see the accessor overload of extractHexMesh()) and builds
/// the adjacency with @p threads threads. With @p tetDarts, fills it with the first dart of
/// every tet; with @p given (and @p givenOut), reads the given rotation of every interior face.
template <class LCC, class ParamFn>
ParametrizedTetMesh lccToParametrizedTetMesh(const LCC& lcc, const ParamFn& param, int threads,
                                             std::vector<typename LCC::Dart_const_handle>* tetDarts = nullptr,
                                             const std::function<int(const LCC&, typename LCC::Dart_const_handle)>* given = nullptr,
                                             std::vector<int>* givenOut = nullptr) {
    using Dart = typename LCC::Dart_const_handle;
    const LccVertexNumbering index(lcc);
    // A closed tet volume has 12 darts: the number of tets without a pass over the darts
    // (one_dart_per_cell<3>().size() walks them all).
    const std::size_t nv = index.size(), nt = lcc.number_of_darts() / 12;
    constexpr std::size_t kMax = static_cast<std::size_t>(INT_MAX) / 4;
    if (nv > kMax || nt > kMax)
        throw InputError("mesh too large: " + std::to_string(nv) + " vertices, " + std::to_string(nt) +
                         " tets (at most " + std::to_string(kMax) + " each)");
    // Filled once each (reserve + push_back, no per-cell growth of the kernel's property
    // arrays) and moved into the kernel.
    std::vector<Vec3d> positions;
    std::vector<std::array<VertexHandle, 4>> cells;
    ParametrizedTetMesh pm;
    positions.reserve(nv);
    cells.reserve(nt);
    pm.params.reserve(nt);
    for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it)
        positions.push_back(lccToVec3d(it->point()));
    std::array<VertexHandle, 4> h;
    std::array<Vec3d, 4> u;
    // One dart per volume in the order of one_dart_per_cell<3>() (the darts in container
    // order, each unmarked one starting a volume whose darts are then marked), marking the
    // 12 darts the tetrahedron check has already found instead of walking the volume again.
    const LccMark<LCC> mark(lcc);
    Dart faces[4][3];
    std::size_t hint[4] = {0, 0, 0, 0};  // per corner: the vertex run found last (LccVertexNumbering::find())
    for (auto it = lcc.darts().begin(); it != lcc.darts().end(); ++it) {
        if (lcc.is_marked(it, mark.id)) continue;
        const std::size_t t = pm.params.size();
        const std::array<Dart, 4> c = lccTetCornerDarts(lcc, Dart(it), t, &faces);
        for (const auto& f : faces)
            for (const Dart& x : f) lcc.mark(x, mark.id);
        for (std::size_t i = 0; i < 4; ++i) {
            h[i] = VertexHandle(static_cast<int>(lccVertexOf(lcc, index, c[i], t, &hint[i])));
            u[i] = lccToVec3d(param(lcc, c[i]));
        }
        cells.push_back(h);
        pm.params.push_back(u);
        if (tetDarts) tetDarts->push_back(c[0]);
        if (given && *given) {
            for (int i = 0; i < 4; ++i) {
                const Dart f = lccFaceOpposite(lcc, c, i);
                int r = 0;
                if (!lcc.template is_free<3>(f)) {
                    r = (*given)(lcc, f);
                    if (r < 0 || r > 23)
                        throw InputError("LCC volume " + std::to_string(t) + ": given rotation " + std::to_string(r) +
                                         " of the face opposite corner " + std::to_string(i) +
                                         " is not a rotation index (0..23)");
                }
                givenOut->push_back(r);
            }
        }
    }
    pm.mesh.assign(std::move(positions), std::move(cells));
    pm.mesh.build_adjacency(threads);
    return pm;
}

/// Reports the transitions and singular edges of @p pm (read from @p lcc, tets starting at
/// @p tetDarts) through @p results.
template <class TetLcc, class HexLcc>
void reportLccTetResults(const TetLcc& lcc, const ParametrizedTetMesh& pm,
                         const std::vector<typename TetLcc::Dart_const_handle>& tetDarts, const ExtractionOptions& options,
                         const LccResults<TetLcc, HexLcc>& results) {
    using Dart = typename TetLcc::Dart_const_handle;
    if (!results.transition && !results.singular_edge) return;
    const int threads = resolveThreadCount(options.threads);
    const Transitions tr = computeTransitions(pm.mesh, pm.params, options.given_rotations, threads);
    const auto corners = [&](std::size_t t) { return std::array<Dart, 4>{tetDarts[t], lcc.beta(tetDarts[t], 1), lcc.beta(tetDarts[t], 1, 1), lcc.beta(tetDarts[t], 2, 0)}; };
    if (results.transition)
        for (std::size_t t = 0; t < tetDarts.size(); ++t) {
            const std::array<Dart, 4> c = corners(t);
            for (int i = 0; i < 4; ++i) {
                const GridTransform g = tr.halfface[4 * t + static_cast<std::size_t>(i)];
                results.transition(lccFaceOpposite(lcc, c, i), g.R.index(), {g.t[0], g.t[1], g.t[2]});
            }
        }
    if (results.singular_edge) {
        const Singularities sing = findSingularities(pm.mesh, pm.params, tr, threads);
        std::unordered_map<std::uint64_t, int> valence;  // (smaller vertex, larger vertex) -> valence
        const auto key = [](int a, int b) {
            return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
        };
        for (const SingularEdge& e : sing.edges) {
            const auto& ev = pm.mesh.edge_vertices(e.edge);
            valence.emplace(key(ev[0].idx(), ev[1].idx()), e.valence);
        }
        // One dart per singular edge: from the first tet (in order) that has it, the dart of
        // that tet running along it.
        for (std::size_t t = 0; t < tetDarts.size() && !valence.empty(); ++t) {
            const std::array<Dart, 4> c = corners(t);
            for (int f = 0; f < 4; ++f) {
                Dart x = lccFaceOpposite(lcc, c, f);
                for (int k = 0; k < 3; ++k, x = lcc.beta(x, 1)) {
                    int a = -1, b = -1;
                    for (int i = 0; i < 4; ++i) {
                        if (lcc.vertex_attribute(c[i]) == lcc.vertex_attribute(x)) a = pm.mesh.cell_vertex(CellHandle(static_cast<int>(t)), i).idx();
                        if (lcc.vertex_attribute(c[i]) == lcc.vertex_attribute(lcc.beta(x, 1)))
                            b = pm.mesh.cell_vertex(CellHandle(static_cast<int>(t)), i).idx();
                    }
                    const auto it = valence.find(key(a, b));
                    if (it == valence.end()) continue;
                    results.singular_edge(x, it->second);
                    valence.erase(it);
                }
            }
        }
    }
}

/// Body of both one-call overloads: read, extract (and report @p results), free the copy, write.
template <class TetLcc, class ParamFn, class HexLcc>
ExtractionReport extractLcc(const TetLcc& tets, const ParamFn& param, HexLcc& hexes, const ExtractionOptions& options,
                            const LccResults<TetLcc, HexLcc>& results) {
    using Dart = typename TetLcc::Dart_const_handle;
    HexMesh hm;
    ExtractionReport report;
    HexProvenance prov;
    std::vector<Dart> tetDarts;
    const bool provenance = results.hex_provenance || results.vertex_provenance;
    {
        std::vector<int> given;
        ExtractionOptions opt = options;
        ParametrizedTetMesh pm = lccToParametrizedTetMesh(tets, param, options.threads,
                                                          results.any() ? &tetDarts : nullptr,
                                                          &results.given_rotation, &given);
        if (results.given_rotation) opt.given_rotations = &given;
        if (provenance) opt.provenance = &prov;
        // The pipeline takes the parameters over unless the transitions are reported from them.
        if (results.transition || results.singular_edge) report = extractHexMesh(pm, hm, opt);
        else report = extractHexMesh(std::move(pm), hm, opt);
        reportLccTetResults(tets, pm, tetDarts, opt, results);
    }
    LccHexOutput<HexLcc> out(hexes);
    fromHexMesh(hm, out);
    if (results.hex_provenance)
        for (std::size_t h = 0; h < prov.hex_source_tet.size() && h < out.cellDarts().size(); ++h) {
            const std::size_t t = static_cast<std::size_t>(prov.hex_source_tet[h]);
            results.hex_provenance(out.cellDarts()[h], t, tetDarts[t], prov.hex_grid_cell[h]);
        }
    if (results.vertex_provenance)
        for (std::size_t v = 0; v < prov.vertex_source_tet.size() && v < out.vertexAttributes().size(); ++v) {
            if (prov.vertex_source_tet[v] < 0) continue;
            const std::size_t t = static_cast<std::size_t>(prov.vertex_source_tet[v]);
            results.vertex_provenance(out.vertexAttributes()[v], t, tetDarts[t], prov.vertex_grid_coords[v]);
        }
    return report;
}

} // namespace detail

template <class TetLcc, class HexLcc,
          std::enable_if_t<detail::IsLcc3<TetLcc>::value && detail::IsLcc3<HexLcc>::value, int>>
ExtractionReport extractHexMesh(const TetLcc& tets, HexLcc& hexes, const ExtractionOptions& options,
                                const LccResults<TetLcc, HexLcc>& results) {
    return detail::extractLcc(tets, LccDartInfoParameter{}, hexes, options, results);
}

template <class TetLcc, class ParamFn, class HexLcc,
          std::enable_if_t<detail::IsLcc3<TetLcc>::value && detail::IsLcc3<HexLcc>::value, int>>
ExtractionReport extractHexMesh(const TetLcc& tets, const ParamFn& param, HexLcc& hexes,
                                const ExtractionOptions& options, const LccResults<TetLcc, HexLcc>& results) {
    return detail::extractLcc(tets, param, hexes, options, results);
}

} // namespace HexEx
