// chooseVertexPreimages() against a direct search written from its documentation: every
// combination of candidates in lexicographic order, each one's hex values sorted anew, the
// first best kept, the other candidates only if the preferred ones leave a hex inverted. The
// library keeps the sorted list up to date from one combination to the next and skips the
// vertices with one candidate; the chosen positions must be the same.

#include <HexEx/Postprocessing/VertexPreimageChoice.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

using namespace HexEx;

namespace {

/// A block of 4 x 3 x 1 unit hexes (5 x 4 x 2 vertices, VTK order).
HexMesh hexBlock() {
    HexMesh m;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 5; ++x) m.vertices.push_back(Vec3d(x, y, z));
    auto v = [](int x, int y, int z) { return x + 5 * y + 20 * z; };
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            m.hexes.push_back({v(x, y, 0), v(x + 1, y, 0), v(x + 1, y + 1, 0), v(x, y + 1, 0), v(x, y, 1), v(x + 1, y, 1), v(x + 1, y + 1, 1),
                               v(x, y + 1, 1)});
    return m;
}

/// A fixed pseudo-random sequence (the test does not depend on the library's generators).
struct Lcg {
    std::uint64_t s;
    /// Next value in [0, 1).
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    }
    /// Next integer in [0, n).
    int below(int n) { return std::min(n - 1, static_cast<int>(next() * n)); }
};

/// The documented choice for the listed vertices @p members of @p c (one cluster),
/// searched directly.
void directChoice(HexMesh& mesh, const VertexCandidates& c, const std::vector<std::size_t>& members) {
    const std::size_t n = members.size();
    std::vector<int> hexes;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (int v : mesh.hexes[h])
            if (std::any_of(members.begin(), members.end(), [&](std::size_t k) { return c.vertex[k] == v; })) {
                hexes.push_back(static_cast<int>(h));
                break;
            }
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<int> count(n), pick(n, 0), best(n, 0);
        for (std::size_t k = 0; k < n; ++k)
            count[k] = pass == 0 ? c.preferred[members[k]] : c.offset[members[k] + 1] - c.offset[members[k]];
        std::vector<double> bestQ;
        for (bool more = true; more;) {
            for (std::size_t k = 0; k < n; ++k)
                mesh.vertices[static_cast<std::size_t>(c.vertex[members[k]])] = c.position[static_cast<std::size_t>(c.offset[members[k]] + pick[k])];
            std::vector<double> q(1, 0.0);
            for (int h : hexes) {
                q.push_back(minScaledJacobian(mesh, mesh.hexes[static_cast<std::size_t>(h)]));
                if (q.back() <= 0) q[0] -= 1.0;
            }
            std::sort(q.begin() + 1, q.end());
            if (bestQ.empty() || q > bestQ) {
                bestQ = q;
                best = pick;
            }
            more = false;
            for (std::size_t k = n; k-- > 0;) {
                if (++pick[k] < count[k]) {
                    more = true;
                    break;
                }
                pick[k] = 0;
            }
        }
        for (std::size_t k = 0; k < n; ++k)
            mesh.vertices[static_cast<std::size_t>(c.vertex[members[k]])] = c.position[static_cast<std::size_t>(c.offset[members[k]] + best[k])];
        if (bestQ[1] > 0) break;
    }
}

/// The documented choice for every cluster of @p c (listed vertices joined through shared
/// hexes; clusters share no hex, so they are searched one by one).
HexMesh directChoice(HexMesh mesh, const VertexCandidates& c) {
    const std::size_t n = c.vertex.size();
    std::vector<int> cluster(n);
    for (std::size_t k = 0; k < n; ++k) cluster[k] = static_cast<int>(k);
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& h : mesh.hexes)
            for (std::size_t a = 0; a < n; ++a)
                for (std::size_t b = 0; b < n; ++b)
                    if (cluster[a] != cluster[b] && std::count(h.begin(), h.end(), c.vertex[a]) && std::count(h.begin(), h.end(), c.vertex[b])) {
                        cluster[a] = cluster[b] = std::min(cluster[a], cluster[b]);
                        changed = true;
                    }
    }
    for (std::size_t r = 0; r < n; ++r) {
        std::vector<std::size_t> members;
        for (std::size_t k = 0; k < n; ++k)
            if (cluster[k] == static_cast<int>(r)) members.push_back(k);
        if (!members.empty()) directChoice(mesh, c, members);
    }
    return mesh;
}

} // namespace

TEST(VertexPreimageChoice, SameChoiceAsTheDirectSearch) {
    Lcg rng{12345};
    int inverted = 0, moved = 0;
    for (int round = 0; round < 300; ++round) {
        const HexMesh mesh = hexBlock();
        VertexCandidates c;
        c.offset.push_back(0);
        // Listed: about a third of the vertices, one to three candidates each (many with
        // one, which the library's counter skips).
        for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
            if (rng.next() >= 0.35) continue;
            const int nCand = 1 + rng.below(rng.next() < 0.5 ? 1 : 3);
            c.vertex.push_back(v);
            c.preferred.push_back(1 + rng.below(nCand));
            for (int k = 0; k < nCand; ++k) {
                const double amp = rng.next() < 0.3 ? 1.2 : 0.3;  // large moves invert hexes
                c.position.push_back(mesh.vertices[static_cast<std::size_t>(v)] +
                                     Vec3d(amp * (rng.next() - 0.5), amp * (rng.next() - 0.5), amp * (rng.next() - 0.5)));
            }
            c.offset.push_back(static_cast<int>(c.position.size()));
        }
        const HexMesh expected = directChoice(mesh, c);
        HexMesh got = mesh;
        chooseVertexPreimages(got, c);
        ASSERT_EQ(got.vertices.size(), expected.vertices.size());
        for (std::size_t v = 0; v < got.vertices.size(); ++v) ASSERT_EQ(got.vertices[v], expected.vertices[v]) << "round " << round << ", vertex " << v;
        for (std::size_t k = 0; k < c.vertex.size(); ++k)
            moved += got.vertices[static_cast<std::size_t>(c.vertex[k])] != c.position[static_cast<std::size_t>(c.offset[k])] ? 1 : 0;
        for (const auto& h : got.hexes) inverted += minScaledJacobian(got, h) <= 0 ? 1 : 0;
    }
    // The rounds exercise both the choice away from the first candidate and the pass over
    // all candidates (some rounds keep an inverted hex).
    EXPECT_GT(moved, 100);
    EXPECT_GT(inverted, 0);
}
