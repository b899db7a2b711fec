"""A test runner for the integrations' tests, which run inside the programs' own Python
(`freecadcmd`, Debian's python3 with inkex) where pytest may be missing: unittest, and the
closing line "N passed, N failed" that CI reads; exit code 1 on any failure."""

from __future__ import annotations

import sys
import unittest
from types import ModuleType


def run(module: ModuleType) -> None:
    """Run every test case of `module` and exit with its verdict."""
    suite = unittest.defaultTestLoader.loadTestsFromModule(module)
    result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    passed = result.testsRun - failed - len(result.skipped)
    skipped = f", {len(result.skipped)} skipped" if result.skipped else ""
    print(f"{passed} passed, {failed} failed{skipped}", flush=True)
    sys.exit(1 if failed or result.testsRun == 0 else 0)
