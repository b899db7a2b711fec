//! The 2-, 4-, 8- and 16-point Gauss–Legendre rules on [−1, 1].
//!
//! Generated at 40 digits by `tools/reference/gauss_table.py N`; only the non-negative
//! half of each symmetric rule is stored, as `(node, weight)`.

/// Half of the 2-point Gauss–Legendre rule: `(x_i, w_i)` with `x_i > 0`.
pub(crate) const GAUSS_2: [(f64, f64); 1] = [(5.773_502_691_896_257e-1, 1.0)];

/// Half of the 4-point Gauss–Legendre rule: `(x_i, w_i)` with `x_i > 0`.
pub(crate) const GAUSS_4: [(f64, f64); 2] = [
    (3.399_810_435_848_562_6e-1, 6.521_451_548_625_461e-1),
    (8.611_363_115_940_526e-1, 3.478_548_451_374_538_6e-1),
];

/// Half of the 8-point Gauss–Legendre rule: `(x_i, w_i)` with `x_i > 0`.
pub(crate) const GAUSS_8: [(f64, f64); 4] = [
    (1.834_346_424_956_498e-1, 3.626_837_833_783_62e-1),
    (5.255_324_099_163_29e-1, 3.137_066_458_778_873e-1),
    (7.966_664_774_136_267e-1, 2.223_810_344_533_744_7e-1),
    (9.602_898_564_975_363e-1, 1.012_285_362_903_762_6e-1),
];

/// Half of the 16-point Gauss–Legendre rule: `(x_i, w_i)` with `x_i > 0`.
pub(crate) const GAUSS_16: [(f64, f64); 8] = [
    (9.501_250_983_763_744e-2, 1.894_506_104_550_685e-1),
    (2.816_035_507_792_589e-1, 1.826_034_150_449_236e-1),
    (4.580_167_776_572_274e-1, 1.691_565_193_950_025_4e-1),
    (6.178_762_444_026_437e-1, 1.495_959_888_165_767_3e-1),
    (7.554_044_083_550_03e-1, 1.246_289_712_555_338_7e-1),
    (8.656_312_023_878_317e-1, 9.515_851_168_249_278e-2),
    (9.445_750_230_732_326e-1, 6.225_352_393_864_789e-2),
    (9.894_009_349_916_499e-1, 2.715_245_941_175_409_5e-2),
];

#[cfg(test)]
mod tests {
    use super::{GAUSS_16, GAUSS_4, GAUSS_8};

    /// A half rule (each node and its mirror image) over [−1, 1]: its weights sum to 2 and it
    /// integrates x^`even` exactly (2/(even + 1)), as an n-point rule does up to degree 2n − 1.
    fn assert_exact(rule: &[(f64, f64)], even: i32) {
        let w: f64 = rule.iter().map(|&(_, w)| 2.0 * w).sum();
        assert!((w - 2.0).abs() < 1e-15, "weights sum to {w}");
        let i: f64 = rule.iter().map(|&(x, w)| 2.0 * w * x.powi(even)).sum();
        let exact = 2.0 / f64::from(even + 1);
        assert!((i - exact).abs() < 1e-15, "x^{even}: {i} against {exact}");
    }

    #[test]
    fn the_4_point_rule_integrates_x6_exactly() {
        assert_exact(&GAUSS_4, 6);
    }

    #[test]
    fn the_8_point_rule_integrates_x14_exactly() {
        assert_exact(&GAUSS_8, 14);
    }

    #[test]
    fn weights_sum_to_two_and_integrate_x30_exactly() {
        assert_exact(&GAUSS_16, 30);
    }
}
