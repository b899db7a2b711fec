//! The linear systems of the G2 joint equations: tridiagonal and cyclic tridiagonal, where
//! the curvature jump at a joint depends only on that joint's unknown and those of its two
//! neighbours, and dense (Gaussian elimination with partial pivoting) for a spline's point
//! conditions, whose unknowns and equations do not pair up one to one.

/// Solve `sub[i] x[i−1] + diag[i] x[i] + sup[i] x[i+1] = rhs[i]` for `i = 0..n`.
///
/// With `cyclic`, `sub[0]` couples row 0 to `x[n−1]` and `sup[n−1]` row `n − 1` to `x[0]`
/// (a closed polygon's joints form a ring); otherwise both are ignored. Returns `None` when
/// a pivot vanishes or the answer is not finite (the caller then takes a smaller step).
pub(crate) fn solve(
    sub: &[f64],
    diag: &[f64],
    sup: &[f64],
    rhs: &[f64],
    cyclic: bool,
) -> Option<Vec<f64>> {
    let n = diag.len();
    if n == 0 {
        return Some(Vec::new());
    }
    if n == 1 {
        let d = diag[0] + if cyclic { sub[0] + sup[0] } else { 0.0 };
        let x = rhs[0] / d;
        return x.is_finite().then(|| vec![x]);
    }
    if !cyclic || n == 2 {
        // n = 2 in a ring: both couplings land on the one other unknown.
        let (mut sub2, mut sup2) = (sub.to_vec(), sup.to_vec());
        if cyclic {
            sup2[0] += sub[0];
            sub2[1] += sup[1];
        }
        return thomas(&sub2, diag, &sup2, rhs);
    }
    // Sherman–Morrison: A = T + u vᵀ with u = (γ, 0, …, 0, c), v = (1, 0, …, 0, a/γ),
    // c = sup[n−1] (row n−1, column 0), a = sub[0] (row 0, column n−1).
    let (a, c) = (sub[0], sup[n - 1]);
    let gamma = -diag[0];
    let mut d = diag.to_vec();
    d[0] -= gamma;
    d[n - 1] -= a * c / gamma;
    let y = thomas(sub, &d, sup, rhs)?;
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = c;
    let z = thomas(sub, &d, sup, &u)?;
    let factor = (y[0] + a / gamma * y[n - 1]) / (1.0 + z[0] + a / gamma * z[n - 1]);
    let x: Vec<f64> = y.iter().zip(&z).map(|(y, z)| y - factor * z).collect();
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Solve the dense `n`×`n` system `a x = rhs` (`a` row by row) by Gaussian elimination with
/// partial pivoting; `None` when a pivot vanishes or the answer is not finite.
pub(crate) fn dense(mut a: Vec<f64>, mut rhs: Vec<f64>) -> Option<Vec<f64>> {
    let n = rhs.len();
    debug_assert_eq!(a.len(), n * n);
    for col in 0..n {
        let pivot =
            (col..n).max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))?;
        if a[pivot * n + col] == 0.0 {
            return None;
        }
        if pivot != col {
            for k in 0..n {
                a.swap(pivot * n + k, col * n + k);
            }
            rhs.swap(pivot, col);
        }
        let p = a[col * n + col];
        for row in col + 1..n {
            let f = a[row * n + col] / p;
            if f != 0.0 {
                for k in col..n {
                    a[row * n + k] -= f * a[col * n + k];
                }
                rhs[row] -= f * rhs[col];
            }
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let tail: f64 = (row + 1..n).map(|k| a[row * n + k] * x[k]).sum();
        x[row] = (rhs[row] - tail) / a[row * n + row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The Thomas algorithm (`sub[0]` and `sup[n−1]` ignored).
fn thomas(sub: &[f64], diag: &[f64], sup: &[f64], rhs: &[f64]) -> Option<Vec<f64>> {
    let n = diag.len();
    let mut c = vec![0.0; n];
    let mut d = vec![0.0; n];
    let mut pivot = diag[0];
    c[0] = sup[0] / pivot;
    d[0] = rhs[0] / pivot;
    for i in 1..n {
        pivot = diag[i] - sub[i] * c[i - 1];
        c[i] = if i + 1 < n { sup[i] / pivot } else { 0.0 };
        d[i] = (rhs[i] - sub[i] * d[i - 1]) / pivot;
    }
    for i in (0..n - 1).rev() {
        d[i] -= c[i] * d[i + 1];
    }
    d.iter().all(|v| v.is_finite()).then_some(d)
}

#[cfg(test)]
mod tests {
    use super::solve;

    /// The residual of the dense product, for a check independent of the elimination.
    fn residual(
        sub: &[f64],
        diag: &[f64],
        sup: &[f64],
        rhs: &[f64],
        x: &[f64],
        cyclic: bool,
    ) -> f64 {
        let n = diag.len();
        (0..n)
            .map(|i| {
                let mut r = diag[i] * x[i] - rhs[i];
                if i > 0 {
                    r += sub[i] * x[i - 1];
                } else if cyclic {
                    r += sub[0] * x[n - 1];
                }
                if i + 1 < n {
                    r += sup[i] * x[i + 1];
                } else if cyclic {
                    r += sup[n - 1] * x[0];
                }
                r.abs()
            })
            .fold(0.0, f64::max)
    }

    /// Dense elimination against the same tridiagonal systems, and a system that needs a
    /// row exchange (a zero on the diagonal).
    #[test]
    fn dense_systems_are_solved_to_rounding() {
        for n in 1..9 {
            let sub: Vec<f64> = (0..n).map(|i| 0.3 + 0.1 * i as f64).collect();
            let sup: Vec<f64> = (0..n).map(|i| -0.7 + 0.05 * i as f64).collect();
            let diag: Vec<f64> = (0..n).map(|i| 3.0 + (i % 3) as f64).collect();
            let rhs: Vec<f64> = (0..n).map(|i| (i as f64).sin() + 1.0).collect();
            let mut a = vec![0.0; n * n];
            for i in 0..n {
                a[i * n + i] = diag[i];
                a[i * n + (i + n - 1) % n] += sub[i];
                a[i * n + (i + 1) % n] += sup[i];
            }
            if n == 1 {
                a[0] = diag[0] + sub[0] + sup[0];
            }
            let x = super::dense(a, rhs.clone()).unwrap();
            assert!(residual(&sub, &diag, &sup, &rhs, &x, true) < 1e-14, "n {n}");
        }
        let x = super::dense(vec![0.0, 2.0, 3.0, 1.0], vec![4.0, 5.0]).unwrap();
        assert!(
            (x[0] - 1.0).abs() < 1e-15 && (x[1] - 2.0).abs() < 1e-15,
            "{x:?}"
        );
    }

    #[test]
    fn open_and_cyclic_systems_are_solved_to_rounding() {
        for n in 1..9 {
            let sub: Vec<f64> = (0..n).map(|i| 0.3 + 0.1 * i as f64).collect();
            let sup: Vec<f64> = (0..n).map(|i| -0.7 + 0.05 * i as f64).collect();
            let diag: Vec<f64> = (0..n).map(|i| 3.0 + (i % 3) as f64).collect();
            let rhs: Vec<f64> = (0..n).map(|i| (i as f64).sin() + 1.0).collect();
            for cyclic in [false, true] {
                let x = solve(&sub, &diag, &sup, &rhs, cyclic).unwrap();
                assert!(
                    residual(&sub, &diag, &sup, &rhs, &x, cyclic) < 1e-14,
                    "n {n} {cyclic}"
                );
            }
        }
    }
}
