//! The resolutions a formula is typeset at, apart from the typesetting so that the error a bad
//! resolution gives ([`super::error`]) can name the limit without depending on the typesetter.

/// Raster resolution of a formula by default: 12 pt at this many dots per inch is about 30
/// pixels to the em, sharp on a label a few decimetres high.
pub const DEFAULT_DPI: u32 = 180;
/// The highest resolution accepted; the typesetter refuses more than 2400.
pub const MAX_DPI: u32 = 1200;
/// The em of a typeset formula, points: the typesetter's own default, which the resolutions
/// here are reckoned in.
pub const FONT_SIZE_PT: u32 = 12;

/// The resolution at which a formula's em is `em_px` pixels: for labels on screen, whose size
/// is given in pixels rather than in metres.
pub fn dpi_for_em(em_px: f32) -> u32 {
    let dpi = (em_px * 72.0 / FONT_SIZE_PT as f32).round();
    if dpi.is_finite() {
        (dpi as u32).clamp(1, MAX_DPI)
    } else {
        DEFAULT_DPI
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_em_in_pixels_gives_the_resolution() {
        assert_eq!(dpi_for_em(30.0), 180, "12 pt at 180 dpi is 30 pixels");
        assert_eq!(dpi_for_em(0.0), 1);
        assert_eq!(dpi_for_em(1e9), MAX_DPI);
        assert_eq!(dpi_for_em(f32::NAN), DEFAULT_DPI);
    }
}
