"""The package: every public name documented, one abi3 extension, the examples run and
write their PNGs, and the stubs name what the module has."""

import inspect
import os
import subprocess
import sys

import pytest

import lac
import lac._lac

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "examples")


def public_members(cls: type) -> list:
    return [name for name in vars(cls) if not name.startswith("_")]


def test_every_public_name_has_a_docstring():
    missing = []
    for name in lac.__all__:
        obj = getattr(lac, name)
        if isinstance(obj, float):
            continue
        if not (obj.__doc__ or "").strip():
            missing.append(name)
        if inspect.isclass(obj):
            for member in public_members(obj):
                if not (getattr(obj, member).__doc__ or "").strip():
                    missing.append(f"{name}.{member}")
    assert missing == []


def test_stubs_cover_the_module():
    stub = open(os.path.join(os.path.dirname(lac.__file__), "_lac.pyi")).read()
    for name in lac.__all__:
        assert f" {name}" in stub or f"{name}:" in stub, name
        obj = getattr(lac, name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for member in public_members(obj):
                assert f" {member}" in stub, f"{name}.{member}"


def test_one_abi3_extension():
    assert lac._lac.__file__.endswith(".abi3.so")
    assert sorted(set(lac.__all__)) == sorted(lac.__all__)


@pytest.mark.parametrize("example", ["fig5_family", "drawable_region", "curvature_comb"])
def test_example_writes_its_png(tmp_path, example):
    script = os.path.join(EXAMPLES, f"{example}.py")
    done = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    png = tmp_path / f"{example}.png"
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(data) > 20_000  # a drawing, not an empty canvas


def test_the_readme_example_runs():
    readme = open(os.path.join(HERE, "..", "..", "..", "README.md")).read()
    section = readme[readme.index("## Python"):]
    start = section.index("```python\n") + len("```python\n")
    code = section[start:section.index("```", start)]
    assert len(code.strip().splitlines()) == 5
    namespace: dict = {}
    exec(compile(code, "README.md", "exec"), namespace)
    batch = namespace["batch"]
    assert len(batch) == 1000 and not batch.ok.all()  # random points: some fail, no raise
    assert namespace["s"].points.shape == (65, 2)
