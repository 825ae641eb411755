//! A model drawn with blocks of different heights (Stage's `z [zmin zmax]`: a table's top and
//! legs) as rangers see it: for each band of heights, the blocks standing there. A beam at a
//! table's leg height meets the legs only.

use super::blocks::{Polygon, block_z, fit_to_size, raw_blocks};
use super::models::Model;
use crate::worldfile::WorldFileError;

/// The blocks standing between two heights above the model's base, m.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeSlice {
    pub low: f64,
    pub high: f64,
    /// Scaled to the model's size, in its own frame.
    pub shape: Vec<Polygon>,
}

/// The slices of `model` (its blocks' z ranges stretched over its height `size[2]`, as Stage
/// fits them), or none when every block spans the same heights (one shape serves all).
pub(super) fn shape_slices(
    model: &Model,
    size: [f64; 3],
) -> Result<Vec<ShapeSlice>, WorldFileError> {
    let raw = raw_blocks(model)?;
    let zs: Vec<[f64; 2]> = model
        .parts
        .iter()
        .filter(|p| p.kind == "block")
        .map(block_z)
        .collect();
    let (low, high) = zs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
            (lo.min(z[0]), hi.max(z[1]))
        });
    if high <= low || zs.iter().all(|z| z[0] <= low && z[1] >= high) {
        return Ok(Vec::new());
    }
    let scale = size[2] / (high - low);
    let zs: Vec<[f64; 2]> = zs
        .iter()
        .map(|z| [(z[0] - low) * scale, (z[1] - low) * scale])
        .collect();
    let shapes = fit_to_size(raw, [size[0], size[1]]);
    let mut cuts: Vec<f64> = zs.iter().flatten().copied().collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    Ok(cuts
        .windows(2)
        .map(|w| ShapeSlice {
            low: w[0],
            high: w[1],
            shape: shapes
                .iter()
                .zip(&zs)
                .filter(|(_, z)| z[0] <= w[0] && z[1] >= w[1])
                .map(|(s, _)| s.clone())
                .collect(),
        })
        .collect())
}

/// The slice a beam `z` above the model's base meets, if any stands there (ends included).
pub fn slice_at(slices: &[ShapeSlice], z: f64) -> Option<&ShapeSlice> {
    slices
        .iter()
        .find(|s| (s.low..=s.high).contains(&z) && !s.shape.is_empty())
}
