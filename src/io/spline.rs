//! The spline kinds of curve files: `bezier` and `bspline`.

use super::{out_of_range, FieldError, Fields, Problem, SplineDocument, SplineKind, MAX_DEGREE};
use bspline::knots::validate_knots;
use curve::ParamCurve;

/// Validates a `bezier` or `bspline` object (unknown fields were already rejected).
pub(super) fn parse_spline(kind: &str, f: &Fields<'_>) -> Result<SplineDocument, FieldError> {
    let points = f.points("points")?;
    let n = points.len();
    let (kind, degree, periodic, knots) = if kind == "bezier" {
        if n < 2 {
            return Err(count("points", "at least 2 points".into(), n));
        }
        if n > MAX_DEGREE + 1 {
            let limit = format!("at most {} points (degree <= {MAX_DEGREE})", MAX_DEGREE + 1);
            return Err(count("points", limit, n));
        }
        (SplineKind::Bezier, n - 1, false, None)
    } else {
        let degree = f.integer("degree", 1, MAX_DEGREE as u64)? as usize;
        let periodic = f.opt_bool("periodic")?.unwrap_or(false);
        let knots = f.opt_numbers("knots")?;
        if periodic && knots.is_some() {
            return Err(("knots".into(), Problem::KnotsWithPeriodic));
        }
        if n <= degree {
            let need = format!("at least {} points for degree {degree}", degree + 1);
            return Err(count("points", need, n));
        }
        (SplineKind::BSpline, degree, periodic, knots)
    };
    let weights = f.opt_numbers("weights")?;
    if let Some(w) = &weights {
        if w.len() != n {
            return Err(count(
                "weights",
                format!("{n} weights (one per point)"),
                w.len(),
            ));
        }
        if let Some(i) = w.iter().position(|&x| x <= 0.0) {
            return Err(out_of_range(&format!("weights[{i}]"), "> 0", w[i]));
        }
    }
    if points.iter().all(|p| *p == points[0]) {
        return Err(("points".into(), Problem::Degenerate));
    }
    if let Some(k) = &knots {
        validate_knots(degree, n, k).map_err(|e| knot_error(e, k.len()))?;
    }

    let plane = if periodic {
        curve::SplineCurve::periodic(degree, &points, weights.as_deref())
    } else {
        curve::SplineCurve::clamped(degree, &points, weights.as_deref(), knots.clone())
    }
    .map_err(|e| match e {
        curve::Error::Spline(e @ bspline::Error::NonPositiveWeight { .. }) => {
            ("weights".to_string(), Problem::Spline(e))
        }
        curve::Error::Spline(e) => ("points".to_string(), Problem::Spline(e)),
        e => ("points".to_string(), Problem::Geometry(e.to_string())),
    })?;
    let curve = plane.curve().clone();

    // Curvature needs two derivatives of the homogeneous form; if they overflow, nothing
    // downstream can be trusted. Only knots packed far too tightly can cause this.
    let d1 = curve.homogeneous().deriv();
    let d2 = d1.deriv();
    if !d1.coefs().iter().chain(d2.coefs()).all(|x| x.is_finite()) {
        let field = if knots.is_some() { "knots" } else { "points" };
        return Err((field.into(), Problem::Overflow));
    }

    let closed = plane.is_closed();
    Ok(SplineDocument {
        plane,
        curve,
        kind,
        periodic,
        closed,
        weighted: weights.is_some(),
        n_points: n,
    })
}

fn count(field: &str, expected: String, got: usize) -> FieldError {
    (field.to_string(), Problem::WrongCount { expected, got })
}

/// Names the knot the spline library complained about.
fn knot_error(e: bspline::Error, len: usize) -> FieldError {
    let field = match &e {
        bspline::Error::DecreasingKnots { index, .. } | bspline::Error::NotFinite { index, .. }
            if *index < len =>
        {
            format!("knots[{index}]")
        }
        _ => "knots".to_string(),
    };
    (field, Problem::Spline(e))
}

#[cfg(test)]
mod tests {
    use crate::io::{parse_curve, CurveKind};

    fn spline(text: &str) -> crate::io::SplineDocument {
        match parse_curve("t.json", text).map(|c| c.shape) {
            Ok(CurveKind::Spline(s)) => *s,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn closedness() {
        let p =
            spline(r#"{"kind":"bspline","degree":2,"periodic":true,"points":[[0,0],[1,0],[1,1]]}"#);
        assert!(p.periodic && p.closed);
        assert_eq!(p.curve.domain(), (0.0, 3.0));
        let c = spline(r#"{"kind":"bspline","degree":2,"points":[[0,0],[1,0],[1,1],[0,0]]}"#);
        assert!(!c.periodic && c.closed);
        let o = spline(r#"{"kind":"bezier","points":[[0,0],[1,0],[1,1]]}"#);
        assert!(!o.closed);
    }

    #[test]
    fn periodic_weights_wrap_with_the_points() {
        let s = spline(
            r#"{"kind":"bspline","degree":2,"periodic":true,"points":[[1,0],[0,1],[-1,0],[0,-1]],"weights":[1,2,1,2]}"#,
        );
        assert!(s.curve.is_rational() && s.weighted);
        // Periodic: the curve closes with matching tangents.
        let (a, b) = s.curve.domain();
        let (mut da, mut db) = ([0.0; 4], [0.0; 4]);
        s.curve.eval_derivs(a, 1, &mut da);
        s.curve.eval_derivs(b, 1, &mut db);
        for (x, y) in da.iter().zip(&db) {
            assert!((x - y).abs() < 1e-12, "{da:?} vs {db:?}");
        }
    }
}
