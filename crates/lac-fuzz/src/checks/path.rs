//! `path`: [`lac::Path::g1`] and [`lac::Path::g2`] from a control polygon. Invariants: each
//! segment on its control triangle (ends, end tangents, monotone curvature, chords between
//! the tangents); consecutive segments (and the last and first of a closed path) meeting
//! with continuous position and tangent, and curvature too in G2; the whole finite.

use kurbo::Point;
use lac::{Curve, Path};

use super::{bounds, build, finite, largest_end_curvature, meet, on_triangles, rounding, Built};
use crate::Input;

/// The checks of a `path` input.
pub(super) fn check(input: &Input, closed: bool, g2: bool) -> Result<bool, String> {
    let Some(Built::Path(path)) = build(input)? else {
        return Ok(false);
    };
    check_path(&path, closed, g2)?;
    Ok(true)
}

/// A path: each segment on its control triangle (ends, end tangents, monotone curvature,
/// chords between tangents); consecutive segments (and the last and first of a closed path)
/// meet with continuous position and tangent, and curvature too in G2; the whole is finite.
fn check_path(path: &Path, closed: bool, g2: bool) -> Result<(), String> {
    let pieces = path.segments();
    let triangles = path.control_triangles();
    if pieces.len() != triangles.len() || pieces.is_empty() {
        return Err(format!(
            "{} segments for {} control triangles",
            pieces.len(),
            triangles.len()
        ));
    }
    finite("arc length", &[path.arc_length()])?;
    on_triangles(pieces, &triangles)?;
    let all: Vec<Point> = triangles.iter().flatten().copied().collect();
    let size = path.arc_length();
    let tol = bounds::POSITION * size + rounding(&all);
    // The whole path sampled: finite everywhere.
    for q in path
        .sample_by_arc_length(65)
        .map_err(|e| format!("sampling a solved path failed: {e}"))?
    {
        finite(
            "path sample",
            &[q.s, q.point.x, q.point.y, q.theta, q.kappa],
        )?;
    }
    // Segments meet one another directly only where no straight piece (an inflection leg)
    // lies between them; those joints are the path's own check (its joints list).
    if !path.straight_pieces().is_empty() {
        return Ok(());
    }
    let pairs = pieces.len() - usize::from(!closed);
    let kmax = largest_end_curvature(pieces);
    for i in 0..pairs {
        let (a, b) = (&pieces[i], &pieces[(i + 1) % pieces.len()]);
        meet(a, b, i, tol, size)?;
        let (ka, kb) = (a.signed_curvature_end(), b.signed_curvature_start());
        if g2 && (ka - kb).abs() > bounds::JOINT_CURVATURE * kmax {
            return Err(format!(
                "curvature jumps after segment {i}: {ka:e} to {kb:e}"
            ));
        }
    }
    Ok(())
}
