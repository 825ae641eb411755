use super::*;
use crate::sim::WallRaster;
use crate::sim::test_halls::{bordered, walled};
use crate::sim::test_randoms::randoms;

/// A few solid cells, for rays walked by hand.
struct Dots<F: Fn(i64, i64) -> bool>(F);

impl<F: Fn(i64, i64) -> bool> Cells for Dots<F> {
    fn ahead(&self, x: i64, y: i64, _: usize) -> u32 {
        u32::from(!(self.0)(x, y))
    }
}

/// Every region but those listed holds something.
struct AllBut(Vec<(i64, i64)>);

impl Regions for AllBut {
    fn populated(&self, x: i64, y: i64) -> bool {
        !self.0.contains(&(x, y))
    }
}

/// A ray of slope 1/10 from (0.5, 0.9) cells of 2 cm, reaching `range`.
fn shallow(range: f64) -> Ray {
    let a = 0.1f64.atan();
    Ray::new(50.0, (0.01, 0.018), (a.cos(), a.sin()), range).unwrap()
}

#[test]
fn a_ray_steps_from_its_cells_middle_not_along_its_line() {
    // 1 m: 49 columns and 4 rows, so the path climbs a row after 6 columns; the line itself
    // (0.1 of a cell below the row's top) climbs after one.
    let ray = shallow(1.0);
    let cos = 0.1f64.atan().cos();
    let at = |x: i64, y: i64| {
        walk(
            &Dots(move |a, b| (a, b) == (x, y)),
            &AllBut(vec![]),
            &ray,
            1.0,
        )
    };
    // Met on the path below the line: 3 whole columns walked.
    let d = at(3, 0).expect("on the path");
    assert!((d - 3.0 / cos / 50.0).abs() < 1e-12, "{d}");
    // The cell the line enters is passed by.
    assert_eq!(at(3, 1), None);
    // Past the sixth column the path has climbed.
    assert!(at(6, 1).is_some() && at(7, 0).is_none());
}

#[test]
fn an_empty_region_is_jumped_along_the_line_keeping_the_steps() {
    // 2 m: 99 columns and 9 rows (a slope of 1/11, not 1/10).
    let ray = shallow(2.0);
    let cos = 0.1f64.atan().cos();
    let wall = Dots(|x, _| x == 64);
    // Region (1, 0) is empty: from (32.5, 3.9), where the path leaves region 0, the ray
    // moves along its line to x = 64 (row 7) and reads from there.
    let jumped = walk(&wall, &AllBut(vec![(1, 0)]), &ray, 2.0).unwrap();
    assert!((jumped - 63.5 / cos / 50.0).abs() < 1e-9, "{jumped}");
    let row7 = Dots(|x, y| (x, y) == (64, 7));
    assert!(walk(&row7, &AllBut(vec![(1, 0)]), &ray, 2.0).is_some());
    // Walked instead, the path is in row 6 there, 64 whole columns out.
    let walked = walk(&wall, &AllBut(vec![]), &ray, 2.0).unwrap();
    assert!((walked - 64.0 / cos / 50.0).abs() < 1e-9, "{walked}");
    assert!(walk(&row7, &AllBut(vec![]), &ray, 2.0).is_none());
}

/// A 6 x 6 m hall of 0.2 m cells around the origin, walls on Stage's raster of 5 cm.
fn hall() -> WallRaster {
    let rows = bordered(30, 30, |r, c| {
        (c == 17 && (5..20).contains(&r)) || (r % 7 == 0 && c == (r * 5) % 27 + 1)
    });
    WallRaster::of(&walled(&rows, 0.2, 0.05)).expect("walls")
}

/// Stage's walk one cell at a time: what the walk's jumps across free cells must keep.
fn stepped<C: Cells, R: Regions>(cells: &C, regions: &R, ray: &Ray, stop: f64) -> Option<f64> {
    let (sx, sy) = ray.step;
    let (ax, ay) = (ray.columns, ray.rows);
    let (mut at, mut error, mut left) = (ray.start, ay - ax, ax + ay);
    let mut crossings = None;
    while left > 0 {
        let (mut cx, mut cy) = (cell_of(at.0), cell_of(at.1));
        let region = (region_of(cx), region_of(cy));
        if regions.populated(region.0, region.1) {
            crossings = None;
            while (region_of(cx), region_of(cy)) == region && left > 0 {
                if cells.ahead(cx, cy, 0) == 0 {
                    let d = ray.distance(at);
                    return (d <= stop).then_some(d);
                }
                if error < 0 {
                    (cx, at.0, error) = (cx + sx, at.0 + sx as f64, error + 2 * ay);
                } else {
                    (cy, at.1, error) = (cy + sy, at.1 + sy as f64, error - 2 * ax);
                }
                left -= 1;
            }
        } else {
            let (to, moved) = crossings
                .get_or_insert_with(|| Crossings::new(ray, at))
                .next()?;
            at = to;
            left = (left as f64 - moved) as i64;
        }
        if ray.distance(at) > stop {
            return None;
        }
    }
    None
}

#[test]
fn jumps_across_free_cells_keep_the_path_cell_for_cell() {
    let raster = hall();
    let mut next = randoms(0x5A57E4);
    let mut hits = 0;
    for k in 0..3000 {
        let (x, y) = (5.6 * next() - 2.8, 5.6 * next() - 2.8);
        let (dy, dx) = (std::f64::consts::TAU * next()).sin_cos();
        let max = 1.0 + 6.0 * next();
        let ray = Ray::new(raster.per_metre, (x, y), (dx, dy), max).unwrap();
        let want = stepped(&raster, &raster, &ray, max);
        assert_eq!(
            walk(&raster, &raster, &ray, max),
            want,
            "{k}: ({x}, {y}) {dx} {dy}"
        );
        // With every region walked, too (the box's walk among the walls' regions).
        let all = AllBut(vec![]);
        assert_eq!(
            walk(&raster, &all, &ray, max),
            stepped(&raster, &all, &ray, max)
        );
        // And with a random third of the regions about the hall empty: a jump goes on only
        // into the regions its path enters, whatever lies beside them.
        let some = AllBut(
            (-4..4)
                .flat_map(|y| (-4..4).map(move |x| (x, y)))
                .filter(|_| next() < 0.33)
                .collect(),
        );
        assert_eq!(
            walk(&raster, &some, &ray, max),
            stepped(&raster, &some, &ray, max),
            "{k}: ({x}, {y}) {dx} {dy} among {:?}",
            some.0
        );
        hits += usize::from(want.is_some());
    }
    assert!(hits > 1500, "{hits}");
}

#[test]
fn free_steps_are_the_patterns_steps() {
    let mut next = randoms(0xF8EE);
    for _ in 0..20_000 {
        let columns = (next() * 60.0) as i64;
        let rows = (next() * 60.0) as i64;
        if columns + rows == 0 {
            continue;
        }
        let (most_x, most_y) = ((next() * 12.0) as i64, (next() * 12.0) as i64);
        let mut error = rows - columns;
        // Somewhere along the pattern.
        for _ in 0..(next() * 30.0) as i64 {
            error += if error < 0 { 2 * rows } else { -2 * columns };
        }
        let (mut i, mut j, mut e) = (0, 0, error);
        loop {
            let (ni, nj) = if e < 0 { (i + 1, j) } else { (i, j + 1) };
            if ni > most_x || nj > most_y {
                break;
            }
            e += if e < 0 { 2 * rows } else { -2 * columns };
            (i, j) = (ni, nj);
        }
        let got = free_steps(
            error,
            (columns, rows),
            divisors(columns, rows),
            most_x,
            most_y,
        );
        assert_eq!(got, (i, j), "{error} {columns} {rows} {most_x} {most_y}");
    }
}
