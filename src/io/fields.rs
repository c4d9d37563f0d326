//! Typed access to the fields of a curve object, each error naming the field.

use super::{Problem, MAX_ABS};
use serde_json::{Map, Value};

/// An error before the file name is attached: (field, problem).
pub(super) type FieldError = (String, Problem);

/// Typed access to the fields of one curve object, naming the field in every error.
pub(crate) struct Fields<'a>(pub(crate) &'a Map<String, Value>);

impl Fields<'_> {
    pub(crate) fn get(&self, key: &str) -> Option<&Value> {
        self.0.get(key)
    }

    pub(crate) fn require(&self, key: &str) -> Result<&Value, FieldError> {
        self.0
            .get(key)
            .ok_or_else(|| (key.to_string(), Problem::Missing))
    }

    pub(crate) fn number(&self, key: &str) -> Result<f64, FieldError> {
        number_at(key, self.require(key)?)
    }

    pub(crate) fn positive(&self, key: &str) -> Result<f64, FieldError> {
        let x = self.number(key)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(out_of_range(key, "> 0", x))
        }
    }

    /// An integer in `[min, max]` (a JSON number without a fractional part, `3.0` included).
    pub(crate) fn integer(&self, key: &str, min: u64, max: u64) -> Result<u64, FieldError> {
        let x = self.number(key)?;
        if x.fract() != 0.0 {
            return Err(out_of_range(key, "an integer", x));
        }
        if x < min as f64 {
            return Err(out_of_range(key, &format!("an integer >= {min}"), x));
        }
        if x > max as f64 {
            return Err(out_of_range(key, &format!("an integer <= {max}"), x));
        }
        Ok(x as u64)
    }

    pub(crate) fn opt_point(&self, key: &str) -> Result<Option<[f64; 2]>, FieldError> {
        self.get(key).map(|v| point_at(key, v)).transpose()
    }

    pub(crate) fn opt_bool(&self, key: &str) -> Result<Option<bool>, FieldError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::Bool(b)) => Ok(Some(*b)),
            Some(v) => Err(wrong_type(key, "true or false", v)),
        }
    }

    /// An array of numbers.
    pub(crate) fn opt_numbers(&self, key: &str) -> Result<Option<Vec<f64>>, FieldError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let items = array_at(key, v, "an array of numbers")?;
        items
            .iter()
            .enumerate()
            .map(|(i, x)| number_at(&format!("{key}[{i}]"), x))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// An array of `[x, y]` points.
    pub(crate) fn points(&self, key: &str) -> Result<Vec<[f64; 2]>, FieldError> {
        let items = array_at(key, self.require(key)?, "an array of [x, y] points")?;
        items
            .iter()
            .enumerate()
            .map(|(i, p)| point_at(&format!("{key}[{i}]"), p))
            .collect()
    }
}

fn array_at<'v>(
    key: &str,
    v: &'v Value,
    expected: &'static str,
) -> Result<&'v Vec<Value>, FieldError> {
    match v {
        Value::Array(items) => Ok(items),
        _ => Err(wrong_type(key, expected, v)),
    }
}

fn point_at(key: &str, v: &Value) -> Result<[f64; 2], FieldError> {
    let items = array_at(key, v, "an [x, y] point")?;
    if items.len() != 2 {
        return Err((
            key.to_string(),
            Problem::WrongCount {
                expected: "2 coordinates [x, y]".into(),
                got: items.len(),
            },
        ));
    }
    Ok([
        number_at(&format!("{key}[0]"), &items[0])?,
        number_at(&format!("{key}[1]"), &items[1])?,
    ])
}

fn number_at(key: &str, v: &Value) -> Result<f64, FieldError> {
    let x = match v {
        Value::Number(n) => n.as_f64(),
        _ => return Err(wrong_type(key, "a number", v)),
    };
    match x {
        Some(x) if x.is_finite() && x.abs() <= MAX_ABS => Ok(x),
        Some(x) => Err((key.to_string(), Problem::TooLarge(x))),
        None => Err(wrong_type(key, "a number", v)),
    }
}

pub(crate) fn out_of_range(key: &str, rule: &str, value: f64) -> FieldError {
    (
        key.to_string(),
        Problem::OutOfRange {
            rule: rule.to_string(),
            value,
        },
    )
}

pub(super) fn wrong_type(key: &str, expected: &'static str, v: &Value) -> FieldError {
    (
        key.to_string(),
        Problem::WrongType {
            expected,
            got: type_name(v),
        },
    )
}

pub(super) fn type_name(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}
