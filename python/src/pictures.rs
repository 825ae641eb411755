//! PNG pictures of what a robot sees, for Jupyter's `_repr_png_`: a scan from above, an
//! occupancy grid, a camera frame.

use std::io::Cursor;

use image::{ImageFormat, Rgb, RgbImage};
use pyo3::PyResult;
use pyo3::exceptions::PyValueError;

/// A camera frame decoded to RGB bytes, row by row from the top.
pub struct RgbFrame {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<u8>,
}

/// Side of a scan picture, pixels.
const SCAN_SIZE: u32 = 320;

fn encode(image: &RgbImage) -> PyResult<Vec<u8>> {
    let mut out = Cursor::new(Vec::new());
    image
        .write_to(&mut out, ImageFormat::Png)
        .map_err(|e| PyValueError::new_err(format!("cannot make the PNG: {e}")))?;
    Ok(out.into_inner())
}

/// The scan's end points seen from above, the robot (red) in the middle facing up, the
/// picture spanning the sensor's range (or the farthest point when the range is unknown).
pub fn scan_png(points: &[[f32; 2]], max_range: f32) -> PyResult<Vec<u8>> {
    let farthest = points
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .filter(|d| d.is_finite())
        .fold(0.0f32, f32::max);
    let reach = if max_range.is_finite() && max_range > 0.0 {
        max_range
    } else {
        farthest.max(1.0)
    };
    let half = SCAN_SIZE as f32 / 2.0;
    let scale = (half - 4.0) / reach;
    let mut image = RgbImage::from_pixel(SCAN_SIZE, SCAN_SIZE, Rgb([255, 255, 255]));
    let mut dot = |x: f32, y: f32, colour: Rgb<u8>, radius: i32| {
        // Robot frame x forward (up), y left (left).
        let (u, v) = (half - y * scale, half - x * scale);
        for du in -radius..=radius {
            for dv in -radius..=radius {
                let (pu, pv) = (u as i32 + du, v as i32 + dv);
                if (0..SCAN_SIZE as i32).contains(&pu) && (0..SCAN_SIZE as i32).contains(&pv) {
                    image.put_pixel(pu as u32, pv as u32, colour);
                }
            }
        }
    };
    for p in points
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
    {
        dot(p[0], p[1], Rgb([20, 60, 160]), 1);
    }
    dot(0.0, 0.0, Rgb([200, 30, 30]), 3);
    encode(&image)
}

/// An occupancy grid, north up: free white, occupied black, unknown grey.
pub fn grid_png(cells: &[i8], width: usize, height: usize) -> PyResult<Vec<u8>> {
    let (w, h) = (u32::try_from(width), u32::try_from(height));
    let (Ok(w), Ok(h)) = (w, h) else {
        return Err(PyValueError::new_err("the map is too large for a picture"));
    };
    let image = RgbImage::from_fn(w, h, |x, y| {
        let row = height - 1 - y as usize;
        let shade = match cells[row * width + x as usize] {
            c if c < 0 => 255,
            0 => 180,
            _ => 0,
        };
        Rgb([shade, shade, shade])
    });
    encode(&image)
}

/// A decoded camera frame.
pub fn rgb_png(frame: &RgbFrame) -> PyResult<Vec<u8>> {
    let image = RgbImage::from_raw(
        frame.width as u32,
        frame.height as u32,
        frame.pixels.clone(),
    )
    .ok_or_else(|| PyValueError::new_err("the frame's size and pixels disagree"))?;
    encode(&image)
}
