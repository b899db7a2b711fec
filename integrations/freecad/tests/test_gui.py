"""The workbench in FreeCAD's GUI, under Xvfb (`make test-integrations` runs it):

    QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad integrations/freecad/tests/test_gui.py

Commands run as a designer runs them: vertices picked in order, the dialog answered with OK,
lac's refusal read from FreeCAD's message box (each modal window is answered by a timer, as a
click would). With LAC_SCREENSHOT=FILE it also saves the 3-D view of a G2 path and its comb.
"""

from __future__ import annotations

import os
import sys
import time
import unittest
from collections.abc import Callable
from typing import Any

import FreeCAD
import FreeCADGui as Gui
import lac
from PySide import QtCore, QtGui

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
import testing  # noqa: E402 (integrations/testing.py)

from lac_freecad import features, gui  # noqa: E402

POLYGON = [(0, 0, 0), (1.5, 0, 0), (3, 0.8, 0), (6, 3.2, 0), (7.5, 4, 0), (9, 4, 0)]


def answer_modal(answer: Callable[[Any], None], seen: list[Any]) -> None:
    """Answer the next modal window (a dialog or a message box) with `answer`, as a click
    would, after noting it in `seen` (a message box by its text: Qt deletes it after)."""

    def poll() -> None:
        window = QtGui.QApplication.activeModalWidget()
        if window is None:
            QtCore.QTimer.singleShot(50, poll)
            return
        seen.append(window.text() if isinstance(window, QtGui.QMessageBox) else window)
        answer(window)

    QtCore.QTimer.singleShot(50, poll)


class Workbench(unittest.TestCase):
    def setUp(self) -> None:
        Gui.activateWorkbench("LacWorkbench")
        self.doc = FreeCAD.newDocument()
        Gui.Selection.clearSelection()

    def tearDown(self) -> None:
        FreeCAD.closeDocument(self.doc.Name)

    def test_every_command_is_registered(self) -> None:
        self.assertEqual(Gui.activeWorkbench().name(), "LacWorkbench")
        for command in gui.COMMANDS:
            self.assertIn(command, Gui.listCommands())

    def test_segment_from_three_picked_vertices(self) -> None:
        points = [(0, 0, 0), (3, 0, 0), (4.2, 1.9, 0)]
        for x, y, z in points:
            v = self.doc.addObject("Part::Vertex", "V")
            v.X, v.Y, v.Z = x, y, z
        self.doc.recompute()
        for v in self.doc.Objects:
            Gui.Selection.addSelection(v)
        seen: list[Any] = []
        answer_modal(lambda dialog: dialog.accept(), seen)
        Gui.runCommand("Lac_Segment")
        self.assertIsInstance(seen[0], gui.PointsDialog)
        [segment] = [o for o in self.doc.Objects if o.Name.startswith("Segment")]
        self.assertEqual([tuple(p) for p in segment.Points], [tuple(map(float, p)) for p in points])
        self.assertAlmostEqual(
            segment.ArcLength, lac.Segment([p[:2] for p in points], 0.5).arc_length
        )

    def test_fit_to_a_selected_edge(self) -> None:
        segment = features.make_curve("segment", [(0, 0, 0), (3, 0, 0), (4.2, 1.9, 0)], self.doc)
        Gui.Selection.addSelection(segment, "Edge1")
        seen: list[Any] = []
        answer_modal(lambda dialog: dialog.accept(), seen)
        Gui.runCommand("Lac_Fit")
        [fit] = [o for o in self.doc.Objects if o.Name.startswith("Fit")]
        self.assertEqual((fit.Error, len(fit.Points)), ("", gui.FIT_SAMPLES))
        # One least-squares segment through points of a segment: that segment again.
        self.assertAlmostEqual(fit.ArcLength, segment.ArcLength, delta=1e-6)

    def test_comb_of_a_selected_edge(self) -> None:
        path = features.make_curve("path", POLYGON, self.doc, Alpha=-0.5)
        Gui.Selection.addSelection(path, "Edge1")
        Gui.runCommand("Lac_Comb")
        [comb] = [o for o in self.doc.Objects if o.Name.startswith("Comb")]
        self.assertEqual(comb.Source[0], path)
        self.assertGreater(len(comb.Shape.Edges), 100)
        self.assertFalse(comb.Monotone)

    def test_refusal_is_lacs_message_in_a_message_box(self) -> None:
        segment = features.make_curve("segment", [(0, 0, 0), (3, 0, 0), (4.2, 1.9, 0)], self.doc)
        try:
            lac.Segment([(0, 0), (3, 0), (4.2, 1.9)], 50.0)
        except lac.NotDrawable as e:
            expected = f"{segment.Label}: {e.message}"
        seen: list[Any] = []
        answer_modal(lambda box: box.accept(), seen)
        segment.Alpha = 50.0
        self.doc.recompute()
        self.assertEqual(seen, [expected])

    def test_dialog_refuses_points_it_cannot_read(self) -> None:
        seen: list[Any] = []

        def type_bad_points(dialog: Any) -> None:
            dialog.points.setText("0,0 1,x 2,1")
            answer_modal(lambda box: box.accept(), seen)
            dialog.accept()

        answer_modal(type_bad_points, seen)
        Gui.runCommand("Lac_Spline")
        self.assertEqual(len(seen), 2)
        self.assertIn('points must be "x,y,z x,y,z …"', seen[1])


def screenshot(path: str) -> None:
    """FreeCAD's window with the README's G2 path and its curvature comb, seen from the
    top, the path selected (its properties in the property editor)."""
    window = Gui.getMainWindow()
    window.resize(1280, 760)
    window.showNormal()
    doc = FreeCAD.newDocument("Screenshot")
    curve = features.make_curve("path", POLYGON, doc, Alpha=-0.5)
    features.make_comb(curve, "Edge1")
    Gui.activeDocument().activeView().viewTop()
    Gui.SendMsgToActiveView("ViewFit")
    mdi = window.findChild(QtGui.QMdiArea)
    for sub in mdi.subWindowList():
        if sub.windowTitle().startswith("Start"):
            sub.close()
    Gui.Selection.addSelection(curve)
    # The property editor fills in from the event loop: a second of it.
    for _ in range(40):
        QtGui.QApplication.processEvents()
        time.sleep(0.025)
    # A grab leaves the OpenGL view blank: the view renders itself offscreen, and is
    # painted where it is.
    picture = window.grab()
    view = next(
        w for w in mdi.activeSubWindow().findChildren(QtGui.QWidget) if "GL" in type(w).__name__
    )
    rendered = path + ".view.png"
    Gui.activeDocument().activeView().saveImage(rendered, view.width(), view.height(), "White")
    painter = QtGui.QPainter(picture)
    painter.drawImage(view.mapTo(window, QtCore.QPoint(0, 0)), QtGui.QImage(rendered))
    painter.end()
    os.remove(rendered)
    # 256 colours: a small PNG for the documentation.
    image = picture.toImage()
    image.convertToFormat(QtGui.QImage.Format_Indexed8, QtCore.Qt.ThresholdDither).save(path)


if os.environ.get("LAC_SCREENSHOT"):
    Gui.activateWorkbench("LacWorkbench")
    screenshot(os.environ["LAC_SCREENSHOT"])
testing.run(sys.modules[__name__])
