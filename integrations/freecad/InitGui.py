# The lac workbench: log-aesthetic curves (segment, compound curve, path, spline, space
# curve, fit) as parametric objects, and the curvature comb of any edge. FreeCAD runs this
# file at start-up with `Gui` and `Workbench` in its namespace; `lac_freecad` is importable
# because FreeCAD puts every folder of Mod on sys.path.


class LacWorkbench(Workbench):  # noqa: F821 (FreeCAD's namespace)
    """Log-aesthetic curves, solved by lac."""

    import os as _os

    import lac_freecad as _lac_freecad

    MenuText = "Log-aesthetic curves"
    ToolTip = "Fair curves whose logarithmic curvature graph is straight (lac)"
    Icon = _os.path.join(_os.path.dirname(_lac_freecad.__file__), "icons", "lac.svg")

    def Initialize(self):
        from lac_freecad import gui

        gui.register()
        self.appendToolbar("lac", gui.COMMANDS)
        self.appendMenu("lac", gui.COMMANDS)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(LacWorkbench())  # noqa: F821
