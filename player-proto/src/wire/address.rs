//! Device addresses: `player_devaddr_t` on the wire, and the string forms people type.

use std::fmt;
use std::net::Ipv4Addr;
use std::str::FromStr;

use bytes::{BufMut, Bytes};

use super::interface::Interface;
use super::xdr::{Xdr, XdrResult};

/// Where a device lives: `host` (opaque server id), `robot` (the TCP port it is served on),
/// interface code and index. 16 bytes on the wire: the two `u16`s are widened.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
#[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
pub struct DevAddr {
    /// The server's IPv4 address as the 4 bytes of memory order packed into a u32 (the real
    /// server sends `0x0100007f` for 127.0.0.1 from a little-endian machine). Treat as opaque.
    pub host: u32,
    /// The port the device is served on.
    pub robot: u32,
    pub interf: Interface,
    pub index: u16,
}

impl DevAddr {
    /// A device address without host and port, as clients send them (`laser:0`).
    pub const fn local(interf: Interface, index: u16) -> Self {
        Self {
            host: 0,
            robot: 0,
            interf,
            index,
        }
    }

    /// The `host` value a Player server on a little-endian machine reports for `ip`.
    pub fn host_from_ipv4(ip: Ipv4Addr) -> u32 {
        u32::from_le_bytes(ip.octets())
    }

    /// The IPv4 address inside `host`, read the way the server wrote it.
    pub fn host_ipv4(&self) -> Ipv4Addr {
        Ipv4Addr::from(self.host.to_le_bytes())
    }

    /// Same interface and index, whatever the host and port.
    pub fn same_device(&self, other: &DevAddr) -> bool {
        self.interf == other.interf && self.index == other.index
    }
}

impl Xdr for DevAddr {
    const MIN_WIRE_SIZE: usize = 16;

    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self> {
        let (input, host) = u32::decode(input, body)?;
        let (input, robot) = u32::decode(input, body)?;
        let (input, interf) = u16::decode(input, body)?;
        let (input, index) = u16::decode(input, body)?;
        Ok((
            input,
            Self {
                host,
                robot,
                interf: Interface(interf),
                index,
            },
        ))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        self.host.encode(out);
        self.robot.encode(out);
        self.interf.0.encode(out);
        self.index.encode(out);
    }

    fn encoded_len(&self) -> usize {
        16
    }
}

impl super::xdr::XdrElement for DevAddr {}

impl fmt::Display for DevAddr {
    /// `laser:0` when host and port are unset, `6665:laser:0` with a port, and
    /// `127.0.0.1:6665:laser:0` when the host is known too.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.host != 0 {
            write!(f, "{}:", self.host_ipv4())?;
        }
        if self.host != 0 || self.robot != 0 {
            write!(f, "{}:", self.robot)?;
        }
        write!(f, "{}:{}", self.interf, self.index)
    }
}

/// Why a device address string was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum AddrParseError {
    #[error("device address {0:?} must look like `laser:0`, `6665:laser:0` or `host:6665:laser:0`")]
    Shape(String),
    #[error("unknown interface {0:?} in device address")]
    UnknownInterface(String),
    #[error("device index {0:?} is not a number from 0 to 65535")]
    Index(String),
    #[error("port {0:?} is not a number from 0 to 65535")]
    Port(String),
    #[error("host {0:?} is not an IPv4 address")]
    Host(String),
}

impl FromStr for DevAddr {
    type Err = AddrParseError;

    /// Accepts Player's forms: `interface:index`, `port:interface:index` (as in a .cfg file's
    /// `provides`), and `host:port:interface:index`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let parts: Vec<&str> = s.split(':').collect();
        let (host, port, interf, index) = match parts.as_slice() {
            [i, n] => (None, None, *i, *n),
            [p, i, n] => (None, Some(*p), *i, *n),
            [h, p, i, n] => (Some(*h), Some(*p), *i, *n),
            _ => return Err(AddrParseError::Shape(s.to_string())),
        };
        let interf = Interface::from_name(interf)
            .ok_or_else(|| AddrParseError::UnknownInterface(interf.to_string()))?;
        let index = index
            .parse()
            .map_err(|_| AddrParseError::Index(index.to_string()))?;
        let robot = match port {
            Some(p) => u32::from(
                p.parse::<u16>()
                    .map_err(|_| AddrParseError::Port(p.to_string()))?,
            ),
            None => 0,
        };
        let host = match host {
            Some("localhost") => DevAddr::host_from_ipv4(Ipv4Addr::LOCALHOST),
            Some(h) => {
                DevAddr::host_from_ipv4(h.parse().map_err(|_| AddrParseError::Host(h.to_string()))?)
            }
            None => 0,
        };
        Ok(DevAddr {
            host,
            robot,
            interf,
            index,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn string_forms_parse_and_display() {
        let a: DevAddr = "laser:0".parse().unwrap();
        assert_eq!(a, DevAddr::local(Interface::LASER, 0));
        assert_eq!(a.to_string(), "laser:0");

        let b: DevAddr = "6665:position2d:1".parse().unwrap();
        assert_eq!(
            (b.robot, b.interf, b.index),
            (6665, Interface::POSITION2D, 1)
        );
        assert_eq!(b.to_string(), "6665:position2d:1");

        let c: DevAddr = "127.0.0.1:6666:ranger:2".parse().unwrap();
        assert_eq!(
            c.host, 0x0100_007f,
            "the value the real server sends for 127.0.0.1"
        );
        assert_eq!(c.to_string(), "127.0.0.1:6666:ranger:2");
    }

    #[test]
    fn bad_strings_say_what_is_wrong() {
        assert!(matches!(
            "laser".parse::<DevAddr>(),
            Err(AddrParseError::Shape(_))
        ));
        assert!(matches!(
            "lazer:0".parse::<DevAddr>(),
            Err(AddrParseError::UnknownInterface(_))
        ));
        assert!(matches!(
            "laser:x".parse::<DevAddr>(),
            Err(AddrParseError::Index(_))
        ));
        assert!(matches!(
            "99999:laser:0".parse::<DevAddr>(),
            Err(AddrParseError::Port(_))
        ));
    }

    #[test]
    fn wire_form_is_16_bytes() {
        let mut out = Vec::new();
        DevAddr {
            host: 0x0100_007f,
            robot: 6665,
            interf: Interface::LASER,
            index: 0,
        }
        .encode(&mut out);
        assert_eq!(
            out,
            [1, 0, 0, 0x7f, 0, 0, 0x1a, 0x09, 0, 0, 0, 6, 0, 0, 0, 0]
        );
    }
}
