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
