/// @file SingularityGraph.cc
/// singularityGraph(): singular edges of the input as a graph of 3D segments.

#include "SingularityGraph.hh"

#include "Transitions.hh"

#include <unordered_map>

namespace HexEx {

SingularityGraph singularityGraph(const ParametrizedTetMesh& pm, const std::vector<int>* givenRotations, int threads) {
    const Transitions tr = computeTransitions(pm.mesh, pm.params, givenRotations, threads);
    const Singularities s = findSingularities(pm.mesh, pm.params, tr, threads);
    SingularityGraph g;
    std::unordered_map<int, int> index;  // tet-mesh vertex -> point
    const auto point = [&](VertexHandle v) {
        const auto [it, inserted] = index.emplace(v.idx(), static_cast<int>(g.points.size()));
        if (inserted) {
            g.points.push_back(pm.mesh.position(v));
            g.point_vertices.push_back(v);
        }
        return it->second;
    };
    g.segments.reserve(s.edges.size());
    for (const SingularEdge& e : s.edges) {
        const auto ev = pm.mesh.edge_vertices(e.edge);
        g.segments.push_back({point(ev[0]), point(ev[1])});
        g.edges.push_back(e.edge);
        g.valences.push_back(e.valence);
    }
    return g;
}

} // namespace HexEx
