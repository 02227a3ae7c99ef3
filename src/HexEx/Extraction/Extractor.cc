#include "../HexEx.hh"

#include "../Core/CompensatedSum.hh"
#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Postprocessing/DartAnnihilation.hh"
#include "../Postprocessing/FaceConnectionRepair.hh"
#include "../Postprocessing/HexMeshAssembly.hh"
#include "../Preprocessing/Sanitization.hh"
#include "ConnectionTracing.hh"
#include "DartExtraction.hh"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <cstring>

namespace HexEx {

namespace {
/// Tets per block of the deterministic parallel sums.
constexpr std::size_t kSumBlock = 4096;

/// Pairs of occurrences that are one grid point seen from both tets of an interior face:
/// points on face j of a dense tet that may be implicit-cell corners, mapped through the
/// face's transition into the neighbour (found once, from the smaller halfface).
std::vector<std::pair<int, int>> joinOccurrencesAcrossFaces(const TetMesh& mesh, const Transitions& tr, const DartSet& ds,
                                                            int threads) {
    const int chunks = std::max(1, threads);
    std::vector<std::vector<std::pair<int, int>>> parts(static_cast<std::size_t>(chunks));
    parallelChunks(ds.dense.size(), chunks, [&](int k, std::size_t b, std::size_t e) {
        auto& out = parts[static_cast<std::size_t>(k)];
        for (std::size_t s = b; s < e; ++s) {
            const DartSet::DenseIndex& di = ds.dense[s];
            if (di.flags.empty()) continue;
            for (int j = 0; j < 4; ++j) {
                const HalfFaceHandle hf = TetMesh::halfface(CellHandle(di.tet), j);
                const HalfFaceHandle opp = mesh.opposite_halfface(hf);
                if (!opp.is_valid() || opp.idx() < hf.idx()) continue;
                const int nb = TetMesh::cell(opp).idx();
                const GridTransform& g = tr.halfface[hf.uidx()];
                std::size_t l = 0;
                for (int x = 0; x < di.dims[0]; ++x)
                    for (int y = 0; y < di.dims[1]; ++y)
                        for (int zc = 0; zc < di.dims[2]; ++zc, ++l) {
                            const unsigned fl = di.flags[l];
                            if (!(fl & 4) || !((fl >> (4 + j)) & 1)) continue;
                            const Vec3i z(di.lo[0] + x, di.lo[1] + y, di.lo[2] + zc);
                            const long o = ds.occurrence(nb, g.apply(z));
                            if (o >= 0) out.emplace_back(static_cast<int>(di.occ_base + static_cast<long>(l)), static_cast<int>(o));
                        }
            }
        }
    });
    std::vector<std::pair<int, int>> all;
    for (auto& p : parts) all.insert(all.end(), p.begin(), p.end());
    return all;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
} // namespace

const char* version() { return "0.1.0"; }

ExtractionReport extractHexMesh(const ParametrizedTetMesh& input, HexMesh& output, const ExtractionOptions& opt) {
    ExtractionReport rep;
    const TetMesh& mesh = input.mesh;
    if (!mesh.has_adjacency()) throw InputError("extractHexMesh: call build_adjacency() on the tet mesh first");
    if (input.params.size() != mesh.n_cells()) throw InputError("extractHexMesh: one parameter set per tet required");
    const int threads = resolveThreadCount(opt.threads);
    rep.threads = threads;
    auto progress = [&](const char* phase, double f) {
        if (opt.progress) opt.progress(phase, f);
    };
    rep.input.vertices = static_cast<long>(mesh.n_vertices());
    rep.input.tets = static_cast<long>(mesh.n_cells());
    rep.input.boundary_faces = static_cast<long>(mesh.n_boundary_faces());

    // Preprocessing: transitions, sanitization, classification.
    auto t0 = std::chrono::steady_clock::now();
    progress("preprocess", 0);
    CornerParams params = input.params;  // the working copy: sanitization changes it
    // Unusable maps are refused up front with a clear message rather than exhausting memory.
    // Sums go per fixed block of tets, then over the blocks in order: the same result for
    // any thread count. An error names the first bad tet (chunks are rethrown in order).
    const std::size_t nBlocks = (params.size() + kSumBlock - 1) / kSumBlock;
    std::vector<double> blockSum(nBlocks, 0.0);
    parallelChunks(nBlocks, threads, [&](int, std::size_t bb, std::size_t be) {
        for (std::size_t blk = bb; blk < be; ++blk)
            for (std::size_t c = blk * kSumBlock; c < std::min(params.size(), (blk + 1) * kSumBlock); ++c) {
                const auto& q = params[c];
                for (const auto& p : q)
                    for (int k = 0; k < 3; ++k) {
                        if (!std::isfinite(p[k])) throw InputError("tet " + std::to_string(c) + ": parameter is not finite");
                        if (std::fabs(p[k]) > 1e9)
                            throw InputError("tet " + std::to_string(c) + ": parameter " + std::to_string(p[k]) +
                                             " is out of range (|u| <= 1e9)");
                    }
                blockSum[blk] += std::fabs(((q[1] - q[0]) % (q[2] - q[0])) | (q[3] - q[0])) / 6.0;
            }
    });
    double absVolume = 0;
    for (double v : blockSum) absVolume += v;
    if (absVolume > opt.max_hexes)
        throw InputError("the map covers a parametric volume of " + std::to_string(absVolume) +
                         " grid cells, more than the limit of " + std::to_string(opt.max_hexes) +
                         " hexes (ExtractionOptions::max_hexes); is the parameter scale right?");
    const std::vector<int>* given = opt.given_rotations;
    if (!given) given = mesh.halfface_props().find<int>(kGivenRotationProperty);
    if (given) {
        if (given->size() != mesh.n_halffaces()) throw InputError("given rotations: one per halfface required");
        for (std::size_t h = 0; h < given->size(); ++h) {
            const int r = (*given)[h];
            const HalfFaceHandle o = mesh.opposite_halfface(HalfFaceHandle(static_cast<int>(h)));
            if (!o.is_valid()) continue;
            if (r < 0 || r >= Rotation::kCount)
                throw InputError("given rotations: halfface " + std::to_string(h) + " has rotation index " + std::to_string(r) + " (must be 0..23)");
            if (Rotation((*given)[o.uidx()]) != Rotation(r).inverse())
                throw InputError("given rotations: halfface " + std::to_string(h) + " and its opposite " + std::to_string(o.idx()) +
                                 " are not inverse to each other");
        }
    }
    const Transitions tr = computeTransitions(mesh, params, given, threads);
    rep.input.ambiguous_transitions = tr.n_ambiguous;
    rep.input.unresolved_transitions = tr.n_unresolved;
    SanitizeOptions so;
    so.epsilon = opt.epsilon;
    so.threads = threads;
    rep.input.snapped_coordinates = sanitizeParameters(mesh, params, tr, so).snapped_coordinates;
    const Singularities sing = findSingularities(mesh, params, tr, threads);
    rep.input.singular_edges = static_cast<long>(sing.edges.size());
    rep.input.singular_vertices = static_cast<long>(sing.vertices.size());
    const std::vector<TetSoS> tets = buildTetSoS(params, threads);
    struct BlockCounts {
        CompensatedSum volume6;
        long flipped = 0, degenerate = 0;
    };
    std::vector<BlockCounts> blocks(nBlocks);
    parallelChunks(nBlocks, threads, [&](int, std::size_t bb, std::size_t be) {
        for (std::size_t blk = bb; blk < be; ++blk)
            for (std::size_t c = blk * kSumBlock; c < std::min(tets.size(), (blk + 1) * kSumBlock); ++c) {
                const TetSoS& T = tets[c];
                if (T.vol < 0) ++blocks[blk].flipped;
                if (T.vol == 0) ++blocks[blk].degenerate;
                const Vec3d e1 = T.p[1] - T.p[0], e2 = T.p[2] - T.p[0], e3 = T.p[3] - T.p[0];
                blocks[blk].volume6.add((e1 % e2) | e3);
            }
    });
    CompensatedSum volume6;
    for (const auto& b : blocks) {
        rep.input.flipped_tets += b.flipped;
        rep.input.degenerate_tets += b.degenerate;
        volume6.add(b.volume6.value());
    }
    rep.input.parametric_volume = volume6.value() / 6.0;
    if (tr.n_unresolved > 0)
        rep.warnings.push_back(std::to_string(tr.n_unresolved) + " transitions on degenerate faces could not be resolved from their neighbours");
    rep.timings_s.preprocess = secondsSince(t0);

    // Darts (the h-vertices are the grid points the darts sit on).
    t0 = std::chrono::steady_clock::now();
    progress("darts", 0);
    // Cells inside one large proper tet need no darts, unless a fold could annihilate them.
    const bool useImplicit = opt.implicit_cells && rep.input.flipped_tets == 0;
    // Grid points on a face may be corners of implicit cells if the face is on the boundary
    // or shared with a proper tet: their vertex is then joined across (joinOccurrencesAcrossFaces).
    std::vector<FaceMask> usableFaces;
    if (useImplicit) {
        usableFaces.assign(tets.size(), 0);
        for (std::size_t c = 0; c < tets.size(); ++c)
            for (int j = 0; j < 4; ++j) {
                const HalfFaceHandle opp = mesh.opposite_halfface(TetMesh::halfface(CellHandle(static_cast<int>(c)), j));
                if (!opp.is_valid() || tets[TetMesh::cell(opp).uidx()].vol > 0)
                    usableFaces[c] = static_cast<FaceMask>(usableFaces[c] | (1u << j));
            }
    }
    DartSet ds = extractDarts(tets, threads, 1e9, useImplicit, useImplicit ? &usableFaces : nullptr, absVolume);
    if (ds.n_occurrences >= std::numeric_limits<int>::max() / 2)
        throw InputError("too many grid points in large tets for 32-bit indices");
    ImplicitCells implicit;
    implicit.n_occurrences = ds.n_occurrences;
    const std::size_t nd = ds.darts.size();
    rep.darts.extracted = static_cast<long>(nd);
    std::vector<signed char> sign(nd);
    std::vector<long> antiPerChunk(static_cast<std::size_t>(threads), 0);
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) {
            sign[d] = ds.darts[d].sign;
            if (sign[d] < 0) ++antiPerChunk[static_cast<std::size_t>(k)];
        }
    });
    for (long a : antiPerChunk) rep.darts.anti += a;
    rep.timings_s.darts = secondsSince(t0);

    // Connections.
    t0 = std::chrono::steady_clock::now();
    progress("connect", 0);
    TraceStats ts;
    std::vector<DartLinks> alpha =
        traceConnections(mesh, tr, tets, ds, threads, ts, [&](double f) { progress("connect", f); });
    // Keep only mutual links: found first, then cut (a cut while others still read could
    // hide an asymmetry from the partner's side).
    std::vector<std::vector<std::pair<std::size_t, int>>> oneSided(static_cast<std::size_t>(threads));
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d)
            for (int i = 0; i < 4; ++i) {
                const int p = alpha[d][i];
                if (p < 0 || p == static_cast<int>(d)) continue;
                if (alpha[static_cast<std::size_t>(p)][i] != static_cast<int>(d)) oneSided[static_cast<std::size_t>(k)].emplace_back(d, i);
            }
    });
    for (const auto& part : oneSided)
        for (const auto& [d, i] : part) {
            ++rep.darts.asymmetric_links;
            alpha[d][i] = kUnconnected;
        }
    rep.timings_s.connect = secondsSince(t0);

    // Postprocessing: annihilation.
    t0 = std::chrono::steady_clock::now();
    progress("postprocess", 0);
    std::vector<char> alive(nd, 1);
    if (opt.merge) {
        const AnnihilationStats as = annihilateDarts(alpha, sign, alive);
        rep.darts.annihilated_pairs = as.pairs;
        rep.darts.remaining_anti = as.remaining_anti;
    } else {
        rep.darts.remaining_anti = rep.darts.anti;
    }
    // Compact the surviving darts into a generalized map.
    std::vector<int> newIndex(nd, -1);
    int n_alive = 0;
    for (std::size_t d = 0; d < nd; ++d)
        if (alive[d]) newIndex[d] = n_alive++;
    // Compact in two steps, chunks in parallel: each chunk first packs its surviving darts
    // to the start of its own range (in place: the write position never passes the read
    // position), then the packed blocks are moved down in chunk order. Missing or removed
    // partners become free links.
    if (useImplicit) {
        implicit.alpha3_occurrence.assign(static_cast<std::size_t>(n_alive), -1);
        implicit.dart_occurrence.assign(static_cast<std::size_t>(n_alive), -1);
    }
    std::vector<DartLinks> links;
    links.swap(alpha);
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
                } else if (i == 3 && implicitPartnerOccurrence(p) >= 0) {
                    l[i] = newIndex[d];  // free in the map; the partner is an implicit cell
                    implicit.alpha3_occurrence[static_cast<std::size_t>(newIndex[d])] = static_cast<int>(implicitPartnerOccurrence(p));
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
    for (long u : unconnected) rep.output.unconnected_darts += u;
    links.resize(static_cast<std::size_t>(n_alive));  // no shrink_to_fit: a copy into fresh memory costs more than the few removed darts save
    GMap<3> g;
    g.assign_links(std::move(links));
    DartGeometry geo;
    geo.mesh = &mesh;
    geo.handedness.resize(static_cast<std::size_t>(n_alive));
    if (opt.merge) {
        rep.output.repaired_face_connections = completePartialFaceConnections(g, threads);
        if (rep.output.repaired_face_connections > 0)
            rep.warnings.push_back(std::to_string(rep.output.repaired_face_connections) +
                                   " partially connected quads were completed (alpha_3 links added)");
    }
    rep.timings_s.postprocess = secondsSince(t0);

    // 3D position of grid point z in tet t by barycentric coordinates (exact zeros where a
    // predicate puts z on a face); optionally the boundary halffaces through z.
    auto gridPointPosition = [&](int t, const Vec3i& zi, std::array<int, 3>* boundaryHf) {
        const TetSoS& T = tets[static_cast<std::size_t>(t)];
        const auto& cv = mesh.cell_vertices(CellHandle(t));
        const Vec3d z = toVec3d(zi);
        // Exact zeros: from the implicit-cell flags where the tet has them, else predicates.
        std::array<int, 4> oz;
        const int slot = ds.dense_slot[static_cast<std::size_t>(t)];
        const DartSet::DenseIndex* di = slot >= 0 ? &ds.dense[static_cast<std::size_t>(slot)] : nullptr;
        const long l = di && !di->flags.empty() ? di->local(zi) : -1;
        if (l >= 0 && (di->flags[static_cast<std::size_t>(l)] & 1)) {
            for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((di->flags[static_cast<std::size_t>(l)] >> (4 + j)) & 1) ? 0 : T.vol;
        } else {
            oz = T.sides(z);
        }
        const Vec3d e1 = T.p[1] - T.p[0], e2 = T.p[2] - T.p[0], e3 = T.p[3] - T.p[0];
        const double V = (e1 % e2) | e3;
        double lam[4];
        double sum = 0;
        for (int j = 0; j < 4; ++j) {
            if (oz[j] == 0) {
                lam[j] = 0;
                continue;
            }
            Vec3d q[4] = {T.p[0], T.p[1], T.p[2], T.p[3]};
            q[j] = z;
            lam[j] = std::max(0.0, (((q[1] - q[0]) % (q[2] - q[0])) | (q[3] - q[0])) / V);
            sum += lam[j];
        }
        Vec3d pos(0, 0, 0);
        int nb = 0;
        for (int j = 0; j < 4; ++j) {
            pos += mesh.position(cv[j]) * (sum > 0 ? lam[j] / sum : 0.25);
            const HalfFaceHandle hf = TetMesh::halfface(CellHandle(t), j);
            if (boundaryHf && oz[j] == 0 && mesh.is_boundary(hf) && nb < 3) (*boundaryHf)[nb++] = hf.idx();
        }
        return pos;
    };

    // Geometry of the surviving darts.
    t0 = std::chrono::steady_clock::now();
    progress("vertices", 0);
    // Darts are sorted by (tet, grid point): a run of alive darts at the same point shares
    // one placed point (position and boundary faces), computed once; every dart refers to
    // its run's point. Runs are counted per chunk, then numbered in order.
    auto runStart = [&](std::size_t d) {
        if (d == 0 || !alive[d - 1]) return true;
        const Dart& P = ds.darts[d - 1];
        const Dart& D = ds.darts[d];
        return P.tet != D.tet || !samePoint(P.z, D.z);
    };
    std::vector<int> runsInChunk(static_cast<std::size_t>(threads) + 1, 0);
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        int n = 0;
        for (std::size_t d = b; d < e; ++d)
            if (alive[d] && runStart(d)) ++n;
        runsInChunk[static_cast<std::size_t>(k) + 1] = n;
    });
    for (std::size_t k = 0; k < static_cast<std::size_t>(threads); ++k) runsInChunk[k + 1] += runsInChunk[k];
    geo.placement.point.resize(static_cast<std::size_t>(n_alive));
    geo.placement.position.resize(static_cast<std::size_t>(runsInChunk.back()));
    geo.placement.boundary_hf.resize(static_cast<std::size_t>(runsInChunk.back()));
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        int run = runsInChunk[static_cast<std::size_t>(k)] - 1;  // a run continued from the previous chunk
        int occ = -1;
        for (std::size_t d = b; d < e; ++d) {
            if (!alive[d]) continue;
            const Dart& D = ds.darts[d];
            const auto dk = static_cast<std::size_t>(newIndex[d]);
            geo.handedness[dk] = static_cast<signed char>(frameHandedness(D.d[0], D.d[1], D.d[2]));
            if (runStart(d)) {
                ++run;
                auto& bhf = geo.placement.boundary_hf[static_cast<std::size_t>(run)];
                bhf = {-1, -1, -1};
                geo.placement.position[static_cast<std::size_t>(run)] = gridPointPosition(D.tet, D.z, &bhf);
                if (useImplicit) occ = static_cast<int>(ds.occurrence(D.tet, D.z));
            } else if (useImplicit && occ < 0 && d == b) {
                occ = static_cast<int>(ds.occurrence(D.tet, D.z));
            }
            geo.placement.point[dk] = run;
            if (useImplicit) implicit.dart_occurrence[dk] = occ;
        }
    });
    if (useImplicit) {
        // The implicit cells, as 8 corner occurrences in VTK order (the tet's chart is
        // right-handed: proper tets only), and their faces on the boundary. Work items are
        // x-slabs of the dense boxes: counted, then filled at their prefix offsets (the
        // order is the sequential one for any thread count).
        struct Slab {
            std::size_t dense, x;
            long count = 0, boundary_quads = 0;
        };
        std::vector<Slab> slabs;
        for (std::size_t s = 0; s < ds.dense.size(); ++s)
            if (!ds.dense[s].flags.empty())
                for (int x = 0; x < ds.dense[s].dims[0]; ++x) slabs.push_back({s, static_cast<std::size_t>(x)});
        auto forSlab = [&](Slab& sl, bool fill, std::size_t at) {
            const DartSet::DenseIndex& di = ds.dense[sl.dense];
            unsigned boundaryFaces = 0;
            for (int j = 0; j < 4; ++j)
                if (mesh.is_boundary(TetMesh::halfface(CellHandle(di.tet), j))) boundaryFaces |= 1u << j;
            const int dy = di.dims[1], dz = di.dims[2];
            const int X = dy * dz, Y = dz, Z = 1;
            const int step[3] = {X, Y, Z};
            const std::size_t l0 = sl.x * static_cast<std::size_t>(X);
            for (std::size_t l = l0; l < l0 + static_cast<std::size_t>(X); ++l) {
                if (!(di.flags[l] & 2)) continue;
                if (fill) {
                    const int c = static_cast<int>(di.occ_base) + static_cast<int>(l);
                    implicit.cells[at++] = {c, c + X, c + X + Y, c + Y, c + Z, c + X + Z, c + X + Y + Z, c + Y + Z};
                    continue;
                }
                ++sl.count;
                if (!boundaryFaces) continue;
                // A face of the cell is on the boundary if its 4 corners share a boundary face.
                for (int a = 0; a < 3; ++a)
                    for (int side = 0; side < 2; ++side) {
                        unsigned common = boundaryFaces;
                        for (int q = 0; q < 8; ++q) {
                            if (((q >> a) & 1) != side) continue;
                            std::size_t lq = l;
                            for (int k = 0; k < 3; ++k)
                                if ((q >> k) & 1) lq += static_cast<std::size_t>(step[k]);
                            common &= static_cast<unsigned>(di.flags[lq]) >> 4;
                        }
                        if (common) ++sl.boundary_quads;
                    }
            }
        };
        parallelChunks(slabs.size(), threads, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t k = b; k < e; ++k) forSlab(slabs[k], false, 0);
        });
        std::vector<std::size_t> slabStart(slabs.size() + 1, 0);
        for (std::size_t k = 0; k < slabs.size(); ++k) {
            slabStart[k + 1] = slabStart[k] + static_cast<std::size_t>(slabs[k].count);
            implicit.boundary_quads += slabs[k].boundary_quads;
        }
        implicit.cells.resize(slabStart.back());
        parallelChunks(slabs.size(), threads, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t k = b; k < e; ++k) forSlab(slabs[k], true, slabStart[k]);
        });
        implicit.joined_occurrences = joinOccurrencesAcrossFaces(mesh, tr, ds, threads);
        implicit.position = [&](long occ) {
            // The dense index holding this occurrence: the last with occ_base <= occ.
            auto it = std::upper_bound(ds.dense.begin(), ds.dense.end(), occ,
                                       [](long o, const DartSet::DenseIndex& di) { return o < di.occ_base; });
            const DartSet::DenseIndex& di = *(it - 1);
            long l = occ - di.occ_base;
            Vec3i z;
            z[2] = di.lo[2] + static_cast<int>(l % di.dims[2]);
            l /= di.dims[2];
            z[1] = di.lo[1] + static_cast<int>(l % di.dims[1]);
            z[0] = di.lo[0] + static_cast<int>(l / di.dims[1]);
            return gridPointPosition(di.tet, z, nullptr);
        };
        rep.darts.implicit_cells = static_cast<long>(implicit.cells.size());
    }
    rep.timings_s.vertices = secondsSince(t0);
    // The extracted darts and per-tet data are not needed any more: free them before the
    // assembly allocates its labels (peak memory).
    std::vector<Dart>().swap(ds.darts);
    std::vector<char>().swap(alive);
    std::vector<int>().swap(newIndex);
    std::vector<signed char>().swap(sign);

    // Validation and assembly.
    t0 = std::chrono::steady_clock::now();
    progress("assemble", 0);
    HexOrbitLabels labels;
    rep.validation = validateHexGMap(g, &labels, threads);
    AssemblyStats st;
    output = assembleHexMesh(g, geo, labels, st, useImplicit ? &implicit : nullptr, threads);
    rep.output.vertices = static_cast<long>(output.vertices.size());
    rep.output.hexes = static_cast<long>(output.hexes.size());
    rep.output.non_hex_cells = st.non_hex_cells;
    if (st.degenerate_faces > 0)
        rep.warnings.push_back(std::to_string(st.degenerate_faces) +
                               " faces of non-hex cells have fewer than 3 distinct vertices and were left out of their polyhedra");
    if (st.collapsed_cells > 0)
        rep.warnings.push_back(std::to_string(st.collapsed_cells) +
                               " non-hex cells collapsed completely (no face with 3 distinct vertices); they are counted but not written");
    rep.output.quads = st.quads;
    rep.output.boundary_quads = st.boundary_quads;
    rep.valid_all_hex = rep.validation.valid() && st.non_hex_cells == 0 && rep.darts.remaining_anti == 0;
    rep.timings_s.assemble = secondsSince(t0);
    progress("done", 1);
    return rep;
}

} // namespace HexEx
