"""Result types of the hexex package: TetMap (a tet mesh with its map), HexMesh and
ExtractionResult."""

from __future__ import annotations

from typing import List, NamedTuple, Optional

import numpy as np


class TetMap(NamedTuple):
    """A tet mesh with its integer-grid map, as returned by :func:`hexex.read_map` and the
    generators. Unpacks into the first three arguments of :func:`hexex.extract`::

        result = hexex.extract(*hexex.read_map("part.hexex"))
    """

    points: np.ndarray
    """Vertex positions, float64, shape (n, 3)."""
    tets: np.ndarray
    """Four vertex indices per tet, int32, shape (m, 4) (positively oriented)."""
    params: np.ndarray
    """Parameter of every tet corner in that tet's chart, float64, shape (m, 4, 3)."""


class HexMesh:
    """A hex mesh: vertex positions, hexahedra in VTK order and the cells that are not
    hexahedra (polyhedra)."""

    def __init__(self, points: np.ndarray, hexes: np.ndarray, polyhedra: Optional[List] = None):
        self.points = points
        """Vertex positions, float64, shape (k, 3)."""
        self.hexes = hexes
        """Hexahedra, int32, shape (h, 8), VTK vertex order (bottom quad 0-1-2-3 counter-
        clockwise seen from the top quad 4-5-6-7, vertex 4 above vertex 0)."""
        self.polyhedra = [] if polyhedra is None else polyhedra
        """Non-hex cells: per cell a list of faces, per face a list of vertex indices
        (outward-oriented loops). Empty for an all-hex mesh."""

    def __repr__(self) -> str:
        return (f"{type(self).__name__}({len(self.points)} vertices, {len(self.hexes)} hexes, "
                f"{len(self.polyhedra)} polyhedra)")

    def to_meshio(self):
        """The mesh as a ``meshio.Mesh`` (requires meshio): one ``hexahedron`` block, plus
        ``polyhedronN`` blocks (N = number of vertices) for the polyhedra."""
        try:
            import meshio
        except ImportError as e:
            raise ImportError("HexMesh.to_meshio() needs meshio: python3 -m pip install meshio") from e
        cells = [("hexahedron", np.asarray(self.hexes))]
        by_size = {}
        for cell in self.polyhedra:
            n = len({v for face in cell for v in face})
            by_size.setdefault(n, []).append([np.asarray(f) for f in cell])
        for n, group in sorted(by_size.items()):
            cells.append((f"polyhedron{n}", group))
        return meshio.Mesh(np.asarray(self.points), cells)


class ExtractionResult(HexMesh):
    """The output of :func:`hexex.extract`: the hex mesh plus the extraction report."""

    def __init__(self, points, hexes, polyhedra, report: dict, provenance=None):
        super().__init__(points, hexes, polyhedra)
        self.report = report
        """The extraction report: a dict with the keys of the JSON report of
        ``hexex extract --report`` (input, output, darts, valid_all_hex, quality,
        timings_s, threads, version, validation, warnings)."""
        self.provenance = provenance
        """With ``extract(..., provenance=True)``: a dict of int32 arrays ``hex_source_tet``
        (h,), ``hex_grid_cell`` (h, 3), ``vertex_source_tet`` (k,), ``vertex_grid_coords``
        (k, 3); otherwise None."""

    @property
    def valid_all_hex(self) -> bool:
        """True if every cell is a hexahedron and the dart map passed validation."""
        return bool(self.report["valid_all_hex"])


class OptimizeResult(HexMesh):
    """The output of :func:`hexex.optimize`: the hex mesh with moved vertices plus the report."""

    def __init__(self, points, hexes, polyhedra, report: dict):
        super().__init__(points, hexes, polyhedra)
        self.report = report
        """The optimisation report: a dict with the fields of ``HexEx::OptimizeReport``
        (min/mean_scaled_jacobian_before/after, min_scaled_jacobian_projected,
        invalid_before/after (hexes not certified valid), histogram_before/after (20 counts
        over [-1, 1]), vertex counts by kind, feature_curves, feature_corners, diagonal,
        max/mean_surface_distance, max/mean_feature_distance, global_blocks, accepted_blocks,
        lbfgs_iterations, local_passes, local_moves, seconds, reached_target, success, message)."""

    @property
    def success(self) -> bool:
        """False if the input was refused (it had inverted hexes; see ``report["message"]``)."""
        return bool(self.report["success"])


class UntangleResult(HexMesh):
    """The output of :func:`hexex.untangle`: the hex mesh with moved vertices plus the report."""

    def __init__(self, points, hexes, polyhedra, report: dict):
        super().__init__(points, hexes, polyhedra)
        self.report = report
        """The untangling report: a dict with the fields of ``HexEx::UntangleReport``
        (hexes, inverted_before, inverted_after (corner Jacobian <= 0), invalid_before,
        invalid_after, undecided_before, undecided_after (the certified test of the whole
        hex, ``validate``), min/mean_scaled_jacobian_before/after,
        free_vertices, moved_vertices, max_displacement, mean_displacement (relative to the
        bounding-box diagonal), released_feature_vertices, attempts, rings, outer_iterations, lbfgs_iterations, quality_iterations,
        seconds, success, budget_exhausted, message)."""

    @property
    def success(self) -> bool:
        """True if every hex is certified valid after untangling (invalid_after and
        undecided_after are 0), not only positive at its 8 corners."""
        return bool(self.report["success"])
