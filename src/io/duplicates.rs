//! Keys given twice in a curve file, at any depth: serde_json keeps the last silently, so the
//! reader looks for them in the text itself.

/// The first key an object of `text` (valid JSON) gives twice, if any, as its path
/// (`segments[2].to`). (serde_json keeps the last silently; another reader may keep the
/// first and compute another curve.)
pub(super) fn duplicate_key(text: &str) -> Option<String> {
    use serde::de::{DeserializeSeed, MapAccess, SeqAccess, Visitor};
    /// Looks for a duplicate key in the value at `path`.
    struct Seek {
        path: String,
    }
    impl<'de> DeserializeSeed<'de> for Seek {
        type Value = Option<String>;
        fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
            d.deserialize_any(self)
        }
    }
    impl<'de> Visitor<'de> for Seek {
        type Value = Option<String>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("any JSON value")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            let (mut seen, mut found) = (std::collections::HashSet::new(), None);
            // (The whole object is read: the parser checks its end.)
            while let Some(key) = map.next_key::<String>()? {
                let path = match self.path.is_empty() {
                    true => key.clone(),
                    false => format!("{}.{key}", self.path),
                };
                let inner = map.next_value_seed(Seek { path: path.clone() })?;
                if found.is_none() {
                    found = if seen.insert(key) { inner } else { Some(path) };
                }
            }
            Ok(found)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
            let mut found = None;
            for i in 0.. {
                let path = format!("{}[{i}]", self.path);
                match seq.next_element_seed(Seek { path })? {
                    Some(inner) => found = found.or(inner),
                    None => break,
                }
            }
            Ok(found)
        }
        fn visit_bool<E>(self, _: bool) -> Result<Self::Value, E> {
            Ok(None)
        }
        fn visit_i64<E>(self, _: i64) -> Result<Self::Value, E> {
            Ok(None)
        }
        fn visit_u64<E>(self, _: u64) -> Result<Self::Value, E> {
            Ok(None)
        }
        fn visit_f64<E>(self, _: f64) -> Result<Self::Value, E> {
            Ok(None)
        }
        fn visit_str<E>(self, _: &str) -> Result<Self::Value, E> {
            Ok(None)
        }
        fn visit_unit<E>(self) -> Result<Self::Value, E> {
            Ok(None)
        }
    }
    let mut de = serde_json::Deserializer::from_str(text);
    Seek {
        path: String::new(),
    }
    .deserialize(&mut de)
    .ok()
    .flatten()
}
