/// @file HexFaceNeighbours.cc
/// The digest of a hex mesh and the check of a face-neighbour table against it.

#include "HexFaceNeighbours.hh"

#include "../Core/Parallel.hh"
#include "HexMeshCheck.hh"

#include <algorithm>
#include <vector>

namespace HexEx {

namespace {

/// Fewer hexes than this are handled on one thread.
constexpr std::size_t kParallelHexes = 20000;

/// A 64-bit mix with good avalanche (the finaliser of splitmix64).
inline std::uint64_t mix64(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

/// True if loop @p a (four vertices) is loop @p b shifted, either way round.
inline bool sameCycle(const int* a, const int* b) {
    int k = 0;
    while (k < 4 && b[k] != a[0]) ++k;
    if (k == 4) return false;
    const bool fwd = b[(k + 1) & 3] == a[1] && b[(k + 2) & 3] == a[2] && b[(k + 3) & 3] == a[3];
    const bool bwd = b[(k + 3) & 3] == a[1] && b[(k + 2) & 3] == a[2] && b[(k + 1) & 3] == a[3];
    return fwd || bwd;
}

} // namespace

std::uint64_t hexMeshDigest(const HexMesh& mesh, int threads) {
    const std::size_t n = mesh.hexes.size();
    const int chunks = n >= kParallelHexes ? std::max(1, threads) : 1;
    std::vector<std::uint64_t> part(static_cast<std::size_t>(chunks), 0);
    // A sum of per-hex terms (each hex's corners and its index mixed): the same for any chunking.
    parallelChunks(n, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::uint64_t s = 0;
        for (std::size_t h = h0; h < h1; ++h) {
            const auto& x = mesh.hexes[h];
            std::uint64_t a = static_cast<std::uint64_t>(static_cast<std::uint32_t>(x[0])) << 32 | static_cast<std::uint32_t>(x[1]);
            std::uint64_t b = static_cast<std::uint64_t>(static_cast<std::uint32_t>(x[2])) << 32 | static_cast<std::uint32_t>(x[3]);
            std::uint64_t d = static_cast<std::uint64_t>(static_cast<std::uint32_t>(x[4])) << 32 | static_cast<std::uint32_t>(x[5]);
            std::uint64_t e = static_cast<std::uint64_t>(static_cast<std::uint32_t>(x[6])) << 32 | static_cast<std::uint32_t>(x[7]);
            s += mix64(mix64(mix64(mix64(a ^ (h * 0x9e3779b97f4a7c15ull)) ^ b) ^ d) ^ e);
        }
        part[static_cast<std::size_t>(c)] = s;
    });
    std::uint64_t s = mix64(n) ^ mix64(mesh.vertices.size() + 0x51ed270b27e3d2d1ull) ^ mix64(mesh.polyhedra.size() + 0x2545f4914f6cdd1dull);
    for (const std::uint64_t x : part) s += x;
    return s;
}

bool hexFaceNeighboursFit(const HexMesh& mesh, const HexFaceNeighbours& table, std::uint64_t digest, int threads,
                          bool compare_vertices) {
    const std::size_t nHex = mesh.hexes.size(), nItems = 6 * nHex;
    if (table.items.size() != nItems || table.digest != digest || nItems > static_cast<std::size_t>(INT32_MAX)) return false;
    const int chunks = nHex >= kParallelHexes ? std::max(1, threads) : 1;
    std::vector<char> ok(static_cast<std::size_t>(chunks), 1);
    const int* nb = table.items.data();
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        bool good = true;
        for (std::size_t l = 6 * h0; l < 6 * h1 && good; ++l) {
            const int n = nb[l];
            if (n == -1) continue;
            good = n >= 0 && static_cast<std::size_t>(n) < nItems && static_cast<std::size_t>(n) != l &&
                   static_cast<std::size_t>(nb[n]) == l;
            if (!good || !compare_vertices) continue;
            int a[4], b[4];
            const auto& ha = mesh.hexes[l / 6];
            const auto& hb = mesh.hexes[static_cast<std::size_t>(n) / 6];
            for (int j = 0; j < 4; ++j) {
                a[j] = ha[static_cast<std::size_t>(kHexFaces[l % 6][j])];
                b[j] = hb[static_cast<std::size_t>(kHexFaces[n % 6][j])];
            }
            good = sameCycle(a, b);
        }
        ok[static_cast<std::size_t>(c)] = good ? 1 : 0;
    });
    return std::all_of(ok.begin(), ok.end(), [](char x) { return x != 0; });
}

} // namespace HexEx
