//! SVG: plain cubic Bézier pieces (no weights: for tools without rational curves) in model
//! units, y up as in CAD: the path data holds the model coordinates unchanged, inside a
//! group that flips y, with a viewBox around the curve and its margin.

use kurbo::{BezPath, Shape};

use super::number::real;

/// The SVG document of the path (model coordinates), stroked `stroke` wide.
pub fn write(path: &BezPath) -> String {
    let b = path.bounding_box();
    let size = b.width().max(b.height()).max(f64::MIN_POSITIVE);
    let margin = 0.05 * size;
    let (x0, y0) = (b.x0 - margin, -(b.y1 + margin));
    let (w, h) = (b.width() + 2.0 * margin, b.height() + 2.0 * margin);
    let stroke = 0.004 * size;
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\">\n\
         <g transform=\"scale(1,-1)\">\n\
         <path id=\"lac-curve\" fill=\"none\" stroke=\"black\" stroke-width=\"{}\" d=\"{}\"/>\n\
         </g>\n</svg>\n",
        real(x0),
        real(y0),
        real(w),
        real(h),
        real(stroke),
        path_data(path)
    )
}

/// Path data with shortest round-trip numbers (SVG numbers take `E` exponents).
fn path_data(path: &BezPath) -> String {
    use kurbo::PathEl;
    let p = |q: kurbo::Point| format!("{},{}", real(q.x), real(q.y));
    path.elements()
        .iter()
        .map(|el| match el {
            PathEl::MoveTo(a) => format!("M{}", p(*a)),
            PathEl::LineTo(a) => format!("L{}", p(*a)),
            PathEl::QuadTo(a, b) => format!("Q{} {}", p(*a), p(*b)),
            PathEl::CurveTo(a, b, c) => format!("C{} {} {}", p(*a), p(*b), p(*c)),
            PathEl::ClosePath => "Z".to_string(),
        })
        .collect::<Vec<_>>()
        .join(" ")
}
