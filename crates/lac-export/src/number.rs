//! Numbers as the CAD formats read them, with the shortest digits that read back to the
//! same `f64` (Rust's float formatting is shortest round-trip).

/// A real with a decimal point always, and an exponent, where one is needed, as `E` with a
/// mantissa that has a point: `1.0`, `0.25`, `1.5E-7`, `1.E300`. STEP (ISO 10303-21 §6.3.2)
/// requires the point; IGES (5.3 §2.2.2.3) requires it too and takes `E`; DXF's readers
/// parse it as C's `strtod` does.
pub(crate) fn real(x: f64) -> String {
    let plain = format!("{x:?}");
    let Some((mantissa, exponent)) = plain.split_once('e') else {
        return plain;
    };
    let mantissa = if mantissa.contains('.') {
        mantissa.to_string()
    } else {
        format!("{mantissa}.")
    };
    format!("{mantissa}E{exponent}")
}

#[cfg(test)]
mod tests {
    use super::real;

    #[test]
    fn reals_have_a_point_and_read_back_exactly() {
        for x in [
            0.0,
            -0.0,
            1.0,
            0.1,
            -2.5,
            1e-7,
            1.5e-7,
            1e300,
            -1.2345678901234567e-300,
            5e-324,
            f64::MAX,
            123456789012345680.0,
            std::f64::consts::PI,
        ] {
            let s = real(x);
            assert!(s.contains('.'), "{s}");
            assert!(!s.contains('e'), "{s}");
            let back: f64 = s.replace('E', "e").parse().unwrap();
            assert_eq!(back.to_bits(), x.to_bits(), "{x} → {s}");
        }
        assert_eq!(real(1e-7), "1.E-7");
        assert_eq!(real(1.5), "1.5");
    }
}
