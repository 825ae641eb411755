//! The 32-byte identification banner a Player server sends before anything else.

use std::fmt;

/// Banner length on the wire (`PLAYER_IDENT_STRLEN`).
pub const BANNER_LEN: usize = 32;

const PREFIX: &[u8] = b"Player v.";

/// A server's banner: `"Player v."` and the version, NUL-padded to 32 bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Banner {
    /// The version text as sent, e.g. `"3.1.1-dev"`.
    pub version: String,
    pub major: u32,
    pub minor: u32,
}

/// Why a banner was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BannerError {
    #[error("not a Player server: banner {0:?} does not start with \"Player v.\"")]
    NotPlayer(String),
    #[error("banner version {0:?} is not a version number")]
    BadVersion(String),
    #[error(
        "Player {0} server: Player 1.x speaks an older, pre-XDR protocol that this client does not implement"
    )]
    Player1(String),
}

impl Banner {
    /// The banner a Player server of this version would send.
    pub fn new(version: &str) -> Result<Banner, BannerError> {
        let (major, minor) = parse_version(version)?;
        Ok(Banner {
            version: version.to_string(),
            major,
            minor,
        })
    }

    /// Parses a received banner. Refuses anything that is not Player, and Player 1.x.
    pub fn parse(raw: &[u8; BANNER_LEN]) -> Result<Banner, BannerError> {
        let end = raw.iter().position(|&b| b == 0).unwrap_or(BANNER_LEN);
        let text = String::from_utf8_lossy(&raw[..end]).into_owned();
        let Some(version) = text.strip_prefix(std::str::from_utf8(PREFIX).expect("ascii")) else {
            return Err(BannerError::NotPlayer(text));
        };
        let banner = Banner::new(version)?;
        if banner.major < 2 {
            return Err(BannerError::Player1(banner.version));
        }
        Ok(banner)
    }

    /// The 32 bytes to send: text, then NULs (byte 31 is always NUL, as Player's 31-byte
    /// formatting limit guarantees).
    pub fn to_bytes(&self) -> [u8; BANNER_LEN] {
        let mut raw = [0u8; BANNER_LEN];
        let text = format!("Player v.{}", self.version);
        let n = text.len().min(BANNER_LEN - 1);
        raw[..n].copy_from_slice(&text.as_bytes()[..n]);
        raw
    }

    /// Player 2.0.x frames messages like 3.x but lays many bodies out differently (floats
    /// where 3.x has doubles); a client should warn rather than misread silently.
    pub fn has_3x_layouts(&self) -> bool {
        (self.major, self.minor) >= (2, 1)
    }
}

impl fmt::Display for Banner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Player v.{}", self.version)
    }
}

fn parse_version(version: &str) -> Result<(u32, u32), BannerError> {
    let bad = || BannerError::BadVersion(version.to_string());
    let mut numbers = version.split(['.', '-']);
    let major = numbers
        .next()
        .and_then(|n| n.parse().ok())
        .ok_or_else(bad)?;
    let minor = numbers
        .next()
        .and_then(|n| n.parse().ok())
        .ok_or_else(bad)?;
    Ok((major, minor))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raw(text: &str) -> [u8; BANNER_LEN] {
        let mut raw = [0u8; BANNER_LEN];
        raw[..text.len()].copy_from_slice(text.as_bytes());
        raw
    }

    #[test]
    fn parses_the_real_servers_banner() {
        let b = Banner::parse(&raw("Player v.3.1.1-dev")).unwrap();
        assert_eq!((b.major, b.minor, b.version.as_str()), (3, 1, "3.1.1-dev"));
        assert!(b.has_3x_layouts());
        assert_eq!(b.to_bytes(), raw("Player v.3.1.1-dev"));
    }

    #[test]
    fn refuses_player_1_and_strangers() {
        assert_eq!(
            Banner::parse(&raw("Player v.1.6.5")),
            Err(BannerError::Player1("1.6.5".into()))
        );
        assert!(matches!(
            Banner::parse(&raw("SSH-2.0-OpenSSH")),
            Err(BannerError::NotPlayer(_))
        ));
        assert!(matches!(
            Banner::parse(&raw("Player v.x")),
            Err(BannerError::BadVersion(_))
        ));
        assert!(
            !Banner::parse(&raw("Player v.2.0.5"))
                .unwrap()
                .has_3x_layouts()
        );
    }
}
