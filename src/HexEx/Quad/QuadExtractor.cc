#include "QuadExtraction.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Postprocessing/DartAnnihilation.hh"
#include "QuadAssembly.hh"
#include "TriangleTracing.hh"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <type_traits>

namespace HexEx {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Parameters beyond this magnitude are refused (grid points must fit in int with room
/// for translations, and sanitized sums must stay exact).
constexpr double kMaxParam = 1 << 28;
} // namespace

QuadExtractionReport extractQuadMesh(const ParametrizedTriMesh& in, QuadMesh& out, const QuadExtractionOptions& opt) {
    QuadExtractionReport rep;
    const long perThread = std::max(1L, opt.min_triangles_per_thread);
    const int threads = static_cast<int>(std::max<long>(
        1, std::min<long>(resolveThreadCount(opt.threads), static_cast<long>(in.triangles.size()) / perThread)));
    rep.threads = threads;
    auto t0 = Clock::now();

    // Preprocessing.
    TriAdjacency adj = buildTriAdjacency(in, threads);
    const std::size_t nf = in.triangles.size();
    const int chunks = std::max(1, threads);
    TriParams params(nf);  // not zeroed: the parallel loop below writes every corner
    {
        // Per chunk, its first bad parameter; the lowest chunk's is the sequential first.
        std::vector<std::string> errors(static_cast<std::size_t>(chunks));
        parallelChunks(nf, chunks, [&](int c, std::size_t fb, std::size_t fe) {
            for (std::size_t f = fb; f < fe; ++f)
                for (int k = 0; k < 3; ++k) {
                    const Vec2d& p = in.params[f][k];
                    if (std::fabs(p[0]) > kMaxParam || std::fabs(p[1]) > kMaxParam) {
                        errors[static_cast<std::size_t>(c)] = "triangle mesh: triangle " + std::to_string(f) +
                                                              ": parameter of corner " + std::to_string(k) +
                                                              " is larger than 2^28 in magnitude";
                        return;
                    }
                    params[f][k] = p;
                }
        });
        for (const std::string& e : errors)
            if (!e.empty()) throw InputError(e);
    }
    const TriTransitions tr = computeTriTransitions(in, adj, params, opt.given_quarter_turns, threads);
    rep.input.snapped_coordinates = sanitizeTriParams(in, adj, params, tr, opt.epsilon, threads);
    const std::vector<signed char> sign = classifyTriangles(params, threads);
    rep.input.vertices = static_cast<long>(in.points.size());
    rep.input.triangles = static_cast<long>(nf);
    // Counts and signed areas per triangle in parallel; the two area sums stay sequential
    // (in triangle order), so they are rounded exactly as before for any thread count.
    std::vector<double, DefaultInitAllocator<double>> triArea(nf);  // every entry written below
    std::vector<std::array<long, 3>> counts(static_cast<std::size_t>(chunks), {0, 0, 0});
    parallelChunks(nf, chunks, [&](int c, std::size_t fb, std::size_t fe) {
        auto& cnt = counts[static_cast<std::size_t>(c)];
        for (std::size_t f = fb; f < fe; ++f) {
            if (sign[f] < 0) ++cnt[0];
            if (sign[f] == 0) ++cnt[1];
            for (std::size_t h = 3 * f; h < 3 * f + 3; ++h)
                if (adj.opposite[h] < 0) ++cnt[2];
            const auto& p = params[f];
            triArea[f] = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
        }
    });
    for (const auto& cnt : counts) {
        rep.input.flipped_triangles += cnt[0];
        rep.input.degenerate_triangles += cnt[1];
        rep.input.boundary_edges += cnt[2];
    }
    double area = 0, unsignedArea = 0;
    for (double a : triArea) {
        area += a;
        unsignedArea += std::fabs(a);
    }
    triArea.clear();
    triArea.shrink_to_fit();
    rep.input.parametric_area = area;
    rep.input.ambiguous_transitions = tr.ambiguous;
    rep.input.unresolved_transitions = tr.unresolved;
    for (int h : vertexHolonomy(in, adj, tr, nullptr, threads))
        if (h > 0) ++rep.input.cones;
    if (!(unsignedArea <= opt.max_quads))
        throw InputError("parameter map too large: unsigned parametric area " + std::to_string(unsignedArea) +
                         " exceeds the limit of " + std::to_string(opt.max_quads) + " quads");
    if (tr.unresolved > 0)
        rep.warnings.push_back(std::to_string(tr.unresolved) +
                               " interior edges of (nearly) zero parametric length have no determined rotation (best fit kept)");
    rep.timings_s.preprocess = since(t0);

    // Darts.
    t0 = Clock::now();
    TriDartSet ds = extractTriDarts(params, sign, 16.0 * opt.max_quads + 1e6, threads);
    rep.darts.extracted = static_cast<long>(ds.darts.size());
    rep.darts.anti = ds.anti;
    rep.timings_s.darts = since(t0);

    // Connections.
    t0 = Clock::now();
    TriTraceStats ts;
    TriLinks links = traceTriConnections(in, adj, params, tr, sign, ds, threads, &ts);
    rep.darts.asymmetric_links = ts.asymmetric;
    rep.timings_s.connect = since(t0);

    // Annihilation (the 3D function: alpha_3 is free throughout) and the final map.
    // Without anti darts there is nothing to annihilate (the function would find no pair),
    // every dart survives and the traced links become the map's in place.
    t0 = Clock::now();
    const std::size_t n = ds.darts.size();
    std::vector<char> alive;  // empty: every dart alive
    if (opt.merge && ds.anti > 0) {
        alive.assign(n, 1);
        std::vector<signed char> dsign(n);
        std::vector<std::array<int, 4>> links4(n);
        parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t d = b; d < e; ++d) {
                dsign[d] = ds.darts[d].sign;
                links4[d] = {links[d][0], links[d][1], links[d][2], static_cast<int>(d)};
            }
        });
        const AnnihilationStats as = annihilateDarts(links4, dsign, alive);
        parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t d = b; d < e; ++d) links[d] = {links4[d][0], links4[d][1], links4[d][2]};
        });
        rep.darts.annihilated_pairs = as.pairs;
        rep.darts.remaining_anti = as.remaining_anti;
    } else {
        rep.darts.remaining_anti = ds.anti;  // 0 when merging
    }
    auto isAlive = [&](std::size_t d) { return alive.empty() || alive[d]; };
    // Compaction of the surviving darts, in parallel: per-chunk counts give each chunk
    // its first new index, so the numbering is the sequential one.
    std::vector<std::size_t> base(static_cast<std::size_t>(chunks) + 1, 0);
    if (!alive.empty())
        parallelChunks(n, chunks, [&](int c, std::size_t b, std::size_t e) {
            std::size_t k = 0;
            for (std::size_t d = b; d < e; ++d) k += alive[d] ? 1 : 0;
            base[static_cast<std::size_t>(c) + 1] = k;
        });
    for (int c = 0; c < chunks; ++c) base[static_cast<std::size_t>(c) + 1] += base[static_cast<std::size_t>(c)];
    const bool allAlive = alive.empty() || base.back() == n;  // then the numbering is the identity
    std::vector<long> unconnected(static_cast<std::size_t>(chunks), 0);
    TriDartVector kept;
    QuadLinks glinks;
    if (allAlive) {
        // Unconnected links (-1) become free ones, in place.
        kept = std::move(ds.darts);
        parallelChunks(n, chunks, [&](int c, std::size_t b, std::size_t e) {
            long& u = unconnected[static_cast<std::size_t>(c)];
            for (std::size_t d = b; d < e; ++d)
                for (int& p : links[d])
                    if (p < 0) {
                        ++u;
                        p = static_cast<int>(d);
                    }
        });
        glinks = std::move(links);
    } else {
        const std::size_t nk = base.back();
        std::vector<int, DefaultInitAllocator<int>> newIndex(n);  // read only where written (alive darts)
        kept.resize(nk);
        parallelChunks(n, chunks, [&](int c, std::size_t b, std::size_t e) {
            std::size_t k = base[static_cast<std::size_t>(c)];
            for (std::size_t d = b; d < e; ++d)
                if (alive[d]) {
                    newIndex[d] = static_cast<int>(k);
                    kept[k++] = ds.darts[d];
                }
        });
        glinks.resize(nk);
        parallelChunks(n, chunks, [&](int c, std::size_t b, std::size_t e) {
            long& u = unconnected[static_cast<std::size_t>(c)];
            for (std::size_t d = b; d < e; ++d) {
                if (!alive[d]) continue;
                const int nd = newIndex[d];
                for (int i = 0; i < 3; ++i) {
                    const int p = links[d][static_cast<std::size_t>(i)];
                    const int np = (p >= 0 && isAlive(static_cast<std::size_t>(p))) ? newIndex[static_cast<std::size_t>(p)] : -1;
                    if (np < 0) {
                        if (p < 0 || !isAlive(static_cast<std::size_t>(p))) ++u;
                        glinks[static_cast<std::size_t>(nd)][static_cast<std::size_t>(i)] = nd;
                    } else {
                        glinks[static_cast<std::size_t>(nd)][static_cast<std::size_t>(i)] = np;
                    }
                }
            }
        });
        links.clear();
        links.shrink_to_fit();
    }
    for (long u : unconnected) rep.output.unconnected_darts += u;
    rep.timings_s.postprocess = since(t0);

    // Validation and assembly.
    t0 = Clock::now();
    QuadOrbitLabels labels;
    rep.validation = validateQuadLinks(glinks, &labels, threads);
    const QuadAssemblyStats as = assembleQuadMesh(glinks, kept, labels, in, params, out, threads);
    rep.output.vertices = static_cast<long>(out.vertices.size());
    rep.output.quads = as.quads;
    rep.output.non_quad_faces = as.polygons;
    rep.output.dropped_faces = as.dropped_faces;
    rep.output.edges = labels.n_edges;
    rep.output.boundary_edges = as.boundary_edges;
    rep.timings_s.assemble = since(t0);

    if (rep.output.unconnected_darts > 0)
        rep.warnings.push_back(std::to_string(rep.output.unconnected_darts) + " dart links could not be traced");
    if (rep.darts.remaining_anti > 0)
        rep.warnings.push_back(std::to_string(rep.darts.remaining_anti) + " anti darts remain after annihilation");
    if (as.polygons > 0) rep.warnings.push_back(std::to_string(as.polygons) + " faces are not quads (written as polygons)");
    if (as.dropped_faces > 0)
        rep.warnings.push_back(std::to_string(as.dropped_faces) + " faces with fewer than three vertices were left out");
    if (!rep.validation.valid()) rep.warnings.push_back("validation: " + rep.validation.summary());
    rep.valid_all_quad = rep.validation.valid() && as.polygons == 0 && as.dropped_faces == 0 && rep.darts.remaining_anti == 0;

    // The large arrays are released on the threads as well: giving their pages back to
    // the system (unmapping) costs about as much per page as touching them first, and done
    // by the destructors it would all fall to the calling thread. About half the bytes each.
    auto release = [](auto& v) { std::decay_t<decltype(v)>().swap(v); };
    parallelChunks(10, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t k = b; k < e; ++k) switch (k) {
                case 0: release(kept); break;
                case 1: release(adj.opposite); break;
                case 2: release(adj.vertex_triangles); break;
                case 3: release(labels.vertex); break;
                case 4: release(labels.edge); break;
                case 5: release(glinks); break;
                case 6: release(params); break;
                case 7: release(labels.face); break;
                case 8: release(ds.offset); break;
                default: release(ds.darts); break;  // empty unless darts were annihilated
            }
    });
    return rep;
}

} // namespace HexEx
