"""The Inkscape extensions, run as Inkscape runs them: each script on an SVG file from a
shell (`PYTHONPATH=/usr/share/inkscape/extensions python3 lac_spline.py --id=… in.svg`),
its output parsed and compared with `lac spline` ($LAC_BIN, else target/debug/lac), and once
through Inkscape itself (its action for the installed extension, under Xvfb).

    PYTHONPATH=/usr/share/inkscape/extensions /usr/bin/python3 integrations/inkscape/tests/test_inkscape.py
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import inkex
import lac
import numpy as np

HERE = Path(__file__).resolve().parent
EXTENSIONS = HERE.parent
ROOT = EXTENSIONS.parent.parent
sys.path[:0] = [str(EXTENSIONS.parent), str(EXTENSIONS)]
import testing  # noqa: E402 (integrations/testing.py)

LAC_BIN = os.environ.get("LAC_BIN", str(ROOT / "target" / "debug" / "lac"))
#: Millimetres in the document and its user units, so that a tolerance in document units
#: is one in path coordinates.
DOCUMENT = """<svg xmlns="http://www.w3.org/2000/svg" xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
 xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" width="200mm" height="120mm" viewBox="0 0 200 120">
<sodipodi:namedview id="view" inkscape:document-units="mm"/>
{body}
</svg>"""
OPEN = [(10, 60), (40, 30), (80, 40), (110, 80), (150, 70), (190, 30)]
CONVEX = [(20, 100), (60, 95), (95, 75), (110, 40)]
CLOSED = [(120, 20), (150, 20), (160, 40), (140, 60), (110, 40)]
TOL = 0.01


def polyline(points: list[tuple[float, float]], closed: bool = False) -> str:
    return "M " + " L ".join(f"{x},{y}" for x, y in points) + (" Z" if closed else "")


def run(script: str, svg: str, *args: str) -> subprocess.CompletedProcess[str]:
    """An extension on a document, from a shell as Inkscape runs it."""
    with tempfile.NamedTemporaryFile("w", suffix=".svg", delete=False) as f:
        f.write(svg)
    env = dict(os.environ, PYTHONPATH="/usr/share/inkscape/extensions")
    try:
        return subprocess.run(
            [sys.executable, str(EXTENSIONS / script), *args, f.name],
            capture_output=True,
            text=True,
            env=env,
            timeout=120,
        )
    finally:
        os.remove(f.name)


def output(done: subprocess.CompletedProcess[str]) -> inkex.SvgDocumentElement:
    if done.returncode != 0:
        raise AssertionError(f"exit code {done.returncode}: {done.stderr}")
    return inkex.load_svg(done.stdout.encode()).getroot()


def pieces_of(element: inkex.PathElement) -> list[list[np.ndarray]]:
    """Each subpath's cubic pieces (4×2 arrays), as inkex reads the path."""
    out = []
    for sub in element.path.to_absolute().to_superpath():
        out.append([np.array([a[1], a[2], b[0], b[1]], float) for a, b in zip(sub, sub[1:])])
    return out


def bezier(c: np.ndarray, t: np.ndarray) -> np.ndarray:
    u = 1 - t
    w = np.stack([u**3, 3 * u * u * t, 3 * u * t * t, t**3], axis=1)
    return w @ c


def dense(pieces: list[np.ndarray], per_piece: int = 200) -> np.ndarray:
    t = np.linspace(0, 1, per_piece)
    return np.vstack([bezier(c, t) for c in pieces])


def distances(points: np.ndarray, line: np.ndarray) -> np.ndarray:
    """Each point's distance to a polyline."""
    a, b = line[:-1], line[1:]
    ab = b - a
    out = np.empty(len(points))
    for i in range(0, len(points), 256):
        p = points[i : i + 256, None, :]
        t = np.clip(((p - a) * ab).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-300), 0, 1)
        out[i : i + 256] = np.linalg.norm(p - (a + t[..., None] * ab), axis=-1).min(axis=1)
    return out


def lac_spline(
    points: list[tuple[float, float]], alpha: float, closed: bool, samples: int
) -> np.ndarray:
    """`lac spline`'s samples of the spline through the points."""
    through = " ".join(f"{x},{y}" for x, y in points)
    args = [
        LAC_BIN,
        "spline",
        "--through",
        through,
        "--alpha",
        repr(alpha),
        "--samples",
        str(samples),
    ]
    done = subprocess.run(
        args + (["--closed"] if closed else []), capture_output=True, text=True, check=True
    )
    return np.array([[r["x"], r["y"]] for r in json.loads(done.stdout)["samples"]])


def two_sided(
    pieces: list[np.ndarray], points: list[tuple[float, float]], alpha: float, closed: bool
) -> float:
    """The larger of: lac's samples' distance to the Béziers, the Béziers' to lac's curve."""
    there = distances(lac_spline(points, alpha, closed, 2001), dense(pieces))
    back = distances(dense(pieces, 50), lac_spline(points, alpha, closed, 10001))
    return float(max(there.max(), back.max()))


class Spline(unittest.TestCase):
    def test_open_and_convex_splines_are_lac_spline_within_the_tolerance(self) -> None:
        for points, alpha in [(OPEN, -1.0), (OPEN, -0.5), (CONVEX, 0.5), (CONVEX, 2.0)]:
            svg = DOCUMENT.format(body=f'<path id="p" d="{polyline(points)}" style="stroke:#000"/>')
            root = output(
                run("lac_spline.py", svg, f"--alpha={alpha}", f"--tolerance={TOL}", "--id=p")
            )
            [pieces] = pieces_of(root.getElementById("p"))
            worst = two_sided(pieces, points, alpha, closed=False)
            print(
                f"\n  alpha {alpha}: {len(pieces)} cubics, deviation {worst:.2e} (tolerance {TOL})",
                end=" ",
            )
            self.assertLess(worst, TOL)
            self.assertTrue(
                np.allclose(pieces[0][0], points[0]) and np.allclose(pieces[-1][3], points[-1])
            )

    def test_closed_subpath_is_closed_and_subpaths_are_kept_apart(self) -> None:
        d = polyline(CONVEX) + " " + polyline(CLOSED, closed=True)
        svg = DOCUMENT.format(body=f'<path id="p" d="{d}"/>')
        root = output(run("lac_spline.py", svg, "--alpha=0.5", f"--tolerance={TOL}", "--id=p"))
        element = root.getElementById("p")
        first, second = pieces_of(element)
        self.assertLess(two_sided(first, CONVEX, 0.5, closed=False), TOL)
        self.assertLess(two_sided(second, CLOSED, 0.5, closed=True), TOL)
        self.assertEqual(str(element.path).count("Z") + str(element.path).count("z"), 1)
        self.assertTrue(np.allclose(second[0][0], second[-1][3]))

    def test_tolerance_is_in_document_units_through_transforms(self) -> None:
        # Inside a group scaled by 4, in a document of 2 mm a user unit, 0.4 mm is 0.05 in
        # the path's coordinates.
        body = f'<g transform="scale(4)"><path id="p" d="{polyline([(x / 4, y / 4) for x, y in OPEN])}"/></g>'
        svg = DOCUMENT.format(body=body).replace(
            'width="200mm" height="120mm"', 'width="400mm" height="240mm"'
        )
        extension = inkex.EffectExtension()
        extension.svg = inkex.load_svg(svg.encode()).getroot()
        import lac_inkscape

        local = lac_inkscape.local_tolerance(extension, extension.svg.getElementById("p"), 0.4)
        self.assertAlmostEqual(local, 0.05, delta=1e-12)
        root = output(run("lac_spline.py", svg, "--tolerance=0.4", "--id=p"))
        [pieces] = pieces_of(root.getElementById("p"))
        self.assertLess(
            two_sided(pieces, [(x / 4, y / 4) for x, y in OPEN], -1.0, closed=False), 0.05
        )

    def test_keep_the_original(self) -> None:
        svg = DOCUMENT.format(body=f'<path id="p" d="{polyline(OPEN)}" style="stroke:#123456"/>')
        root = output(run("lac_spline.py", svg, "--keep=true", "--id=p"))
        paths = list(root.descendants().filter(inkex.PathElement))
        self.assertEqual(len(paths), 2)
        self.assertEqual(str(paths[0].path), str(inkex.Path(polyline(OPEN))))
        self.assertEqual(paths[1].style["stroke"], "#123456")
        self.assertLess(two_sided(pieces_of(paths[1])[0], OPEN, -1.0, closed=False), TOL)


def derivative(c: np.ndarray, t: float) -> np.ndarray:
    u = 1 - t
    return 3 * (u * u * (c[1] - c[0]) + 2 * u * t * (c[2] - c[1]) + t * t * (c[3] - c[2]))


def second_derivative(c: np.ndarray, t: float) -> np.ndarray:
    return 6 * ((1 - t) * (c[2] - 2 * c[1] + c[0]) + t * (c[3] - 2 * c[2] + c[1]))


def signed_curvature(c: np.ndarray, t: float) -> float:
    """A cubic's curvature by its derivatives (the test's own formula)."""
    d1, d2 = derivative(c, t), second_derivative(c, t)
    return float((d1[0] * d2[1] - d1[1] * d2[0]) / np.linalg.norm(d1) ** 3)


def foot_on(pieces: list[np.ndarray], p: np.ndarray) -> tuple[np.ndarray, float]:
    """The piece and parameter of the point of the pieces nearest to p (a grid, then
    Newton on (B(t) - p) . B'(t) = 0)."""
    grid = np.linspace(0, 1, 1001)
    k, i = min(
        (
            (k, int(np.argmin(np.linalg.norm(bezier(c, grid) - p, axis=1))))
            for k, c in enumerate(pieces)
        ),
        key=lambda ki: float(np.linalg.norm(bezier(pieces[ki[0]], grid[ki[1] : ki[1] + 1])[0] - p)),
    )
    c, t = pieces[k], float(grid[i])
    for _ in range(8):
        r = bezier(c, np.array([t]))[0] - p
        d1, d2 = derivative(c, t), second_derivative(c, t)
        t = min(1.0, max(0.0, t - float(r @ d1) / float(d1 @ d1 + r @ d2)))
    return c, t


class Comb(unittest.TestCase):
    def test_teeth_are_the_curvature_of_the_path_times_the_scale(self) -> None:
        spline = output(
            run(
                "lac_spline.py",
                DOCUMENT.format(body=f'<path id="p" d="{polyline(OPEN)}"/>'),
                "--id=p",
            )
        )
        root = output(
            run("lac_comb.py", spline.tostring().decode(), "--id=p", "--teeth=60", "--scale=100")
        )
        [pieces] = pieces_of(root.getElementById("p"))
        group = root.getElementById("p").getnext()
        self.assertIsInstance(group, inkex.Group)
        self.assertTrue(group.get_id().startswith("lac-comb-p"))
        *teeth, tips = pieces_of(next(iter(group.descendants().filter(inkex.PathElement))))
        self.assertTrue(60 <= len(teeth) <= 60 + 2 * len(pieces), len(teeth))
        self.assertEqual(len(tips), len(teeth) - 1)
        for [tooth] in teeth:
            foot, tip = tooth[0], tooth[3]
            piece, t = foot_on(pieces, foot)
            kappa = signed_curvature(piece, t)
            self.assertAlmostEqual(float(np.linalg.norm(tip - foot)), 100 * abs(kappa), delta=1e-6)
            # Away from the centre of curvature, which is on the left of the tangent for
            # kappa > 0.
            d1 = derivative(piece, t)
            self.assertLessEqual(float(np.dot(tip - foot, [-d1[1], d1[0]])) * kappa, 1e-12)

    def test_comb_of_a_polyline_with_lines(self) -> None:
        svg = DOCUMENT.format(body='<path id="p" d="M 10,10 L 50,10 C 70,10 80,30 80,50"/>')
        root = output(run("lac_comb.py", svg, "--id=p", "--teeth=2"))
        group = root.getElementById("p").getnext()
        # Two pieces of two teeth each (their ends), the joint once; and the tips' line.
        *teeth, tips = pieces_of(next(iter(group.descendants().filter(inkex.PathElement))))
        self.assertEqual(len(teeth), 3)
        self.assertAlmostEqual(float(np.linalg.norm(teeth[0][0][3] - teeth[0][0][0])), 0.0)


class Fair(unittest.TestCase):
    def test_fairs_a_noisy_polyline_within_the_tolerance(self) -> None:
        seg = lac.Segment([(10, 100), (100, 100), (170, 20)], 0.5)
        rng = np.random.default_rng(7)
        noisy = seg.sample(60).points + rng.normal(0, 0.2, (60, 2))
        svg = DOCUMENT.format(body=f'<path id="p" d="{polyline([tuple(p) for p in noisy])}"/>')
        root = output(run("lac_fair.py", svg, "--id=p", "--tolerance=1"))
        [pieces] = pieces_of(root.getElementById("p"))
        line = dense(pieces)
        # Every node of the polyline within the tolerance (and the export's 1 %).
        self.assertLess(distances(noisy, line).max(), 1.01)
        self.assertLess(len(pieces), 12)
        # Closer to the curve the noise was added to than the noise itself.
        self.assertLess(distances(seg.sample(400).points, line).max(), 0.6)


class BadInput(unittest.TestCase):
    """Inkscape's error dialog (the message on stderr, a non-zero exit code) with lac's
    message, never a traceback."""

    def assert_refused(self, script: str, d: str, expected: str, *args: str) -> None:
        done = run(script, DOCUMENT.format(body=f'<path id="p" d="{d}"/>'), "--id=p", *args)
        self.assertNotEqual(done.returncode, 0)
        self.assertNotIn("Traceback", done.stderr)
        self.assertEqual(done.stderr.strip(), expected)

    def message(self, points: list[tuple[float, float]], alpha: float) -> str:
        try:
            lac.Spline(points, alpha)
        except lac.LacError as e:
            return f"lac: path p: {e.message}"
        raise AssertionError("lac accepted it")

    def test_one_node(self) -> None:
        self.assert_refused("lac_spline.py", "M 10,10", self.message([(10, 10)], -1.0))
        for script in ("lac_comb.py", "lac_fair.py"):
            self.assert_refused(
                script, "M 10,10", "lac: path p has no length: draw two nodes apart"
            )

    def test_coincident_nodes(self) -> None:
        points = [(0, 0), (0, 0), (10, 10), (20, 0)]
        self.assert_refused("lac_spline.py", polyline(points), self.message(points, -1.0))

    def test_alpha_that_cannot_inflect(self) -> None:
        self.assert_refused("lac_spline.py", polyline(OPEN), self.message(OPEN, 0.5), "--alpha=0.5")

    def test_nothing_selected(self) -> None:
        done = run("lac_spline.py", DOCUMENT.format(body='<path id="p" d="M 0,0 L 1,1"/>'))
        self.assertEqual(done.stderr.strip(), "lac: select one or more paths first")


@unittest.skipUnless(
    shutil.which("xvfb-run") and shutil.which("inkscape"), "needs inkscape and xvfb-run"
)
class Inkscape(unittest.TestCase):
    def test_inkscape_runs_the_installed_extension(self) -> None:
        with tempfile.TemporaryDirectory() as tmp:
            source, out = Path(tmp, "in.svg"), Path(tmp, "out.svg")
            source.write_text(DOCUMENT.format(body=f'<path id="p" d="{polyline(OPEN)}"/>'))
            actions = f"select-by-id:p;org.lac.spline.noprefs;export-filename:{out};export-plain-svg;export-do"
            subprocess.run(
                [
                    "xvfb-run",
                    "-a",
                    "inkscape",
                    "--batch-process",
                    f"--actions={actions}",
                    str(source),
                ],
                capture_output=True,
                timeout=120,
                check=True,
            )
            root = inkex.load_svg(str(out)).getroot()
            [pieces] = pieces_of(root.getElementById("p"))
            self.assertLess(two_sided(pieces, OPEN, -1.0, closed=False), TOL)


testing.run(sys.modules[__name__])
