//! How the wire's own types look in serde formats (JSON for the web page): bytes as base64
//! strings, a string as its text, an interface as its name. Only with the `serde` feature.
//!
//! Numbers keep their XDR types; a float that JSON cannot hold (NaN, ±∞) becomes `null`, as
//! `serde_json` writes it, and a reader takes `null` as "no reading".

use base64::Engine;
use base64::engine::general_purpose::STANDARD;
use bytes::Bytes;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::{DevAddr, Interface, Opaque, PlayerString};

/// `#[serde(with = …)]` for a [`Bytes`] field: base64 text.
pub mod serde_bytes {
    use super::*;

    pub fn serialize<S: Serializer>(bytes: &Bytes, out: S) -> Result<S::Ok, S::Error> {
        out.serialize_str(&STANDARD.encode(bytes))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(input: D) -> Result<Bytes, D::Error> {
        let text = <std::borrow::Cow<'de, str>>::deserialize(input)?;
        STANDARD
            .decode(text.as_bytes())
            .map(Bytes::from)
            .map_err(|e| D::Error::custom(format!("bytes are not base64: {e}")))
    }
}

impl Serialize for Opaque {
    fn serialize<S: Serializer>(&self, out: S) -> Result<S::Ok, S::Error> {
        serde_bytes::serialize(&self.0, out)
    }
}

impl<'de> Deserialize<'de> for Opaque {
    fn deserialize<D: Deserializer<'de>>(input: D) -> Result<Self, D::Error> {
        serde_bytes::deserialize(input).map(Opaque)
    }
}

impl Serialize for PlayerString {
    fn serialize<S: Serializer>(&self, out: S) -> Result<S::Ok, S::Error> {
        out.serialize_str(&self.as_str())
    }
}

impl<'de> Deserialize<'de> for PlayerString {
    fn deserialize<D: Deserializer<'de>>(input: D) -> Result<Self, D::Error> {
        let text = <std::borrow::Cow<'de, str>>::deserialize(input)?;
        Ok(PlayerString::new(&text))
    }
}

impl Serialize for Interface {
    /// The name (`"laser"`), or the number for codes Player does not define.
    fn serialize<S: Serializer>(&self, out: S) -> Result<S::Ok, S::Error> {
        match self.name() {
            Some(name) => out.serialize_str(name),
            None => out.serialize_u16(self.0),
        }
    }
}

impl<'de> Deserialize<'de> for Interface {
    fn deserialize<D: Deserializer<'de>>(input: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum NameOrCode<'a> {
            Code(u16),
            Name(std::borrow::Cow<'a, str>),
        }
        match NameOrCode::deserialize(input)? {
            NameOrCode::Code(code) => Ok(Interface(code)),
            NameOrCode::Name(name) => Interface::from_name(&name)
                .ok_or_else(|| D::Error::custom(format!("no interface is named {name:?}"))),
        }
    }
}

impl Serialize for DevAddr {
    /// `"laser:0"`: the host and port are the connection's, said once beside it.
    fn serialize<S: Serializer>(&self, out: S) -> Result<S::Ok, S::Error> {
        out.collect_str(&format_args!("{}:{}", self.interf, self.index))
    }
}

impl<'de> Deserialize<'de> for DevAddr {
    fn deserialize<D: Deserializer<'de>>(input: D) -> Result<Self, D::Error> {
        let text = <std::borrow::Cow<'de, str>>::deserialize(input)?;
        text.parse::<DevAddr>()
            .map_err(|e| D::Error::custom(format!("device {text:?}: {e}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::laser::{Laser, LaserScan};
    use crate::message::Body;

    #[test]
    fn a_scan_reads_as_json_with_names_and_base64() {
        let body = Body::Laser(Laser::Scan(LaserScan {
            min_angle: -1.5,
            max_angle: 1.5,
            resolution: 1.5,
            max_range: 8.0,
            ranges: vec![1.0, 2.5, f32::NAN],
            intensity: Opaque::from(vec![1, 2, 3]),
            id: 7,
        }));
        let json = serde_json::to_string(&body).unwrap();
        assert_eq!(
            json,
            r#"{"Laser":{"Scan":{"min_angle":-1.5,"max_angle":1.5,"resolution":1.5,"max_range":8.0,"ranges":[1.0,2.5,null],"intensity":"AQID","id":7}}}"#
        );
    }

    #[test]
    fn names_addresses_and_strings_come_back() {
        let addr: DevAddr = serde_json::from_str(r#""ranger:2""#).unwrap();
        assert_eq!((addr.interf, addr.index), (Interface::RANGER, 2));
        assert_eq!(serde_json::to_string(&addr).unwrap(), r#""ranger:2""#);
        assert_eq!(
            serde_json::from_str::<Interface>("130").unwrap(),
            Interface(130)
        );
        let err = serde_json::from_str::<Interface>(r#""warpdrive""#).unwrap_err();
        assert!(err.to_string().contains("warpdrive"), "{err}");
        let err = serde_json::from_str::<Opaque>(r#""not base64!""#).unwrap_err();
        assert!(err.to_string().contains("base64"), "{err}");
        let name: PlayerString = serde_json::from_str(r#""stage""#).unwrap();
        assert_eq!(name.wire_bytes(), b"stage\0");
    }
}
