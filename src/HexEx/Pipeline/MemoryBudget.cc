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
/// Bytes per point of the box around the large flipped tets with cheap folds: the proper
/// and the flipped owner masks (8 + 8) and the "mixed" flag (FoldCancellation.cc).
constexpr double kOwnerBytesPerBoxPoint = 17;

/// "12.5" or "3.1e+05": a volume for messages.
std::string formatVolume(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, v < 1e5 ? "%.1f" : "%.3g", v);
    return buf;
}
} // namespace

MemoryEstimate estimateMemory(const PreprocessOutput& pre, bool implicit_cells, std::uint64_t budget, bool cheap_folds) {
    MemoryEstimate est;
    est.budget = budget;
    est.largest_tets = pre.cost.largest_input;
    const TetCostSummary& c = pre.cost;
    double points = implicit_cells ? c.points_implicit : c.points;
    double fixed = c.dense_bytes + kBytesPerTet * static_cast<double>(pre.tets.size());
    // Cheap folds (FoldCancellation.cc): where large flipped tets lie over large proper ones,
    // both layers lose their darts; what they cost instead is the owner masks over the box
    // around the large flipped tets. The fold cancellation skips a box much larger than the
    // flipped tets' own boxes, and then nothing cancels.
    if (cheap_folds && c.large_flipped > 0 && c.flipped_union_box <= 4 * c.flipped_box_points + 1e6) {
        points = std::max(0.0, points - 2 * std::min(c.large_proper, c.large_flipped));
        fixed += kOwnerBytesPerBoxPoint * c.flipped_union_box;
        est.cheap_folds = true;
    }
    est.darts = 48 * points;
    est.bytes = est.darts * kBytesPerDart + fixed;
    if (budget == 0) {
        est.max_darts = std::numeric_limits<std::size_t>::max();
    } else {
        const double room = static_cast<double>(budget) - fixed;
        est.max_darts = room <= 0 ? 0 : static_cast<std::size_t>(std::min(room / kBytesPerDart, 1e18));
    }
    return est;
}

std::string largestImagesText(const std::vector<std::pair<int, double>>& largest) {
    std::string text;
    for (std::size_t k = 0; k < largest.size(); ++k)
        text += std::string(k ? ", " : "") + "tet " + std::to_string(largest[k].first) + " (" + formatVolume(largest[k].second) +
                " grid cells)";
    return text;
}

std::string memoryRefusal(const std::string& cause, const MemoryEstimate* est) {
    std::string msg = cause;
    if (est && !est->largest_tets.empty()) {
        msg += ". The tets with the largest parametric images in the input: " + largestImagesText(est->largest_tets);
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

bool budgetAllows(const MemoryEstimate& est, double extra_bytes) {
    return est.budget == 0 || est.bytes + extra_bytes <= static_cast<double>(est.budget);
}

} // namespace HexEx
