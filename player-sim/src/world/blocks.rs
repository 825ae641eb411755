//! Stage's `block( points N point[0] [x y] … z [zmin zmax] )` shapes. As Stage does, the
//! points of all of a model's blocks are taken together and stretched to fill the model's
//! `size`: their common bounding box is centred on the model's origin and scaled along x and y
//! separately (so the units the points are written in do not matter, only their proportions).

use super::Pose;
use super::models::Model;
use super::properties::{err, number, numbers};
use crate::worldfile::{Block, WorldFileError};

/// A polygon's corners in metres, in order.
pub type Polygon = Vec<[f64; 2]>;

/// More corners than this in one block is refused (a typo such as `points 1e9`, not a shape).
const MAX_POINTS: f64 = 100_000.0;

/// The blocks of `model`, scaled to its `size` x and y, in the model's own frame; empty when
/// it has none.
pub(super) fn model_blocks(model: &Model, size: [f64; 2]) -> Result<Vec<Polygon>, WorldFileError> {
    if !size.iter().all(|s| s.is_finite()) {
        return Err(err(&model.pos, "a model with blocks needs a finite size"));
    }
    Ok(fit_to_size(raw_blocks(model)?, size))
}

/// The points of `model`'s blocks as written.
pub(super) fn raw_blocks(model: &Model) -> Result<Vec<Polygon>, WorldFileError> {
    model
        .parts
        .iter()
        .filter(|p| p.kind == "block")
        .map(block_points)
        .collect()
}

/// A block's `z [zmin zmax]` as written, Stage's `[0 1]` when it gives none.
pub(super) fn block_z(block: &Block) -> [f64; 2] {
    block
        .get("z")
        .and_then(|p| p.value.numbers())
        .filter(|n| n.len() >= 2 && n[0].is_finite() && n[1].is_finite())
        .map_or([0.0, 1.0], |n| [n[0], n[1]])
}

/// Does `model` draw itself with blocks?
pub(super) fn has_blocks(model: &Model) -> bool {
    model.parts.iter().any(|p| p.kind == "block")
}

/// The blocks of `model` that do not span its full height (their `z` range is not that of all
/// its blocks together): Stage's rays pass over or under them at other heights, ours, in the
/// plane, do not.
pub(super) fn partial_height_blocks(model: &Model) -> Vec<&Block> {
    let z_of = |b: &Block| {
        b.get("z")
            .and_then(|p| p.value.numbers())
            .filter(|n| n.len() >= 2)
            .map(|n| [n[0], n[1]])
    };
    let blocks: Vec<&Block> = model.parts.iter().filter(|p| p.kind == "block").collect();
    let ranges: Vec<Option<[f64; 2]>> = blocks.iter().map(|b| z_of(b)).collect();
    let (low, high) = ranges
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
            (lo.min(z[0]), hi.max(z[1]))
        });
    blocks
        .into_iter()
        .zip(ranges)
        .filter(|(_, z)| z.is_some_and(|z| z[0] > low || z[1] < high))
        .map(|(b, _)| b)
        .collect()
}

/// One block's points as written.
fn block_points(block: &Block) -> Result<Polygon, WorldFileError> {
    let Some(count) = block.get("points") else {
        return Err(err(&block.pos, "block without `points N`"));
    };
    let n = number(count)?;
    if !(3.0..=MAX_POINTS).contains(&n) || n.fract() != 0.0 {
        return Err(err(
            &count.pos,
            format!("points must be a whole number from 3 to {MAX_POINTS}, not {n}"),
        ));
    }
    let mut points = Vec::with_capacity(n as usize);
    for i in 0..n as usize {
        let key = format!("point[{i}]");
        let Some(p) = block.get(&key) else {
            return Err(err(
                &block.pos,
                format!("block of {n} points has no {key} [x y]"),
            ));
        };
        let xy = numbers(Some(p), 2, &p.pos)?;
        if !(xy[0].is_finite() && xy[1].is_finite()) {
            return Err(err(&p.pos, format!("{key} must be finite")));
        }
        points.push([xy[0], xy[1]]);
    }
    if let Some(z) = block.get("z") {
        numbers(Some(z), 2, &z.pos)?;
    }
    Ok(points)
}

/// Stretches the blocks' common bounding box onto `size`, centred on the origin.
pub(super) fn fit_to_size(blocks: Vec<Polygon>, size: [f64; 2]) -> Vec<Polygon> {
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in blocks.iter().flatten() {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    // A flat extent (all points on a line) keeps its zero width rather than dividing by zero.
    let scale: [f64; 2] = std::array::from_fn(|k| size[k] / (max[k] - min[k]).max(f64::EPSILON));
    let centre: [f64; 2] = std::array::from_fn(|k| (min[k] + max[k]) / 2.0);
    blocks
        .into_iter()
        .map(|polygon| {
            polygon
                .into_iter()
                .map(|p| std::array::from_fn(|k| (p[k] - centre[k]) * scale[k]))
                .collect()
        })
        .collect()
}

/// `polygon` (in a model's frame) placed at the model's `pose`.
pub fn placed(polygon: &[[f64; 2]], pose: Pose) -> Polygon {
    let (s, c) = pose.a.sin_cos();
    polygon
        .iter()
        .map(|&[x, y]| [pose.x + c * x - s * y, pose.y + s * x + c * y])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::worldfile::{Item, parse_text};

    fn model(text: &str) -> Model {
        let Item::Block(block) = parse_text(text, "t.world").unwrap().remove(0) else {
            panic!("not a block")
        };
        Model {
            kind: "model".into(),
            declared: "model".into(),
            properties: block.properties,
            children: Vec::new(),
            parts: block.children,
            pos: block.pos,
        }
    }

    #[test]
    fn points_are_stretched_to_the_model_size_around_its_origin() {
        let m = model(
            "model( block( points 3 point[0] [0 0] point[1] [10 0] point[2] [10 5] z [0 1] ) \
             block( points 4 point[0] [0 0] point[1] [1 0] point[2] [1 10] point[3] [0 10] ) )",
        );
        let blocks = model_blocks(&m, [4.0, 2.0]).unwrap();
        assert_eq!(blocks.len(), 2);
        // Together the blocks span 10 x 10 units: 0.4 m per unit in x, 0.2 m in y.
        assert_eq!(blocks[0], vec![[-2.0, -1.0], [2.0, -1.0], [2.0, 0.0]]);
        assert_eq!(blocks[1][2], [-1.6, 1.0]);
    }

    #[test]
    fn malformed_blocks_say_where() {
        let few = model("model(\n block( points 2 point[0] [0 0] point[1] [1 1] ) )");
        let e = model_blocks(&few, [1.0, 1.0]).unwrap_err().to_string();
        assert!(e.starts_with("t.world:2:") && e.contains("from 3"), "{e}");
        let missing = model("model( block( points 3 point[0] [0 0] point[2] [1 1] ) )");
        let e = model_blocks(&missing, [1.0, 1.0]).unwrap_err().to_string();
        assert!(e.contains("no point[1]"), "{e}");
        let huge = model("model( block( points 1e12 ) )");
        assert!(model_blocks(&huge, [1.0, 1.0]).is_err());
    }

    #[test]
    fn blocks_lower_than_the_others_are_told_apart() {
        let m = model(
            "model( block( points 3 point[0] [0 0] point[1] [1 0] point[2] [0 1] z [0 1] ) \
             block( points 3 point[0] [0 0] point[1] [1 0] point[2] [0 1] z [0 0.2] ) \
             block( points 3 point[0] [0 0] point[1] [1 0] point[2] [0 1] ) )",
        );
        let low = partial_height_blocks(&m);
        assert_eq!(low.len(), 1);
        assert_eq!(
            low[0].get("z").unwrap().value.numbers(),
            Some(vec![0.0, 0.2])
        );
    }

    #[test]
    fn placing_rotates_then_moves() {
        let pose = Pose {
            x: 1.0,
            y: 2.0,
            a: std::f64::consts::FRAC_PI_2,
        };
        let p = placed(&[[1.0, 0.0]], pose);
        assert!((p[0][0] - 1.0).abs() < 1e-12 && (p[0][1] - 3.0).abs() < 1e-12);
    }
}
