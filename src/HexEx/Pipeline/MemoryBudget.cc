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

/// "12.5" or "3.1e+05": a volume for messages.
std::string formatVolume(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, v < 1e5 ? "%.1f" : "%.3g", v);
    return buf;
}
} // namespace

MemoryEstimate estimateMemory(const PreprocessOutput& pre, bool implicit_cells, std::uint64_t budget) {
    MemoryEstimate est;
    est.budget = budget;
    est.largest_tets = pre.cost.largest_input;
    est.darts = 48 * (implicit_cells ? pre.cost.points_implicit : pre.cost.points);
    const double fixed = pre.cost.dense_bytes + kBytesPerTet * static_cast<double>(pre.tets.size());
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

} // namespace HexEx
