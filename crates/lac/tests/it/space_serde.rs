//! With the `serde` feature (`cargo test -p lac --features serde --test it space_serde`): the
//! space-curve types round-trip through JSON under their snake_case names, and a standard
//! form read from JSON is checked as `SpaceForm::new` checks it.
#![cfg(feature = "serde")]

use lac::SpaceCurve;
use lac::{
    BoundBy, Error, SpaceForm, SpaceFormParams, SpaceSegment, SpaceShape, TorsionType, TurningCell,
    Vec3,
};
use serde_json::{json, Value};

fn params() -> SpaceFormParams {
    SpaceFormParams {
        alpha: 1.0,
        beta: -1.0,
        lambda: 1.0,
        omega: 1.0,
        nu: 1.0,
        torsion: TorsionType::One,
    }
}

#[test]
fn a_point_is_an_object_of_three_coordinates() {
    let p = Vec3::new(1.5, -2.0, 0.25);
    let value = serde_json::to_value(p).unwrap();
    assert_eq!(value, json!({"x": 1.5, "y": -2.0, "z": 0.25}));
    assert_eq!(serde_json::from_value::<Vec3>(value).unwrap(), p);
}

#[test]
fn a_standard_form_is_written_as_its_parameters_and_checked_when_read() {
    let form = SpaceForm::new(params()).unwrap();
    let value = serde_json::to_value(form).unwrap();
    assert_eq!(
        value,
        json!({"alpha": 1.0, "beta": -1.0, "lambda": 1.0, "omega": 1.0, "nu": 1.0,
               "torsion": "one"})
    );
    assert_eq!(serde_json::from_value::<SpaceForm>(value).unwrap(), form);
    let bad = json!({"alpha": 1.0, "beta": -1.0, "lambda": 1.0, "omega": 1.0, "nu": -1.0,
                     "torsion": "two"});
    let err = serde_json::from_value::<SpaceForm>(bad.clone()).unwrap_err();
    assert!(err.to_string().contains("nu"), "{err}");
    // The parameters alone are plain data; SpaceForm::new gives the same error.
    let raw: SpaceFormParams = serde_json::from_value(bad).unwrap();
    assert!(matches!(
        SpaceForm::new(raw),
        Err(Error::OutOfRange { name: "nu", .. })
    ));
}

#[test]
fn the_classification_round_trips_with_snake_case_names() {
    let c = SpaceForm::new(params()).unwrap().classify();
    let value = serde_json::to_value(c).unwrap();
    assert_eq!(value["row"], json!({"torsion": "one", "number": 24}));
    assert_eq!(value["lower"]["end"], "lower");
    assert_eq!(value["lower"]["binds"], "rho");
    assert_eq!(value["lower"]["theta"], "infinite");
    assert_eq!(
        value["lower"]["phi"],
        json!({"cut_short": {"diverges_at_own_end": true}})
    );
    assert_eq!(
        value["lower"]["rho"],
        json!({"limit": "zero", "star": true})
    );
    assert_eq!(value["upper"]["kappa_over_tau"], "infinite");
    assert_eq!(c.lower.binds, BoundBy::Rho);
    assert_eq!(
        c.lower.phi,
        TurningCell::CutShort {
            diverges_at_own_end: true
        }
    );
    // The lower end is finite here (s = −1/(Λα) = −1); JSON has no infinity, so an infinite
    // end would be written as null and not read back.
    assert!(c.lower.s.is_finite() && c.upper.s.is_finite());
    let back: lac::SpaceClassification = serde_json::from_value(value).unwrap();
    assert_eq!(back, c);
}

#[test]
fn frames_shapes_and_similarities_round_trip() {
    let points = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(2.0, 1.0, 0.5),
        Vec3::new(2.0, 2.0, 1.5),
    ];
    let shape = SpaceShape {
        alpha: 0.5,
        beta: 0.0,
        omega: 0.3,
        torsion: TorsionType::Two,
    };
    let seg = SpaceSegment::from_control_points(points, shape).unwrap();
    let text = serde_json::to_string(&seg.shape()).unwrap();
    assert_eq!(
        text,
        r#"{"alpha":0.5,"beta":0.0,"omega":0.3,"torsion":"two"}"#
    );
    assert_eq!(serde_json::from_str::<SpaceShape>(&text).unwrap(), shape);
    let transform = *seg.transform().unwrap();
    let value: Value = serde_json::to_value(transform).unwrap();
    assert!(value["translation"]["x"].is_number() && value["rotation"][2][2].is_number());
    assert_eq!(
        serde_json::from_value::<lac::Similarity3>(value).unwrap(),
        transform
    );
    for frame in seg.sample_by_arc_length(3).unwrap() {
        let text = serde_json::to_string(&frame).unwrap();
        assert_eq!(serde_json::from_str::<lac::Frame>(&text).unwrap(), frame);
    }
}
