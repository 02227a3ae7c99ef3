"""hexex.validate: the certified validity counts (a hex can be positive at its 8 corners and
still have a negative Jacobian inside)."""

import numpy as np

import hexex

# Positive Jacobian at all 8 corners, negative at (u, v, w) = (0.25, 1, 0) (HexValidityTest).
TWISTED = np.array([
    [0.34903947519629847, -0.040657101802294204, -0.14580526119256942],
    [1.3158235993425553, -0.22753776138255985, -0.32283547238959748],
    [0.66302905271037815, 0.96539898402132385, -0.21103170472141899],
    [0.38309908700906353, 1.3863647837410384, 0.3657617023242497],
    [-0.26060920847350455, -0.27169702399717743, 0.61007095309834447],
    [1.21923850574767, -0.22315681136377602, 0.88364110018111863],
    [0.63601846817499119, 1.4113433695468787, 0.7938652942780513],
    [-0.3339704468756034, 1.045714042671493, 1.3534283884624589],
])
UNIT = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)


def two_hexes(first, second):
    points = np.vstack([first, second + [3, 0, 0]])
    hexes = np.arange(16, dtype=np.int32).reshape(2, 8)
    return hexex.HexMesh(points, hexes)


def test_negative_inside_is_invalid_not_inverted():
    q = hexex.validate(two_hexes(UNIT, TWISTED))["quality"]
    assert q["inverted_hexes"] == 0
    assert q["invalid_hexes"] == 1
    assert q["undecided_hexes"] == 0
    assert q["first_invalid_hex"] == 1
    assert q["certified_valid"] is False


def test_unit_cubes_are_certified():
    q = hexex.validate(two_hexes(UNIT, UNIT))["quality"]
    assert (q["inverted_hexes"], q["invalid_hexes"], q["first_invalid_hex"]) == (0, 0, -1)
    assert q["certified_valid"] is True


def test_extract_report_has_certified_keys():
    r = hexex.extract(*hexex.generate_cylinder(5, 2, 2, 2, 2))
    q = r.report["quality"]
    assert q["invalid_hexes"] == 0 and q["undecided_hexes"] == 0 and q["certified_valid"] is True
