//! `space`: [`lac::SpaceSegment::from_control_points`], and the cubic pieces `lac export`
//! writes of it. Invariants: finite Frenet frames, orthonormal and right-handed; the curve
//! starting at P0 along the first leg and ending at P3 along the last; its cubic pieces (at
//! a relative tolerance of 1e-4) a typed error or finite, on the segment's ends, sharing
//! their joins and within the tolerance at the middle of every piece.

use lac::SpaceCurve;
use lac::{SpaceSegment, Tolerance, Vec3};

use super::{bounds, build, finite, Built};
use crate::Input;

/// The checks of a `space` input.
pub(super) fn check(input: &Input, points: &[[f64; 3]; 4]) -> Result<bool, String> {
    let pts = points.map(Vec3::from_array);
    let Some(Built::Space(seg)) = build(input)? else {
        return Ok(false);
    };
    check_space(&seg, &pts)?;
    check_space_cubics(&seg)?;
    Ok(true)
}

/// A space segment: finite frames, orthonormal and right-handed; starts at P0 along the
/// first leg, ends at P3 along the last.
fn check_space(seg: &SpaceSegment, pts: &[Vec3; 4]) -> Result<(), String> {
    let len = seg.arc_length();
    let frames = seg.sample_by_arc_length(33).map_err(|e| e.to_string())?;
    let chord = (pts[3] - pts[0]).length();
    let magnitude = pts
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()).max(p.z.abs()))
        .fold(0.0, f64::max);
    let tol = bounds::POSITION * chord + 64.0 * f64::EPSILON * magnitude;
    finite("arc length", &[len])?;
    for f in &frames {
        let v = [f.point, f.tangent, f.normal, f.binormal];
        finite(
            "frame",
            &v.iter()
                .flat_map(|p| [p.x, p.y, p.z])
                .chain([f.s, f.curvature, f.torsion])
                .collect::<Vec<_>>(),
        )?;
        let orth = [
            (f.tangent.length() - 1.0).abs(),
            (f.normal.length() - 1.0).abs(),
            f.tangent.dot(f.normal).abs(),
            (f.tangent.cross(f.normal) - f.binormal).length(),
        ];
        if orth.iter().any(|e| *e > 1e-9) {
            return Err(format!("frame not orthonormal at s = {}", f.s));
        }
        if f.curvature < 0.0 {
            return Err("negative curvature".to_string());
        }
    }
    let (a, b) = (frames[0], frames[frames.len() - 1]);
    if (a.point - pts[0]).length() > tol || (b.point - pts[3]).length() > 64.0 * tol {
        return Err(format!(
            "space segment ends off: {:e}, {:e} (chord {chord:e})",
            (a.point - pts[0]).length(),
            (b.point - pts[3]).length()
        ));
    }
    let t0 = (pts[1] - pts[0]).normalize();
    let t1 = (pts[3] - pts[2]).normalize();
    let allowed = bounds::TANGENT + 1e3 * tol / chord;
    let off0 = a.tangent.angle_to(t0);
    let off1 = b.tangent.angle_to(t1);
    if off0 > allowed || off1 > allowed {
        return Err(format!("space end tangents off by {off0:e}, {off1:e} rad"));
    }
    Ok(())
}

/// The cubic pieces of a solved space segment (`SpaceSegment::to_cubics`, what `lac export`
/// writes) at a relative tolerance of 1e-4: a typed error, or pieces with finite points, the
/// segment's ends, shared joins and a deviation within the tolerance, re-measured here at
/// the middle of every piece against the segment's own point there.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must fail the checks
fn check_space_cubics(seg: &SpaceSegment) -> Result<(), String> {
    let Ok(chain) = seg.to_cubics(Tolerance::Relative(1e-4)) else {
        return Ok(());
    };
    let len = seg.arc_length();
    let tol = 1e-4 * len;
    let pieces = &chain.pieces;
    if pieces.is_empty() || pieces.len() > lac::MAX_PIECES {
        return Err(format!("space cubics: {} pieces", pieces.len()));
    }
    let coords: Vec<f64> = pieces
        .iter()
        .flat_map(|p| p.points.iter().flat_map(|q| q.to_array()))
        .collect();
    finite("space cubics", &coords)?;
    if !(chain.max_deviation <= tol) {
        return Err(format!(
            "space cubics: deviation {:e} over the tolerance {tol:e}",
            chain.max_deviation
        ));
    }
    for w in pieces.windows(2) {
        if w[0].points[3] != w[1].points[0] || w[0].s.1 != w[1].s.0 {
            return Err("space cubics: pieces that do not share their join".into());
        }
    }
    // u = 0.3 is between the fit's 48 steps: the pair there is not one it measured, and the
    // fit's margin (accepted below 0.98 of the tolerance) must cover it.
    let at: Vec<f64> = pieces
        .iter()
        .map(|p| p.s.0 + 0.3 * (p.s.1 - p.s.0))
        .collect();
    let frames = seg.frames(&at).map_err(|e| e.to_string())?;
    for (p, f) in pieces.iter().zip(&frames) {
        let d = p.eval(0.3).distance(f.point);
        if !(d <= tol) {
            return Err(format!(
                "space cubics: {d:e} from the curve at a piece's middle"
            ));
        }
    }
    Ok(())
}
