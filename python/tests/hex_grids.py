"""Hex meshes built in the tests (imported by the test modules; pytest puts this folder on
sys.path)."""

import numpy as np


def grid_cube(n):
    """The unit cube as an n x n x n grid of hexes: (points (k, 3), hexes (n^3, 8) int32, VTK order)."""
    i = np.arange(n + 1)
    z, y, x = np.meshgrid(i, i, i, indexing="ij")
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1) / n

    def vid(a, b, c):
        return (c * (n + 1) + b) * (n + 1) + a

    hexes = [[vid(a, b, c), vid(a + 1, b, c), vid(a + 1, b + 1, c), vid(a, b + 1, c), vid(a, b, c + 1),
              vid(a + 1, b, c + 1), vid(a + 1, b + 1, c + 1), vid(a, b + 1, c + 1)]
             for c in range(n) for b in range(n) for a in range(n)]
    return points, np.array(hexes, dtype=np.int32)
