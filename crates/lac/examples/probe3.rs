//! probe3 (not committed)
use kurbo::Point;
use lac::CompoundCurve;
fn main() {
    let p = [
        Point::new(18.355573376593092, -4.1034245222609025),
        Point::new(18.31898748730786, -4.16866570720479),
        Point::new(18.366831693312832, -4.2261799660070105),
    ];
    let c = CompoundCurve::from_three_points(p, 0.5, -1.0, 0.4223044074130602).unwrap();
    println!(
        "lambda {:.17e} L {:.17e} joint {:.17e} k0 {:.17e} kj {:.17e} k1 {:.17e}",
        c.lambda(),
        c.arc_length(),
        c.joint_s(),
        c.curvature_start(),
        c.curvature_joint(),
        c.curvature_end()
    );
}
