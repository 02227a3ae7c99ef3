#include "MemoryBudget.hh"

#include "../Core/Error.hh"
#include "../Core/Memory.hh"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace HexEx {

namespace {
/// Fixed bytes per tet beyond the input: working parameters, predicates, transitions,
/// per-tet dart offsets.
constexpr double kBytesPerTet = 256;
/// Smallest bounding box (grid points) that gets a dense index (as in extractDarts()).
constexpr double kDenseMinPoints = 64;
/// Bytes per box point of a dense index: 4 (offset) + 1 (flags).
constexpr double kBytesPerBoxPoint = 5;

/// Area of the triangle a, b, c.
double area(const Vec3d& a, const Vec3d& b, const Vec3d& c) { return 0.5 * ((b - a) % (c - a)).norm(); }

/// "12.5" or "3.1e+05": a volume for messages.
std::string formatVolume(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, v < 1e5 ? "%.1f" : "%.3g", v);
    return buf;
}
} // namespace

MemoryEstimate estimateMemory(const PreprocessOutput& pre, const CornerParams& input_params, bool implicit_cells,
                              std::uint64_t budget) {
    MemoryEstimate est;
    est.budget = budget;
    double points = 0, denseBytes = 0;
    std::vector<std::pair<int, double>> top;  // kept sorted, largest first, at most 5
    for (std::size_t c = 0; c < pre.tets.size(); ++c) {
        const TetSoS& T = pre.tets[c];
        const auto& p = pre.params[c];
        const double vol = std::fabs(((p[1] - p[0]) % (p[2] - p[0])) | (p[3] - p[0])) / 6.0;
        const auto& q = input_params[c];
        const double inputVol = std::fabs(((q[1] - q[0]) % (q[2] - q[0])) | (q[3] - q[0])) / 6.0;
        if (top.size() < 5 || inputVol > top.back().second) {
            const std::pair<int, double> e(static_cast<int>(c), inputVol);
            top.insert(std::upper_bound(top.begin(), top.end(), e, [](const auto& a, const auto& b) { return a.second > b.second; }), e);
            if (top.size() > 5) top.pop_back();
        }
        if (T.vol == 0) continue;
        double box = 1;
        for (int a = 0; a < 3; ++a) {
            const double lo = std::min({p[0][a], p[1][a], p[2][a], p[3][a]});
            const double hi = std::max({p[0][a], p[1][a], p[2][a], p[3][a]});
            box *= std::max(0.0, std::floor(hi) - std::ceil(lo) + 1);
        }
        double pts = vol;
        if (box >= kDenseMinPoints) {
            denseBytes += kBytesPerBoxPoint * box;
            if (implicit_cells && T.vol > 0) {
                // Explicit darts only in a shell along the faces (cells cut by a face): about
                // 0.2 darts/48 per unit of face area on the cylinders, 0.5 leaves a margin.
                const double faces = area(p[1], p[2], p[3]) + area(p[0], p[2], p[3]) + area(p[0], p[1], p[3]) + area(p[0], p[1], p[2]);
                pts = std::min(vol, 0.5 * faces);
            }
        }
        points += pts;
    }
    est.largest_tets = top;
    est.darts = 48 * points;
    est.bytes = est.darts * kBytesPerDart + denseBytes + kBytesPerTet * static_cast<double>(pre.tets.size());
    if (budget == 0) {
        est.max_darts = std::numeric_limits<std::size_t>::max();
    } else {
        const double room = static_cast<double>(budget) - denseBytes - kBytesPerTet * static_cast<double>(pre.tets.size());
        est.max_darts = room <= 0 ? 0 : static_cast<std::size_t>(std::min(room / kBytesPerDart, 1e18));
    }
    return est;
}

std::string memoryRefusal(const std::string& cause, const MemoryEstimate* est) {
    std::string msg = cause;
    if (est && !est->largest_tets.empty()) {
        msg += ". The tets with the largest parametric images in the input:";
        for (std::size_t k = 0; k < est->largest_tets.size(); ++k)
            msg += std::string(k ? "," : "") + " tet " + std::to_string(est->largest_tets[k].first) + " (" +
                   formatVolume(est->largest_tets[k].second) + " grid cells)";
        msg += ". A tet whose image is far larger than the others' usually means a wrong parameter: check these tets";
        if (est->bytes > 0) msg += "; otherwise allow more memory, e.g. " + formatBytes(1.25 * est->bytes) + ",";
        else msg += "; otherwise allow more memory";
    } else {
        msg += ". Allow more memory";
    }
    msg += " with ExtractionOptions::max_memory (hexex extract --max-memory SIZE)";
    return msg;
}

void checkMemoryBudget(const MemoryEstimate& est) {
    if (est.budget == 0 || est.bytes <= static_cast<double>(est.budget)) return;
    char darts[32];
    std::snprintf(darts, sizeof darts, "%.3g", est.darts);
    throw ResourceError(memoryRefusal("the extraction would need about " + formatBytes(est.bytes) + " of memory (about " +
                                          darts + " darts), more than the budget of " +
                                          formatBytes(static_cast<double>(est.budget)),
                                      &est));
}

} // namespace HexEx
