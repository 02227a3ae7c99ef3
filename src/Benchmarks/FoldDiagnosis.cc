/// @file FoldDiagnosis.cc
/// Diagnosis of hexes that `hexex extract --untangle` leaves not certified valid (issue 32/33,
/// S1 x2): extracts a `.hexex` map, untangles as `extract --untangle` does (boundary on the
/// map's tet boundary), and prints
///  - the hexes that are not certified valid before and after untangling,
///  - the boundary doublets (boundaryDoublets()),
///  - the hexes outside the input volume reached from the extraction's not-valid hexes
///    (hexesOutsideSurface(), centre winding number below 1/2),
///  - an experiment: those hexes removed from the extraction (removeHexes()), the newly
///    exposed boundary vertices put on the closest point of the surface, then untangled
///    without a boundary layer; the not-valid counts. (OptimizeOptions::pillow does the same
///    with the layer in between; see Documentation/algorithm.md, boundary pillowing: "The
///    fold on S1 x2".)
///
/// Usage: fold_diagnosis MAP.hexex [threads]   (default 2 threads)

#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/FoldedBoundary.hh>
#include <HexEx/Untangling/SurfaceProjection.hh>
#include <HexEx/Untangling/TriangleSurface.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

/// Indices of the hexes of @p m that are not certified valid.
std::vector<int> notValid(const HexEx::HexMesh& m, int threads) {
    const auto v = HexEx::hexValidities(m, threads);
    std::vector<int> out;
    for (std::size_t c = 0; c < v.size(); ++c)
        if (v[c] != HexEx::HexValidity::Valid) out.push_back(static_cast<int>(c));
    return out;
}

/// Prints the count and the list of @p hexes with their scaled Jacobians.
void printHexes(const char* what, const HexEx::HexMesh& m, const std::vector<int>& hexes) {
    const auto sj = HexEx::scaledJacobians(m);
    std::printf("%s: %zu\n", what, hexes.size());
    for (const int c : hexes) std::printf("  hex %d  scaled Jacobian %.4g\n", c, sj[static_cast<std::size_t>(c)]);
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: fold_diagnosis MAP.hexex [threads]\n");
        return 2;
    }
    const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
    try {
        const HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(argv[1]);
        HexEx::ExtractionOptions eo;
        eo.threads = threads;
        HexEx::HexMesh extracted;
        HexEx::extractHexMesh(pm, extracted, eo);
        const HexEx::TriangleSurface surface = HexEx::tetMeshBoundary(pm.mesh);
        std::printf("extraction: %zu hexes, %zu vertices\n", extracted.hexes.size(), extracted.vertices.size());
        const std::vector<int> bad = notValid(extracted, threads);
        printHexes("not certified valid after the extraction", extracted, bad);

        HexEx::UntangleOptions uo;
        uo.threads = threads;
        HexEx::HexMesh untangled = extracted;
        HexEx::untangleHexMesh(untangled, uo, &surface);
        printHexes("not certified valid after untangling", untangled, notValid(untangled, threads));
        const std::vector<int> doublets = HexEx::boundaryDoublets(untangled);
        std::printf("boundary doublets after untangling: %zu\n", doublets.size());
        for (const int v : doublets) {
            const auto& p = untangled.vertices[static_cast<std::size_t>(v)];
            std::printf("  vertex %d at (%.6g, %.6g, %.6g)\n", v, p[0], p[1], p[2]);
        }

        const std::vector<int> outside = HexEx::hexesOutsideSurface(extracted, surface, bad);
        printHexes("hexes outside the input volume reached from those of the extraction", extracted, outside);

        // Experiment: remove them, put the exposed boundary vertices on the surface, untangle.
        HexEx::HexMesh trimmed = extracted;
        const std::vector<int> exposed = HexEx::removeHexes(trimmed, outside);
        const HexEx::SurfaceProjection proj(surface, uo.feature_angle_deg);
        double moved_max = 0;
        long moved = 0;
        for (const int v : exposed) {
            HexEx::Vec3d& p = trimmed.vertices[static_cast<std::size_t>(v)];
            const HexEx::Vec3d q = proj.closestOnSurface(p);
            const double d = (q - p).norm();
            if (d > 0) {
                ++moved;
                moved_max = std::max(moved_max, d);
            }
            p = q;
        }
        std::printf("trimmed: %zu hexes; %ld exposed vertices put on the surface (moved up to %.4g)\n",
                    trimmed.hexes.size(), moved, moved_max);
        printHexes("  not certified valid after putting them on the surface", trimmed, notValid(trimmed, threads));
        const HexEx::UntangleReport ur = HexEx::untangleHexMesh(trimmed, uo, &surface);
        printHexes("  not certified valid after untangling the trimmed mesh", trimmed, notValid(trimmed, threads));
        std::printf("  untangler: %s\n", ur.message.empty() ? "success" : ur.message.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fold_diagnosis: %s\n", e.what());
        return 2;
    }
    return 0;
}
