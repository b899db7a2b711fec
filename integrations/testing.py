"""A test runner for the integrations' tests, which run inside the programs' own Python
(`freecadcmd`, FreeCAD's GUI, Debian's python3 with inkex) where pytest may be missing:
unittest, and the closing line "N passed, N failed" that CI reads; exit code 1 on any
failure."""

from __future__ import annotations

import os
import sys
import unittest
from types import ModuleType


def run(module: ModuleType) -> None:
    """Run every test case of `module` and end the process with its verdict. The report
    goes to the process's own standard output (FreeCAD's GUI redirects `sys.stdout` to its
    report view), and the process ends at once: FreeCAD catches `SystemExit` from a script
    and would keep its window open."""
    out = sys.__stdout__
    suite = unittest.defaultTestLoader.loadTestsFromModule(module)
    result = unittest.TextTestRunner(stream=out, verbosity=2).run(suite)
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    passed = result.testsRun - failed - len(result.skipped)
    skipped = f", {len(result.skipped)} skipped" if result.skipped else ""
    print(f"{passed} passed, {failed} failed{skipped}", file=out, flush=True)
    sys.stderr.flush()
    os._exit(1 if failed or result.testsRun == 0 else 0)
