"""Shapes, dtypes and ownership of the returned arrays; thread independence; interop."""

import threading
import time

import numpy as np
import pytest

import hexex


def test_map_arrays_of_generators():
    m = hexex.generate_cube(3, 2)
    assert isinstance(m, hexex.TetMap)
    assert m.points.shape == (64, 3) and m.points.dtype == np.float64
    assert m.tets.shape == (162, 4) and m.tets.dtype == np.int32
    assert m.params.shape == (162, 4, 3) and m.params.dtype == np.float64
    # The cube map is scale * position at every corner.
    assert np.array_equal(m.params, 2 * m.points[m.tets])


def test_result_arrays_outlive_everything():
    r = hexex.extract(*hexex.generate_cube(2, 2))
    points, hexes = r.points, r.hexes
    del r
    import gc
    gc.collect()
    assert points.shape == (27, 3) and hexes.shape == (8, 8)
    assert hexes.min() == 0 and hexes.max() == 26
    assert points.min() == 0.0 and points.max() == 1.0


def test_hex_orientation_is_vtk_positive():
    r = hexex.extract(*hexex.generate_cube(2, 2))
    p = r.points[r.hexes]  # (h, 8, 3)
    jac = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 3] - p[:, 0]), p[:, 4] - p[:, 0])
    assert np.all(jac > 0)


def test_thread_count_does_not_change_output():
    m = hexex.perturb(hexex.generate_cube(5, 5), 1.0, seed=11)
    runs = [hexex.extract(*m, threads=t) for t in (1, 2, 3)]
    for r in runs[1:]:
        assert np.array_equal(r.points, runs[0].points)
        assert np.array_equal(r.hexes, runs[0].hexes)
        assert r.polyhedra == runs[0].polyhedra
        strip = lambda rep: {k: v for k, v in rep.items() if k not in ("timings_s", "threads")}
        assert strip(r.report) == strip(runs[0].report)
    assert [r.report["threads"] for r in runs] == [1, 2, 3]
    assert runs[0].report["input"]["flipped_tets"] > 0


def test_concurrent_python_threads():
    m = hexex.generate_cylinder(4, 3, 3, 2, 2)
    results = [None] * 3

    def work(i):
        results[i] = hexex.extract(*m, threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        assert len(r.hexes) == 4 * 3 * 3 * 3 and r.valid_all_hex
        assert np.array_equal(r.hexes, results[0].hexes)


def test_input_arrays_are_not_modified():
    m = hexex.perturb(hexex.generate_cube(3, 3), 0.5, seed=1)
    copies = [a.copy() for a in m]
    hexex.extract(*m)
    for a, b in zip(m, copies):
        assert np.array_equal(a, b)


def test_hex_mesh_round_trip(tmp_path):
    r = hexex.extract(*hexex.generate_twisted_ring(8, 2, 8, 2))
    for ext in (".vtu", ".vtk", ".ovm", ".ovmb", ".mesh"):
        path = tmp_path / f"t{ext}"
        hexex.write_hex_mesh(path, r)
        back = hexex.read_hex_mesh(path)
        assert isinstance(back, hexex.HexMesh)
        assert np.array_equal(back.points, r.points), ext
        if ext not in (".ovm", ".ovmb"):  # .ovm stores faces; the reader rebuilds VTK order from them
            assert np.array_equal(back.hexes, r.hexes), ext
        assert hexex.validate(back)["valid_all_hex"], ext


def test_to_meshio(tmp_path):
    meshio = pytest.importorskip("meshio")
    r = hexex.extract(*hexex.generate_cylinder(3, 2, 2, 2, 2))
    mesh = r.to_meshio()
    assert isinstance(mesh, meshio.Mesh)
    assert [c.type for c in mesh.cells] == ["hexahedron"]
    assert np.array_equal(mesh.cells[0].data, r.hexes)
    for binary in (False, True):  # meshio's ASCII and its default (zlib-compressed base64) .vtu
        path = tmp_path / f"m{int(binary)}.vtu"
        mesh.write(path, binary=binary)
        back = meshio.read(path)
        assert back.points.shape == (57, 3)
        assert np.array_equal(back.cells_dict["hexahedron"], r.hexes)
        # And our reader reads what meshio wrote.
        mine = hexex.read_hex_mesh(path)
        assert np.array_equal(mine.hexes, r.hexes)
        if binary:
            assert np.array_equal(mine.points, r.points)
        else:  # meshio's ASCII writer rounds the coordinates
            assert np.allclose(mine.points, r.points, rtol=0, atol=1e-12)


def test_polyhedra_in_meshio_and_validation():
    meshio = pytest.importorskip("meshio")
    cube = hexex.extract(*hexex.generate_cube(1, 1))
    # One extra cell that is not a hex: a tet on top of the cube's vertex 4-5-7 plane.
    apex = len(cube.points)
    points = np.vstack([cube.points, [[0.0, 0.0, 2.0]]])
    h = cube.hexes[0]
    tet = [[int(h[4]), int(h[5]), int(h[7])], [int(h[4]), apex, int(h[5])], [int(h[5]), apex, int(h[7])],
           [int(h[7]), apex, int(h[4])]]
    mesh = hexex.HexMesh(points, cube.hexes, [tet])
    check = hexex.validate(mesh)
    assert (check["hexes"], check["non_hex_cells"], check["valid_all_hex"]) == (1, 1, False)
    mm = mesh.to_meshio()
    assert [c.type for c in mm.cells] == ["hexahedron", "polyhedron4"]


def test_gil_is_released_during_extraction():
    # A Python thread counts while the main thread extracts. If the C++ call held the GIL,
    # the counter could only move in the Python parts around it (about one switch interval,
    # a few thousand steps); with the GIL released it keeps its pace. The pace is measured
    # first while the main thread sleeps (which releases the GIL), so machine load cancels.
    m = hexex.generate_cube(24, 12)
    count = [0]
    stop = threading.Event()

    def counter():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=counter)
    t.start()
    try:
        time.sleep(0.05)
        c0, t0 = count[0], time.perf_counter()
        time.sleep(0.2)
        pace = (count[0] - c0) / (time.perf_counter() - t0)
        c1, t1 = count[0], time.perf_counter()
        r = hexex.extract(*m, threads=1)
        during, elapsed = count[0] - c1, time.perf_counter() - t1
    finally:
        stop.set()
        t.join()
    assert len(r.hexes) == 12**3
    assert during > 0.1 * pace * elapsed, (during, pace, elapsed)
