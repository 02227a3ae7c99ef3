#pragma once
/// @file GMapValidator.hh
/// @ingroup pipeline
/// The one validator of paper section 3.1, equations 1-6, for 3D generalized maps of
/// hexahedral meshes. Used by the tests, the CLI report and the benchmarks.

#include "GMap.hh"

#include <functional>
#include <string>
#include <vector>

namespace HexEx {

/// One dart that fails one check of validateHexGMap().
struct GMapViolation {
    std::string check;  ///< "not_involution", "open_link", "eq1" .. "eq6"
    int dart = -1;      ///< the dart (index in the map)
    /// Output vertices of the dart's face (its <alpha_0, alpha_1> orbit walked from the
    /// dart), filled by describeViolations() when the mesh is assembled; empty otherwise.
    std::vector<int> face_vertices;
};

/// Violations found by validateHexGMap(), counted per dart (or per orbit where noted).
struct GMapValidation {
    /// At most this many example darts are kept per check.
    static constexpr int kExamplesPerCheck = 4;
    long darts = 0;                 ///< alive darts checked
    long not_involution = 0;        ///< darts with alpha_i(alpha_i(d)) != d or linked to an erased dart
    long open_links = 0;            ///< darts with a free alpha_0, alpha_1 or alpha_2 (cell not closed)
    long eq1_edge_connection = 0;   ///< (alpha_0 alpha_2)^2 != id: faces not connected over a whole edge
    long eq2_face_connection = 0;   ///< (alpha_0 alpha_3)^2 or (alpha_1 alpha_3)^2 != id (alpha_3 not free)
    long eq3_quad = 0;              ///< darts whose <alpha_0, alpha_1> orbit does not have 8 darts
    long eq4_corner = 0;            ///< darts whose <alpha_1, alpha_2> orbit does not have 6 darts
    long eq5_strip = 0;             ///< darts whose <alpha_0, alpha_1 alpha_2 alpha_1> orbit does not have 8 darts
    long eq6_hex = 0;               ///< darts whose <alpha_0, alpha_1, alpha_2> orbit does not have 48 darts
    long boundary_darts = 0;        ///< darts with free alpha_3 (on the boundary)
    /// Examples when invalid: for each failing check, its first kExamplesPerCheck darts in
    /// dart order (so the same for any thread count), in the order of the checks above.
    std::vector<GMapViolation> examples;
    /// True if no violation was found.
    bool valid() const {
        return not_involution == 0 && open_links == 0 && eq1_edge_connection == 0 && eq2_face_connection == 0 &&
               eq3_quad == 0 && eq4_corner == 0 && eq5_strip == 0 && eq6_hex == 0;
    }
    /// One-line human-readable summary.
    std::string summary() const;
};

/// Orbit labels computed by the validator and reused by the mesh assembly.
struct HexOrbitLabels {
    std::vector<int> face;        ///< <alpha_0, alpha_1> orbit label per dart (-1 for erased darts)
    std::vector<int> corner;      ///< <alpha_1, alpha_2> orbit label per dart
    std::vector<int> cell;        ///< <alpha_0, alpha_1, alpha_2> orbit label per dart
    std::vector<int> face_size;   ///< darts per face orbit
    std::vector<int> corner_size; ///< darts per corner orbit
    std::vector<int> cell_size;   ///< darts per cell orbit
    /// The darts of every cell, in breadth-first order from the cell's smallest dart (not
    /// sorted): cell c holds
    /// cell_darts[cell_offset[c] .. cell_offset[c + 1]). Filled (together with exact face and
    /// corner orbits) only when every dart is alive and every link is an involution;
    /// otherwise both are empty.
    std::vector<int> cell_darts;
    std::vector<int> cell_offset; ///< see cell_darts (n cells + 1 entries, or empty)
};

/// Checks every alive dart of @p g against equations 1-6 of the paper and the involution
/// property. Linear time. If @p labels is given, the face, corner and cell orbits are
/// returned there. Cells are numbered in order of their smallest dart. When every dart is
/// alive and every link an involution (the usual case), faces are numbered cell by cell (in
/// the order of the cells) and labels->cell_darts is filled; otherwise faces are numbered in
/// order of their smallest dart. Corners are always numbered in order of their smallest dart.
/// @p threads runs the checks (and the independent orbit labelings of the general case) in
/// parallel; the result does not depend on it.
/// @p beside, if given, is work that does not depend on the validation: it is called once,
/// with the number of threads it may use, on the checks' threads after the checks when they
/// run beside the sequential cell search (two or more threads, large maps), else after the
/// validation's own work.
GMapValidation validateHexGMap(const GMap<3>& g, HexOrbitLabels* labels = nullptr, int threads = 1,
                               const std::function<void(int)>& beside = nullptr);

/// Output vertices of each example's face: @p vertex_label gives the output vertex of every
/// dart (-1 for none); the face is walked from the example dart by alpha_0 and alpha_1
/// (at most 16 steps).
void describeViolations(const GMap<3>& g, const std::vector<int>& vertex_label, GMapValidation& v);

/// Labels the orbits of @p g for the links in @p mask (bit i = alpha_i): returns a label
/// per dart (-1 for erased darts), labels numbered 0.. in order of their smallest dart.
std::vector<int> labelOrbits(const GMap<3>& g, unsigned mask, int* n_labels = nullptr);

/// The same labels as labelOrbits(g, 0b1110, n_labels) (vertices: <alpha_1, alpha_2,
/// alpha_3> orbits, numbered in order of their smallest dart), computed from the corner
/// orbits in @p labels (joined over alpha_3) when validateHexGMap() filled labels.cell_darts.
std::vector<int> labelVertexOrbits(const GMap<3>& g, const HexOrbitLabels& labels, int* n_labels = nullptr);

/// Number of <alpha_0, alpha_1, alpha_3> orbits (quads), and in @p boundary how many of
/// them hold a dart with a free alpha_3; computed from the face orbits in @p labels (joined
/// over alpha_3) when validateHexGMap() filled labels.cell_darts.
long countQuadOrbits(const GMap<3>& g, const HexOrbitLabels& labels, long* boundary);

} // namespace HexEx
