//! DXF (AutoCAD R2000, `AC1015`): each curve a SPLINE entity with weights.
//!
//! The file has a HEADER (version, handle seed, millimetres as the insertion units) and an
//! ENTITIES section; readers build the tables and layouts a drawing of only entities needs
//! (ezdxf's `audit()` finds nothing to fix). A SPLINE (group codes of the DXF reference):
//! flags 70 = 8 (planar) + 4 (rational), degree 71 = 3, knot count 72, control point count
//! 73, fit points 74 = 0, knot and control-point tolerances 42/43, the knots (40), then each
//! control point (10/20/30) followed by its weight (41).

use super::number::real;
use super::nurbs::Nurbs;

/// The DXF document of `curves` (one SPLINE each).
pub fn write(curves: &[Nurbs]) -> String {
    let mut out = String::new();
    let mut pair = |code: u32, value: &str| {
        out.push_str(&format!("{code:>3}\n{value}\n"));
    };
    pair(0, "SECTION");
    pair(2, "HEADER");
    pair(9, "$ACADVER");
    pair(1, "AC1015");
    pair(9, "$HANDSEED");
    pair(5, &format!("{:X}", 0x100 + curves.len() + 1));
    pair(9, "$INSUNITS");
    pair(70, "4");
    pair(9, "$MEASUREMENT");
    pair(70, "1");
    pair(0, "ENDSEC");
    pair(0, "SECTION");
    pair(2, "ENTITIES");
    for (i, curve) in curves.iter().enumerate() {
        pair(0, "SPLINE");
        pair(5, &format!("{:X}", 0x100 + i));
        pair(100, "AcDbEntity");
        pair(8, "0");
        pair(100, "AcDbSpline");
        if curve.planar {
            pair(210, "0.0");
            pair(220, "0.0");
            pair(230, "1.0");
        }
        let flags = 4 + if curve.planar { 8 } else { 0 };
        pair(70, &flags.to_string());
        pair(71, "3");
        pair(72, &curve.knots.len().to_string());
        pair(73, &curve.control_points.len().to_string());
        pair(74, "0");
        pair(42, "1.0E-10");
        pair(43, "1.0E-10");
        for &k in &curve.knots {
            pair(40, &real(k));
        }
        for (p, &w) in curve.control_points.iter().zip(&curve.weights) {
            pair(10, &real(p[0]));
            pair(20, &real(p[1]));
            pair(30, &real(p[2]));
            pair(41, &real(w));
        }
    }
    pair(0, "ENDSEC");
    pair(0, "EOF");
    out
}
