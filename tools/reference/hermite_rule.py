"""Exact coefficients of the two-point Hermite (Obreshkov) quadrature used in
crates/lac/src/segment/sampling.rs: integral over [0, h] of f = sum_k h^(k+1) (a_k f^(k)(0) + b_k f^(k)(h)),
exact for polynomials of degree 2m + 1 (m derivatives at each end).

Run: python3 tools/reference/hermite_rule.py 5
"""
import sys
from fractions import Fraction
from math import factorial


def rule(m):
    n = 2 * m + 2
    rows = []
    for j in range(n):  # exact for x^j on [0, 1]
        at0 = [Fraction(factorial(j)) if j == k else Fraction(0) for k in range(m + 1)]
        at1 = [Fraction(factorial(j), factorial(j - k)) if k <= j else Fraction(0) for k in range(m + 1)]
        rows.append(at0 + at1 + [Fraction(1, j + 1)])
    for c in range(n):  # Gauss-Jordan in exact arithmetic
        p = next(r for r in range(c, n) if rows[r][c] != 0)
        rows[c], rows[p] = rows[p], rows[c]
        rows[c] = [x / rows[c][c] for x in rows[c]]
        for r in range(n):
            if r != c and rows[r][c] != 0:
                f = rows[r][c]
                rows[r] = [x - f * y for x, y in zip(rows[r], rows[c])]
    sol = [rows[i][-1] for i in range(n)]
    return sol[: m + 1], sol[m + 1 :]


if __name__ == "__main__":
    m = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    a, b = rule(m)
    print("at 0:", ", ".join(map(str, a)))
    print("at h:", ", ".join(map(str, b)))
