/// @file ArcOutputHash.cc
/// Prints a 64-bit hash of the edge arcs and face patches (every field of HexArcs, point
/// coordinates by their bit patterns) for generated cases (valid and folded maps) and for
/// .hexex files given on the command line, at the given thread counts. Used to check that
/// speed work on the arcs stage keeps its output bit-identical: compare the printed lines
/// before and after a change.
///
/// Usage: `arc_output_hash [--threads 1,2] [FILE.hexex]...`

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>

#include "OutputHasher.hh"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Hasher = HexExBench::OutputHasher;

std::uint64_t hashArcs(const HexEx::HexArcs& a) {
    Hasher H;
    H.all(a.edges);
    H.all(a.faces);
    H.all(a.hex_edges);
    H.all(a.hex_faces);
    H.all(a.hex_face_sign);
    H.all(a.arc_offset);
    H.points(a.arc_points);
    H.all(a.patch_offset);
    H.all(a.patch_triangles);
    H.points(a.patch_points);
    H.all(a.failed_edges);
    H.all(a.failed_faces);
    return H.h;
}

} // namespace

int main(int argc, char** argv) {
    using namespace HexEx;
    std::vector<int> threads = {1, 2};
    struct Case {
        std::string name;
        ParametrizedTetMesh pm;
    };
    std::vector<Case> cases;
    std::vector<std::string> files;
    for (int a = 1; a < argc; ++a) {
        if (!std::strcmp(argv[a], "--threads") && a + 1 < argc) {
            threads.clear();
            std::stringstream ss(argv[++a]);
            std::string t;
            while (std::getline(ss, t, ',')) threads.push_back(std::stoi(t));
        } else if (argv[a][0] == '-') {
            std::fprintf(stderr, "usage: arc_output_hash [--threads 1,2] [FILE.hexex]...\n");
            return 2;
        } else {
            files.emplace_back(argv[a]);
        }
    }
    cases.push_back({"cube n=6 s=4", generateCube(6, 4)});
    cases.push_back({"cube n=2 s=7 (implicit)", generateCube(2, 7)});
    for (int k = 3; k <= 6; ++k) {
        ParametrizedTetMesh pm = generateCylinder(k, 3, 2, 3, 2);
        applyRandomChartTransforms(pm, static_cast<unsigned>(k));
        cases.push_back({"cylinder k=" + std::to_string(k) + " charts", std::move(pm)});
    }
    cases.push_back({"ring", generateRing(6, 2, 2, 6, 3, 2)});
    cases.push_back({"twisted ring", generateTwistedRing(6, 2, 4, 2)});
    for (double amp : {0.4, 1.5, 3.0})
        for (unsigned seed : {1u, 2u}) {
            ParametrizedTetMesh pm = generateCylinder(3, 3, 2, 3, 2);
            perturbParameters(pm, amp, seed);
            cases.push_back({"folded cylinder a=" + std::to_string(amp).substr(0, 3) + " seed " + std::to_string(seed), std::move(pm)});
        }
    {
        ParametrizedTetMesh pm = generateCube(8, 4);
        perturbParameters(pm, 1.0, 1);
        cases.push_back({"perturbed cube", std::move(pm)});
    }
    for (const std::string& f : files) cases.push_back({f, readHexExFile(f)});

    Hasher combined;
    for (Case& c : cases) {
        c.pm.mesh.build_adjacency();
        for (int t : threads) {
            HexMesh hm;
            HexArcs arcs;
            ExtractionOptions opt;
            opt.threads = t;
            opt.arcs = &arcs;
            extractHexMesh(c.pm, hm, opt);
            const std::uint64_t h = hashArcs(arcs);
            combined.add(h);
            std::printf("%-36s threads %d  edges %7zu  faces %7zu  arc pts %8zu  patch pts %9zu  tris %9zu  failed %zu/%zu  hash %016llx\n",
                        c.name.c_str(), t, arcs.edges.size(), arcs.faces.size(), arcs.arc_points.size(),
                        arcs.patch_points.size(), arcs.patch_triangles.size(),
                        arcs.failed_edges.size(), arcs.failed_faces.size(), static_cast<unsigned long long>(h));
        }
    }
    std::printf("combined %016llx\n", static_cast<unsigned long long>(combined.h));
    return 0;
}
