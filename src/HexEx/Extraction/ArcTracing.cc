#include "ArcTracing.hh"

#include "../Core/Prefetch.hh"
#include "../Mesh/TetMesh.hh"
#include "ConnectionTracing.hh"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace HexEx {

namespace {

/// Longest edge walk (tets visited); a valid map needs a handful.
constexpr int kMaxArcSteps = 1 << 16;
/// Most tets one face patch may visit.
constexpr std::size_t kMaxPatchTets = 1 << 16;
/// Parametric distance below which a point counts as on the square's border (only decides
/// whether a clipped side leads on into a neighbour; see traceFacePatch()).
constexpr double kBorderTolerance = 1e-9;

/// Orientation of tet T with corner j replaced by x (o_j(x), the barycentric numerator).
double subVolume(const TetSoS& T, int j, const Vec3d& x) {
    Vec3d q[4] = {T.p[0], T.p[1], T.p[2], T.p[3]};
    q[j] = x;
    return tetVolume6(q[0], q[1], q[2], q[3]);
}

/// Signed parametric volume of T.
double volume(const TetSoS& T) { return tetVolume6(T.p[0], T.p[1], T.p[2], T.p[3]); }

/// 3D point with barycentric coordinates @p lam (normalized here) in tet @p t.
Vec3d mapBack(const TetMesh& mesh, int t, const double lam[4]) {
    const auto& cv = mesh.cell_vertices(CellHandle(t));
    double sum = 0;
    for (int j = 0; j < 4; ++j) sum += lam[j];
    Vec3d x(0, 0, 0);
    for (int j = 0; j < 4; ++j) x += mesh.position(cv[j]) * (sum > 0 ? lam[j] / sum : 0.25);
    return x;
}

/// True if grid point @p z lies in the closed bounding box of T's parameters. Outside it,
/// some face plane separates z strictly from T, so the exact test T.contains() is false
/// for any perturbation: this cheap test skips the four orientation predicates on most
/// steps of an edge walk.
bool inClosedBox(const TetSoS& T, const Vec3i& z) {
    for (int k = 0; k < 3; ++k) {
        const double x = z[k];
        const double lo = std::min(std::min(T.p[0][k], T.p[1][k]), std::min(T.p[2][k], T.p[3][k]));
        const double hi = std::max(std::max(T.p[0][k], T.p[1][k]), std::max(T.p[2][k], T.p[3][k]));
        if (x < lo || x > hi) return false;
    }
    return true;
}

/// Position of grid point @p z of a non-degenerate tet, with exact zeros on its faces.
Vec3d gridPoint(const TetMesh& mesh, const TetSoS& T, int t, const Vec3i& z) {
    const Vec3d x = toVec3d(z);
    const std::array<int, 4> oz = T.sides(x);
    const double V = volume(T);
    double lam[4];
    for (int j = 0; j < 4; ++j) lam[j] = oz[j] == 0 ? 0.0 : std::max(0.0, subVolume(T, j, x) / V);
    return mapBack(mesh, t, lam);
}

/// Where the line through @p z along @p dir leaves tet @p t through its face @p f.
Vec3d lineCrossing(const TetMesh& mesh, const TetSoS& T, int t, int f, const Vec3i& zi, AxisDir dir) {
    const int ax = dirAxis(dir);
    const Vec3d z = toVec3d(zi);
    Vec3d step(0, 0, 0);
    step[ax] = dirSign(dir);
    double lam[4];
    if (T.vol != 0) {
        // o_k(z + s step) = a_k + b_k s is affine along the line.
        double a[4], b[4];
        for (int k = 0; k < 4; ++k) {
            a[k] = subVolume(T, k, z);
            b[k] = subVolume(T, k, z + step) - a[k];
        }
        double s;
        if (T.g[f][ax] != 0 && b[f] != 0) {
            s = -a[f] / b[f];
        } else {
            // The line runs in the plane of face f (chosen by the tie-breaking): it leaves
            // where the first of the other faces stops it.
            s = std::numeric_limits<double>::infinity();
            for (int k = 0; k < 4; ++k)
                if (k != f && T.vol * dirSign(dir) * T.g[k][ax] < 0 && b[k] != 0) s = std::min(s, -a[k] / b[k]);
            if (!std::isfinite(s)) s = 0;
        }
        const double V = volume(T);
        for (int k = 0; k < 4; ++k) lam[k] = k == f ? 0.0 : std::max(0.0, (a[k] + b[k] * s) / V);
        return mapBack(mesh, t, lam);
    }
    // Degenerate tet: the line meets face f's plane where its projection along the line's
    // axis falls into the projected triangle.
    const int i = (ax + 1) % 3, j = (ax + 2) % 3;
    const int* fc = TetMesh::kFaceCorners[f];
    const Vec3d &A = T.p[fc[0]], &B = T.p[fc[1]], &C = T.p[fc[2]];
    const double den = (B[i] - A[i]) * (C[j] - A[j]) - (C[i] - A[i]) * (B[j] - A[j]);
    for (int k = 0; k < 4; ++k) lam[k] = 0;
    if (den == 0) {
        for (int q = 0; q < 3; ++q) lam[fc[q]] = 1;
        return mapBack(mesh, t, lam);
    }
    const double lb = ((z[i] - A[i]) * (C[j] - A[j]) - (C[i] - A[i]) * (z[j] - A[j])) / den;
    const double lc = ((B[i] - A[i]) * (z[j] - A[j]) - (z[i] - A[i]) * (B[j] - A[j])) / den;
    lam[fc[1]] = std::max(0.0, lb);
    lam[fc[2]] = std::max(0.0, lc);
    lam[fc[0]] = std::max(0.0, 1 - lb - lc);
    return mapBack(mesh, t, lam);
}

/// A grid point with a frame in the current tet's chart.
struct Chart {
    Vec3i z;
    std::array<AxisDir, 3> d;
};

Chart transformed(const GridTransform& g, const Chart& c) {
    return {g.apply(c.z), {g.applyDir(c.d[0]), g.applyDir(c.d[1]), g.applyDir(c.d[2])}};
}

/// A vertex of a clipped polygon: square coordinates (a along d0, b along d1) and
/// barycentric coordinates in the tet; `side` labels the side to the next vertex (local tet
/// face, or -1 for the square's border).
/// Trivial (no member initializers): polygons of them live on the stack in the hot loop and
/// are filled field by field.
struct PolyVertex {
    double a, b;
    double lam[4];
    int side;
};

/// A convex polygon of at most kMaxVertices vertices, on the stack (the section of a tet has
/// at most 4, and each of the 4 clips adds at most one).
class Polygon {
public:
    static constexpr std::size_t kMaxVertices = 8;
    Polygon() = default;
    // Copies move only the vertices in use (the polygons are copied in the flood's inner loop).
    Polygon(const Polygon& o) : n_(o.n_) { std::copy(o.v_, o.v_ + n_, v_); }
    Polygon& operator=(const Polygon& o) {
        n_ = o.n_;
        std::copy(o.v_, o.v_ + n_, v_);
        return *this;
    }
    std::size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }
    PolyVertex& operator[](std::size_t k) { return v_[k]; }
    const PolyVertex& operator[](std::size_t k) const { return v_[k]; }
    void push_back(const PolyVertex& x) {
        if (n_ < kMaxVertices) v_[n_++] = x;
    }
    void clear() { n_ = 0; }

private:
    PolyVertex v_[kMaxVertices];
    std::size_t n_ = 0;
};

/// The section of tet T by the square's plane moved by e along d[2] (vertices on the plane
/// count as behind it), as a counter-clockwise polygon in square coordinates. Empty if the
/// tet lies on one side.
Polygon planeSection(const TetSoS& T, const Chart& c) {
    const int wa = dirAxis(c.d[2]), aa = dirAxis(c.d[0]), ba = dirAxis(c.d[1]);
    const double ws = dirSign(c.d[2]), as = dirSign(c.d[0]), bs = dirSign(c.d[1]);
    const double w0 = c.z[wa];
    int above[4], below[4], na = 0, nb = 0;
    for (int j = 0; j < 4; ++j) {
        if (ws * (T.p[j][wa] - w0) > 0) above[na++] = j;
        else below[nb++] = j;
    }
    Polygon poly;
    if (na == 0 || nb == 0) return poly;
    auto cut = [&](int p, int q) {  // p above, q behind: the point where edge pq meets the plane
        const double wp = T.p[p][wa], wq = T.p[q][wa];
        const double s = wq == w0 ? 0.0 : (w0 - wq) / (wp - wq);
        PolyVertex v;
        v.side = -1;
        v.lam[0] = v.lam[1] = v.lam[2] = v.lam[3] = 0;
        const Vec3d x = T.p[q] + (T.p[p] - T.p[q]) * s;
        v.a = as * (x[aa] - c.z[aa]);
        v.b = bs * (x[ba] - c.z[ba]);
        v.lam[q] = 1 - s;
        v.lam[p] = s;
        return v;
    };
    if (na == 1 || nb == 1) {
        const int s = na == 1 ? above[0] : below[0];
        int o[3], n = 0;
        for (int j = 0; j < 4; ++j)
            if (j != s) o[n++] = j;
        for (int k = 0; k < 3; ++k) {
            PolyVertex v = na == 1 ? cut(s, o[k]) : cut(o[k], s);
            v.side = o[(k + 2) % 3];  // the side to the next point lies in the face opposite the remaining corner
            poly.push_back(v);
        }
    } else {
        const int p1 = above[0], p2 = above[1], q1 = below[0], q2 = below[1];
        PolyVertex v[4] = {cut(p1, q1), cut(p1, q2), cut(p2, q2), cut(p2, q1)};
        v[0].side = p2;
        v[1].side = q1;
        v[2].side = p1;
        v[3].side = q2;
        for (const PolyVertex& x : v) poly.push_back(x);
    }
    double area2 = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const PolyVertex &u = poly[k], &w = poly[(k + 1) % poly.size()];
        area2 += u.a * w.b - w.a * u.b;
    }
    if (area2 < 0) {
        // Reverse: the side from new vertex k to k+1 is the old side from n-2-k to n-1-k.
        const std::size_t n = poly.size();
        Polygon r;
        for (std::size_t k = 0; k < n; ++k) {
            r.push_back(poly[n - 1 - k]);
            r[k].side = poly[(2 * n - 2 - k) % n].side;
        }
        poly = r;
    }
    return poly;
}

/// Clips @p poly by the half plane sign * (coordinate - bound) <= 0 (coordinate a or b).
void clip(Polygon& poly, bool useA, double bound, double sign) {
    if (poly.empty()) return;
    auto h = [&](const PolyVertex& v) { return sign * ((useA ? v.a : v.b) - bound); };  // inside if <= 0
    const std::size_t n = poly.size();
    bool allInside = true;
    for (std::size_t k = 0; k < n && allInside; ++k) allInside = h(poly[k]) <= 0;
    if (allInside) return;  // the common case: nothing to cut
    Polygon out;
    for (std::size_t k = 0; k < n; ++k) {
        const PolyVertex &cur = poly[k], &nxt = poly[(k + 1) % n];
        const double hc = h(cur), hn = h(nxt);
        const bool inC = hc <= 0, inN = hn <= 0;
        if (inC) out.push_back(cur);
        if (inC != inN) {
            const double s = hc / (hc - hn);
            PolyVertex x;
            x.a = cur.a + (nxt.a - cur.a) * s;
            x.b = cur.b + (nxt.b - cur.b) * s;
            (useA ? x.a : x.b) = bound;
            for (int j = 0; j < 4; ++j) x.lam[j] = cur.lam[j] + (nxt.lam[j] - cur.lam[j]) * s;
            x.side = inC ? -1 : cur.side;
            out.push_back(x);
        }
    }
    poly = out;
}

bool strictlyInside(double a, double b) {
    return a > kBorderTolerance && a < 1 - kBorderTolerance && b > kBorderTolerance && b < 1 - kBorderTolerance;
}

} // namespace

bool traceEdgeArc(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets, const ArcStart& start,
                  std::vector<Vec3d>& points) {
    if (start.tet < 0 || static_cast<std::size_t>(start.tet) >= tets.size()) return false;
    int t = start.tet;
    const int vol0 = tets[static_cast<std::size_t>(t)].vol;
    if (vol0 == 0) return false;
    Chart from{start.z, start.d};
    Chart to{start.z + dirVec(start.d[0]), {dirNeg(start.d[0]), start.d[1], start.d[2]}};
    bool swapped = false;
    int sign = vol0;
    const std::size_t first = points.size();
    points.push_back(gridPoint(mesh, tets[static_cast<std::size_t>(t)], t, from.z));
    int entry = -1;
    for (int step = 0; step < kMaxArcSteps; ++step) {
        const TetSoS& T = tets[static_cast<std::size_t>(t)];
        if (!swapped && T.vol == vol0 && inClosedBox(T, to.z) && T.contains(T.sides(toVec3d(to.z)), to.d[0], to.d[1], to.d[2])) {
            points.push_back(gridPoint(mesh, T, t, to.z));
            return true;
        }
        const int f = edgeTraceExitFace(mesh, T, t, from.z, from.d, entry);
        const HalfFaceHandle hf = TetMesh::halfface(CellHandle(t), f < 0 ? 0 : f);
        const HalfFaceHandle opp = f < 0 ? HalfFaceHandle() : mesh.opposite_halfface(hf);
        if (!opp.is_valid()) break;
        points.push_back(lineCrossing(mesh, T, t, f, from.z, from.d[0]));
        if (!tr.halfface.is_identity(hf.uidx())) {
            const GridTransform g = tr.halfface[hf.uidx()];
            from = transformed(g, from);
            to = transformed(g, to);
        }
        t = TetMesh::cell(opp).idx();
        entry = TetMesh::opposite_corner(opp);
        const int sv = tets[static_cast<std::size_t>(t)].vol;
        if (sv != 0 && sv != sign) {
            std::swap(from, to);
            swapped = !swapped;
            sign = sv;
        }
    }
    points.resize(first);
    return false;
}

bool traceFacePatch(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets,
                    const std::vector<ArcStart>& starts, std::vector<Vec3d>& points,
                    std::vector<std::array<int, 3>>& triangles, double& signed_area) {
    PatchScratch scratch;
    return traceFacePatch(mesh, tr, tets, starts, points, triangles, signed_area, scratch);
}

bool traceFacePatch(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets,
                    const std::vector<ArcStart>& starts, std::vector<Vec3d>& points,
                    std::vector<std::array<int, 3>>& triangles, double& signed_area, PatchScratch& scratch) {
    signed_area = 0;
    // A visited (tet, square) is keyed by the square's smallest corner, its two axes and the
    // perturbation direction, so that starts at different corners of one square agree.
    using Key = PatchScratch::Key;
    auto key = [](int t, const Chart& c) {
        Vec3i lo = c.z;
        for (int k = 0; k < 2; ++k)
            if (dirSign(c.d[static_cast<std::size_t>(k)]) < 0) --lo[dirAxis(c.d[static_cast<std::size_t>(k)])];
        const int a0 = dirAxis(c.d[0]), a1 = dirAxis(c.d[1]);
        return Key{t, lo[0], lo[1], lo[2], std::min(a0, a1), std::max(a0, a1), c.d[2]};
    };
    // Visited squares: a short list searched linearly (floods are small), a set beyond.
    std::vector<Key>& few = scratch.few;
    std::set<Key>& many = scratch.many;
    few.clear();
    many.clear();
    auto firstVisit = [&](const Key& k) {
        if (many.empty()) {
            for (const Key& x : few)  // the tet differs almost always: compare it first
                if (x[0] == k[0] && x == k) return false;
            few.push_back(k);
            if (few.size() > 64) many.insert(few.begin(), few.end());
            return true;
        }
        return many.insert(k).second;
    };
    using Item = PatchScratch::Item;
    std::vector<Item>& queue = scratch.queue;
    queue.clear();
    for (const ArcStart& st : starts) {
        if (st.tet < 0 || static_cast<std::size_t>(st.tet) >= tets.size()) continue;
        const Chart c{st.z, st.d};
        if (firstVisit(key(st.tet, c))) queue.push_back({st.tet, -1, c.z, c.d});
    }
    for (std::size_t head = 0; head < queue.size(); ++head) {
        if (queue.size() > kMaxPatchTets) return false;
        const int t = queue[head].tet, entry = queue[head].entry;
        const Chart c{queue[head].z, queue[head].d};
        const TetSoS& T = tets[static_cast<std::size_t>(t)];
        Polygon poly = planeSection(T, c);
        clip(poly, true, 0, -1);
        clip(poly, true, 1, 1);
        clip(poly, false, 0, -1);
        clip(poly, false, 1, 1);
        const std::size_t n = poly.size();
        if (n < 2) continue;
        // Triangles (a fan; zero-area ones left out) and the signed parametric area.
        if (n >= 3 && T.vol != 0) {
            const int base = static_cast<int>(points.size());
            const auto& cv = mesh.cell_vertices(CellHandle(t));
            const Vec3d X[4] = {mesh.position(cv[0]), mesh.position(cv[1]), mesh.position(cv[2]), mesh.position(cv[3])};
            for (std::size_t k = 0; k < n; ++k) {
                // The section's barycentric coordinates are convex combinations already (sum 1).
                const double* l = poly[k].lam;
                points.push_back(X[0] * l[0] + X[1] * l[1] + X[2] * l[2] + X[3] * l[3]);
            }
            for (std::size_t k = 1; k + 1 < n; ++k) {
                const PolyVertex &p0 = poly[0], &p1 = poly[k], &p2 = poly[k + 1];
                const double area = 0.5 * ((p1.a - p0.a) * (p2.b - p0.b) - (p2.a - p0.a) * (p1.b - p0.b));
                if (area <= 0) continue;
                triangles.push_back({base, base + static_cast<int>(k), base + static_cast<int>(k) + 1});
                signed_area += T.vol * area;
            }
        }
        // Go on across every tet face that cuts the square along a side inside it.
        for (std::size_t k = 0; k < n; ++k) {
            const PolyVertex &u = poly[k], &w = poly[(k + 1) % n];
            if (u.side < 0 || u.side == entry || (u.a == w.a && u.b == w.b)) continue;
            if (!strictlyInside(0.5 * (u.a + w.a), 0.5 * (u.b + w.b))) continue;
            const HalfFaceHandle hf = TetMesh::halfface(CellHandle(t), u.side);
            const HalfFaceHandle opp = mesh.opposite_halfface(hf);
            if (!opp.is_valid()) continue;
            const Chart next = tr.halfface.is_identity(hf.uidx()) ? c : transformed(tr.halfface[hf.uidx()], c);
            const int nt = TetMesh::cell(opp).idx();
            if (firstVisit(key(nt, next))) {
                queue.push_back({nt, TetMesh::opposite_corner(opp), next.z, next.d});
                // Its data is read when the item comes up: ask for it now.
                prefetch(&tets[static_cast<std::size_t>(nt)]);
                prefetch(&mesh.cell_vertices(CellHandle(nt)));
            }
        }
    }
    return true;
}

} // namespace HexEx
