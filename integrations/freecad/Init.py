# The lac workbench needs nothing at FreeCAD's start without the GUI: scripts import
# `lac_freecad` (this folder is on sys.path).
