//! A serde serializer that writes nothing and lists the path of every
//! number that is NaN or infinite: JSON cannot tell such a number (written
//! as `null`) from an absent value, so reports are checked before they are
//! serialised.

use serde::ser::{self, Serialize};
use std::fmt;

/// Paths (`ranking[3].gain`) of the non-finite numbers in `value`.
pub fn non_finite<T: Serialize + ?Sized>(value: &T) -> Vec<String> {
    let mut c = Checker::default();
    value.serialize(&mut c).unwrap();
    c.found
}

#[derive(Default)]
struct Checker {
    path: Vec<String>,
    found: Vec<String>,
    index: Vec<usize>,
}

#[derive(Debug)]
struct Never;
impl fmt::Display for Never {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("never")
    }
}
impl std::error::Error for Never {}
impl ser::Error for Never {
    fn custom<T: fmt::Display>(_: T) -> Self {
        Never
    }
}

type R = Result<(), Never>;

impl Checker {
    fn float(&mut self, v: f64) -> R {
        if !v.is_finite() {
            self.found.push(format!("{} = {v}", self.path.concat()));
        }
        Ok(())
    }
    fn field<T: Serialize + ?Sized>(&mut self, name: String, v: &T) -> R {
        self.path.push(name);
        v.serialize(&mut *self)?;
        self.path.pop();
        Ok(())
    }
    fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
        let i = self.index.last_mut().map_or(0, |i| {
            *i += 1;
            *i - 1
        });
        self.field(format!("[{i}]"), v)
    }
    fn open(&mut self) -> Result<&mut Self, Never> {
        self.index.push(0);
        Ok(self)
    }
    fn close(&mut self) -> R {
        self.index.pop();
        Ok(())
    }
}

macro_rules! ignore {
    ($($f:ident: $t:ty),*) => {
        $(fn $f(self, _: $t) -> R { Ok(()) })*
    };
}

impl ser::Serializer for &mut Checker {
    type Ok = ();
    type Error = Never;
    type SerializeSeq = Self;
    type SerializeTuple = Self;
    type SerializeTupleStruct = Self;
    type SerializeTupleVariant = Self;
    type SerializeMap = Self;
    type SerializeStruct = Self;
    type SerializeStructVariant = Self;

    ignore!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str, serialize_bytes: &[u8],
        serialize_unit_struct: &'static str);
    fn serialize_f32(self, v: f32) -> R {
        self.float(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> R {
        self.float(v)
    }
    fn serialize_none(self) -> R {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> R {
        v.serialize(self)
    }
    fn serialize_unit(self) -> R {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> R {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, v: &T) -> R {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        v: &T,
    ) -> R {
        self.field(format!(".{variant}"), v)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self, Never> {
        self.open()
    }
    fn serialize_tuple(self, _: usize) -> Result<Self, Never> {
        self.open()
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Self, Never> {
        self.open()
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self, Never> {
        self.open()
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self, Never> {
        self.open()
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, Never> {
        self.open()
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self, Never> {
        self.open()
    }
}

macro_rules! sequence {
    ($($tr:ident :: $m:ident),*) => {$(
        impl ser::$tr for &mut Checker {
            type Ok = ();
            type Error = Never;
            fn $m<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
                self.element(v)
            }
            fn end(self) -> R {
                self.close()
            }
        }
    )*};
}
sequence!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

macro_rules! record {
    ($($tr:ident),*) => {$(
        impl ser::$tr for &mut Checker {
            type Ok = ();
            type Error = Never;
            fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, v: &T) -> R {
                self.field(format!(".{key}"), v)
            }
            fn end(self) -> R {
                self.close()
            }
        }
    )*};
}
record!(SerializeStruct, SerializeStructVariant);

impl ser::SerializeMap for &mut Checker {
    type Ok = ();
    type Error = Never;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> R {
        // Keys are names; a float key would be checked as a value.
        let name = serde_json::to_string(key).unwrap_or_default();
        self.path.push(format!(".{}", name.trim_matches('"')));
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
        v.serialize(&mut **self)?;
        self.path.pop();
        Ok(())
    }
    fn end(self) -> R {
        self.close()
    }
}

#[test]
fn the_checker_finds_every_non_finite_number() {
    #[derive(serde::Serialize)]
    struct Inner {
        a: f64,
        b: Option<f64>,
    }
    #[derive(serde::Serialize)]
    struct Outer {
        x: Vec<Inner>,
        m: std::collections::BTreeMap<String, (f64, f32)>,
    }
    let v = Outer {
        x: vec![
            Inner { a: 1.0, b: None },
            Inner {
                a: f64::NAN,
                b: Some(f64::INFINITY),
            },
        ],
        m: [("k".to_string(), (0.0, f32::NEG_INFINITY))].into(),
    };
    assert_eq!(
        non_finite(&v),
        vec![".x[1].a = NaN", ".x[1].b = inf", ".m.k[1] = -inf"]
    );
}
