//! How a result's doubts read in its documents: the contract's `certified` and `reason`
//! fields, and the one trait every result answers them by.

use super::{Doubt, Doubts};
use serde::de::Deserializer;
use serde::ser::{SerializeMap, Serializer};
use serde::{Deserialize, Serialize};

/// A result that says whether it is certified, and why not: the contract's `certified` and
/// `reason`, read off the doubts it carries.
///
/// ```
/// use numeric::certificate::{Doubt, Doubts, Verdict};
///
/// struct Found {
///     doubts: Doubts,
/// }
/// impl Verdict for Found {
///     fn doubts(&self) -> &Doubts {
///         &self.doubts
///     }
/// }
/// let found = Found { doubts: Doubt::SearchLimit.into() };
/// assert!(!found.certified());
/// assert_eq!(found.reason().as_deref(), Some("a search limit was hit"));
/// ```
pub trait Verdict {
    /// The doubts met (none: certified).
    fn doubts(&self) -> &Doubts;

    /// True when every decision was proven.
    fn certified(&self) -> bool {
        self.doubts().is_empty()
    }

    /// Why the result is not certified (its first doubt, stated), if it is not.
    fn reason(&self) -> Option<String> {
        self.doubts().reason()
    }
}

/// [`Verdict`] for result types that keep their doubts in a field `doubts: Doubts`, each type
/// with its own attributes (a doc comment, an example).
///
/// ```
/// use numeric::certificate::{Doubt, Doubts, Verdict};
///
/// struct Found {
///     doubts: Doubts,
/// }
/// numeric::impl_verdict!(Found);
/// assert!(!Found { doubts: Doubt::SearchLimit.into() }.certified());
/// ```
#[macro_export]
macro_rules! impl_verdict {
    ($($(#[$attr:meta])* $t:ty),+ $(,)?) => {
        $(
            $(#[$attr])*
            impl $crate::certificate::Verdict for $t {
                fn doubts(&self) -> &$crate::certificate::Doubts {
                    &self.doubts
                }
            }
        )+
    };
}

impl Verdict for Doubts {
    fn doubts(&self) -> &Doubts {
        self
    }
}

/// Written as the contract's fields, to be flattened into a result's document:
/// `"certified": bool` and, when it is false, `"reason": string`.
impl Serialize for Doubts {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let reason = self.reason();
        let mut map = serializer.serialize_map(Some(1 + usize::from(reason.is_some())))?;
        map.serialize_entry("certified", &self.is_empty())?;
        if let Some(reason) = reason {
            map.serialize_entry("reason", &reason)?;
        }
        map.end()
    }
}

/// The contract's fields as a document writes them.
#[derive(Deserialize)]
struct StatedFields {
    certified: bool,
    #[serde(default)]
    reason: Option<String>,
}

/// Read back from the contract's fields: an uncertified document's reason becomes a
/// [`Doubt::Stated`] (its kind is not written in the document).
impl<'de> Deserialize<'de> for Doubts {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let fields = StatedFields::deserialize(deserializer)?;
        Ok(if fields.certified {
            Doubts::none()
        } else {
            Doubt::Stated {
                reason: fields.reason.unwrap_or_default(),
            }
            .into()
        })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[derive(Serialize, Deserialize, PartialEq, Debug)]
    struct Found {
        count: usize,
        #[serde(flatten)]
        doubts: Doubts,
        complete: bool,
    }

    #[test]
    fn a_result_writes_the_contracts_fields_and_reads_them_back() {
        let proven = Found {
            count: 2,
            doubts: Doubts::none(),
            complete: true,
        };
        let text = serde_json::to_string(&proven).unwrap();
        assert_eq!(text, r#"{"count":2,"certified":true,"complete":true}"#);
        assert_eq!(serde_json::from_str::<Found>(&text).unwrap(), proven);

        let mut doubts = Doubts::from(Doubt::NearCusp);
        doubts.add(Doubt::SearchLimit);
        let doubted = Found {
            count: 0,
            doubts,
            complete: false,
        };
        let text = serde_json::to_string(&doubted).unwrap();
        let reason = Doubt::NearCusp.to_string();
        assert_eq!(
            text,
            format!(r#"{{"count":0,"certified":false,"reason":"{reason}","complete":false}}"#)
        );
        let back: Found = serde_json::from_str(&text).unwrap();
        assert!(!back.doubts.certified());
        assert_eq!(back.doubts.reason(), Some(reason));
    }
}
