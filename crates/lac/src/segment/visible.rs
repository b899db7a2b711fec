//! What no sample shows: a solver's check that a chain of segments does not hide its turning
//! within a trillionth of its length of an end.

use crate::foundation::error::{Error, NotDrawable, Result};
use crate::segment::Segment;

/// The share of a curve's arc length next to each end in which it may not turn by more
/// than [`HIDDEN_TURNING`]: a feature below a trillionth of the curve's size is resolved by
/// its own coordinates (16 digits) to 4 digits or fewer, so no sample, polyline or export
/// shows it.
pub const HIDDEN_SHARE: f64 = 1e-12;

/// The largest turning (radians) allowed within [`HIDDEN_SHARE`] of an end. A cusp end
/// (α > 1, ρ → 0 with a definite tangent) turns by O(share^((α−1)/α)) there, well below it
/// for α ≥ 1.2; a hook (all the turning at a radius far below the curve's size, as when a
/// flat triangle meets α near 1) turns by tens of degrees.
pub const HIDDEN_TURNING: f64 = 1e-2;

/// A solver's check that no turning hides at an end of the chain: the turning within
/// [`HIDDEN_SHARE`] of the arc length from the first and from the last point.
pub(crate) fn check_visible_ends(pieces: &[Segment]) -> Result<()> {
    let len: f64 = pieces.iter().map(Segment::length).sum();
    let near = HIDDEN_SHARE * len;
    // Curvature is monotone along each piece, so no stretch of the chain is more curved
    // than its most curved piece end: the turning within `near` of an end is at most that
    // curvature times `near`. Far below the limit (all but extreme curvature ratios) there
    // is nothing to measure.
    let most_curved = pieces.iter().fold(0.0f64, |m, p| {
        let (k0, k1) = p.end_curvatures();
        m.max(k0.abs()).max(k1.abs())
    });
    if most_curved * near <= 0.5 * HIDDEN_TURNING {
        return Ok(());
    }
    let (first, last) = (&pieces[0], &pieces[pieces.len() - 1]);
    let at_start = {
        let s = near.min(first.length());
        (first.theta_of(&first.station_at_s(s)?) - first.theta_of(&first.station_at_s(0.0)?)).abs()
    };
    let at_end = {
        let l = last.length();
        let s = (l - near).max(0.0);
        (last.theta_of(&last.station_at_s(l)?) - last.theta_of(&last.station_at_s(s)?)).abs()
    };
    for (turning, at_first) in [(at_start, true), (at_end, false)] {
        if turning > HIDDEN_TURNING {
            let (k0, k1) = (first.end_curvatures().0, last.end_curvatures().1);
            return Err(Error::NotDrawable(NotDrawable::HiddenTurn {
                at_first,
                turning,
                curvature_ratio: if at_first { k0 / k1 } else { k1 / k0 }.abs(),
            }));
        }
    }
    Ok(())
}
