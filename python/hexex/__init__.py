"""HexEx for Python: robust hex-mesh extraction from integer-grid maps, numpy in and out.

    import hexex
    m = hexex.generate_cube(n=4, scale=3)          # or hexex.read_map("part.hexex")
    r = hexex.extract(m.points, m.tets, m.params)   # same as hexex.extract(*m)
    print(r.hexes.shape, r.valid_all_hex, r.report["output"])
    hexex.write_hex_mesh("part.vtu", r)

See Documentation/python.md for the whole API.
"""

from . import _core
from ._api import (HexExWarning, extract, generate_cube, generate_cylinder, generate_ring, generate_twisted_ring,
                   map_statistics, optimize, parameter_noise, perturb, perturb_hex_mesh, random_charts, read_hex_mesh, read_map,
                   untangle, validate, write_hex_mesh, write_map)
from ._types import ExtractionResult, HexMesh, OptimizeResult, TetMap, UntangleResult

__version__ = _core.version()
"""Version of the C++ library the module was built from (x.y.z)."""

__all__ = [
    "ExtractionResult", "HexExWarning", "HexMesh", "TetMap", "__version__", "extract", "generate_cube",
    "generate_cylinder", "generate_ring", "generate_twisted_ring", "map_statistics", "OptimizeResult", "optimize",
    "parameter_noise", "perturb", "perturb_hex_mesh",
    "random_charts", "read_hex_mesh", "read_map", "UntangleResult", "untangle", "validate", "write_hex_mesh",
    "write_map",
]
