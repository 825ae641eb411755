use super::*;

fn raster_of(cells: &[(i64, i64)]) -> WallRaster {
    let (x0, y0) = (-10, -10);
    let mut r = WallRaster {
        resolution: 0.02,
        per_metre: 50.0,
        first: (x0, y0),
        width: 40,
        height: 30,
        clearance: vec![MAX_CLEARANCE; 1200],
        ahead: Default::default(),
        boxes: Default::default(),
        tiles: None,
        region_map: Default::default(),
    };
    for &(x, y) in cells {
        r.mark(x, y);
    }
    r.count_clearance();
    r
}

#[test]
fn clearance_is_the_distance_to_the_nearest_wall_cell() {
    let walls = [(0, 0), (5, -3), (12, 12), (-8, 15)];
    let r = raster_of(&walls);
    for y in -10..20 {
        for x in -10..30 {
            let want = walls
                .iter()
                .map(|&(a, b)| (a - x).abs().max((b - y).abs()))
                .min()
                .unwrap();
            assert_eq!(i64::from(r.clearance(x, y)), want, "({x}, {y})");
        }
    }
    // Outside: at least a cell, growing with the distance.
    assert_eq!(r.clearance(-40, 0), 30);
}

#[test]
fn a_line_is_four_connected_and_ends_at_both_ends() {
    let mut r = raster_of(&[]);
    r.mark_line((-5, -5), (7, 2));
    let walls: Vec<(i64, i64)> = (-10..30)
        .flat_map(|x| (-10..20).map(move |y| (x, y)))
        .filter(|&(x, y)| r.clearance[((y + 10) * 40 + x + 10) as usize] == 0)
        .collect();
    assert_eq!(walls.len(), 12 + 7 + 1);
    assert!(walls.contains(&(-5, -5)) && walls.contains(&(7, 2)));
}

/// A region holds a wall when one of its cells is a wall, and only then: the regions are told
/// from their corner cells' squares, and the raster's first cell lies on no region's corner.
#[test]
fn the_walls_regions_are_those_holding_a_wall_cell() {
    use crate::sim::raster_walk::{Regions, region_of};
    use crate::sim::test_randoms::randoms;
    let mut next = randoms(0x4E61);
    for _ in 0..20 {
        let mut r = WallRaster {
            first: (-70, -70),
            width: 140,
            height: 140,
            clearance: vec![MAX_CLEARANCE; 140 * 140],
            ..raster_of(&[])
        };
        // Regions -2 to 1 each way lie wholly within the raster.
        let walls: Vec<(i64, i64)> = (0..6)
            .map(|_| ((next() * 128.0) as i64 - 64, (next() * 128.0) as i64 - 64))
            .collect();
        for &(x, y) in &walls {
            r.mark(x, y);
        }
        r.count_clearance();
        for ry in -2..2 {
            for rx in -2..2 {
                let held = walls
                    .iter()
                    .any(|&(x, y)| (region_of(x), region_of(y)) == (rx, ry));
                assert_eq!(r.regions().populated(rx, ry), held, "region ({rx}, {ry})");
            }
        }
    }
}
