"""Print the Gauss-Legendre table used by crates/lac/src/foundation/gauss.rs (nodes on [-1, 1]).

Run: python3 tools/reference/gauss_table.py 16
Only the non-negative half is printed; the rule is symmetric.
"""
import sys

import mpmath as mp

mp.mp.dps = 40
n = int(sys.argv[1]) if len(sys.argv) > 1 else 16
pairs = []
for k in range(1, n // 2 + 1):
    # Newton on P_n from the Tricomi initial guess.
    x = mp.cos(mp.pi * (k - mp.mpf(1) / 4) / (n + mp.mpf(1) / 2))
    for _ in range(100):
        p, dp = mp.legendre(n, x), mp.diff(lambda t: mp.legendre(n, t), x)
        dx = p / dp
        x -= dx
        if abs(dx) < mp.mpf(10) ** -38:
            break
    dp = mp.diff(lambda t: mp.legendre(n, t), x)
    w = 2 / ((1 - x * x) * dp * dp)
    pairs.append((x, w))
for x, w in sorted(pairs):
    print(f"    ({mp.nstr(x, 20, min_fixed=-1, max_fixed=1)}, {mp.nstr(w, 20, min_fixed=-1, max_fixed=1)}),")
