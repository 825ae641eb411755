//! Device masks: which devices of the connected Player servers a handler applies to.
//!
//! `laser:sicklms200:*` means every `laser` whose driver is `sicklms200`, any index. Every
//! part may be `*` or left out; a mask may also name the server (`host`, `port`).

use std::fmt;

use player_proto::{DevAddr, Interface};

/// A device as a connected server reports it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FoundDevice {
    pub host: String,
    pub port: u16,
    pub addr: DevAddr,
    pub driver: String,
}

/// A pattern over devices. `None` in a field matches anything.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct DeviceMask {
    pub host: Option<String>,
    pub port: Option<u16>,
    pub interface: Option<Interface>,
    pub driver: Option<String>,
    pub index: Option<u16>,
}

/// Why a mask was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MaskError {
    #[error(
        "unknown interface {0:?} (expected a Player interface name such as laser, ranger, position2d)"
    )]
    Interface(String),
    #[error("index {0:?} is not a number from 0 to 65535 or *")]
    Index(String),
    #[error("port {0:?} is not a number from 1 to 65535 or *")]
    Port(String),
    #[error("mask {0:?} has more than three parts (expected interface:driver:index)")]
    Shape(String),
}

fn wildcard(value: Option<&str>) -> Option<&str> {
    value.map(str::trim).filter(|v| !v.is_empty() && *v != "*")
}

impl DeviceMask {
    /// Parses the string form `interface[:driver[:index]]`.
    pub fn parse(text: &str) -> Result<DeviceMask, MaskError> {
        let parts: Vec<&str> = text.split(':').collect();
        if parts.len() > 3 {
            return Err(MaskError::Shape(text.to_string()));
        }
        DeviceMask::from_parts(
            None,
            None,
            parts.first().copied(),
            parts.get(1).copied(),
            parts.get(2).copied(),
        )
    }

    /// Builds a mask from separately given fields (XML attributes); `*` or absent = any.
    pub fn from_parts(
        host: Option<&str>,
        port: Option<&str>,
        interface: Option<&str>,
        driver: Option<&str>,
        index: Option<&str>,
    ) -> Result<DeviceMask, MaskError> {
        let interface = wildcard(interface)
            .map(|name| Interface::from_name(name).ok_or_else(|| MaskError::Interface(name.into())))
            .transpose()?;
        let index = wildcard(index)
            .map(|i| i.parse().map_err(|_| MaskError::Index(i.into())))
            .transpose()?;
        let port = wildcard(port)
            .map(|p| match p.parse::<u16>() {
                Ok(n) if n > 0 => Ok(n),
                _ => Err(MaskError::Port(p.into())),
            })
            .transpose()?;
        Ok(DeviceMask {
            host: wildcard(host).map(str::to_string),
            port,
            interface,
            driver: wildcard(driver).map(str::to_string),
            index,
        })
    }

    /// Does this device fit the mask? Driver names compare exactly, host names ignoring case.
    pub fn matches(&self, device: &FoundDevice) -> bool {
        self.host
            .as_ref()
            .is_none_or(|h| h.eq_ignore_ascii_case(&device.host))
            && self.port.is_none_or(|p| p == device.port)
            && self.interface.is_none_or(|i| i == device.addr.interf)
            && self.driver.as_ref().is_none_or(|d| *d == device.driver)
            && self.index.is_none_or(|i| i == device.addr.index)
    }
}

impl fmt::Display for DeviceMask {
    /// The string form, `*` for every unset part.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let interface = self.interface.map_or("*".to_string(), |i| i.to_string());
        let driver = self.driver.as_deref().unwrap_or("*");
        let index = self.index.map_or("*".to_string(), |i| i.to_string());
        write!(f, "{interface}:{driver}:{index}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn device(port: u16, addr: &str, driver: &str) -> FoundDevice {
        FoundDevice {
            host: "localhost".into(),
            port,
            addr: addr.parse().unwrap(),
            driver: driver.into(),
        }
    }

    #[test]
    fn string_form_with_wildcards() {
        let mask = DeviceMask::parse("laser:sicklms200:*").unwrap();
        assert!(mask.matches(&device(6665, "laser:0", "sicklms200")));
        assert!(mask.matches(&device(6666, "laser:3", "sicklms200")));
        assert!(!mask.matches(&device(6665, "laser:0", "stage")));
        assert!(!mask.matches(&device(6665, "ranger:0", "sicklms200")));
        assert_eq!(mask.to_string(), "laser:sicklms200:*");
    }

    #[test]
    fn index_port_and_host() {
        let mask = DeviceMask::from_parts(
            Some("LOCALHOST"),
            Some("6666"),
            Some("ranger"),
            None,
            Some("1"),
        )
        .unwrap();
        assert!(mask.matches(&device(6666, "ranger:1", "stage")));
        assert!(!mask.matches(&device(6665, "ranger:1", "stage")));
        assert!(!mask.matches(&device(6666, "ranger:0", "stage")));
    }

    #[test]
    fn everything_matches_the_empty_mask() {
        assert!(
            DeviceMask::parse("*")
                .unwrap()
                .matches(&device(1, "camera:0", "x"))
        );
    }

    #[test]
    fn bad_masks_say_why() {
        assert_eq!(
            DeviceMask::parse("lazer:*:*"),
            Err(MaskError::Interface("lazer".into()))
        );
        assert_eq!(
            DeviceMask::parse("laser:*:x"),
            Err(MaskError::Index("x".into()))
        );
        assert!(matches!(
            DeviceMask::parse("a:b:c:d"),
            Err(MaskError::Shape(_))
        ));
    }
}
