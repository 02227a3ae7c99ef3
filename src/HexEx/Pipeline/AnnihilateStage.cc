#include "AnnihilateStage.hh"

#include "../Core/Parallel.hh"
#include "../Postprocessing/DartAnnihilation.hh"
#include "../Postprocessing/DartReconnection.hh"
#include "../Postprocessing/FaceConnectionRepair.hh"
#include "../Postprocessing/FaceRelinking.hh"

#include <algorithm>
#include <cstring>
#include <functional>
#include <string>

namespace HexEx {

AnnihilateOutput annihilateStage(const AnnihilateInput& in) {
    AnnihilateOutput out;
    const std::size_t nd = in.alpha->size();
    out.alive.assign(nd, 1);
    if (in.merge) {
        std::function<bool(int, int)> samePlace;
        if (in.darts)
            samePlace = [&ds = in.darts->darts](int a, int b) {
                const Dart& A = ds[static_cast<std::size_t>(a)];
                const Dart& B = ds[static_cast<std::size_t>(b)];
                return A.tet == B.tet && samePoint(A.z, B.z);
            };
        // Cells still broken after the phase-by-phase retry: regroup their darts into cubes and
        // re-link them; if that leaves none broken, the other orders are not tried.
        AnnihilationRetry retry = in.retry;
        retry.threads = in.phased_beside ? in.threads : 1;  // the phase-by-phase retry beside the first pass (same result)
        if (retry.enabled && in.darts)
            retry.repair = [&](const std::vector<int>& broken) {
                std::vector<std::pair<int, std::array<int, 4>>> undo;
                out.reconnection = reconnectBrokenCells(*in.alpha, out.alive, in.darts->darts, in.chart_components, &broken, &undo);
                const ReconnectionStats& r = out.reconnection;
                // Groups broken only in alpha_3 are left to the face repair and relinking, as
                // AnnihilationRetry::keep_alpha3_only leaves them.
                const bool kept = r.reconnected_cells > 0 && r.unresolved_cells == 0 && (r.alpha3_only_groups == 0 || retry.keep_alpha3_only);
                // Not kept: the other orders run on the links as the annihilation left them
                // (it restores only the darts it touched itself).
                if (!kept)
                    for (auto it = undo.rbegin(); it != undo.rend(); ++it) (*in.alpha)[static_cast<std::size_t>(it->first)] = it->second;
                return kept;
            };
        const AnnihilationStats as = annihilateDarts(*in.alpha, *in.sign, out.alive, &out.heir, samePlace, retry, in.mutual_links);
        out.stats = as;
        out.pairs = as.pairs;
        out.remaining_anti = as.remaining_anti;
        // Broken cells that no order of the annihilation avoids: regroup their darts into
        // cubes and re-link them (only then; every other map keeps its links).
        if (!as.repaired) out.reconnection = ReconnectionStats();  // a failed attempt during the retries
        if (in.retry.enabled && as.broken_cells_after > 0 && in.darts && !as.repaired) {
            out.reconnection = reconnectBrokenCells(*in.alpha, out.alive, in.darts->darts, in.chart_components);
            for (std::size_t k = 0; k < out.reconnection.unresolved.size(); ++k) {
                const auto& u = out.reconnection.unresolved[k];
                const auto& n = out.reconnection.unresolved_size[k];
                out.unreconnected.push_back({u.first, in.darts->darts[static_cast<std::size_t>(u.first)].tet, n.first, n.second, u.second});
                out.warnings.push_back("broken hex cells at dart " + std::to_string(u.first) + " (tet " +
                                       std::to_string(in.darts->darts[static_cast<std::size_t>(u.first)].tet) +
                                       ") could not be reconnected: " + u.second);
            }
        }
    } else {
        out.remaining_anti = in.anti;
    }
    // Survivors numbered in order: counted per chunk, then numbered from the chunk's prefix.
    out.new_index.resize(nd);
    const int chunks = std::max(1, std::min(in.threads, static_cast<int>(nd / 65536) + 1));
    std::vector<int> before(static_cast<std::size_t>(chunks) + 1, 0);
    parallelChunks(nd, chunks, [&](int k, std::size_t b, std::size_t e) {
        int n = 0;
        for (std::size_t d = b; d < e; ++d) n += out.alive[d] ? 1 : 0;
        before[static_cast<std::size_t>(k) + 1] = n;
    });
    for (std::size_t k = 0; k < static_cast<std::size_t>(chunks); ++k) before[k + 1] += before[k];
    parallelChunks(nd, chunks, [&](int k, std::size_t b, std::size_t e) {
        int next = before[static_cast<std::size_t>(k)];
        for (std::size_t d = b; d < e; ++d) out.new_index[d] = out.alive[d] ? next++ : -1;
    });
    out.n_alive = before.back();
    return out;
}

MapOutput buildMapStage(MapInput&& in) {
    MapOutput out;
    const std::vector<char>& alive = in.survivors->alive;
    const std::vector<int>& newIndex = in.survivors->new_index;
    const int threads = in.threads;
    std::vector<DartLinks> links;
    links.swap(in.alpha);
    const std::size_t nd = links.size();
    // Compact in two steps, chunks in parallel: each chunk first packs its surviving darts
    // to the start of its own range (in place: the write position never passes the read
    // position), then the packed blocks are moved down in chunk order. Missing or removed
    // partners (and implicit-cell partners, see implicitAlpha3Occurrences()) become free links.
    std::vector<long> unconnected(static_cast<std::size_t>(threads), 0);
    std::vector<std::size_t> chunkBegin(static_cast<std::size_t>(threads), 0), chunkKept(static_cast<std::size_t>(threads), 0);
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        std::size_t w = b;
        for (std::size_t d = b; d < e; ++d) {
            if (!alive[d]) continue;
            DartLinks l;
            for (int i = 0; i < 4; ++i) {
                const int p = links[d][i];
                if (p >= 0 && alive[static_cast<std::size_t>(p)]) {
                    l[i] = newIndex[static_cast<std::size_t>(p)];
                } else {
                    l[i] = newIndex[d];
                    if (i < 3) ++unconnected[static_cast<std::size_t>(k)];
                }
            }
            links[w++] = l;
        }
        chunkBegin[static_cast<std::size_t>(k)] = b;
        chunkKept[static_cast<std::size_t>(k)] = w - b;
    });
    for (std::size_t k = 0, dst = 0; k < chunkBegin.size(); dst += chunkKept[k], ++k)
        if (dst != chunkBegin[k] && chunkKept[k] > 0)
            std::memmove(static_cast<void*>(&links[dst]), &links[chunkBegin[k]], chunkKept[k] * sizeof(DartLinks));
    for (long u : unconnected) out.unconnected_darts += u;
    links.resize(static_cast<std::size_t>(in.survivors->n_alive));
    // Give the removed darts' room back when they were the majority (fold-heavy maps): the
    // copy is at most half the old array. With few removals the copy costs more than it saves.
    if (links.size() < nd / 2) links.shrink_to_fit();
    out.map.assign_links(std::move(links));
    if (in.repair_faces) {
        out.repaired_face_connections = completePartialFaceConnections(out.map, threads);
        if (out.repaired_face_connections > 0)
            out.warnings.push_back(std::to_string(out.repaired_face_connections) +
                                   " partially connected quads were completed (alpha_3 links added)");
    }
    // Only annihilation re-links darts: without removed pairs every alpha_3 link is a traced one.
    if (in.repair_faces && in.survivors->pairs > 0) {
        const FaceRelinkStats rs = relinkInconsistentFaces(out.map);
        out.inconsistent_faces = rs.inconsistent_faces;
        out.relinked_faces = rs.relinked_faces;
        if (rs.inconsistent_faces > 0)
            out.warnings.push_back(std::to_string(rs.inconsistent_faces) + " quads had inconsistent alpha_3 links after the annihilation; " +
                                   std::to_string(rs.relinked_faces) + " of them were linked again by their vertices");
    }
    return out;
}

} // namespace HexEx
