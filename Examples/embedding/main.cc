/// @file main.cc
/// HexEx built as a subproject (add_subdirectory): extracts a generated 2 x 2 x 2 cube and
/// exits 0 if the result is 8 valid hexes.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>

#include <iostream>

int main() {
    HexEx::ParametrizedTetMesh cube = HexEx::generateCube(2, 2);
    cube.mesh.build_adjacency();
    HexEx::HexMesh hexes;
    const HexEx::ExtractionReport report = HexEx::extractHexMesh(cube, hexes);
    std::cout << hexes.hexes.size() << " hexes, valid all-hex " << report.valid_all_hex << "\n";
    return report.valid_all_hex && hexes.hexes.size() == 8 ? 0 : 1;
}
