#!/usr/bin/env python3
"""Rotate the Prius lines (ps_1.txt … ps_5.txt, x y z in mm) into the x-y plane and write
them as "x y" lines (ps_N.xy) to the folder given, as the data's authors do before fitting."""

import math
import pathlib
import sys

# The normal of the lines' plane, measured by the data's authors.
N = (-0.99856279183126328558018, -0.05357678971846480814323, 0.00137053771081513875094)


def rotate(p):
    """Turn about z by minus the normal's polar angle, then about y by minus its azimuth."""
    nxy = math.hypot(N[0], N[1])
    nxyz = math.hypot(nxy, N[2])
    cp, sp = N[0] / nxy, N[1] / nxy
    ca, sa = N[2] / nxyz, nxy / nxyz
    x, y, z = p
    x, y = cp * x + sp * y, -sp * x + cp * y
    x, z = ca * x - sa * z, sa * x + ca * z
    return x, y, z


def main():
    here = pathlib.Path(__file__).resolve().parent
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    out.mkdir(parents=True, exist_ok=True)
    assert all(abs(a - b) < 1e-12 for a, b in zip(rotate(N), (0.0, 0.0, 1.0)))
    for k in range(1, 6):
        rows = []
        for line in (here / f"ps_{k}.txt").read_text().splitlines():
            if line.strip():
                x, y, _ = rotate(tuple(float(v) for v in line.split()[:3]))
                rows.append(f"{x!r} {y!r}")
        (out / f"ps_{k}.xy").write_text("\n".join(rows) + "\n")
        print(f"{out / f'ps_{k}.xy'}: {len(rows)} points")


if __name__ == "__main__":
    main()
