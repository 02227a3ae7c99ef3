#include "DartStage.hh"

#include "../Core/Error.hh"
#include "../Core/Memory.hh"
#include "../Core/Parallel.hh"
#include "../Extraction/FoldCancellation.hh"
#include "ImplicitCellPath.hh"

#include <algorithm>

#include <limits>

namespace HexEx {

DartStageOutput extractDartStage(const DartStageInput& in) {
    DartStageOutput out;
    out.implicit_cells = in.implicit_cells;
    std::vector<FaceMask> usableFaces;
    if (in.implicit_cells) usableFaces = implicitCellFaces(*in.mesh, *in.tets);
    const std::size_t maxDarts = in.budget ? in.budget->max_darts : static_cast<std::size_t>(-1);
    std::vector<int> components;
    const bool folds = std::any_of(in.tets->begin(), in.tets->end(), [](const TetSoS& T) { return T.vol < 0; });
    // The components serve only the cancellation, which looks only at flipped tets with a
    // dense index: maps whose flipped tets are all small (maps built from hex meshes) skip
    // them. The extraction is the same: it cancels nothing there either, and its dart cap
    // gives the same verdict before or after a cancellation that removes nothing.
    if (in.cheap_folds && in.transitions && folds && mayCancelFoldPoints(*in.tets))
        components = identityChartComponents(*in.mesh, *in.transitions);
    try {
        out.darts = extractDarts(*in.tets, in.threads, 1e9, in.implicit_cells, in.implicit_cells ? &usableFaces : nullptr,
                                 in.abs_volume, maxDarts, components.empty() ? nullptr : &components);
    } catch (const ResourceError&) {
        throw ResourceError(memoryRefusal("the darts of the map need more than the memory budget of " +
                                              formatBytes(static_cast<double>(in.budget->budget)) + " (stopped after " +
                                              std::to_string(maxDarts) + " darts; estimated " + formatBytes(in.budget->bytes) + ")",
                                          in.budget));
    }
    if (out.darts.n_occurrences >= std::numeric_limits<int>::max() / 2)
        throw InputError("too many grid points in large tets for 32-bit indices");
    const std::size_t nd = out.darts.darts.size();
    out.sign.resize(nd);
    std::vector<long> antiPerChunk(static_cast<std::size_t>(in.threads), 0);
    // A dart's sign is its tet's volume sign (extractDarts() gives every dart of a tet that
    // sign). With many darts per tet it is filled tet range by tet range, without a pass
    // over the darts (20 bytes read per byte written: about 10 ms of pig x2's stage, 16 darts
    // per tet); with few (cube s=40: one per tet) the loop over the tets cost more than that
    // pass (+8 ms), which is kept there. The chunks split the darts, not the tets (the
    // cylinder's few large tets hold most of them).
    const std::vector<std::size_t>& begin = out.darts.tet_begin;
    const bool byTet = nd >= 8 * in.tets->size();
    parallelChunks(nd, in.threads, [&](int k, std::size_t b, std::size_t e) {
        long& anti = antiPerChunk[static_cast<std::size_t>(k)];
        if (!byTet) {
            for (std::size_t d = b; d < e; ++d) {
                out.sign[d] = out.darts.darts[d].sign;
                if (out.sign[d] < 0) ++anti;
            }
            return;
        }
        // The tet holding dart b: the last with tet_begin <= b.
        auto t = static_cast<std::size_t>(std::upper_bound(begin.begin(), begin.end(), b) - begin.begin()) - 1;
        for (std::size_t d = b; d < e; ++t) {
            const std::size_t hi = std::min(e, begin[t + 1]);
            if (d == hi) continue;
            const auto s = static_cast<signed char>((*in.tets)[t].vol);
            std::fill(out.sign.begin() + static_cast<long>(d), out.sign.begin() + static_cast<long>(hi), s);
            if (s < 0) anti += static_cast<long>(hi - d);
            d = hi;
        }
    });
    for (long a : antiPerChunk) out.anti += a;
    return out;
}

} // namespace HexEx
