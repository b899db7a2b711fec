//! STEP (ISO 10303-21, application protocol 214, automotive design): each curve a bounded
//! rational B-spline, the complex entity (BOUNDED_CURVE() B_SPLINE_CURVE(…)
//! B_SPLINE_CURVE_WITH_KNOTS(…) CURVE() GEOMETRIC_REPRESENTATION_ITEM()
//! RATIONAL_B_SPLINE_CURVE(…) REPRESENTATION_ITEM('')), its partial entities in alphabetical
//! order as Part 21 requires; the curves in a GEOMETRIC_CURVE_SET of a
//! GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION, the shape of a PRODUCT, in
//! millimetres, which a kernel transfers as edges.

use std::fmt::Write;

use super::number::real;
use super::nurbs::Nurbs;
use super::Meta;

/// A STEP string literal: apostrophes doubled, only printable ASCII kept.
fn string(text: &str) -> String {
    let kept: String = text
        .chars()
        .filter(|c| c.is_ascii() && !c.is_ascii_control() && *c != '\\')
        .collect();
    format!("'{}'", kept.replace('\'', "''"))
}

fn list<T>(items: &[T], f: impl Fn(&T) -> String) -> String {
    format!("({})", items.iter().map(f).collect::<Vec<_>>().join(","))
}

/// The STEP document of `curves`; `uncertainty` is the length accuracy declared (mm).
pub fn write(curves: &[Nurbs], meta: &Meta, uncertainty: f64) -> String {
    let mut data = String::new();
    let mut next = 0usize;
    let mut entity = |text: String| -> usize {
        next += 1;
        let _ = writeln!(data, "#{next}={text};");
        next
    };
    let app = entity("APPLICATION_CONTEXT('automotive design')".into());
    entity(format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{app})"
    ));
    let product_context = entity(format!("PRODUCT_CONTEXT('',#{app},'mechanical')"));
    let name = string(&meta.name);
    let product = entity(format!("PRODUCT({name},{name},'',(#{product_context}))"));
    entity(format!(
        "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#{product}))"
    ));
    let formation = entity(format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"));
    let definition_context = entity(format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{app},'design')"
    ));
    let definition = entity(format!(
        "PRODUCT_DEFINITION('design','',#{formation},#{definition_context})"
    ));
    let shape = entity(format!("PRODUCT_DEFINITION_SHAPE('','',#{definition})"));
    let length = entity("(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.))".into());
    let angle = entity("(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.))".into());
    let solid = entity("(NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT())".into());
    let accuracy = entity(format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE({}),#{length},'distance_accuracy_value',\
         'confusion accuracy')",
        real(uncertainty)
    ));
    let context = entity(format!(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{accuracy})) \
         GLOBAL_UNIT_ASSIGNED_CONTEXT((#{length},#{angle},#{solid})) REPRESENTATION_CONTEXT('',''))"
    ));
    let origin = entity("CARTESIAN_POINT('',(0.,0.,0.))".into());
    let z = entity("DIRECTION('',(0.,0.,1.))".into());
    let x = entity("DIRECTION('',(1.,0.,0.))".into());
    let placement = entity(format!("AXIS2_PLACEMENT_3D('',#{origin},#{z},#{x})"));
    let mut ids = Vec::new();
    for curve in curves {
        let points: Vec<usize> = curve
            .control_points
            .iter()
            .map(|p| entity(format!("CARTESIAN_POINT('',{})", list(p, |x| real(*x)))))
            .collect();
        let (mult, values) = curve.knot_multiplicities();
        ids.push(entity(format!(
            "(BOUNDED_CURVE() B_SPLINE_CURVE(3,{},.UNSPECIFIED.,.F.,.F.) \
             B_SPLINE_CURVE_WITH_KNOTS({},{},.UNSPECIFIED.) CURVE() \
             GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE({}) REPRESENTATION_ITEM(''))",
            list(&points, |i| format!("#{i}")),
            list(&mult, |m| m.to_string()),
            list(&values, |k| real(*k)),
            list(&curve.weights, |w| real(*w)),
        )));
    }
    let set = entity(format!(
        "GEOMETRIC_CURVE_SET('',{})",
        list(&ids, |i| format!("#{i}"))
    ));
    let representation = entity(format!(
        "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION({name},(#{set},#{placement}),\
         #{context})"
    ));
    entity(format!(
        "SHAPE_DEFINITION_REPRESENTATION(#{shape},#{representation})"
    ));
    format!(
        "ISO-10303-21;\nHEADER;\n\
         FILE_DESCRIPTION(('a log-aesthetic curve as rational B-splines, lac export'),'2;1');\n\
         FILE_NAME({},{},(''),(''),'lac {}','lac {}','');\n\
         FILE_SCHEMA(('AUTOMOTIVE_DESIGN {{ 1 0 10303 214 1 1 1 1 }}'));\n\
         ENDSEC;\nDATA;\n{data}ENDSEC;\nEND-ISO-10303-21;\n",
        string(&meta.name),
        string(&meta.timestamp),
        meta.version,
        meta.version
    )
}
