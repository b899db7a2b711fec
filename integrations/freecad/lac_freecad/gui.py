"""The workbench's commands, dialog and view providers (imported only with the GUI up).

A kind's command takes the selected vertices (in the order they were picked) as its points,
or asks for them in a dialog built from the kind's parameters; the fit command also takes a
selected edge and fits its sampled points. Errors are shown in a message box with lac's
message.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

import FreeCAD
import FreeCADGui as Gui
import Part
import lac
from PySide import QtGui

from .features import KINDS, Kind, make_comb, make_curve

ICONS = os.path.join(os.path.dirname(__file__), "icons")
TITLE = "Log-aesthetic curves"
#: Points sampled from a selected edge for the fit command.
FIT_SAMPLES = 200


def icon(name: str) -> str:
    return os.path.join(ICONS, f"{name}.svg")


def show_error(message: str) -> None:
    """lac's message in FreeCAD's own message box."""
    QtGui.QMessageBox.critical(Gui.getMainWindow(), TITLE, message)


def guarded(action: Callable[[], None]) -> None:
    """Run a command's action, showing lac's refusals (and other input errors) as a
    message box rather than a traceback in the report view."""
    try:
        action()
    except (lac.LacError, ValueError) as e:
        show_error(getattr(e, "message", None) or str(e))


class ViewProvider:
    """An object's icon; combs are drawn thin and orange."""

    def __init__(self, vobj: Any, name: str) -> None:
        vobj.Proxy = self
        self.name = name
        if name == "comb":
            vobj.LineColor = vobj.PointColor = (1.0, 0.55, 0.0)
            vobj.LineWidth = vobj.PointSize = 1.0
        else:
            vobj.LineWidth = 3.0

    def getIcon(self) -> str:  # noqa: N802 (FreeCAD's name)
        return icon(self.name)

    def attach(self, vobj: Any) -> None:
        self.Object = vobj.Object

    def __getstate__(self) -> str:
        return self.name

    def __setstate__(self, state: str) -> None:
        self.name = state

    dumps, loads = __getstate__, __setstate__


def selected_points() -> list[FreeCAD.Vector]:
    """The selected vertices in the order they were picked (a selected object whose shape
    is one vertex, a Draft point, counts as one)."""
    points = []
    for sel in Gui.Selection.getSelectionEx():
        subs = [s for s in sel.SubObjects if isinstance(s, Part.Vertex)]
        if subs:
            points += [v.Point for v in subs]
        elif hasattr(sel.Object, "Shape") and len(sel.Object.Shape.Vertexes) == 1:
            points.append(sel.Object.Shape.Vertexes[0].Point)
    return points


def selected_edges() -> list[tuple[Any, str]]:
    """The selected edges as (object, "EdgeN"); an object of one edge selected whole
    counts as ("object", "")."""
    edges = []
    for sel in Gui.Selection.getSelectionEx():
        names = [n for n in sel.SubElementNames if n.startswith("Edge")]
        if names:
            edges += [(sel.Object, n) for n in names]
        elif hasattr(sel.Object, "Shape") and len(sel.Object.Shape.Edges) == 1:
            edges.append((sel.Object, ""))
    return edges


class PointsDialog(QtGui.QDialog):
    """The points and parameters of a new curve of one kind."""

    def __init__(self, kind: Kind, points: list[FreeCAD.Vector]) -> None:
        super().__init__(Gui.getMainWindow())
        self.kind = kind
        self.setWindowTitle(kind.title)
        form = QtGui.QFormLayout(self)
        self.points = QtGui.QLineEdit(
            " ".join(f"{p.x:g},{p.y:g},{p.z:g}" for p in points)
            or " ".join(",".join(f"{c:g}" for c in p) for p in kind.example)
        )
        self.points.setToolTip(f'{kind.points.capitalize()}: "x,y,z x,y,z …"')
        form.addRow("Points", self.points)
        self.fields: dict[str, Any] = {}
        for p in kind.parameters:
            if p.type == "App::PropertyBool":
                field = QtGui.QCheckBox()
                field.setChecked(p.default)
            elif p.type == "App::PropertyInteger":
                field = QtGui.QSpinBox()
                field.setRange(0, 1000)
                field.setValue(p.default)
            else:
                field = QtGui.QDoubleSpinBox()
                field.setDecimals(4)
                field.setRange(-100.0, 100.0)
                field.setSingleStep(0.1)
                field.setValue(p.default)
            field.setToolTip(p.doc)
            form.addRow(p.name, field)
            self.fields[p.name] = field
        buttons = QtGui.QDialogButtonBox(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)

    def values(self) -> tuple[list[tuple[float, ...]], dict[str, Any]]:
        """The points typed and the parameters chosen."""
        try:
            points = [
                tuple(float(c) for c in p.split(","))
                for p in self.points.text().replace(";", " ").split()
            ]
        except ValueError as e:
            raise ValueError(f'points must be "x,y,z x,y,z …": {e}') from None
        parameters = {
            name: f.isChecked() if isinstance(f, QtGui.QCheckBox) else f.value()
            for name, f in self.fields.items()
        }
        return points, parameters


class CurveCommand:
    """Create a curve of one kind from the selected vertices, or from the dialog."""

    def __init__(self, kind: Kind) -> None:
        self.kind = kind

    def GetResources(self) -> dict[str, str]:  # noqa: N802 (FreeCAD's name)
        lo, hi = self.kind.count
        return {
            "Pixmap": icon(self.kind.name),
            "MenuText": self.kind.title,
            "ToolTip": f"{self.kind.title} from {self.kind.points}: select "
            f"{lo}{'' if hi == lo else ' or more' if hi is None else f' to {hi}'} vertices, "
            "or enter them in a dialog",
        }

    def IsActive(self) -> bool:  # noqa: N802
        return True

    def Activated(self) -> None:  # noqa: N802
        guarded(self.create)

    def create(self) -> None:
        points = self.points()
        lo, hi = self.kind.count
        dialog = PointsDialog(self.kind, points if lo <= len(points) <= (hi or 10**9) else [])
        if not dialog.exec_():
            return
        points, parameters = dialog.values()
        doc = FreeCAD.ActiveDocument or FreeCAD.newDocument()
        doc.openTransaction(self.kind.title)
        obj = make_curve(self.kind.name, points, doc, **parameters)
        doc.commitTransaction()
        if obj.Error:
            return  # shown already (features.rebuild); the object stays to be edited
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(obj)

    def points(self) -> list[FreeCAD.Vector]:
        return selected_points()


class FitCommand(CurveCommand):
    """Fit a log-aesthetic path to the selected vertices, or to a selected edge's points."""

    def points(self) -> list[FreeCAD.Vector]:
        edges = selected_edges()
        if len(edges) == 1:
            obj, sub = edges[0]
            edge = obj.Shape.getElement(sub) if sub else obj.Shape.Edges[0]
            return edge.discretize(Number=FIT_SAMPLES)
        return selected_points()


class CombCommand:
    """The curvature comb of each selected edge, with its logarithmic curvature graph's
    slope and monotonicity in the report view."""

    def GetResources(self) -> dict[str, str]:  # noqa: N802
        return {
            "Pixmap": icon("comb"),
            "MenuText": "Curvature comb",
            "ToolTip": "The curvature comb of the selected edges, and lac's analysis of "
            "their curvature (slope of the logarithmic curvature graph, monotonicity)",
        }

    def IsActive(self) -> bool:  # noqa: N802
        return bool(selected_edges())

    def Activated(self) -> None:  # noqa: N802
        guarded(self.create)

    def create(self) -> None:
        for obj, sub in selected_edges():
            comb = make_comb(obj, sub)
            if not comb.Error:
                FreeCAD.Console.PrintMessage(
                    f"{obj.Label} {sub}: LCG slope {comb.Alpha:.6g}, {comb.Verdict}\n"
                )


COMMANDS: list[str] = [f"Lac_{k.name.capitalize()}" for k in KINDS.values()] + ["Lac_Comb"]


def register() -> None:
    """Register every command with FreeCAD (the workbench's toolbar lists `COMMANDS`)."""
    for k in KINDS.values():
        command = FitCommand(k) if k.name == "fit" else CurveCommand(k)
        Gui.addCommand(f"Lac_{k.name.capitalize()}", command)
    Gui.addCommand("Lac_Comb", CombCommand())
