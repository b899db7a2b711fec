"""Parametric objects (`Part::FeaturePython`): a log-aesthetic curve whose properties are its
points and slopes, rebuilt by lac whenever one changes, and the curvature comb of any edge,
rebuilt when that edge changes.

Each kind of curve is described once, in `KINDS`: its points, its parameters (FreeCAD
properties with their defaults) and how it is built from them. The workbench's commands and
dialogs iterate that list.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Optional, TypeVar

import FreeCAD
import Part
import lac

from . import analysis, curves

GROUP = "Curve"
RESULT = "Result"


@dataclass(frozen=True)
class Parameter:
    """A property of a kind: its name, FreeCAD type, default and tooltip."""

    name: str
    type: str
    default: Any
    doc: str


@dataclass(frozen=True)
class Kind:
    """A kind of curve: what its points are, how many, its parameters and its build."""

    name: str
    title: str
    points: str
    count: tuple[int, Optional[int]]
    example: Sequence[tuple[float, float, float]]
    parameters: Sequence[Parameter]
    build: Callable[[Any], curves.Built]


def _alpha(default: float = 0.5, name: str = "Alpha", what: str = "") -> Parameter:
    return Parameter(
        name, "App::PropertyFloat", default, f"Slope of the logarithmic curvature graph{what}"
    )


CLOSED = Parameter("Closed", "App::PropertyBool", False, "The last point joins the first")


def _optional(value: float) -> Optional[float]:
    return value if value > 0 else None


KINDS: dict[str, Kind] = {
    k.name: k
    for k in [
        Kind(
            "segment",
            "Log-aesthetic segment",
            "three control points",
            (3, 3),
            [(0, 0, 0), (3, 0, 0), (4.2, 1.9, 0)],
            [_alpha()],
            lambda o: curves.segment(o.Points, o.Alpha, o.Tolerance),
        ),
        Kind(
            "compound",
            "Compound-rhythm curve",
            "three control points (with Ratio) or four",
            (3, 4),
            [(0, 0, 0), (2, 0, 0), (2.6, 1.2, 0)],
            [
                _alpha(-1.0, "Alpha0", " of the first piece"),
                _alpha(2.0, "Alpha1", " of the second piece"),
                Parameter(
                    "Ratio",
                    "App::PropertyFloat",
                    0.5,
                    "Share of the turning taken by the first piece (three points only)",
                ),
            ],
            lambda o: curves.compound(
                o.Points, o.Alpha0, o.Alpha1, o.Ratio if len(o.Points) == 3 else None, o.Tolerance
            ),
        ),
        Kind(
            "path",
            "Log-aesthetic path",
            "a control polygon of three or more points",
            (3, None),
            [(0, 0, 0), (1.5, 0, 0), (3, 0.8, 0), (6, 3.2, 0), (7.5, 4, 0), (9, 4, 0)],
            [
                _alpha(-0.5),
                Parameter("G2", "App::PropertyBool", True, "Continuous curvature at the joints"),
                CLOSED,
            ],
            lambda o: curves.path(o.Points, o.Alpha, o.G2, o.Closed, o.Tolerance),
        ),
        Kind(
            "spline",
            "Log-aesthetic spline",
            "three or more points to pass through",
            (3, None),
            [(0, 0, 0), (2, 0.3, 0), (3.5, 1.5, 0), (4, 3, 0)],
            [_alpha(), CLOSED],
            lambda o: curves.spline(o.Points, o.Alpha, o.Closed, o.Tolerance),
        ),
        Kind(
            "space",
            "Log-aesthetic space curve",
            "four 3-D control points",
            (4, 4),
            [(0, 0, 0), (3, 0, 0), (3, 3, 1.5), (0, 3, 3)],
            [
                _alpha(),
                Parameter("Beta", "App::PropertyFloat", 0.0, "Slope of the torsion graph"),
                Parameter("Omega", "App::PropertyFloat", 0.3, "Torsion parameter omega"),
            ],
            lambda o: curves.space(o.Points, o.Alpha, o.Beta, o.Omega, o.Tolerance),
        ),
        Kind(
            "fit",
            "Fitted log-aesthetic path",
            "the points to fit (sampled from an edge, or picked)",
            (3, None),
            [],
            [
                Parameter(
                    "FitTolerance",
                    "App::PropertyFloat",
                    0.0,
                    "Largest distance from a point to the path (0: one least-squares segment)",
                ),
                Parameter(
                    "MaxSegments", "App::PropertyInteger", 0, "At most this many (0: lac's default)"
                ),
                CLOSED,
            ],
            lambda o: curves.fit(
                o.Points,
                _optional(o.FitTolerance),
                o.Closed,
                o.MaxSegments or None,
                export_tolerance=o.Tolerance,
            ),
        ),
    ]
}


T = TypeVar("T")


def rebuild(obj: Any, make: Callable[[], T]) -> Optional[T]:
    """`make()`, or None when lac refuses the object's input: then its `Error` property
    holds lac's message, which goes to the report view (and a dialog in the GUI), and the
    object keeps its last shape. A traceback would tell a designer nothing."""
    try:
        made = make()
    except (lac.LacError, ValueError) as e:
        message = getattr(e, "message", None) or str(e)
        obj.Error = message
        FreeCAD.Console.PrintError(f"{obj.Label}: {message}\n")
        if FreeCAD.GuiUp:
            from . import gui

            gui.show_error(f"{obj.Label}: {message}")
        return None
    obj.Error = ""
    return made


def _add_results(obj: Any, results: Sequence[tuple[str, str, str]]) -> None:
    """Read-only properties that the object computes, and its `Error`."""
    for name, type_, doc in [
        *results,
        ("Error", "App::PropertyString", "Why lac refused the input (empty when it did not)"),
    ]:
        obj.addProperty(type_, name, RESULT, doc)
        obj.setEditorMode(name, 1)


class Proxy:
    """A proxy with nothing to save beside its object's properties (FreeCAD 0.20 calls
    `__getstate__`/`__setstate__` when saving and opening a document; 0.21 `dumps`/`loads`)."""

    def __getstate__(self) -> None:
        return None

    def __setstate__(self, state: Any) -> None:
        return None

    dumps, loads = __getstate__, __setstate__


class Curve(Proxy):
    """The proxy of a log-aesthetic curve object: builds its shape from its properties."""

    def __init__(self, obj: Any, kind: Kind) -> None:
        obj.Proxy = self
        obj.addProperty("App::PropertyString", "Kind", GROUP, "The kind of curve")
        obj.Kind = kind.name
        obj.setEditorMode("Kind", 1)
        obj.addProperty("App::PropertyVectorList", "Points", GROUP, kind.points.capitalize())
        for p in kind.parameters:
            obj.addProperty(p.type, p.name, GROUP, p.doc)
            setattr(obj, p.name, p.default)
        obj.addProperty(
            "App::PropertyFloat",
            "Tolerance",
            GROUP,
            "Largest deviation of the B-spline from the exact curve (model units)",
        )
        obj.Tolerance = curves.TOLERANCE
        _add_results(
            obj,
            [
                ("Pieces", "App::PropertyInteger", "Rational cubic pieces of the B-spline"),
                ("MaxDeviation", "App::PropertyFloat", "Deviation measured on the B-spline"),
                ("ArcLength", "App::PropertyFloat", "Arc length of the exact curve"),
            ],
        )

    def execute(self, obj: Any) -> None:
        built = rebuild(obj, lambda: KINDS[obj.Kind].build(obj))
        if built is not None:
            obj.Shape = built.shape
            obj.Pieces = int(built.report["pieces"])
            obj.MaxDeviation = float(built.report["max_deviation"])
            obj.ArcLength = float(built.report["arc_length"])


class Comb(Proxy):
    """The proxy of a curvature comb: the comb of its source edge, and that edge's
    logarithmic curvature graph's slope and monotonicity as lac measures them."""

    def __init__(self, obj: Any, source: Any, subelement: str) -> None:
        obj.Proxy = self
        obj.addProperty("App::PropertyLinkSub", "Source", "Comb", "The edge")
        obj.Source = (source, [subelement])
        obj.addProperty("App::PropertyInteger", "Samples", "Comb", "Number of teeth")
        obj.Samples = analysis.COMB_SAMPLES
        obj.addProperty(
            "App::PropertyFloat", "Scale", "Comb", "Tooth length per unit curvature (0: automatic)"
        )
        _add_results(
            obj,
            [
                ("Alpha", "App::PropertyFloat", "Slope fitted to the logarithmic curvature graph"),
                ("Monotone", "App::PropertyBool", "Whether the curvature is monotone"),
                ("Verdict", "App::PropertyString", "Where the curvature stops being monotone"),
            ],
        )

    def execute(self, obj: Any) -> None:
        def measure() -> tuple[Part.Compound, analysis.LogCurvatureGraph]:
            edge = source_edge(obj.Source)
            comb = analysis.curvature_comb(edge, obj.Samples, obj.Scale or None)
            return comb, analysis.log_curvature_graph(edge)

        measured = rebuild(obj, measure)
        if measured is not None:
            obj.Shape, graph = measured
            obj.Alpha = float("nan") if graph.alpha is None else graph.alpha
            obj.Monotone = graph.monotone
            obj.Verdict = graph.not_monotone or "monotone"


def source_edge(link: Any) -> Part.Edge:
    """The edge a `PropertyLinkSub` names (an object and "EdgeN", or an object whose shape
    has one edge)."""
    obj, subs = link
    shape = obj.Shape
    if subs and subs[0]:
        return shape.getElement(subs[0])
    if len(shape.Edges) != 1:
        raise ValueError(f"{obj.Label} has {len(shape.Edges)} edges: select one")
    return shape.Edges[0]


def make_curve(
    kind: str,
    points: Sequence[curves.PointLike],
    doc: Optional[Any] = None,
    **parameters: Any,
) -> Any:
    """A new log-aesthetic curve object in `doc` (the active document) with these points
    and parameters (the kind's properties, e.g. `Alpha=-1`), recomputed."""
    doc = doc or FreeCAD.ActiveDocument or FreeCAD.newDocument()
    k = KINDS[kind]
    obj = doc.addObject("Part::FeaturePython", kind.capitalize())
    obj.Label = k.title
    Curve(obj, k)
    obj.Points = curves.vectors(points)
    for name, value in parameters.items():
        setattr(obj, name, value)
    _view(obj, kind)
    doc.recompute()
    return obj


def make_comb(source: Any, subelement: str = "", doc: Optional[Any] = None) -> Any:
    """A new curvature comb object of `source`'s edge `subelement` ("Edge1"; empty when
    `source` has one edge), recomputed."""
    doc = doc or source.Document
    obj = doc.addObject("Part::FeaturePython", "Comb")
    obj.Label = f"Comb of {source.Label}"
    Comb(obj, source, subelement)
    _view(obj, "comb")
    doc.recompute()
    return obj


def _view(obj: Any, icon: str) -> None:
    """The object's icon and colour in the GUI (nothing without it)."""
    if FreeCAD.GuiUp:
        from . import gui

        gui.ViewProvider(obj.ViewObject, icon)
