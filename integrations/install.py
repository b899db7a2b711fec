"""Install lac's integrations for the current user (root: for root; `make integrations`
runs this): the lac wheel where Debian's /usr/bin/python3 finds it (and so FreeCAD and
Inkscape, which run it), the FreeCAD workbench into FreeCAD's Mod folder and the Inkscape
extensions into Inkscape's extensions folder.

    /usr/bin/python3 integrations/install.py --wheel target/wheels/lac-….whl --pip .venv/bin/pip
"""

from __future__ import annotations

import argparse
import os
import shutil
import site
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
#: The workbench's folder name under Mod (not "lac": Mod's folders are on sys.path, and
#: the package `lac` must stay the bindings).
WORKBENCH = "LogAesthetic"


def site_packages() -> Path:
    """Where /usr/bin/python3 imports from: the system's local site for root, the user's
    site otherwise."""
    if os.geteuid() == 0:
        return Path(site.getsitepackages()[0])
    return Path(site.getusersitepackages())


def freecad_mod() -> Path:
    """FreeCAD's user Mod folder, as FreeCAD itself names it."""
    out = subprocess.run(
        ["freecadcmd", "-c", "import FreeCAD; print('USERDIR=' + FreeCAD.getUserAppDataDir())"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    line = next(x for x in out.splitlines() if x.startswith("USERDIR="))
    return Path(line.removeprefix("USERDIR=")) / "Mod"


def inkscape_extensions() -> Path:
    """Inkscape's user extensions folder."""
    out = subprocess.run(
        ["inkscape", "--user-data-directory"], capture_output=True, text=True, check=True
    )
    return Path(out.stdout.strip()) / "extensions"


def copy_tree(source: Path, target: Path) -> None:
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(source, target, ignore=shutil.ignore_patterns("tests", "__pycache__"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--wheel", type=Path, help="the lac wheel to install")
    parser.add_argument("--pip", default="pip", help="a pip to install it with")
    args = parser.parse_args()
    if args.wheel:
        target = site_packages()
        subprocess.run(
            [
                args.pip,
                "install",
                "--quiet",
                "--disable-pip-version-check",
                "--no-deps",
                "--upgrade",
                "--target",
                str(target),
                str(args.wheel),
            ],
            check=True,
        )
        print(f"lac bindings: {target}")
    mod = freecad_mod() / WORKBENCH
    copy_tree(HERE / "freecad", mod)
    print(f"FreeCAD workbench: {mod}")
    extensions = inkscape_extensions()
    extensions.mkdir(parents=True, exist_ok=True)
    for f in sorted((HERE / "inkscape").iterdir()):
        if f.suffix in (".py", ".inx"):
            shutil.copy2(f, extensions / f.name)
    print(f"Inkscape extensions: {extensions}")
    if sys.executable != "/usr/bin/python3":
        print("note: run with /usr/bin/python3 to install for Debian's FreeCAD and Inkscape")


if __name__ == "__main__":
    main()
