/// @file cgal_lcc.cc
/// A CGAL Linear_cell_complex of tets in, an LCC of hexahedra out: builds the unit cube
/// from six tets with CGAL's make_tetrahedron() and sew3_same_facets(), stores the map
/// "parameter = 2 * position" in the darts, extracts through the adapter and checks the
/// result with CGAL's own tests (is_valid, is_volume_combinatorial_hexahedron). Exits 0
/// only if the 2x2x2 hexes come out right.

#include <HexEx/Adapters/CgalLinearCellComplex.hh>

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include <array>
#include <iostream>
#include <tuple>

namespace {

/// LCC items whose darts carry the parameter of their vertex in their volume's chart.
struct ParamItems {
    template <class Refs>
    struct Dart_wrapper {
        typedef CGAL::Cell_attribute_with_point<Refs> Vertex_attribute;
        typedef std::tuple<Vertex_attribute> Attributes;
        typedef std::array<double, 3> Dart_info;
    };
};

using TetLcc = CGAL::Linear_cell_complex_for_combinatorial_map<3, 3, CGAL::Linear_cell_complex_traits<3>, ParamItems>;
using HexLcc = CGAL::Linear_cell_complex_for_combinatorial_map<3>;

} // namespace

int main() {
    // The unit cube as six positively oriented tets around its diagonal 0-7.
    TetLcc tets;
    auto corner = [](int i) { return TetLcc::Point(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
    const int cube[6][4] = {{0, 1, 3, 7}, {0, 5, 1, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 6, 4, 7}};
    for (const auto& t : cube) {
        const auto d = tets.make_tetrahedron(corner(t[0]), corner(t[1]), corner(t[2]), corner(t[3]));
        // The map, per dart: the parameter of the dart's vertex (here seamless: 2 * position).
        for (auto it = tets.darts_of_cell<3>(d).begin(); it != tets.darts_of_cell<3>(d).end(); ++it) {
            const TetLcc::Point& p = tets.point(it);
            tets.info(it) = {2 * p.x(), 2 * p.y(), 2 * p.z()};
        }
    }
    tets.sew3_same_facets();

    HexLcc hexes;
    HexEx::LccHexOutput<HexLcc> output(hexes);
    const HexEx::ExtractionReport report = HexEx::extractHexMesh(HexEx::LccTetMesh(tets), output);

    bool allHex = true;
    for (auto d : output.cellDarts()) allHex = allHex && hexes.is_volume_combinatorial_hexahedron(d);
    std::cout << "hex LCC: " << hexes.one_dart_per_cell<3>().size() << " volumes, "
              << hexes.number_of_vertex_attributes() << " vertices, valid " << hexes.is_valid()
              << ", all hexahedra " << allHex << ", valid all-hex " << report.valid_all_hex << "\n";
    const bool ok = report.valid_all_hex && hexes.is_valid() && allHex && output.cellDarts().size() == 8 &&
                    hexes.number_of_vertex_attributes() == 27 && output.unsewnFaces() == 0;
    return ok ? 0 : 1;
}
