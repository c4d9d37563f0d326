//! The HEADER section's `$INSUNITS`: the unit of the drawing's coordinates.

use super::Failure;
use crate::io::Problem;

/// The units of `$INSUNITS` codes 1 to 24, in order (0 is unitless). Codes 21 to 24 are the
/// United States survey foot, inch, yard and mile.
const INSUNITS_NAMES: [&str; 24] = [
    "in", "ft", "mi", "mm", "cm", "m", "km", "uin", "mil", "yd", "angstrom", "nm", "um", "dm",
    "dam", "hm", "Gm", "au", "ly", "pc", "us_ft", "us_in", "us_yd", "us_mi",
];

/// The unit `$INSUNITS` (its value as written, if the header has it) names: `None` when absent
/// or 0 (unitless); a value that is no unit code is refused, naming the variable.
pub(super) fn units(value: Option<&str>) -> Result<Option<String>, Failure> {
    let Some(value) = value else {
        return Ok(None);
    };
    let field = "HEADER $INSUNITS".to_string();
    let code: i64 = value.trim().parse().map_err(|_| {
        (
            field.clone(),
            Problem::Syntax(format!("`{}` is not an integer", value.trim())),
        )
    })?;
    if code == 0 {
        return Ok(None);
    }
    usize::try_from(code - 1)
        .ok()
        .and_then(|i| INSUNITS_NAMES.get(i))
        .map(|u| Some(u.to_string()))
        .ok_or((
            field,
            Problem::OutOfRange {
                rule: format!("a unit code from 0 to {}", INSUNITS_NAMES.len()),
                value: code as f64,
            },
        ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_codes() {
        assert_eq!(units(None), Ok(None));
        assert_eq!(units(Some("0")), Ok(None));
        assert_eq!(units(Some("     4")).unwrap().as_deref(), Some("mm"));
        assert_eq!(units(Some("1")).unwrap().as_deref(), Some("in"));
        assert_eq!(units(Some("20")).unwrap().as_deref(), Some("pc"));
        assert_eq!(units(Some("21")).unwrap().as_deref(), Some("us_ft"));
        for bad in ["25", "-1", "mm", ""] {
            let (field, _) = units(Some(bad)).unwrap_err();
            assert_eq!(field, "HEADER $INSUNITS");
        }
    }
}
