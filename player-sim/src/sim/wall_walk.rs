//! The walls' raster (`wall_raster.rs`) as Stage's rays walk it (`raster_walk.rs`): its free
//! squares are the cells a ray jumps across, and the regions holding a wall cell are the ones a
//! ray walks. Kept apart from both so that the walk knows nothing of how the walls were marked,
//! and the raster nothing of how rays cross it.

use super::raster_walk::{Cells, REGION_BITS, Ray, RegionMap, Regions, region_of, walk};
use super::wall_raster::WallRaster;

impl Cells for WallRaster {
    #[inline]
    fn ahead(&self, x: i64, y: i64, q: usize) -> u32 {
        WallRaster::ahead(self, x, y, q)
    }
}

impl WallRaster {
    /// Distance from `(x, y)` along the unit direction `(dx, dy)` to where a ray of a sensor
    /// reaching `max` meets the first wall cell on Stage's path, if it does (0 when it starts
    /// in one), with only the walls' regions walked.
    pub fn cast(&self, x: f64, y: f64, dx: f64, dy: f64, max: f64) -> Option<f64> {
        self.cast_among(x, y, dx, dy, max, self.regions())
    }

    /// [`WallRaster::cast`] walking the regions `regions` holds (the walls' and the bodies'
    /// about the sensor, its own robot's among them: Stage walks every region a body's cells
    /// lie in).
    pub(super) fn cast_among(
        &self,
        x: f64,
        y: f64,
        dx: f64,
        dy: f64,
        max: f64,
        regions: &RegionMap,
    ) -> Option<f64> {
        let ray = Ray::new(self.per_metre, (x, y), (dx, dy), max)?;
        walk(self, regions, &ray, max)
    }

    /// The regions holding a wall cell, worked out on the first ray: a region holds one when
    /// the free square from its south-west cell to the north-east is smaller than the region
    /// (beyond the raster's edge this errs towards holding one). A tiled raster (a large hall)
    /// reads its wall boxes instead, which would otherwise work out every tile here.
    pub(in crate::sim) fn regions(&self) -> &RegionMap {
        self.region_map.get_or_init(|| {
            let (low, high) = self.cell_bounds();
            let mut map = RegionMap::over(low, high);
            if self.is_tiled() {
                for &[x0, y0, x1, y1] in self.boxes.all() {
                    for y in region_of(y0)..=region_of(y1) {
                        for x in region_of(x0)..=region_of(x1) {
                            map.hold(x, y);
                        }
                    }
                }
                return map;
            }
            let side = 1 << REGION_BITS;
            for y in region_of(low.1)..=region_of(high.1) {
                for x in region_of(low.0)..=region_of(high.0) {
                    if self.ahead(x << REGION_BITS, y << REGION_BITS, 0) < side {
                        map.hold(x, y);
                    }
                }
            }
            map
        })
    }
}

impl Regions for WallRaster {
    #[inline]
    fn populated(&self, x: i64, y: i64) -> bool {
        self.regions().populated(x, y)
    }
}
