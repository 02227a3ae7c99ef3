#include "QuadGMapValidator.hh"

#include <sstream>

namespace HexEx {

namespace {
/// Labels the orbits of two involutions (bits a and b) by search, smallest dart first.
std::vector<int> labelPair(const GMap<2>& g, int a, int b, std::vector<int>& size) {
    const auto& L = g.links();
    const std::size_t n = L.size();
    std::vector<int> label(n, -1), stack;
    size.clear();
    for (std::size_t s = 0; s < n; ++s) {
        if (!g.is_alive(DartHandle(static_cast<int>(s))) || label[s] >= 0) continue;
        const int l = static_cast<int>(size.size());
        size.push_back(0);
        label[s] = l;
        stack.assign(1, static_cast<int>(s));
        while (!stack.empty()) {
            const int d = stack.back();
            stack.pop_back();
            ++size[static_cast<std::size_t>(l)];
            for (int i : {a, b}) {
                const int e = L[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)];
                if (e < 0 || static_cast<std::size_t>(e) >= n || !g.is_alive(DartHandle(e)) || label[static_cast<std::size_t>(e)] >= 0)
                    continue;
                label[static_cast<std::size_t>(e)] = l;
                stack.push_back(e);
            }
        }
    }
    return label;
}
} // namespace

std::string QuadGMapValidation::summary() const {
    std::ostringstream os;
    os << (valid() ? "valid" : "INVALID") << ": " << darts << " darts, " << not_involution << " non-involutive, "
       << open_links << " open, eq1 " << eq1_edge_connection << ", eq3 " << eq3_quad << ", " << boundary_darts
       << " boundary darts";
    return os.str();
}

QuadGMapValidation validateQuadGMap(const GMap<2>& g, QuadOrbitLabels* labels) {
    QuadGMapValidation v;
    const auto& L = g.links();
    const std::size_t n = L.size();
    auto alive = [&](int d) { return d >= 0 && static_cast<std::size_t>(d) < n && g.is_alive(DartHandle(d)); };
    for (std::size_t s = 0; s < n; ++s) {
        const int d = static_cast<int>(s);
        if (!alive(d)) continue;
        ++v.darts;
        bool inv = true;
        for (int i = 0; i < 3; ++i) {
            const int p = L[s][static_cast<std::size_t>(i)];
            if (!alive(p) || L[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)] != d) inv = false;
        }
        if (!inv) {
            ++v.not_involution;
            continue;
        }
        if (L[s][0] == d || L[s][1] == d) ++v.open_links;
        if (L[s][2] == d) {
            ++v.boundary_darts;
        } else {
            // (alpha_0 alpha_2)^2 = id: alpha_0 and alpha_2 commute.
            const int x = L[static_cast<std::size_t>(L[s][0])][2];
            const int y = L[static_cast<std::size_t>(L[s][2])][0];
            if (x != y) ++v.eq1_edge_connection;
        }
    }
    std::vector<int> fsize, vsize, esize;
    std::vector<int> face = labelPair(g, 0, 1, fsize);
    for (std::size_t s = 0; s < n; ++s)
        if (face[s] >= 0 && fsize[static_cast<std::size_t>(face[s])] != 8) ++v.eq3_quad;
    if (labels) {
        labels->face = std::move(face);
        labels->n_faces = static_cast<int>(fsize.size());
        labels->vertex = labelPair(g, 1, 2, vsize);
        labels->n_vertices = static_cast<int>(vsize.size());
        labels->edge = labelPair(g, 0, 2, esize);
        labels->n_edges = static_cast<int>(esize.size());
    }
    return v;
}

} // namespace HexEx
