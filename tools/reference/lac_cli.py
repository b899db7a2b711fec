"""Running the `lac` binary from the pytest cross-checks.

The binary is $LAC_BIN (default target/release/lac). Under `make test` LAC_BIN is set, and a
binary or subcommand that cannot run is a failure; run by hand without it, the command-line
tests are skipped with the reason instead.
"""

import os
import subprocess

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def lac_bin():
    return os.path.join(ROOT, os.environ.get("LAC_BIN", os.path.join("target", "release", "lac")))


def require(sub):
    """Skip (or, with LAC_BIN set, fail) unless `lac SUB --help` runs."""
    give_up = pytest.fail if "LAC_BIN" in os.environ else pytest.skip
    try:
        run = subprocess.run([lac_bin(), sub, "--help"], capture_output=True, text=True,
                             timeout=60)
    except OSError as e:
        give_up(f"`{lac_bin()} {sub} --help` cannot run ({e}): build it with "
                "`cargo build --release -p lac-cli` or set LAC_BIN")
    if run.returncode != 0:
        give_up(f"`{lac_bin()} {sub} --help` failed (exit {run.returncode})")
