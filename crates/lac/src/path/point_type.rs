//! What a spline asks of each of its points beyond passing through it: the point types of
//! [`Spline::from_points_with`](super::Spline::from_points_with), after Spiro's (smooth,
//! corner, left and right line–curve points), with a given tangent and G2 Hermite ends.

/// The type of a point of a spline (docs/math.md, splines with point types).
///
/// | type | tangent | curvature |
/// |---|---|---|
/// | `Smooth` | continuous, solved | continuous |
/// | `Tangent(θ)` | continuous, θ | continuous |
/// | `Corner { before, after }` | may break: each side given or, `None`, the circle's through the point and its next two points on that side | each side its own |
///
/// An open spline's first and last points have one side only: there `Tangent(θ)` gives the
/// end's direction and `Smooth`/`Corner` leave it to [`SplineEnd::angle`] (default: the
/// circle through the end and its next two points).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum PointType {
    /// G2, its tangent direction solved (the points of [`Spline::from_points`](super::Spline::from_points)).
    #[default]
    Smooth,
    /// G2 with the given tangent direction, radians (e.g. 0 or π/2 at an extremum).
    Tangent(f64),
    /// The curve passes through and its tangent may break: each side ends there like an
    /// open spline, its direction given (radians) or free.
    Corner {
        /// The direction in which the curve arrives, or free.
        before: Option<f64>,
        /// The direction in which it leaves, or free.
        after: Option<f64>,
    },
}

impl PointType {
    /// A corner whose two sides are both free.
    pub const CORNER: PointType = PointType::Corner {
        before: None,
        after: None,
    };

    /// Its name, as `lac spline --types` spells it: `smooth`, `tangent` or `corner`.
    pub fn name(&self) -> &'static str {
        match self {
            PointType::Smooth => "smooth",
            PointType::Tangent(_) => "tangent",
            PointType::Corner { .. } => "corner",
        }
    }
}

/// What is given at an open spline's first or last point: its tangent direction (radians;
/// default the circle's through the end and its next two points) and its curvature (signed,
/// positive turning left; default free). Both given make a G2 Hermite end, which blends the
/// spline into a neighbouring curve with continuous curvature.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SplineEnd {
    /// The tangent direction, radians.
    pub angle: Option<f64>,
    /// The signed curvature, 1/length.
    pub curvature: Option<f64>,
}

/// Point types, straight spans and end conditions of a spline; the default is
/// [`Spline::from_points`](super::Spline::from_points)' spline (every point smooth, no
/// straight span, the ends' tangents from circles).
///
/// ```
/// use kurbo::Point;
/// use lac::{Closure, PointType, Spline, SplineOptions};
///
/// // A D-shaped outline: a straight stem from P0 to P1, the bowl through P2 horizontal.
/// let points = [
///     Point::new(0.0, 0.0), Point::new(0.0, 4.0), Point::new(2.0, 3.6),
///     Point::new(3.0, 2.0), Point::new(2.0, 0.4),
/// ];
/// let options = SplineOptions {
///     types: vec![PointType::Smooth, PointType::Smooth, PointType::Smooth,
///                 PointType::Tangent(-std::f64::consts::FRAC_PI_2), PointType::Smooth],
///     lines: vec![0],
///     ..SplineOptions::default()
/// };
/// let spline = Spline::from_points_with(&points, -1.0, Closure::Closed, &options)?;
/// let stem = &spline.point_reports()[1];
/// assert!(stem.curvatures[1].unwrap().abs() <= 1e-12 * spline.max_abs_curvature());
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SplineOptions {
    /// The type of each point, in order (empty: every point smooth).
    pub types: Vec<PointType>,
    /// The straight spans: `i` makes the span from point `i` to point `i + 1` (the last to
    /// the first when closed) a straight line, which the curve on either side meets with
    /// zero curvature (needs α < 0) unless the point there is a corner.
    pub lines: Vec<usize>,
    /// An open spline's first point.
    pub start: SplineEnd,
    /// An open spline's last point.
    pub end: SplineEnd,
}

impl SplineOptions {
    /// The options of [`Spline::from_points`](super::Spline::from_points): every point
    /// smooth, an open spline's end directions `ends` (radians) or the circles'.
    pub fn with_ends(ends: Option<[f64; 2]>) -> SplineOptions {
        SplineOptions {
            start: SplineEnd {
                angle: ends.map(|e| e[0]),
                curvature: None,
            },
            end: SplineEnd {
                angle: ends.map(|e| e[1]),
                curvature: None,
            },
            ..SplineOptions::default()
        }
    }

    /// Whether it asks for nothing beyond a smooth spline with given end directions.
    pub fn is_smooth(&self) -> bool {
        self.types.iter().all(|t| *t == PointType::Smooth)
            && self.lines.is_empty()
            && self.start.curvature.is_none()
            && self.end.curvature.is_none()
    }
}
