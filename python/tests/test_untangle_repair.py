"""extract(untangle=True) falls back to pillowing where untangling alone leaves hexes not
certified valid (HexEx::untangleWithRepair(), as ``hexex extract --untangle``)."""

import lzma
import pathlib

import numpy as np
import pytest

import hexex

S1X2 = pathlib.Path(__file__).resolve().parents[2].parent / "shared" / "data" / "S1_polycube_scale2.hexex.xz"


def test_pillow_must_be_true_false_or_none():
    m = hexex.generate_cube(2, 2)
    with pytest.raises(TypeError, match="pillow must be True, False or None, got str"):
        hexex.extract(m.points, m.tets, m.params, untangle=True, pillow="yes")


def test_no_repair_where_untangling_suffices():
    m = hexex.perturb(hexex.generate_cube(3, 3), 0.8, seed=3)
    r = hexex.extract(m.points, m.tets, m.params, untangle=True)
    assert r.report["untangle"]["invalid_after"] == 0
    assert "optimize" not in r.report
    assert not any("pillowing repair" in w for w in r.report.get("warnings", []))


@pytest.mark.skipif(not S1X2.exists(), reason=f"shared data not found: {S1X2}")
def test_s1x2_untangle_repairs_the_flap(tmp_path):
    path = tmp_path / "s1x2.hexex"
    path.write_bytes(lzma.decompress(S1X2.read_bytes()))
    m = hexex.read_map(path)
    r = hexex.extract(m.points, m.tets, m.params, untangle=True, threads=2)
    assert r.report["untangle"]["invalid_after"] == 1  # untangling alone
    assert r.report["optimize"]["trimmed_hexes"] == 9
    assert r.report["optimize"]["pillowed_hexes"] == 22796  # 22,736 layer hexes, 12 flat corners split (+60)
    assert r.hexes.shape == (107134, 8)
    assert r.report["quality"]["invalid_hexes"] == 0
    assert r.report["quality"]["undecided_hexes"] == 0
    assert any(w.startswith("untangling alone left 1 hexes not certified valid; repaired as with --pillow: 9 hexes")
               for w in r.report["warnings"])
    kept = hexex.extract(m.points, m.tets, m.params, untangle=True, pillow=False, threads=2)
    assert kept.hexes.shape == (84347, 8)
    assert kept.report["quality"]["invalid_hexes"] == 1
    assert "optimize" not in kept.report
    # The same mesh as asking for the layer.
    assert np.array_equal(r.hexes, hexex.extract(m.points, m.tets, m.params, pillow=True, threads=2).hexes)
