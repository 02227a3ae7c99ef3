#include "LocalVertexCheck.hh"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace HexEx {

namespace {

/// Labels of orbits, filled on demand (one int per dart, -1 unlabelled), and the darts of
/// each labelled orbit (in the order they were labelled).
class OrbitLabels {
public:
    OrbitLabels(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, std::array<int, 3> links)
        : alpha_(alpha), alive_(alive), links_(links), label_(alpha.size(), -1) {}

    /// The label of @p d's orbit; labels the orbit (its darts listed for darts()) the first
    /// time, and then sets @p fresh (if given).
    int of(int d, bool* fresh = nullptr) {
        if (fresh) *fresh = label_[static_cast<std::size_t>(d)] < 0;
        if (label_[static_cast<std::size_t>(d)] >= 0) return label_[static_cast<std::size_t>(d)];
        const int id = next_++;
        stack_.assign(1, d);
        label_[static_cast<std::size_t>(d)] = id;
        while (!stack_.empty()) {
            const int x = stack_.back();
            stack_.pop_back();
            members_.push_back(x);
            for (int i : links_) {
                const int p = alpha_[static_cast<std::size_t>(x)][static_cast<std::size_t>(i)];
                if (p < 0 || p == x || !alive_[static_cast<std::size_t>(p)] || label_[static_cast<std::size_t>(p)] >= 0) continue;
                label_[static_cast<std::size_t>(p)] = id;
                stack_.push_back(p);
            }
        }
        start_.push_back(static_cast<int>(members_.size()));
        return id;
    }

    /// The darts of orbit @p label (labelled before).
    std::pair<const int*, const int*> darts(int label) const {
        return {members_.data() + start_[static_cast<std::size_t>(label)], members_.data() + start_[static_cast<std::size_t>(label) + 1]};
    }

private:
    const std::vector<std::array<int, 4>>& alpha_;
    const std::vector<char>& alive_;
    const std::array<int, 3> links_;
    std::vector<int> label_;
    std::vector<int> stack_;
    std::vector<int> members_;     // darts of the orbits, label after label
    std::vector<int> start_{0};    // per label: first of its darts in members_
    int next_ = 0;
};

} // namespace

long countMergedVertexQuads(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& seeds) {
    OrbitLabels vertex(alpha, alive, {{1, 2, 3}}), face(alpha, alive, {{0, 1, 3}});
    std::vector<std::array<int, 4>> quads;        // sorted vertex labels of each quad looked at (once per face)
    std::vector<char> vertexDone;                 // per vertex label: its quads were looked at
    std::vector<int> atVertex;
    long merged = 0;
    for (int s : seeds) {
        if (s < 0 || !alive[static_cast<std::size_t>(s)]) continue;
        const int v = vertex.of(s);
        if (static_cast<std::size_t>(v) >= vertexDone.size()) vertexDone.resize(static_cast<std::size_t>(v) + 1, 0);
        if (vertexDone[static_cast<std::size_t>(v)]) continue;
        vertexDone[static_cast<std::size_t>(v)] = 1;
        // Its darts as listed when it was labelled, here or earlier as the corner of a quad
        // (the same set as a search of its orbit from s; the order does not matter: each quad
        // is looked at once, and what is counted depends only on its vertex set). Copied:
        // labelling more vertices below grows the list.
        const auto range = vertex.darts(v);
        atVertex.assign(range.first, range.second);
        for (int x : atVertex) {
            bool fresh = false;
            const auto inFace = face.darts(face.of(x, &fresh));
            if (!fresh) continue;  // this quad was looked at before
            std::array<int, 4> corners{{-1, -1, -1, -1}};
            int n = 0;
            bool repeated = false;
            for (const int* y = inFace.first; y != inFace.second; ++y) {
                const int c = vertex.of(*y);
                if (std::find(corners.begin(), corners.begin() + n, c) != corners.begin() + n) continue;
                if (n == 4) {
                    repeated = true;  // more than four vertices: not a quad of a valid hex
                    break;
                }
                corners[static_cast<std::size_t>(n++)] = c;
            }
            if (repeated || n != 4) {
                ++merged;
                continue;
            }
            std::sort(corners.begin(), corners.end());
            quads.push_back(corners);
        }
    }
    // Each face is listed once: equal vertex sets are different faces on the same vertices.
    std::sort(quads.begin(), quads.end());
    for (std::size_t k = 1; k < quads.size(); ++k)
        if (quads[k] == quads[k - 1]) ++merged;
    return merged;
}

} // namespace HexEx
