"""`lac.Path` answers what `lac path` answers (the same Rust code), G1 and G2, through
inflections, warm-started, and raises the library's errors."""

import numpy as np
import pytest

import lac

S_POLYGON = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.5), (5.0, 2.5), (6.0, 3.0), (7.0, 3.0)]


def arg(points):
    return " ".join(f"{x!r},{y!r}" for x, y in points)


def test_g2_path_through_an_inflection_equals_the_command_line(cli):
    ref = cli("path", "--polygon", arg(S_POLYGON), "--alpha", "-1", "--g2", "--samples", "9")
    path = lac.Path(S_POLYGON, -1.0)
    assert path.continuity == "g2"
    assert path.arc_length == ref["arc_length"]
    assert path.max_curvature_jump == ref["max_curvature_jump"]
    tri = path.control_triangles
    assert tri.shape == (4, 3, 2)
    assert tri.tolist() == [s["control_points"] for s in ref["segments"]]
    assert path.end_curvatures.tolist() == [s["curvature"] for s in ref["segments"]]
    (leg, start, end), = path.straight_pieces
    line = ref["straight_pieces"][0]
    assert leg == line["leg"] and [list(start), list(end)] == line["points"]
    samples = path.sample(9)
    assert samples.kappa.tolist() == [s["kappa"] for s in ref["samples"]]
    # The curvature is zero at the straight piece's ends to 1e-9 of the largest.
    k = path.end_curvatures
    assert abs(k[1, 1]) <= 1e-9 * np.abs(k).max() and abs(k[2, 0]) <= 1e-9 * np.abs(k).max()


def test_warm_start_g1_and_errors():
    polygon = [(0.0, 0.0), (2.0, 0.0), (3.5, 1.0), (4.0, 3.0), (3.0, 4.5), (1.0, 5.0)]
    cold = lac.Path(polygon, 0.5)
    moved = np.array(polygon)
    moved[3, 0] += 0.05
    warm = lac.Path(moved, 0.5, warm=cold.joint_fractions)
    assert warm.max_curvature_jump <= 1e-9
    g1 = lac.Path(polygon, [0.0, 0.5, 1.0, 1.0], g2=False, fractions=[0.3, 0.5, 0.7])
    assert g1.continuity == "g1"
    assert g1.joint_fractions.tolist() == [0.3, 0.5, 0.7]
    with pytest.raises(lac.LacError, match="leg P2-P3"):
        lac.Path(S_POLYGON, 0.5)  # alpha >= 0 cannot reach zero curvature
    with pytest.raises(lac.InvalidInput):
        lac.Path([(0.0, 0.0), (1.0, 0.0)], 0.5)
    with pytest.raises(lac.InvalidInput):
        lac.Path([0.0, 1.0, 2.0], 0.5)
