"""extract(..., provenance=True): source tet and grid cell per hex, grid coordinates per vertex."""

import numpy as np
import pytest

import hexex


def barycentric(corners, u):
    """Barycentric coordinates of the points u (n, 3) in the tets corners (n, 4, 3)."""
    m = np.stack([corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 0]], axis=2)
    l = np.linalg.solve(m, (u - corners[:, 0])[..., None])[..., 0]
    return np.concatenate([1 - l.sum(axis=1, keepdims=True), l], axis=1)


def test_cube_grid_cells_and_source_tets_contain_the_centres():
    points, tets, params = hexex.generate_cube(3, 2)  # parameter = 2 x position, one chart
    r = hexex.extract(points, tets, params, provenance=True)
    p = r.provenance
    assert p["hex_source_tet"].shape == (8,) and p["hex_source_tet"].dtype == np.int32
    assert p["hex_grid_cell"].shape == (8, 3)
    assert p["vertex_grid_coords"].shape == (27, 3)
    centre = 2 * r.points[r.hexes].mean(axis=1)
    assert np.allclose(centre, p["hex_grid_cell"] + 0.5)
    assert (barycentric(params[p["hex_source_tet"]], centre) > -1e-9).all()
    assert np.array_equal(p["vertex_grid_coords"], np.rint(2 * r.points).astype(np.int32))


def test_singular_cylinder_grid_coords_map_back_to_the_positions():
    points, tets, params = hexex.generate_cylinder(3, 2, 2, 2, 2)
    r = hexex.extract(points, tets, params, provenance=True, threads=1)
    p = r.provenance
    t = p["vertex_source_tet"]
    assert (t >= 0).all()
    lam = barycentric(params[t], p["vertex_grid_coords"].astype(float))
    assert (lam > -1e-9).all()
    mapped = np.einsum("ni,nij->nj", lam, points[tets[t]])
    assert np.allclose(mapped, r.points, atol=1e-9)
    r2 = hexex.extract(points, tets, params, provenance=True, threads=2)
    for key in p:
        assert np.array_equal(p[key], r2.provenance[key])


def test_off_by_default():
    r = hexex.extract(*hexex.generate_cube(2, 2))
    assert r.provenance is None


def test_not_with_pillow():
    with pytest.raises(ValueError, match="provenance=True cannot be combined with pillow=True"):
        hexex.extract(*hexex.generate_cube(2, 2), provenance=True, pillow=True)
