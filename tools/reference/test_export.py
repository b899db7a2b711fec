"""`lac export` read back by independent CAD readers.

    LAC_BIN=target/release/lac .venv/bin/python -m pytest tools/reference/test_export.py -q

Each format is written by the `lac` binary and read by a reader that is not lac:

* DXF: ezdxf (`readfile`, `audit()` with no errors and no fixes, the SPLINE entities
  evaluated by ezdxf's own B-spline);
* STEP and IGES: OpenCascade through OCP (`STEPControl_Reader` / `IGESControl_Reader`: the
  file reads, transfers, the shape passes `BRepCheck_Analyzer`, its edges' curves are
  evaluated by OCC);
* JSON: geomdl (NURBS-Python) evaluates the B-splines;
* SVG: svgpathtools parses the path data.

Every curve a reader evaluates is compared with the exact curve, both ways: the exact curve's
points (`lac segment|compound|space --format json`, 401 samples equally spaced in arc
length; for a path, each of its segments solved again by `lac segment` from the control
triangle `lac path` reports, so that no interpolation interval straddles a joint) are projected onto the reader's curve, and the reader's points onto the exact curve
(a cubic Hermite interpolant of those samples with their exact tangents, whose own error is
below 1e-13 at this spacing). The largest distance must be within the tolerance asked. At
the joins, the curvature vector the reader evaluates on either side must agree (G2) for
planar curves, the tangent (G1) for space curves. A file a reader rejects fails its test.
"""

import json
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from lac_cli import lac_bin, require

# (name, solving subcommand, arguments): a segment (α = 0.5), a clothoid (α = −1), a
# compound "valley" (α0 = −1 into α1 = 2) and a space segment.
CURVES = [
    ("segment", "segment", ["--points", "0,0 3,0 4.2,1.9", "--alpha", "0.5"]),
    ("clothoid", "segment", ["--points", "0,0 3,0 4,1.5", "--alpha", "-1"]),
    ("compound", "compound",
     ["--points", "0,0 2,0 2.6,1.2", "--alpha0", "-1", "--alpha1", "2", "--ratio", "0.5"]),
    ("space", "space",
     ["--points", "0,0,0 3,0,0 3,3,1.5 0,3,3", "--alpha", "0.5", "--beta", "0",
      "--omega", "0.3"]),
    # Multi-segment paths (lac path): an open G2 path of three segments and a closed G2
    # path of five, on a convex polygon.
    ("path", "path", ["--polygon", "0,0 3,0 4,2 2,4 -1,2", "--alpha", "1", "--g2"]),
    ("closed", "path",
     ["--polygon", "0,0 3,0 4,2 2,4 -1,2", "--alpha", "0.5", "--closed", "--g2"]),
    # An S-shaped G2 path (the README's): through an inflection, where two segments end at
    # zero curvature on either side of a straight piece.
    ("spath", "path",
     ["--polygon", "0,0 1.5,0 3,0.8 6,3.2 7.5,4 9,4", "--alpha", "-0.5", "--g2"]),
    # A closed G2 path through two inflections (a figure eight): a straight piece on each
    # crossing leg, one of them the leg that closes the polygon, so the last piece of the
    # curve is straight and ends where the first segment starts.
    ("eight", "path",
     ["--polygon", "1.5,-1 3,-1.8 4.5,-1 4.5,1 3,1.8 1.5,1 -1.5,-1 -3,-1.8 -4.5,-1 -4.5,1 "
      "-3,1.8 -1.5,1", "--alpha", "-1", "--closed", "--g2"]),
]
# A G1 path (curvature jumps at its joints): read back, G1 at the joints, not G2.
G1_PATH = ("g1path", "path", ["--polygon", "0,0 3,0 4,2 2,4 -1,2", "--alphas", "1,0.5,0.8"])
PLANAR = [c for c in CURVES if c[0] != "space"]
SAMPLES = 401
TOLERANCES = [1e-6, 1e-9]


@pytest.fixture(scope="module", autouse=True)
def require_export():
    require("export")


def run(args, expect=0):
    proc = subprocess.run([lac_bin(), *args], capture_output=True, text=True, timeout=300)
    assert proc.returncode == expect, (args, proc.stderr)
    return proc


def export(tmp_path, curve, fmt, tolerance, pieces=False):
    """Write the file; return its path and the report."""
    name, _, args = curve
    path = tmp_path / f"{name}.{fmt}"
    extra = ["--pieces"] if pieces else []
    proc = run(["export", *args, "--format", fmt, "--tolerance", repr(tolerance), *extra,
                "-o", str(path)])
    report = json.loads(proc.stderr.strip().splitlines()[-1])
    assert report["format"] == fmt and report["pieces"] >= 1
    assert report["max_deviation"] <= tolerance
    return path, report


def Exact(curve):
    """The exact curve: a path is the chain of its segments, anything else one curve."""
    if curve[1] == "path":
        return ExactChain(curve)
    return ExactOne(curve)


class ExactChain:
    """A path's pieces end to end: each segment an `ExactOne` of its control triangle and
    slope, each straight piece (on an inflection leg, after the segment ending on that leg)
    a `Line`."""

    def __init__(self, curve):
        report = json.loads(run(["path", *curve[2], "--samples", "2"]).stdout)
        lines = {piece["leg"]: piece for piece in report["straight_pieces"]}
        self.parts = []
        for seg in report["segments"]:
            points = " ".join(f"{x!r},{y!r}" for x, y in seg["control_points"])
            self.parts.append(ExactOne(("seg", "segment",
                                        ["--points", points, "--alpha", repr(seg["alpha"])])))
            # The segment of vertex j ends on leg j.
            if seg["vertex"] in lines:
                self.parts.append(Line(*lines[seg["vertex"]]["points"]))
        self.starts = np.cumsum([0.0] + [p.length for p in self.parts])
        self.length = self.starts[-1]
        assert abs(self.length - report["arc_length"]) < 1e-12 * self.length
        self.p = np.concatenate([p.p for p in self.parts])

    def __call__(self, s):
        s = np.clip(np.atleast_1d(np.asarray(s, dtype=float)), 0.0, self.length)
        k = np.clip(np.searchsorted(self.starts, s, side="right") - 1, 0, len(self.parts) - 1)
        out = np.empty((len(s), 3))
        for i, part in enumerate(self.parts):
            sel = k == i
            if sel.any():
                out[sel] = part(s[sel] - self.starts[i])
        return out


class Line:
    """A straight piece from a to b."""

    def __init__(self, a, b):
        self.a = np.array([a[0], a[1], 0.0])
        self.b = np.array([b[0], b[1], 0.0])
        self.length = float(np.linalg.norm(self.b - self.a))
        self.p = np.array([self.a, self.b])

    def __call__(self, s):
        u = np.clip(np.asarray(s, dtype=float), 0.0, self.length)[:, None] / self.length
        return self.a + u * (self.b - self.a)


class ExactOne:
    """The exact curve from lac's own samples: a cubic Hermite interpolant in arc length."""

    def __init__(self, curve):
        _, sub, args = curve
        frames = ["--frames"] if sub == "space" else []
        out = json.loads(run([sub, *args, "--samples", str(SAMPLES), *frames]).stdout)
        rows = out["samples"]
        self.s = np.array([r["s"] for r in rows])
        if sub == "space":
            self.p = np.array([[r["x"], r["y"], r["z"]] for r in rows])
            self.t = np.array([r["t"] for r in rows])
        else:
            self.p = np.array([[r["x"], r["y"], 0.0] for r in rows])
            th = np.array([r["theta"] for r in rows])
            self.t = np.stack([np.cos(th), np.sin(th), np.zeros_like(th)], axis=1)
        self.length = self.s[-1]

    def __call__(self, s):
        s = np.clip(np.asarray(s, dtype=float), 0.0, self.length)
        i = np.clip(np.searchsorted(self.s, s) - 1, 0, len(self.s) - 2)
        h = (self.s[i + 1] - self.s[i])[:, None]
        u = ((s - self.s[i]) / (self.s[i + 1] - self.s[i]))[:, None]
        h00 = 2 * u**3 - 3 * u**2 + 1
        h10 = u**3 - 2 * u**2 + u
        h01 = -2 * u**3 + 3 * u**2
        h11 = u**3 - u**2
        return (h00 * self.p[i] + h10 * h * self.t[i] + h01 * self.p[i + 1]
                + h11 * h * self.t[i + 1])


def distances(points, curves, dense=4000):
    """Distance from each of `points` to the nearest of `curves`, each (f, a, b): f takes an
    array of parameters in [a, b] and returns (n, 3) points. The nearest of about `dense`
    samples in all, refined by golden section on the neighbouring intervals of the two
    nearest samples (at a join the nearest may be the end of the curve that does not hold
    the foot of the perpendicular), all points of one curve at once."""
    points = np.asarray(points)
    per = max(8, dense // len(curves))
    ts, cs, ps = [], [], []
    for c, (f, a, b) in enumerate(curves):
        t = np.linspace(a, b, per)
        ts.append(t)
        cs.append(np.full(per, c))
        ps.append(f(t))
    ts, cs, ps = np.concatenate(ts), np.concatenate(cs), np.concatenate(ps)
    d2 = ((points[:, None, :] - ps[None, :, :]) ** 2).sum(axis=2)
    best = np.sqrt(d2.min(axis=1))
    nearest = np.argsort(d2, axis=1)[:, :2]
    g = (np.sqrt(5) - 1) / 2
    for rank in range(2):
        idx = nearest[:, rank]
        for c, (f, a, b) in enumerate(curves):
            sel = np.nonzero(cs[idx] == c)[0]
            if len(sel) == 0:
                continue
            q = points[sel]
            step = (b - a) / (per - 1)
            lo = np.maximum(a, ts[idx[sel]] - step)
            hi = np.minimum(b, ts[idx[sel]] + step)
            dist = lambda t: ((f(t) - q) ** 2).sum(axis=1)
            x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
            f1, f2 = dist(x1), dist(x2)
            for _ in range(40):
                left = f1 < f2
                hi = np.where(left, x2, hi)
                lo = np.where(left, lo, x1)
                nx1 = np.where(left, hi - g * (hi - lo), x2)
                nx2 = np.where(left, x1, lo + g * (hi - lo))
                x1, x2 = nx1, nx2
                # Evaluate only the new point of each bracket (the other is kept).
                new = np.where(left, x1, x2)
                fn = dist(new)
                f1, f2 = np.where(left, fn, f2), np.where(left, f1, fn)
            best[sel] = np.minimum(best[sel], np.sqrt(np.minimum(f1, f2)))
    return best


def two_sided(exact, curves):
    """The largest distance between the exact curve and the reader's curves (a list of
    (f, a, b)) both ways."""
    to_reader = distances(exact.p, curves)
    # Reader → exact: about 400 points of the reader's curves onto the exact interpolant.
    per = max(3, 400 // len(curves))
    q = np.concatenate([f(np.linspace(a, b, per)) for f, a, b in curves])
    back = distances(q, [(exact, 0.0, exact.length)], dense=8001)
    return max(float(np.max(to_reader)), float(np.max(back)))


def curvature_vector(d1, d2):
    d1, d2 = np.asarray(d1, float), np.asarray(d2, float)
    v2 = d1 @ d1
    return (d2 - (d1 @ d2) / v2 * d1) / v2


def assert_g2(left, right, planar, scale):
    """(d1, d2) at a join from each side: tangents equal, and for planar curves the
    curvature vectors too (relative to the largest curvature, `scale`)."""
    (a1, a2), (b1, b2) = left, right
    ta, tb = np.asarray(a1) / np.linalg.norm(a1), np.asarray(b1) / np.linalg.norm(b1)
    assert np.linalg.norm(ta - tb) < 1e-9
    if planar:
        ka, kb = curvature_vector(a1, a2), curvature_vector(b1, b2)
        assert np.linalg.norm(ka - kb) < 1e-8 * scale, (ka, kb)


# --------------------------------------------------------------------------------- OCC


def occ_edges(path):
    from OCP.BRep import BRep_Tool
    from OCP.BRepCheck import BRepCheck_Analyzer
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.IGESControl import IGESControl_Reader
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    reader = STEPControl_Reader() if path.suffix == ".step" else IGESControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone, f"OCC cannot read {path}"
    assert reader.TransferRoots() >= 1, "nothing transferred"
    shape = reader.OneShape()
    assert not shape.IsNull()
    assert BRepCheck_Analyzer(shape).IsValid(), "BRepCheck_Analyzer: invalid shape"
    edges = []
    ex = TopExp_Explorer(shape, TopAbs_EDGE)
    while ex.More():
        edge = TopoDS.Edge(ex.Current())
        curve = BRep_Tool.Curve_s(edge, 0.0, 0.0)
        edges.append(curve)
        ex.Next()
    assert edges, "no edge"
    return edges


def occ_eval(curve):
    def f(ts):
        out = []
        for t in np.atleast_1d(ts):
            p = curve.Value(float(t))
            out.append([p.X(), p.Y(), p.Z()])
        return np.array(out)
    return f, curve.FirstParameter(), curve.LastParameter()


def occ_d2(curve, t, span=None):
    from OCP.gp import gp_Pnt, gp_Vec
    p, v1, v2 = gp_Pnt(), gp_Vec(), gp_Vec()
    if span is None:
        curve.D2(t, p, v1, v2)
    else:
        curve.LocalD2(t, span[0], span[1], p, v1, v2)
    return [v1.X(), v1.Y(), v1.Z()], [v2.X(), v2.Y(), v2.Z()]


def check_occ_g2(edges, planar, scale):
    from OCP.Geom import Geom_BSplineCurve
    # Within one B-spline: both sides of every interior knot (LocalD2 on each span).
    for c in edges:
        assert isinstance(c, Geom_BSplineCurve)
        for k in range(2, c.NbKnots()):
            u = c.Knot(k)
            assert_g2(occ_d2(c, u, (k - 1, k)), occ_d2(c, u, (k, k + 1)), planar, scale)
    # Between consecutive curves (the reader may split a curve at its C0 knots).
    ordered = sorted(edges, key=lambda c: c.FirstParameter())
    for a, b in zip(ordered, ordered[1:]):
        pa, pb = a.Value(a.LastParameter()), b.Value(b.FirstParameter())
        if pa.Distance(pb) < 1e-12 * (1 + scale):
            assert_g2(occ_d2(a, a.LastParameter()), occ_d2(b, b.FirstParameter()), planar,
                      scale)


@pytest.mark.parametrize("curve", CURVES, ids=[c[0] for c in CURVES])
@pytest.mark.parametrize("fmt", ["step", "iges"])
@pytest.mark.parametrize("tolerance", TOLERANCES)
def test_opencascade_reads_and_evaluates_within_tolerance(tmp_path, curve, fmt, tolerance):
    path, report = export(tmp_path, curve, fmt, tolerance)
    edges = occ_edges(path)
    exact = Exact(curve)
    d = two_sided(exact, [occ_eval(c) for c in edges])
    assert d <= tolerance, f"OCC's curve is {d:.3e} from the exact one"
    planar = curve[0] != "space"
    check_occ_g2(edges, planar, scale=1.0)
    # The reader keeps every knot span (IGES may split the curve at its C0 knots).
    spans = sum(c.NbKnots() - 1 for c in edges)
    assert spans == report["pieces"]


@pytest.mark.parametrize("curve", [CURVES[0], CURVES[3]], ids=["segment", "space"])
@pytest.mark.parametrize("fmt", ["step", "iges"])
def test_opencascade_reads_the_pieces_variant(tmp_path, curve, fmt):
    path, report = export(tmp_path, curve, fmt, 1e-8, pieces=True)
    edges = occ_edges(path)
    assert len(edges) == report["pieces"] and all(c.NbKnots() == 2 for c in edges)
    d = two_sided(Exact(curve), [occ_eval(c) for c in edges])
    assert d <= 1e-8
    check_occ_g2(edges, curve[0] != "space", scale=1.0)


# ------------------------------------------------------------------------------- ezdxf


def ezdxf_splines(path):
    import ezdxf
    doc = ezdxf.readfile(str(path))
    auditor = doc.audit()
    assert not auditor.has_errors, [e.message for e in auditor.errors]
    assert not auditor.has_fixes, [e.message for e in auditor.fixes]
    splines = [e for e in doc.modelspace() if e.dxftype() == "SPLINE"]
    assert splines and len(splines) == len(doc.modelspace())
    return splines


def ezdxf_eval(spline):
    bs = spline.construction_tool()
    def f(ts):
        return np.array([list(bs.point(float(t))) for t in np.atleast_1d(ts)])
    return f, bs.knots()[0], bs.knots()[-1]


@pytest.mark.parametrize("curve", CURVES, ids=[c[0] for c in CURVES])
@pytest.mark.parametrize("pieces", [False, True], ids=["one", "pieces"])
def test_ezdxf_audits_clean_and_evaluates_within_tolerance(tmp_path, curve, pieces):
    tolerance = 1e-7
    path, report = export(tmp_path, curve, "dxf", tolerance, pieces)
    splines = ezdxf_splines(path)
    assert len(splines) == (report["pieces"] if pieces else 1)
    for s in splines:
        assert s.dxf.degree == 3
        assert s.dxf.flags & 4 or report["polynomial"], "rational flag"
        assert len(s.knots) == len(s.control_points) + 4
    d = two_sided(Exact(curve), [ezdxf_eval(s) for s in splines])
    assert d <= tolerance, f"ezdxf's curve is {d:.3e} from the exact one"


# ------------------------------------------------------------------------------ geomdl


def geomdl_curves(path):
    from geomdl import NURBS
    doc = json.loads(path.read_text())
    out = []
    for row in doc["curves"]:
        c = NURBS.Curve()
        c.degree = row["degree"]
        dim = row["dimension"]
        pts = [p + [0.0] * (3 - dim) for p in row["control_points"]]
        # geomdl takes weighted control points (x w, y w, z w, w).
        c.ctrlptsw = [[x * w, y * w, z * w, w] for (x, y, z), w in zip(pts, row["weights"])]
        c.knotvector = row["knots"]
        out.append(c)
    return doc, out


def geomdl_eval(c):
    a, b = c.knotvector[0], c.knotvector[-1]
    def f(ts):
        return np.array([c.evaluate_single(float(np.clip(t, a, b))) for t in np.atleast_1d(ts)])
    return f, a, b


@pytest.mark.parametrize("curve", CURVES, ids=[c[0] for c in CURVES])
def test_geomdl_evaluates_the_json_within_tolerance_with_g2_joins(tmp_path, curve):
    tolerance = 1e-9
    path, report = export(tmp_path, curve, "json", tolerance)
    doc, curves = geomdl_curves(path)
    assert len(curves) == 1 and doc["pieces"] == report["pieces"]
    d = two_sided(Exact(curve), [geomdl_eval(c) for c in curves])
    assert d <= tolerance, f"geomdl's curve is {d:.3e} from the exact one"
    c = curves[0]
    knots = sorted(set(c.knotvector))[1:-1]
    span = c.knotvector[-1] - c.knotvector[0]
    for k in knots:
        # Across the gap of 2 eps the tangent turns by κ 2 eps and the curvature changes by
        # about |dκ/ds| 2 eps: far below the bounds below for curves up to ~10 units long.
        eps = 1e-9 * span
        left = c.derivatives(k - eps, order=2)
        right = c.derivatives(k + eps, order=2)
        ka, kb = curvature_vector(left[1], left[2]), curvature_vector(right[1], right[2])
        ta = np.asarray(left[1]) / np.linalg.norm(left[1])
        tb = np.asarray(right[1]) / np.linalg.norm(right[1])
        assert np.linalg.norm(ta - tb) < 1e-6
        if curve[0] != "space":
            assert np.linalg.norm(ka - kb) < 1e-5


# ------------------------------------------------------------------------- svgpathtools


@pytest.mark.parametrize("curve", PLANAR, ids=[c[0] for c in PLANAR])
def test_svgpathtools_reads_plain_cubics_within_tolerance(tmp_path, curve):
    from svgpathtools import CubicBezier, parse_path
    tolerance = 1e-7
    path, report = export(tmp_path, curve, "svg", tolerance)
    assert report["polynomial"]
    root = ET.parse(path).getroot()
    ns = {"svg": "http://www.w3.org/2000/svg"}
    assert root.get("viewBox")
    group = root.find("svg:g", ns)
    assert group.get("transform") == "scale(1,-1)"
    svg_path = parse_path(group.find("svg:path", ns).get("d"))
    assert len(svg_path) == report["pieces"]
    assert all(isinstance(seg, CubicBezier) for seg in svg_path)
    n = len(svg_path)

    def f(ts):
        pts = [svg_path.point(float(np.clip(t, 0.0, 1.0))) for t in np.atleast_1d(ts)]
        return np.array([[p.real, p.imag, 0.0] for p in pts])
    exact = Exact(curve)
    d = two_sided(exact, [f_piece(seg) for seg in svg_path])
    assert d <= tolerance, f"the SVG path is {d:.3e} from the exact one"
    assert n >= 1 and np.linalg.norm(f(np.array([0.0]))[0] - exact.p[0]) < 1e-12


def f_piece(seg):
    def f(ts):
        pts = [seg.point(float(np.clip(t, 0.0, 1.0))) for t in np.atleast_1d(ts)]
        return np.array([[p.real, p.imag, 0.0] for p in pts])
    return f, 0.0, 1.0


# ---------------------------------------------------------------------------- refusals


def test_a_tolerance_that_cannot_be_met_is_refused_with_a_typed_error(tmp_path):
    out = tmp_path / "never.step"
    # Below 1e-12 of the arc length no deviation can be certified: refused before any work.
    proc = run(["export", *CURVES[0][2], "--tolerance", "1e-15", "-o", str(out)], expect=3)
    assert json.loads(proc.stderr)["error"]["kind"] == "tolerance_not_met"
    proc = run(["export", *CURVES[3][2], "--relative-tolerance", "1e-13", "-o", str(out)],
               expect=3)
    assert json.loads(proc.stderr)["error"]["kind"] == "tolerance_not_met"
    # A negative tolerance is an invalid request.
    proc = run(["export", *CURVES[0][2], "--tolerance", "-1", "-o", str(out)], expect=2)
    assert json.loads(proc.stderr)["error"]["kind"] == "out_of_range"
    assert not out.exists()
    # SVG has no space curves.
    proc = run(["export", *CURVES[3][2], "--format", "svg", "-o", str(out)], expect=2)
    assert json.loads(proc.stderr)["error"]["kind"] == "usage"


def test_a_solved_result_on_standard_input_exports_the_same_file(tmp_path):
    _, sub, args = CURVES[2]
    result = run([sub, *args]).stdout
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    run(["export", *args, "-o", str(a)])
    proc = subprocess.run([lac_bin(), "export", "-", "-o", str(b)], input=result,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(a.read_text())["curves"] == json.loads(b.read_text())["curves"]


# ------------------------------------------------------------------------------- paths


@pytest.mark.parametrize("fmt", ["step", "iges", "dxf", "json", "svg"])
def test_a_g1_path_reads_back_within_tolerance_g1_at_its_joints(tmp_path, fmt):
    tolerance = 1e-7
    path, report = export(tmp_path, G1_PATH, fmt, tolerance)
    assert report["kind"] == "path" and report["continuity"] == "G1"
    exact = Exact(G1_PATH)
    if fmt in ("step", "iges"):
        curves = [occ_eval(c) for c in occ_edges(path)]
    elif fmt == "dxf":
        curves = [ezdxf_eval(s) for s in ezdxf_splines(path)]
    elif fmt == "json":
        curves = [geomdl_eval(c) for c in geomdl_curves(path)[1]]
    else:
        from svgpathtools import parse_path
        ns = {"svg": "http://www.w3.org/2000/svg"}
        group = ET.parse(path).getroot().find("svg:g", ns)
        curves = [f_piece(seg) for seg in parse_path(group.find("svg:path", ns).get("d"))]
    d = two_sided(exact, curves)
    assert d <= tolerance, f"the {fmt} reader's curve is {d:.3e} from the exact path"


def test_a_g1_path_keeps_its_curvature_jumps_and_its_tangents_at_the_joints(tmp_path):
    path, _ = export(tmp_path, G1_PATH, "json", 1e-9)
    doc, curves = geomdl_curves(path)
    c = curves[0]
    joints = json.loads(run(["path", *G1_PATH[2], "--samples", "2"]).stdout)["joints"]
    written = np.array(sorted(set(doc["curves"][0]["knots"])))
    for j in joints:
        i = np.argmin(abs(written - j["s"]))
        assert abs(written[i] - j["s"]) < 1e-6, "every joint is a knot"
        # geomdl normalises the knot vector to [0, 1].
        k = (written[i] - written[0]) / (written[-1] - written[0])
        eps = 1e-9
        left, right = c.derivatives(k - eps, order=2), c.derivatives(k + eps, order=2)
        ta = np.asarray(left[1]) / np.linalg.norm(left[1])
        tb = np.asarray(right[1]) / np.linalg.norm(right[1])
        assert np.linalg.norm(ta - tb) < 1e-6
        # The signed curvature on either side is the path's, jump and all.
        for (d1, d2), kappa in zip([left[1:], right[1:]], j["curvature"]):
            d1, d2 = np.asarray(d1), np.asarray(d2)
            signed = (d1[0] * d2[1] - d1[1] * d2[0]) / np.linalg.norm(d1) ** 3
            assert abs(signed - kappa) < 1e-5 * (1 + abs(kappa)), (signed, kappa)


def test_a_closed_path_ends_where_it_starts_in_every_reader(tmp_path):
    curve = CURVES[5]
    path, _ = export(tmp_path, curve, "step", 1e-8)
    edges = occ_edges(path)
    ordered = sorted(edges, key=lambda c: c.FirstParameter())
    a, b = ordered[0], ordered[-1]
    assert a.Value(a.FirstParameter()).Distance(b.Value(b.LastParameter())) < 1e-12
    # And the seam is G2 as the path is: tangent and curvature vector equal there.
    assert_g2(occ_d2(b, b.LastParameter()), occ_d2(a, a.FirstParameter()), True, 1.0)


def test_lac_paths_result_on_standard_input_exports_the_same_file(tmp_path):
    _, sub, args = CURVES[4]
    result = run([sub, *args]).stdout
    a, b = tmp_path / "a.dxf", tmp_path / "b.dxf"
    run(["export", *args, "-o", str(a)])
    proc = subprocess.run([lac_bin(), "export", "-", "-o", str(b)], input=result,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert a.read_text() == b.read_text()
