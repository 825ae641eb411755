use super::*;

#[test]
fn a_leg_is_met_on_its_cells_not_its_outline() {
    // A 3 cm leg from 1.985 to 2.015 m: cells 99 to 100 of 2 cm (1.98 to 2.02 m). With
    // nothing else about, Stage's ray jumps the empty regions to the leg's (from x = 96
    // cells, 1.92 m) and walks on in whole cells from there: it meets cell 99 at x = 99,
    // 98.5 cells (1.97 m) from its start half a cell east of 0.
    let l = Placed::leg(2.0, 0.0);
    let d = l
        .cast_cells(0.02, (0.01, 0.0), (1.0, 0.0), 8.0, None)
        .unwrap();
    assert!((d.unwrap() - 1.97).abs() < 1e-9, "{d:?}");
    // A beam passing 1.5 cm north of the leg's edge still meets its cell row (0 to 2 cm
    // holds the edge at 1.5 cm; the beam at 3 cm does not).
    let beside = l
        .cast_cells(0.02, (0.01, 0.019), (1.0, 0.0), 8.0, None)
        .unwrap();
    assert!(beside.is_some());
    let clear = l
        .cast_cells(0.02, (0.01, 0.041), (1.0, 0.0), 8.0, None)
        .unwrap();
    assert_eq!(clear, None);
    // Away from it, or beyond the reach: nothing.
    assert_eq!(
        l.cast_cells(0.02, (0.01, 0.0), (-1.0, 0.0), 8.0, None)
            .unwrap(),
        None
    );
    assert_eq!(
        l.cast_cells(0.02, (0.01, 0.0), (1.0, 0.0), 1.0, None)
            .unwrap(),
        None
    );
}

#[test]
fn only_the_outline_is_solid() {
    let b = Placed {
        half_length: 0.5,
        half_width: 0.5,
        ..Placed::leg(0.0, 0.0)
    };
    // From inside, the far side.
    let d = b
        .cast_cells(0.02, (0.01, 0.01), (1.0, 0.0), 8.0, None)
        .unwrap();
    assert!((d.unwrap() - 0.49).abs() < 0.021, "{d:?}");
    // A box too large for a raster is cast exactly by the caller.
    let hall = Placed {
        half_length: 500.0,
        half_width: 500.0,
        ..b
    };
    assert!(
        hall.cast_cells(0.02, (0.0, 0.0), (1.0, 0.0), 8.0, None)
            .is_none()
    );
}

/// A body's walk jumps across the cells about it and visits what a walk cell by cell visits:
/// random rays across a hall strewn with walls, with a body placed at random near each.
#[test]
fn jumps_about_a_body_keep_the_path_cell_for_cell() {
    use crate::sim::WallRaster;
    use crate::sim::test_halls::{bordered, walled};
    use crate::sim::test_randoms::randoms;
    use crate::world::floor_i64;
    use std::f64::consts::TAU;

    let mut next = randoms(0x7A_4E_0F);
    let rows = bordered(80, 80, |_, _| next() < 0.02);
    let resolution = 0.05;
    let raster = WallRaster::of(&walled(&rows, 0.5, resolution)).expect("walls");
    let mut met = 0;
    for k in 0..4000 {
        let (x, y) = (38.0 * next() - 19.0, 38.0 * next() - 19.0);
        let (dy, dx) = (TAU * next()).sin_cos();
        let max = [2.0, 5.0, 8.0][k % 3];
        let along = max * next();
        let turn = TAU * next();
        let placed = Placed {
            x: x + dx * along + next() - 0.5,
            y: y + dy * along + next() - 0.5,
            sin: turn.sin(),
            cos: turn.cos(),
            half_length: 0.1 + 0.3 * next(),
            half_width: 0.1 + 0.2 * next(),
            shape: &[],
        };
        let cells = BoxCells::of(&placed, resolution).expect("cells");
        let span = |v: f64, s: f64| floor_i64((v + s * max) / resolution) + 64 * s as i64;
        let mut regions =
            RegionMap::over((span(x, -1.0), span(y, -1.0)), (span(x, 1.0), span(y, 1.0)));
        regions.hold_all(raster.regions());
        let scene = RayScene {
            range: max,
            regions: regions.into(),
        };
        // Beyond the body, as a scan's walks stop.
        let stop = along + 1.0;
        let jumped = cells.cast_in(&scene, (x, y), (dx, dy), stop);
        let ray = Ray::new(1.0 / resolution, (x, y), (dx, dy), max).expect("ray");
        let regions = Both(&cells.regions, &*scene.regions);
        assert_eq!(
            jumped,
            walk(&OneByOne(&cells), &regions, &ray, stop),
            "{k}: ({x}, {y}) along ({dx}, {dy}) to {max}"
        );
        met += usize::from(jumped.is_some());
    }
    assert!(met > 1000, "{met}");
}

/// A body's cells walked one at a time: its free cells are 1, however far from the body.
struct OneByOne<'a>(&'a BoxCells);

impl Cells for OneByOne<'_> {
    fn ahead(&self, x: i64, y: i64, q: usize) -> u32 {
        self.0.ahead(x, y, q).min(1)
    }
}
