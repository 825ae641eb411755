//! A plugin's parameters as the composition gave them, and written back on save.
//!
//! pv3d turns each `<plugin>` element into a [`PluginConfig`]; a plugin reads its parameters
//! with defaults for every one, and returns its current state as a `PluginConfig` when the
//! composition is saved. Errors name the parameter and where it was written.

use player_proto::DevAddr;

/// One parameter element: `<fillLaserCspace>1</fillLaserCspace>` or
/// `<parentNode interface="position2d" index="0"/>`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Param {
    pub name: String,
    pub text: String,
    pub attributes: Vec<(String, String)>,
    /// `file:line:col` of the element, for error messages.
    pub origin: String,
}

impl Param {
    pub fn new(name: &str, text: impl Into<String>) -> Param {
        Param {
            name: name.to_string(),
            text: text.into(),
            ..Param::default()
        }
    }

    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }
}

/// The device a plugin was made for (from its `<playerDeviceMask>`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeviceRef {
    pub host: String,
    pub port: u16,
    pub addr: DevAddr,
    pub driver: String,
}

impl std::fmt::Display for DeviceRef {
    /// `laser:0@localhost:6665`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}@{}:{}",
            self.addr.interf, self.addr.index, self.host, self.port
        )
    }
}

/// A plugin's configuration.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PluginConfig {
    pub library: String,
    pub id: String,
    pub device: Option<DeviceRef>,
    pub params: Vec<Param>,
    /// `file:line:col` of the `<plugin>` element.
    pub origin: String,
    /// The folder of the file the plugin was written in: file parameters are relative to it.
    pub base_dir: std::path::PathBuf,
}

/// A parameter with a value the plugin cannot use.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{origin}: <{param}> of {library}: {message}")]
pub struct ConfigValueError {
    pub origin: String,
    pub library: String,
    pub param: String,
    pub message: String,
}

impl PluginConfig {
    pub fn param(&self, name: &str) -> Option<&Param> {
        self.params.iter().find(|p| p.name == name)
    }

    fn error(&self, param: &Param, message: String) -> ConfigValueError {
        ConfigValueError {
            origin: if param.origin.is_empty() {
                self.origin.clone()
            } else {
                param.origin.clone()
            },
            library: self.library.clone(),
            param: param.name.clone(),
            message,
        }
    }

    /// A boolean parameter (`1`/`0`, `true`/`false`, `yes`/`no`), or `default`.
    pub fn bool(&self, name: &str, default: bool) -> Result<bool, ConfigValueError> {
        let Some(p) = self.param(name) else {
            return Ok(default);
        };
        match p.text.trim().to_ascii_lowercase().as_str() {
            "1" | "true" | "yes" | "on" => Ok(true),
            "0" | "false" | "no" | "off" => Ok(false),
            other => Err(self.error(
                p,
                format!("expected 1 or 0 (true or false), found {other:?}"),
            )),
        }
    }

    /// A number parameter within `range`, or `default`.
    pub fn number(
        &self,
        name: &str,
        default: f64,
        range: std::ops::RangeInclusive<f64>,
    ) -> Result<f64, ConfigValueError> {
        let Some(p) = self.param(name) else {
            return Ok(default);
        };
        let value: f64 =
            p.text.trim().parse().map_err(|_| {
                self.error(p, format!("expected a number, found {:?}", p.text.trim()))
            })?;
        if !range.contains(&value) {
            return Err(self.error(
                p,
                format!("{value} is outside {}..={}", range.start(), range.end()),
            ));
        }
        Ok(value)
    }

    /// A colour parameter: `#rrggbb`, `#rrggbbaa` or a few names; or `default`.
    pub fn color(
        &self,
        name: &str,
        default: crate::scene::Rgba,
    ) -> Result<crate::scene::Rgba, ConfigValueError> {
        let Some(p) = self.param(name) else {
            return Ok(default);
        };
        parse_color(p.text.trim()).ok_or_else(|| {
            self.error(
                p,
                format!(
                    "expected a colour such as #ff8000 or red, found {:?}",
                    p.text.trim()
                ),
            )
        })
    }

    /// A list of numbers (`20 16`), exactly `n` of them, or `None` when absent.
    pub fn numbers(&self, name: &str, n: usize) -> Result<Option<Vec<f64>>, ConfigValueError> {
        let Some(p) = self.param(name) else {
            return Ok(None);
        };
        let values: Option<Vec<f64>> = p.text.split_whitespace().map(|t| t.parse().ok()).collect();
        match values {
            Some(v) if v.len() == n => Ok(Some(v)),
            _ => Err(self.error(
                p,
                format!(
                    "expected {n} numbers separated by spaces, found {:?}",
                    p.text.trim()
                ),
            )),
        }
    }

    /// A file parameter, resolved against the composition's folder.
    pub fn path(&self, name: &str) -> Option<std::path::PathBuf> {
        self.text(name).map(|t| self.base_dir.join(t))
    }

    /// Text parameter, or `None`.
    pub fn text(&self, name: &str) -> Option<&str> {
        self.param(name)
            .map(|p| p.text.trim())
            .filter(|t| !t.is_empty())
    }

    /// Sets a flag as [`PluginConfig::bool`] reads it back: `1` or `0`.
    pub fn set_bool(&mut self, name: &str, value: bool) {
        self.set(name, if value { "1" } else { "0" });
    }

    /// `kind` followed by the device this plugin draws (`Laser laser:0@host:6665`), or `kind`
    /// alone for a plugin with no device: the item tree's and the scene's names.
    pub fn titled(&self, kind: &str) -> String {
        match &self.device {
            Some(d) => format!("{kind} {d}"),
            None => kind.to_string(),
        }
    }

    /// Sets (or adds) a parameter's text, for writing state back.
    pub fn set(&mut self, name: &str, text: impl Into<String>) {
        let text = text.into();
        match self.params.iter_mut().find(|p| p.name == name) {
            Some(p) => p.text = text,
            None => self.params.push(Param::new(name, text)),
        }
    }
}

/// `#rrggbb`, `#rrggbbaa`, or one of a few colour names.
pub fn parse_color(text: &str) -> Option<crate::scene::Rgba> {
    use crate::scene::Rgba;
    let named = match text.to_ascii_lowercase().as_str() {
        "red" => Some(Rgba::rgb(230, 60, 50)),
        "green" => Some(Rgba::rgb(60, 190, 80)),
        "blue" => Some(Rgba::rgb(60, 110, 230)),
        "yellow" => Some(Rgba::rgb(240, 210, 50)),
        "cyan" => Some(Rgba::rgb(60, 210, 220)),
        "magenta" => Some(Rgba::rgb(220, 70, 200)),
        "orange" => Some(Rgba::rgb(250, 150, 40)),
        "white" => Some(Rgba::WHITE),
        "black" => Some(Rgba::BLACK),
        "gray" | "grey" => Some(Rgba::rgb(128, 128, 128)),
        _ => None,
    };
    if named.is_some() {
        return named;
    }
    let hex = text.strip_prefix('#')?;
    let byte = |i: usize| u8::from_str_radix(hex.get(i..i + 2)?, 16).ok();
    match hex.len() {
        6 => Some(Rgba::rgb(byte(0)?, byte(2)?, byte(4)?)),
        8 => Some(Rgba([byte(0)?, byte(2)?, byte(4)?, byte(6)?])),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Rgba;

    fn config(params: &[(&str, &str)]) -> PluginConfig {
        PluginConfig {
            library: "libpv3d_test".into(),
            origin: "a.xml:3:5".into(),
            params: params
                .iter()
                .map(|(n, t)| Param {
                    origin: format!("a.xml:4:{}", n.len()),
                    ..Param::new(n, *t)
                })
                .collect(),
            ..PluginConfig::default()
        }
    }

    #[test]
    fn defaults_apply_and_bad_values_say_where() {
        let c = config(&[
            ("fill", "1"),
            ("width", "3.5"),
            ("color", "#ff8000"),
            ("bad", "maybe"),
        ]);
        assert!(c.bool("fill", false).unwrap());
        assert!(c.bool("absent", true).unwrap());
        assert_eq!(c.number("width", 1.0, 0.0..=10.0).unwrap(), 3.5);
        assert_eq!(
            c.color("color", Rgba::WHITE).unwrap(),
            Rgba::rgb(255, 128, 0)
        );
        let err = c.bool("bad", false).unwrap_err().to_string();
        assert_eq!(
            err,
            "a.xml:4:3: <bad> of libpv3d_test: expected 1 or 0 (true or false), found \"maybe\""
        );
        assert!(c.number("width", 1.0, 0.0..=2.0).is_err());
    }
}
