#pragma once
/// @file CgalLinearCellComplexT_impl.hh
/// Template bodies of the CGAL Linear_cell_complex adapter's one-call overloads of
/// extractHexMesh() (declared in CgalLinearCellComplex.hh, which includes this file): the tets
/// are read straight into the built-in kernel, extracted, the copy freed, and the result
/// written into the user's LCC.

#include "../Core/Error.hh"
#include "../HexExTraits.hh"

#include <array>
#include <climits>
#include <cstddef>
#include <string>

namespace HexEx {
namespace detail {

/// Copies the tets of @p lcc into the built-in kernel (the order of LccTetMesh) with the
/// parameters given by @p param (see the accessor overload of extractHexMesh()) and builds
/// the adjacency with @p threads threads.
template <class LCC, class ParamFn>
ParametrizedTetMesh lccToParametrizedTetMesh(const LCC& lcc, const ParamFn& param, int threads) {
    using Dart = typename LCC::Dart_const_handle;
    const std::unordered_map<const void*, std::size_t> index = lccVertexIndex(lcc);
    // A closed tet volume has 12 darts: the number of tets without a pass over the darts
    // (one_dart_per_cell<3>().size() walks them all).
    const std::size_t nv = index.size(), nt = lcc.number_of_darts() / 12;
    constexpr std::size_t kMax = static_cast<std::size_t>(INT_MAX) / 4;
    if (nv > kMax || nt > kMax)
        throw InputError("mesh too large: " + std::to_string(nv) + " vertices, " + std::to_string(nt) +
                         " tets (at most " + std::to_string(kMax) + " each)");
    ParametrizedTetMesh pm;
    pm.mesh.reserve(nv, nt);
    pm.params.reserve(nt);
    for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it)
        pm.mesh.add_vertex(lccToVec3d(it->point()));
    std::array<VertexHandle, 4> h;
    std::array<Vec3d, 4> u;
    for (auto it = lcc.template one_dart_per_cell<3>().begin(); it != lcc.template one_dart_per_cell<3>().end(); ++it) {
        const std::size_t t = pm.params.size();
        const std::array<Dart, 4> c = lccTetCornerDarts(lcc, Dart(it), t);
        for (std::size_t i = 0; i < 4; ++i) {
            h[i] = VertexHandle(static_cast<int>(lccVertexOf(lcc, index, c[i], t)));
            u[i] = lccToVec3d(param(lcc, c[i]));
        }
        pm.mesh.add_cell(h);
        pm.params.push_back(u);
    }
    pm.mesh.build_adjacency(threads);
    return pm;
}

/// Body of both one-call overloads: read, extract, free the copy, write.
template <class TetLcc, class ParamFn, class HexLcc>
ExtractionReport extractLcc(const TetLcc& tets, const ParamFn& param, HexLcc& hexes, const ExtractionOptions& options) {
    HexMesh hm;
    ExtractionReport report;
    {
        const ParametrizedTetMesh pm = lccToParametrizedTetMesh(tets, param, options.threads);
        report = extractHexMesh(pm, hm, options);
    }
    LccHexOutput<HexLcc> out(hexes);
    fromHexMesh(hm, out);
    return report;
}

} // namespace detail

template <class TetLcc, class HexLcc,
          std::enable_if_t<detail::IsLcc3<TetLcc>::value && detail::IsLcc3<HexLcc>::value, int>>
ExtractionReport extractHexMesh(const TetLcc& tets, HexLcc& hexes, const ExtractionOptions& options) {
    return detail::extractLcc(tets, LccDartInfoParameter{}, hexes, options);
}

template <class TetLcc, class ParamFn, class HexLcc,
          std::enable_if_t<detail::IsLcc3<TetLcc>::value && detail::IsLcc3<HexLcc>::value, int>>
ExtractionReport extractHexMesh(const TetLcc& tets, const ParamFn& param, HexLcc& hexes,
                                const ExtractionOptions& options) {
    return detail::extractLcc(tets, param, hexes, options);
}

} // namespace HexEx
