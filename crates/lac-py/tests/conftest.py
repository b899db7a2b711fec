"""Shared helpers: the `lac` command line as the reference the bindings must equal.

The binary is $LAC_BIN (under `make py` the test-profile target/debug/lac that `cargo test`
builds); run by hand without it, target/debug/lac is tried and the comparisons are skipped
when it is missing.
"""

import json
import os
import subprocess

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))


def lac_bin() -> str:
    return os.environ.get("LAC_BIN", os.path.join(ROOT, "target", "debug", "lac"))


@pytest.fixture(scope="session")
def cli():
    """Run `lac ARGS...` and parse its one line of JSON (stdout, or the error on stderr)."""
    if not os.access(lac_bin(), os.X_OK):
        give_up = pytest.fail if "LAC_BIN" in os.environ else pytest.skip
        give_up(f"{lac_bin()} is not built: cargo test --workspace --no-run, or set LAC_BIN")

    def run(*args: str) -> dict:
        done = subprocess.run([lac_bin(), *args], capture_output=True, text=True, timeout=120)
        text = done.stdout if done.returncode == 0 else done.stderr
        return json.loads(text.strip().splitlines()[0])

    return run


def points_arg(points) -> str:
    """Points as the command line takes them, with every digit (repr round-trips)."""
    return " ".join(",".join(repr(float(c)) for c in p) for p in points)
