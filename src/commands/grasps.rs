//! `grasps`: the two-finger force-closure grasps of one closed curve, for a friction
//! coefficient, in the curve's own parameter.

use super::errors::{antipodal_error, number, refuse};
use super::prepared::spline_with_corners;
use super::{as_profile, one_curve, CommandError, FailureKind, UsageError};
use crate::io::{Curve, CurveKind};
use curve::Boundary;
use grasp::{GraspOptions, Grasps};

/// The grasp options checked on their own, as the command line names them (before any file
/// is read: a usage error comes first): `--friction` a finite number above 0, the widths
/// finite and above 0, `--min-width` below `--max-width`.
pub fn validate_grasp_options(opts: &GraspOptions) -> Result<(), CommandError> {
    let positive = |option: &str, value: f64, what: &str| {
        if value.is_finite() && value > 0.0 {
            Ok(())
        } else {
            Err(CommandError::from(UsageError::OutOfRange {
                command: Some("grasps"),
                option: option.into(),
                value: number(value),
                expected: format!("must be a finite {what} > 0"),
            }))
        }
    };
    positive("friction", opts.friction, "coefficient")?;
    for (option, width) in [("min-width", opts.min_width), ("max-width", opts.max_width)] {
        if let Some(w) = width {
            positive(option, w, "width")?;
        }
    }
    if let (Some(lo), Some(hi)) = (opts.min_width, opts.max_width) {
        if lo >= hi {
            return Err(UsageError::OutOfRange {
                command: Some("grasps"),
                option: "max-width".into(),
                value: number(hi),
                expected: format!("must be above --min-width ({})", number(lo)),
            }
            .into());
        }
    }
    Ok(())
}

/// The grasps of a curve read, with `opts`: a spline or an analytic shape as its exact curve,
/// a line or an arc and a profile as a profile. A region is refused (the command takes one
/// curve); an open curve and one known by evaluation only are refused as bad input naming
/// the file; a drawing's unread outline makes
/// the result not certified.
pub fn grasps(curve: &Curve, opts: &GraspOptions) -> Result<Grasps, CommandError> {
    validate_grasp_options(opts)?;
    one_curve(&[curve], "grasps")?;
    // A spline with corners (degree 1, a full knot where it turns, a corner at its seam) is
    // the profile of its pieces, its corners' cones taking part.
    let cornered = spline_with_corners(curve)?;
    let profile;
    let boundary: Boundary<'_> = match (&curve.shape, &cornered) {
        (_, Some(pieces)) => Boundary::Profile(pieces),
        (CurveKind::Spline(_) | CurveKind::Analytic(_), None) => {
            Boundary::Curve(curve.plane_curve())
        }
        (CurveKind::Profile(p), None) => Boundary::Profile(p),
        _ => {
            profile = as_profile(curve, "grasps")?;
            Boundary::Profile(&profile)
        }
    };
    let mut found = grasp::grasps(boundary, opts).map_err(|e| grasp_error(e, curve))?;
    if let Some(doubt) = curve.drawing_outline_doubt() {
        found.doubts.add(doubt);
    }
    Ok(found)
}

/// The field of `curve`'s document a refusal of its shape is about.
fn shape_field(curve: &Curve) -> &'static str {
    match curve.shape {
        CurveKind::Spline(_) => "points",
        CurveKind::Profile(_) => "segments",
        _ => "kind",
    }
}

/// A refusal of the grasp crate as the tool reports it: an option out of range is a usage
/// error; a curve the command does not take (open, known by evaluation only, refused by the
/// antipodal search) is bad input naming the file; the
/// rest is the computation's failure.
fn grasp_error(e: grasp::Error, curve: &Curve) -> CommandError {
    use grasp::Error as E;
    match e {
        E::Option {
            field,
            value,
            expected,
        } => UsageError::OutOfRange {
            command: Some("grasps"),
            option: field.replace('_', "-"),
            value: number(value),
            expected: expected.into(),
        }
        .into(),
        E::NotClosed => refuse(
            curve,
            shape_field(curve),
            "grasps need a closed curve; this one is open",
        ),
        E::NotExact => refuse(
            curve,
            "kind",
            "grasps need the curve's exact form (a spline or an analytic shape); this one is \
             known by evaluation only",
        ),
        E::Antipodal(inner) => {
            let mapped = antipodal_error(inner.clone(), &[curve]);
            match mapped.kind() {
                FailureKind::Input => mapped,
                _ => CommandError::Grasp(E::Antipodal(inner)),
            }
        }
        E::Spline(_) | E::Curve(_) | E::ZeroSet(_) => CommandError::Grasp(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn options(mu: f64, widths: [Option<f64>; 2]) -> GraspOptions {
        GraspOptions {
            min_width: widths[0],
            max_width: widths[1],
            ..GraspOptions::friction(mu)
        }
    }

    /// Each option out of range is a usage error naming it as the command line spells it.
    #[test]
    fn options_out_of_range_name_the_option() {
        let cases = [
            (
                options(0.0, [None; 2]),
                "grasps: --friction: 0 is out of range",
            ),
            (
                options(f64::NAN, [None; 2]),
                "grasps: --friction: NaN is out of range",
            ),
            (
                options(0.3, [Some(-1.0), None]),
                "grasps: --min-width: -1 is out of range",
            ),
            (
                options(0.3, [None, Some(f64::INFINITY)]),
                "grasps: --max-width: inf is out of range",
            ),
            (
                options(0.3, [Some(2.0), Some(1.0)]),
                "grasps: --max-width: 1 is out of range: must be above --min-width (2)",
            ),
        ];
        for (opts, text) in cases {
            let Err(e) = validate_grasp_options(&opts) else {
                panic!("{opts:?} accepted");
            };
            assert!(e.message().starts_with(text), "{}", e.message());
            assert_eq!(e.exit_code(), 2, "{text}");
        }
        assert!(validate_grasp_options(&options(0.3, [Some(1.0), Some(2.0)])).is_ok());
    }

    /// The crate's own refusal of an option is worded as the command line names it.
    #[test]
    fn the_crates_option_refusal_is_a_usage_error() {
        let curve = Curve::new(
            "c.json",
            CurveKind::Analytic(curve::shapes::Shape::Circle(
                curve::shapes::Circle::new(1.0, [0.0, 0.0]).unwrap_or_else(|_| unreachable!()),
            )),
        );
        let e = grasp_error(
            grasp::Error::Option {
                field: "min_width",
                value: -1.0,
                expected: "a finite width above 0",
            },
            &curve,
        );
        assert_eq!(
            e.message(),
            "grasps: --min-width: -1 is out of range: a finite width above 0"
        );
        assert_eq!(e.exit_code(), 2);
        let e = grasp_error(grasp::Error::NotClosed, &curve);
        assert_eq!(e.kind(), FailureKind::Input);
        assert!(e.message().contains("c.json"), "{}", e.message());
    }
}
