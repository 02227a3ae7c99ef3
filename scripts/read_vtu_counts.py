#!/usr/bin/env python3
"""Independent reader of VTK XML UnstructuredGrid (.vtu) files with ASCII data arrays.

Uses only the Python standard library (xml.etree), independent of the HexEx C++ code, to
cross-check the .vtu writer. Prints one line: "points cells hexes polyhedra", summed over
all pieces. Checks that the cell arrays are consistent (offsets increasing and within the
connectivity, one type per cell, point indices in range, polyhedron face streams matching
faceoffsets) and exits with status 1 and a message on stderr if they are not.

usage: read_vtu_counts.py FILE.vtu
"""

import sys
import xml.etree.ElementTree as ET

VTK_HEXAHEDRON = 12
VTK_POLYHEDRON = 42


def fail(msg):
    sys.stderr.write("read_vtu_counts: %s\n" % msg)
    sys.exit(1)


def values(array, conv):
    if array is None:
        return []
    fmt = array.get("format", "ascii")
    if fmt != "ascii":
        fail("DataArray %r has format %r (only ascii is supported)" % (array.get("Name"), fmt))
    return [conv(tok) for tok in (array.text or "").split()]


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: read_vtu_counts.py FILE.vtu\n")
        return 2
    try:
        root = ET.parse(argv[1]).getroot()
    except (OSError, ET.ParseError) as e:
        fail(str(e))
    if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
        fail("not a VTK UnstructuredGrid file")
    points = cells = hexes = polys = 0
    for piece in root.iter("Piece"):
        npts = int(piece.get("NumberOfPoints"))
        ncells = int(piece.get("NumberOfCells"))
        coords = values(piece.find("Points/DataArray"), float)
        if len(coords) != 3 * npts:
            fail("%d coordinates for %d points" % (len(coords), npts))
        arrays = {a.get("Name"): a for a in piece.findall("Cells/DataArray")}
        conn = values(arrays.get("connectivity"), int)
        offsets = values(arrays.get("offsets"), int)
        types = values(arrays.get("types"), int)
        faces = values(arrays.get("faces"), int)
        faceoffsets = values(arrays.get("faceoffsets"), int)
        if len(offsets) != ncells or len(types) != ncells:
            fail("offsets/types do not match NumberOfCells")
        prev = 0
        for o in offsets:
            if o < prev or o > len(conn):
                fail("bad offset %d" % o)
            prev = o
        if any(i < 0 or i >= npts for i in conn):
            fail("point index out of range")
        face_start = 0
        for c, t in enumerate(types):
            if t == VTK_POLYHEDRON:
                end = faceoffsets[c]
                stream = faces[face_start:end]
                if not stream:
                    fail("polyhedron %d has no faces" % c)
                k, nf = 1, stream[0]
                for _ in range(nf):
                    n = stream[k]
                    ids = stream[k + 1:k + 1 + n]
                    if len(ids) != n or any(i < 0 or i >= npts for i in ids):
                        fail("bad face in polyhedron %d" % c)
                    k += 1 + n
                if k != len(stream):
                    fail("face stream of polyhedron %d has the wrong length" % c)
                face_start = end
                polys += 1
            elif t == VTK_HEXAHEDRON:
                begin = offsets[c - 1] if c > 0 else 0
                if offsets[c] - begin != 8:
                    fail("hexahedron %d does not have 8 points" % c)
                hexes += 1
        points += npts
        cells += ncells
    print("%d %d %d %d" % (points, cells, hexes, polys))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
