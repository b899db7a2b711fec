"""`lac space --format obj|ply` read back by real readers.

    LAC_BIN=target/release/lac .venv/bin/python -m pytest tools/reference/test_space_export.py -q

PLY is read by plyfile (every element and property as declared: the vertices' x, y, z,
kappa and tau, the edges' vertex1 and vertex2, the comments), OBJ by trimesh (which loads
the vertices and, having no polyline type, ignores the `l` element) and, where VTK is
installed (it is not in requirements.txt: 0.5 GB), by VTK's vtkOBJReader, which also reads
the polyline.  Both files must hold the same numbers, bit for bit, as the JSON of the same
run.  The tests are skipped, with the reason, when `$LAC_BIN space --help` does not succeed.
"""

import json
import os
import subprocess

import numpy as np
import plyfile
import pytest
import trimesh

from lac_cli import lac_bin, require


# (points, options): a right-handed segment, a mirrored one (negative torsion) whose standard
# form is also reversed, and coplanar points (the planar segment, torsion 0).
CASES = [
    ("0,0,0 1,0,0 2,1,0.3 2,2,1", ["--alpha", "0", "--beta", "0", "--omega", "0.3"]),
    ("0,0,0 2,0,0 2.5,1,-0.3 2.5,1.5,-1", ["--alpha", "0.5", "--beta", "1", "--type", "2"]),
    ("0,0,0 1,0,0 2,1,0.5 2,2,1", ["--alpha", "-1", "--beta", "0"]),
]
SAMPLES = 41


@pytest.fixture(scope="module", autouse=True)
def require_space():
    require("space")


def lac_space(points, options, *extra):
    args = [lac_bin(), "space", "--points", points, *options, "--samples", str(SAMPLES), *extra]
    run = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, (args, run.stderr)
    return run.stdout


def samples(points, options):
    """The JSON samples as an (n, 5) array of x, y, z, kappa, tau."""
    out = json.loads(lac_space(points, options))
    return np.array([[s["x"], s["y"], s["z"], s["kappa"], s["tau"]] for s in out["samples"]])


def export(tmp_path, points, options, fmt):
    path = tmp_path / f"curve.{fmt}"
    assert lac_space(points, options, "--format", fmt, "-o", str(path)) == ""
    return path


@pytest.mark.parametrize("points,options", CASES)
def test_ply_reads_with_plyfile(tmp_path, points, options):
    want = samples(points, options)
    ply = plyfile.PlyData.read(str(export(tmp_path, points, options, "ply")))
    assert ply.text and [e.name for e in ply.elements] == ["vertex", "edge"]
    assert any(c.startswith("lac space") for c in ply.comments)
    vertex = ply["vertex"]
    assert [p.name for p in vertex.properties] == ["x", "y", "z", "kappa", "tau"]
    assert vertex.count == SAMPLES
    got = np.column_stack([vertex[name] for name in ("x", "y", "z", "kappa", "tau")])
    assert got.dtype == np.float64
    np.testing.assert_array_equal(got, want)
    edge = ply["edge"]
    assert [p.name for p in edge.properties] == ["vertex1", "vertex2"]
    assert edge.count == SAMPLES - 1
    np.testing.assert_array_equal(edge["vertex1"], np.arange(SAMPLES - 1))
    np.testing.assert_array_equal(edge["vertex2"], np.arange(1, SAMPLES))


@pytest.mark.parametrize("points,options", CASES)
def test_obj_vertices_read_with_trimesh(tmp_path, points, options):
    want = samples(points, options)
    loaded = trimesh.load(str(export(tmp_path, points, options, "obj")), process=False)
    np.testing.assert_array_equal(np.asarray(loaded.vertices), want[:, :3])


@pytest.mark.parametrize("points,options", CASES)
def test_obj_polyline_reads_with_vtk(tmp_path, points, options):
    obj_reader = pytest.importorskip("vtkmodules.vtkIOGeometry",
                                     reason="VTK is not installed").vtkOBJReader
    want = samples(points, options)
    reader = obj_reader()
    reader.SetFileName(str(export(tmp_path, points, options, "obj")))
    reader.Update()
    data = reader.GetOutput()
    assert data.GetNumberOfPoints() == SAMPLES
    assert data.GetNumberOfLines() == 1 and data.GetNumberOfPolys() == 0
    ids = data.GetCell(0).GetPointIds()
    order = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
    assert order == list(range(SAMPLES))
    # vtkOBJReader stores float32 points.
    got = np.array([data.GetPoint(i) for i in order])
    np.testing.assert_allclose(got, want[:, :3], rtol=0, atol=1e-6 * np.abs(want[:, :3]).max())
