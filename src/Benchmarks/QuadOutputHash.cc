/// @file QuadOutputHash.cc
/// Prints a 64-bit hash of everything extractQuadMesh() returns (vertex bit patterns,
/// quads, polygons and every report count except timings) for the benchmark inputs and a
/// set of harder 2D shapes, at the given thread counts. Used to check that speed work
/// keeps the output bit-identical: compare the printed lines before and after a change.
///
/// Usage: `quad_output_hash [--threads 1,2] [--quick]` (`--quick` skips the two
/// one-million-triangle benchmark inputs).

#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/QuadGenerators.hh>

#include "OutputHasher.hh"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Hasher = HexExBench::OutputHasher;

std::uint64_t hashResult(const HexEx::QuadMesh& qm, const HexEx::QuadExtractionReport& r) {
    Hasher H;
    H.add(qm.vertices.size());
    for (const auto& v : qm.vertices)
        for (int k = 0; k < 3; ++k) H.add(v[k]);
    H.add(qm.quads.size());
    for (const auto& q : qm.quads) H.add(q);
    H.add(qm.polygons.size());
    for (const auto& p : qm.polygons) {
        H.add(p.size());
        for (int v : p) H.add(v);
    }
    const auto& i = r.input;
    for (long x : {i.vertices, i.triangles, i.boundary_edges, i.flipped_triangles, i.degenerate_triangles, i.cones,
                   i.ambiguous_transitions, i.unresolved_transitions, i.snapped_coordinates})
        H.add(x);
    H.add(i.parametric_area);
    const auto& o = r.output;
    for (long x : {o.vertices, o.quads, o.non_quad_faces, o.edges, o.boundary_edges, o.unconnected_darts, o.dropped_faces})
        H.add(x);
    const auto& d = r.darts;
    for (long x : {d.extracted, d.anti, d.annihilated_pairs, d.remaining_anti, d.asymmetric_links}) H.add(x);
    const auto& v = r.validation;
    for (long x : {v.darts, v.not_involution, v.open_links, v.eq1_edge_connection, v.eq3_quad, v.boundary_darts}) H.add(x);
    H.add(r.valid_all_quad);
    for (const auto& w : r.warnings) H.bytes(w.data(), w.size());
    return H.h;
}

} // namespace

int main(int argc, char** argv) {
    using namespace HexEx;
    std::vector<int> threads = {1, 2};
    bool quick = false;
    for (int a = 1; a < argc; ++a) {
        if (!std::strcmp(argv[a], "--threads") && a + 1 < argc) {
            threads.clear();
            std::stringstream ss(argv[++a]);
            std::string t;
            while (std::getline(ss, t, ',')) threads.push_back(std::stoi(t));
        } else if (!std::strcmp(argv[a], "--quick")) {
            quick = true;
        } else {
            std::fprintf(stderr, "usage: quad_output_hash [--threads 1,2] [--quick]\n");
            return 2;
        }
    }
    struct Case {
        std::string name;
        ParametrizedTriMesh mesh;
    };
    std::vector<Case> cases;
    if (!quick) {
        cases.push_back({"disk5", generateConeDisk(5, 316, 316)});
        cases.push_back({"disk5-perturbed", cases[0].mesh});
        perturbTriParameters(cases[1].mesh, 0.3, 1);
    }
    for (int k : {3, 5, 6})
        for (unsigned seed : {1u, 2u}) {
            ParametrizedTriMesh m = generateConeDisk(k, 12, 30);
            perturbTriParameters(m, 0.5, seed);
            cases.push_back({"cone" + std::to_string(k) + "-perturbed-" + std::to_string(seed), m});
            applyRandomTriCharts(m, seed + 7);
            cases.push_back({"cone" + std::to_string(k) + "-perturbed-charts-" + std::to_string(seed), m});
        }
    {
        ParametrizedTriMesh m = generateSquare(40, 20);
        perturbTriParameters(m, 0.5, 3);
        cases.push_back({"square-perturbed", m});
        for (auto& t : m.params)
            for (auto& p : t) p = Vec2d(std::round(2 * p[0]) / 2, std::round(2 * p[1]) / 2);
        applyRandomTriCharts(m, 4);
        cases.push_back({"square-degenerate", m});
    }
    {
        ParametrizedTriMesh m = generateTorus(9, 7, 20, 17);
        applyRandomTriCharts(m, 5);
        applyTriParameterNoise(m, 1e-11, 6);
        cases.push_back({"torus-charts-noise", m});
        ParametrizedTriMesh s = generateQuarterTurnSeam(9, 14);
        applyRandomTriCharts(s, 7);
        applyTriParameterNoise(s, 1e-11, 8);
        cases.push_back({"seam-charts-noise", s});
        ParametrizedTriMesh u = generateSquare(9, 1);
        for (auto& t : u.params)
            for (auto& p : t) p *= 6.5;
        cases.push_back({"square-unaligned", u});
        ParametrizedTriMesh c = generateConeDisk(6, 10, 10);
        applyTriParameterNoise(c, 0.2, 9);
        cases.push_back({"cone6-noise", c});
    }
    Hasher all;
    for (const Case& c : cases)
        for (int t : threads) {
            QuadMesh qm;
            QuadExtractionOptions opt;
            opt.threads = t;
            opt.min_triangles_per_thread = 1;  // the hash must not depend on the thread count, so really use them
            const QuadExtractionReport r = extractQuadMesh(c.mesh, qm, opt);
            const std::uint64_t h = hashResult(qm, r);
            all.add(h);
            std::printf("%-32s threads %d  quads %8ld  polys %4ld  valid %d  hash %016llx\n", c.name.c_str(), t,
                        r.output.quads, r.output.non_quad_faces, r.valid_all_quad ? 1 : 0,
                        static_cast<unsigned long long>(h));
        }
    std::printf("combined %016llx\n", static_cast<unsigned long long>(all.h));
    return 0;
}
