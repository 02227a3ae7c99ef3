#include "PreprocessStage.hh"

#include "../Core/CompensatedSum.hh"
#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Extraction/DartExtraction.hh"
#include "../Preprocessing/Sanitization.hh"
#include "MemoryBudget.hh"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace HexEx {

namespace {
/// Tets per block of the deterministic parallel sums.
constexpr std::size_t kSumBlock = 4096;
/// Bytes per box point of a dense index: 4 (offset) + 1 (flags).
constexpr double kBytesPerBoxPoint = 5;

/// Ordering of (tet, volume) entries: larger volume first, then smaller tet.
bool largerImage(const std::pair<int, double>& a, const std::pair<int, double>& b) {
    return a.second != b.second ? a.second > b.second : a.first < b.first;
}

/// Keeps @p top the 5 largest entries (largerImage order) after offering @p e.
void offerLargest(std::vector<std::pair<int, double>>& top, const std::pair<int, double>& e) {
    if (top.size() == 5 && !largerImage(e, top.back())) return;
    top.insert(std::upper_bound(top.begin(), top.end(), e, largerImage), e);
    if (top.size() > 5) top.pop_back();
}

/// std::floor and std::ceil for |x| <= 1e9 (the parameters are checked to be) by the
/// truncating conversion, without libm calls: the same values up to the sign of a zero,
/// which the box sizes below (differences plus one, products of non-negative numbers) do
/// not see.
double floorChecked(double x) {
    const double t = static_cast<double>(static_cast<long long>(x));
    return t > x ? t - 1 : t;
}
/// See floorChecked().
double ceilChecked(double x) {
    const double t = static_cast<double>(static_cast<long long>(x));
    return t < x ? t + 1 : t;
}

/// Area of the triangle a, b, c.
double area(const Vec3d& a, const Vec3d& b, const Vec3d& c) { return 0.5 * ((b - a) % (c - a)).norm(); }

/// Checks every parameter and returns the unsigned parametric volume. Sums go per fixed
/// block of tets, then over the blocks in order: the same result for any thread count.
/// An error names the first bad tet (chunks are rethrown in order).
double checkedAbsVolume(const CornerParams& params, int threads, std::vector<std::pair<int, double>>& largest) {
    const std::size_t nBlocks = (params.size() + kSumBlock - 1) / kSumBlock;
    std::vector<double> blockSum(nBlocks, 0.0);
    std::vector<std::vector<std::pair<int, double>>> blockTop(nBlocks);
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
                const double vol = std::fabs(tetVolume6(q[0], q[1], q[2], q[3])) / 6.0;
                blockSum[blk] += vol;
                offerLargest(blockTop[blk], {static_cast<int>(c), vol});
            }
    });
    double absVolume = 0;
    for (double v : blockSum) absVolume += v;
    for (const auto& top : blockTop)
        for (const auto& e : top) offerLargest(largest, e);
    return absVolume;
}

/// Checks that given rotations are one per halfface, in range and inverse across faces.
void checkGivenRotations(const TetMesh& mesh, const std::vector<int>& given) {
    if (given.size() != mesh.n_halffaces()) throw InputError("given rotations: one per halfface required");
    for (std::size_t h = 0; h < given.size(); ++h) {
        const int r = given[h];
        const HalfFaceHandle o = mesh.opposite_halfface(HalfFaceHandle(static_cast<int>(h)));
        if (!o.is_valid()) continue;
        if (r < 0 || r >= Rotation::kCount)
            throw InputError("given rotations: halfface " + std::to_string(h) + " has rotation index " + std::to_string(r) + " (must be 0..23)");
        if (Rotation(given[o.uidx()]) != Rotation(r).inverse())
            throw InputError("given rotations: halfface " + std::to_string(h) + " and its opposite " + std::to_string(o.idx()) +
                             " are not inverse to each other");
    }
}

/// Builds the symbolic-perturbation data of every tet into @p tets (sized to the tets) and,
/// in the same pass while the tet is in the cache, counts flipped and degenerate tets and
/// sums the signed volume (deterministic blocks); sums the sizes the memory estimate needs
/// into @p cost.
void buildAndClassify(const CornerParams& params, std::vector<TetSoS>& tets, int threads, ExtractionReport::Input& stats,
                      TetCostSummary& cost) {
    struct BlockCounts {
        CompensatedSum volume6;
        long flipped = 0, degenerate = 0;
        double points = 0, pointsImplicit = 0, denseBytes = 0;
        double largeProper = 0, largeFlipped = 0, flippedBox = 0;
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};  // box around the large flipped tets
    };
    const std::size_t nBlocks = (tets.size() + kSumBlock - 1) / kSumBlock;
    std::vector<BlockCounts> blocks(nBlocks);
    parallelChunks(nBlocks, threads, [&](int, std::size_t bb, std::size_t be) {
        for (std::size_t blk = bb; blk < be; ++blk)
            for (std::size_t c = blk * kSumBlock; c < std::min(tets.size(), (blk + 1) * kSumBlock); ++c) {
                tets[c] = TetSoS(params[c]);
                const TetSoS& T = tets[c];
                if (T.vol < 0) ++blocks[blk].flipped;
                if (T.vol == 0) ++blocks[blk].degenerate;
                const Vec3d e1 = T.p[1] - T.p[0], e2 = T.p[2] - T.p[0], e3 = T.p[3] - T.p[0];
                const double v6 = (e1 % e2) | e3;
                blocks[blk].volume6.add(v6);
                if (T.vol == 0) continue;
                // Memory estimate: grid cells of the image; with implicit cells, large proper
                // tets have explicit darts only in a shell along their faces (cells cut by a
                // face): about 0.2 grid points per unit of face area on the cylinders, 0.5
                // leaves a margin.
                const double vol = std::fabs(v6) / 6.0;
                Vec3d lo = T.p[0], hi = T.p[0];
                for (int i = 1; i < 4; ++i) {
                    lo.minimize(T.p[i]);
                    hi.maximize(T.p[i]);
                }
                double box = 1;
                for (int a = 0; a < 3; ++a) box *= std::max(0.0, floorChecked(hi[a]) - ceilChecked(lo[a]) + 1);
                double shell = vol;
                if (box >= kDenseIndexMinPoints) {
                    BlockCounts& B = blocks[blk];
                    B.denseBytes += kBytesPerBoxPoint * box;
                    (T.vol > 0 ? B.largeProper : B.largeFlipped) += vol;
                    if (T.vol < 0) {
                        B.flippedBox += box;
                        for (int a = 0; a < 3; ++a) {
                            B.lo[a] = std::min(B.lo[a], ceilChecked(lo[a]));
                            B.hi[a] = std::max(B.hi[a], floorChecked(hi[a]));
                        }
                    }
                    if (T.vol > 0) {
                        const Vec3d* p = T.p;
                        const double faces = area(p[1], p[2], p[3]) + area(p[0], p[2], p[3]) + area(p[0], p[1], p[3]) + area(p[0], p[1], p[2]);
                        shell = std::min(vol, 0.5 * faces);
                    }
                }
                blocks[blk].points += vol;
                blocks[blk].pointsImplicit += shell;
            }
    });
    CompensatedSum volume6;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& b : blocks) {
        cost.large_proper += b.largeProper;
        cost.large_flipped += b.largeFlipped;
        cost.flipped_box_points += b.flippedBox;
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b.lo[a]);
            hi[a] = std::max(hi[a], b.hi[a]);
        }
        stats.flipped_tets += b.flipped;
        stats.degenerate_tets += b.degenerate;
        volume6.add(b.volume6.value());
        cost.points += b.points;
        cost.points_implicit += b.pointsImplicit;
        cost.dense_bytes += b.denseBytes;
    }
    stats.parametric_volume = volume6.value() / 6.0;
    if (cost.flipped_box_points > 0) {
        cost.flipped_union_box = 1;
        for (int a = 0; a < 3; ++a) cost.flipped_union_box *= std::max(0.0, hi[a] - lo[a] + 1);
    }
}
/// One line naming the replaced corners (the first three) and what to check.
std::string repairWarning(const SanitizeStats& ss) {
    auto vec = [](const Vec3d& v) {
        std::ostringstream o;
        o << std::setprecision(10) << '(' << v[0] << ' ' << v[1] << ' ' << v[2] << ')';
        return o.str();
    };
    const bool one = ss.repaired_corners == 1;
    std::string text = std::to_string(ss.repaired_corners) +
                       (one ? " corner parameter disagreed with the majority of the tets at its vertex and was "
                              "replaced by the majority value (a corrupted number in the input?):"
                            : " corner parameters disagreed with the majority of the tets at their vertex and were "
                              "replaced by the majority value (corrupted numbers in the input?):");
    for (std::size_t k = 0; k < ss.repairs.size() && k < 3; ++k) {
        const CornerRepair& r = ss.repairs[k];
        text += (k ? "; " : " ") + std::string("tet ") + std::to_string(r.tet) + " corner " +
                std::to_string(r.corner) + " (vertex " + std::to_string(r.vertex) + ") " + vec(r.original) + " -> " +
                vec(r.repaired);
    }
    if (ss.repaired_corners > 3) text += "; ...";
    return text;
}
} // namespace

PreprocessOutput preprocess(const PreprocessInput& in) {
    const ParametrizedTetMesh& input = *in.input;
    const TetMesh& mesh = input.mesh;
    if (!mesh.has_adjacency()) throw InputError("extractHexMesh: call build_adjacency() on the tet mesh first");
    if (input.params.size() != mesh.n_cells()) throw InputError("extractHexMesh: one parameter set per tet required");
    PreprocessOutput out;
    out.stats.vertices = static_cast<long>(mesh.n_vertices());
    out.stats.tets = static_cast<long>(mesh.n_cells());
    out.stats.boundary_faces = static_cast<long>(mesh.n_boundary_faces());
    // The working copy (sanitization changes it), taken over when the caller owns the input.
    if (in.owned_params) out.params = std::move(*in.owned_params);
    else out.params = input.params;
    // Unusable maps are refused up front with a clear message rather than exhausting memory.
    out.abs_volume = checkedAbsVolume(out.params, in.threads, out.cost.largest_input);
    // The volume limit is checked after the sanitization, which may repair corrupted corners
    // (a typo's needle is gone then); transitions and sanitization cost time linear in the
    // tets whatever the volume, and the range check above keeps their numbers bounded.
    auto checkVolume = [&] {
        if (out.abs_volume <= in.max_hexes) return;
        throw InputError("the map covers a parametric volume of " + std::to_string(out.abs_volume) +
                         " grid cells, more than the limit of " + std::to_string(in.max_hexes) +
                         " hexes (ExtractionOptions::max_hexes); is the parameter scale right? The tets with the largest "
                         "parametric images: " + largestImagesText(out.cost.largest_input));
    };
    const std::vector<int>* given = in.given_rotations;
    if (!given) given = mesh.halfface_props().find<int>(kGivenRotationProperty);
    if (given) checkGivenRotations(mesh, *given);
    out.transitions = computeTransitions(mesh, out.params, given, in.threads);
    out.stats.ambiguous_transitions = out.transitions.n_ambiguous;
    out.stats.unresolved_transitions = out.transitions.n_unresolved;
    SanitizeOptions so;
    so.epsilon = in.epsilon;
    so.threads = in.threads;
    const SanitizeStats ss = sanitizeParameters(mesh, out.params, out.transitions, so);
    if (ss.repaired_corners > 0) {
        std::vector<std::pair<int, double>> largestSanitized;
        out.abs_volume = checkedAbsVolume(out.params, in.threads, largestSanitized);
    }
    checkVolume();
    out.stats.snapped_coordinates = ss.snapped_coordinates;
    out.stats.inconsistent_transitions = out.transitions.n_inconsistent;
    out.stats.repaired_corners = ss.repaired_corners;
    out.stats.repairs = ss.repairs;
    const Singularities sing = findSingularities(mesh, out.params, out.transitions, in.threads);
    out.stats.singular_edges = static_cast<long>(sing.edges.size());
    out.stats.singular_vertices = static_cast<long>(sing.vertices.size());
    out.tets.resize(out.params.size());
    buildAndClassify(out.params, out.tets, in.threads, out.stats, out.cost);
    if (ss.repaired_corners > 0) out.warnings.push_back(repairWarning(ss));
    else if (out.transitions.n_inconsistent > 0)
        out.warnings.push_back(std::to_string(out.transitions.n_inconsistent) +
                               " interior faces have a corner whose parameter disagrees with the other two (the map "
                               "is not continuous there); their transitions were fitted to the two that agree");
    if (out.transitions.n_unresolved > 0)
        out.warnings.push_back(std::to_string(out.transitions.n_unresolved) +
                               " transitions could not be resolved from their neighbours (faces whose parameters leave the "
                               "rotation open: degenerate faces, or faces with a corrupted corner next to a boundary or "
                               "singular edge); the best fit was taken");
    return out;
}

} // namespace HexEx
