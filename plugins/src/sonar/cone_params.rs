//! The parameters of range cones, shared by `libpv3d_sonar` and `libpv3d_ranger`: read from
//! the composition with defaults, edited in the plugin's panel, written back on save.
//!
//! `drawCones` (1) fills each cone, `drawConeOutline` (1) outlines it, `color` (#50c8a0),
//! `alpha` (0.3, opacity of the fill, 0–1), `coneAngle` (15, full opening in degrees, used
//! when the device does not say), `maxConeLength` (20 m), `maxRange` (none: the device's, when
//! it says) — readings at or beyond it are "no echo", drawn as a faint outline.

use crate::sonar::cones::ConeStyle;
use framework::config::{ConfigValueError, PluginConfig};

/// Reads the cone parameters, with the defaults of [`ConeStyle::default`].
pub fn cone_style_from_config(config: &PluginConfig) -> Result<ConeStyle, ConfigValueError> {
    let defaults = ConeStyle::default();
    let alpha = config.number("alpha", f64::from(defaults.fill_alpha) / 255.0, 0.0..=1.0)?;
    let width = config.number(
        "coneAngle",
        f64::from(defaults.width.to_degrees()).round(),
        0.0..=360.0,
    )?;
    Ok(ConeStyle {
        fill: config.bool("drawCones", defaults.fill)?,
        outline: config.bool("drawConeOutline", defaults.outline)?,
        color: config.color("color", defaults.color)?,
        fill_alpha: (alpha * 255.0).round() as u8,
        width: (width as f32).to_radians(),
        max_length: config.number("maxConeLength", f64::from(defaults.max_length), 0.0..=1e4)?
            as f32,
        no_return: config.number("maxRange", f64::INFINITY, 0.0..=1e4)? as f32,
    })
}

/// Writes the state a person can change in the panel back into `config`.
pub fn write_cone_style(style: &ConeStyle, config: &mut PluginConfig) {
    config.set_bool("drawCones", style.fill);
    config.set_bool("drawConeOutline", style.outline);
    config.set(
        "alpha",
        format!("{:.2}", f32::from(style.fill_alpha) / 255.0),
    );
}

/// The cone controls of a plugin's panel. Returns whether anything changed.
pub fn cone_style_ui(ui: &mut egui::Ui, style: &mut ConeStyle) -> bool {
    let before = *style;
    ui.checkbox(&mut style.fill, "fill cones");
    ui.checkbox(&mut style.outline, "outline cones");
    ui.add(egui::Slider::new(&mut style.fill_alpha, 0..=255).text("opacity"));
    before != *style
}

#[cfg(test)]
mod tests {
    use super::*;
    use framework::config::Param;

    #[test]
    fn defaults_then_values_then_written_back() {
        let mut config = PluginConfig::default();
        assert_eq!(
            cone_style_from_config(&config).unwrap(),
            ConeStyle::default()
        );
        config.params.push(Param::new("alpha", "1"));
        config.params.push(Param::new("drawCones", "0"));
        config.params.push(Param::new("coneAngle", "30"));
        let style = cone_style_from_config(&config).unwrap();
        assert_eq!(style.fill_alpha, 255);
        assert!(!style.fill);
        assert!((style.width - 30f32.to_radians()).abs() < 1e-6);
        let mut saved = PluginConfig::default();
        write_cone_style(&style, &mut saved);
        assert_eq!(saved.param("alpha").unwrap().text, "1.00");
        assert_eq!(saved.param("drawCones").unwrap().text, "0");
    }

    #[test]
    fn an_angle_out_of_range_is_refused() {
        let mut config = PluginConfig::default();
        config.params.push(Param::new("coneAngle", "400"));
        assert!(cone_style_from_config(&config).is_err());
    }
}
