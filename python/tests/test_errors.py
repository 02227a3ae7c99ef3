"""Bad input raises TypeError/ValueError with the library's message; nothing crashes."""

import numpy as np
import pytest

import hexex


@pytest.fixture(scope="module")
def cube():
    return hexex.generate_cube(2, 2)


def test_index_out_of_range(cube):
    tets = np.where(cube.tets == 0, 999, cube.tets)
    with pytest.raises(ValueError, match=r"^tet 0: vertex index 999 out of range \(the mesh has 27 vertices\)$"):
        hexex.extract(cube.points, tets, cube.params)


def test_negative_index_int64(cube):
    tets = np.where(cube.tets == 0, -1, cube.tets).astype(np.int64)
    with pytest.raises(ValueError, match=r"^tet 0: vertex index -1 out of range"):
        hexex.extract(cube.points, tets, cube.params)


def test_repeated_vertex(cube):
    tets = cube.tets.copy()
    tets[3, 1] = tets[3, 0]
    with pytest.raises(ValueError, match=rf"^tet 3: vertex {tets[3, 0]} appears twice$"):
        hexex.extract(cube.points, tets, cube.params)


def test_non_finite_parameter(cube):
    params = cube.params.copy()
    params[7, 2, 1] = np.inf
    with pytest.raises(ValueError, match=r"^tet 7: parameter is not finite$"):
        hexex.extract(cube.points, cube.tets, params)


def test_non_manifold_mesh():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1], [-1, -1, -1.0]])
    tets = np.array([[0, 1, 2, 3], [0, 1, 2, 4], [0, 1, 2, 5]])
    with pytest.raises(ValueError, match=r"^non-manifold mesh: face \(0, 2, 1\) of tet 0 is shared by 3 tets$"):
        hexex.extract(points, tets, np.zeros((3, 4, 3)))


def test_absurd_scale_is_refused(cube):
    with pytest.raises(ValueError, match=r"more than the limit of .* hexes"):
        hexex.extract(cube.points, cube.tets, cube.params * 1e6)


@pytest.mark.parametrize("bad,exc,message", [
    (lambda m: (m.points[:, :2], m.tets, m.params), ValueError, r"^points must have shape \(n, 3\), got \(27, 2\)$"),
    (lambda m: (m.points, m.tets[:, :3], m.params), ValueError, r"^tets must have shape \(n, 4\), got \(48, 3\)$"),
    (lambda m: (m.points, m.tets, m.params[:-1]), ValueError, r"^params must have shape \(48, 4, 3\), got \(47, 4, 3\)$"),
    (lambda m: (m.points, m.tets, m.params.reshape(48, 12)), ValueError, r"^params must have shape \(48, 4, 3\)"),
    (lambda m: (m.points, m.tets.astype(float), m.params), TypeError, r"^tets must be an integer array, got dtype float64$"),
    (lambda m: (m.points.astype(complex), m.tets, m.params), TypeError, r"^points must be a float array"),
    (lambda m: ("abc", m.tets, m.params), TypeError, r"^points must be a float array"),
    (lambda m: (None, m.tets, m.params), TypeError, r"^points must be an array, got None$"),
    (lambda m: (m.points, m.tets, m.params.astype(bool)), TypeError, r"^params must be a float array"),
])
def test_wrong_shapes_and_dtypes(cube, bad, exc, message):
    with pytest.raises(exc, match=message):
        hexex.extract(*bad(cube))


def test_other_dtypes_are_converted(cube):
    ref = hexex.extract(*cube)
    r = hexex.extract(cube.points.astype(np.float32), cube.tets.astype(np.uint16),
                      np.asfortranarray(cube.params))
    assert np.array_equal(r.hexes, ref.hexes) and np.array_equal(r.points, ref.points)


def test_option_errors(cube):
    with pytest.raises(ValueError, match=r"^threads must be >= 0, got -1$"):
        hexex.extract(*cube, threads=-1)
    with pytest.raises(TypeError, match=r"^threads must be an int, got float$"):
        hexex.extract(*cube, threads=1.5)
    with pytest.raises(ValueError, match=r"^epsilon must be in \[0, 0.5\), got 0.7$"):
        hexex.extract(*cube, epsilon=0.7)
    with pytest.raises(ValueError, match=r"^epsilon must be in \[0, 0.5\), got null$"):
        hexex.extract(*cube, epsilon=float("nan"))


def test_given_rotations(cube):
    n = len(cube.tets)
    r = hexex.extract(*cube, rotations=np.zeros((n, 4), dtype=np.int64))
    assert (len(r.hexes), len(r.points)) == (8, 27)
    with pytest.raises(ValueError, match=r"^given rotations: halfface \d+ and its opposite \d+ are not inverse to each other$"):
        hexex.extract(*cube, rotations=np.full((n, 4), 5))
    with pytest.raises(ValueError, match=r"^given rotations: halfface \d+ has rotation index 99 \(must be 0..23\)$"):
        hexex.extract(*cube, rotations=np.full((n, 4), 99))
    with pytest.raises(ValueError, match=r"^rotations must have shape \(48, 4\)"):
        hexex.extract(*cube, rotations=np.zeros((n, 3), dtype=np.int32))


def test_read_errors_name_file_and_line(tmp_path):
    missing = tmp_path / "missing.hexex"
    with pytest.raises(ValueError, match=rf"^{missing}: cannot open file: No such file or directory$"):
        hexex.read_map(missing)
    bad = tmp_path / "bad.hexex"
    bad.write_text("3\n0 0 0\n1 0 x\n")
    with pytest.raises(ValueError, match=rf"^{bad}:3: expected a number for z coordinate of vertex 1, got 'x'$"):
        hexex.read_map(bad)
    with pytest.raises(TypeError, match=r"^path must be a str or os.PathLike, got int$"):
        hexex.read_map(3)


def test_write_errors(tmp_path, cube):
    r = hexex.extract(*cube)
    with pytest.raises(ValueError, match=r"unknown|extension"):
        hexex.write_hex_mesh(tmp_path / "x.txt", r)
    with pytest.raises(ValueError, match=r"\.hexex format only"):
        hexex.write_map(tmp_path / "x.vtu", cube)
    bad = hexex.HexMesh(r.points, np.full((1, 8), 1000, dtype=np.int32))
    with pytest.raises(ValueError):
        hexex.write_hex_mesh(tmp_path / "bad.vtu", bad)
    with pytest.raises(ValueError, match=r"binary|compressed|ascii"):
        hexex.write_hex_mesh(tmp_path / "z.vtu", r, encoding="gzip")
    with pytest.raises(TypeError, match=r"expected a HexMesh"):
        hexex.write_hex_mesh(tmp_path / "y.vtu", cube)


def test_generator_errors():
    with pytest.raises(ValueError, match=r"^mesh too large \(6000000000000 tets; at most 50000000\)$"):
        hexex.generate_cube(10000, 1)
    with pytest.raises(ValueError, match=r"^n must be >= 1, got 0$"):
        hexex.generate_cube(0, 1)
    with pytest.raises(ValueError, match=r"^valence must be >= 3, got 2$"):
        hexex.generate_cylinder(2)
    with pytest.raises(ValueError):
        hexex.generate_twisted_ring(nv=3)
    with pytest.raises(ValueError, match=r"amplitude"):
        hexex.perturb(hexex.generate_cube(1, 1), -1.0)


def test_random_input_never_crashes():
    rng = np.random.default_rng(7)
    outcomes = set()
    for _ in range(40):
        n = int(rng.integers(4, 12))
        m = int(rng.integers(1, 10))
        points = rng.normal(size=(n, 3))
        tets = rng.integers(-1, n + 1, size=(m, 4))
        params = rng.normal(scale=3, size=(m, 4, 3))
        try:
            r = hexex.extract(points, tets, params)
            outcomes.add("ok")
            assert r.report["input"]["tets"] == m
        except ValueError:
            outcomes.add("error")
    assert outcomes == {"ok", "error"}


def test_memory_budget_raises_memory_error():
    m = hexex.generate_cube(2, 40)  # 64,000 hexes from 48 tets
    with pytest.raises(MemoryError, match=r"memory|budget"):
        hexex.extract(*m, max_memory=1_000_000)
    with pytest.raises(ValueError, match=r"^max_memory must be >= 0, got -1$"):
        hexex.extract(*m, max_memory=-1)


def test_corrupted_corner_is_repaired_and_reported():
    m = hexex.generate_cube(3, 3)
    clean = hexex.extract(*m)
    counts = np.bincount(m.tets.ravel())
    t, k = np.argwhere(m.tets == counts.argmax())[0]  # a corner of the vertex with the most tets
    params = m.params.copy()
    params[t, k, 1] = 1e4  # one typo
    r = hexex.extract(m.points, m.tets, params)
    assert len(r.hexes) == 27 and r.report["valid_all_hex"]
    np.testing.assert_array_equal(r.points, clean.points)
    np.testing.assert_array_equal(r.hexes, clean.hexes)
    assert r.report["input"]["repaired_corners"] == 1
    rep = r.report["input"]["repairs"][0]
    assert (rep["tet"], rep["corner"], rep["vertex"]) == (t, k, counts.argmax())
    assert rep["original"][1] == 1e4 and rep["repaired"][1] == m.params[t, k, 1]
    assert any("corner parameter disagreed with the majority" in w for w in r.report["warnings"])
