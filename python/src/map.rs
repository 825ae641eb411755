//! `robot.map(i)`: the occupancy grid a map server holds, fetched tile by tile and handed to
//! Python as one numpy array.

use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use player_proto::interfaces::map::{Map as MapMessages, MapData};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;

use crate::link::DeviceCore;

/// Cells asked for per request: a 640 x 640 tile stays well under any server's message limit.
const TILE: u32 = 640;

/// An occupancy grid: `grid[row, col]`, row 0 at the bottom (lowest y); -1 free, 0 unknown,
/// +1 occupied. Cell `(row, col)` covers `origin + (col, row) * resolution`.
#[pyclass(frozen, module = "player3")]
pub struct Grid {
    cells: Arc<Vec<i8>>,
    width: usize,
    height: usize,
    /// Metres per cell.
    #[pyo3(get)]
    resolution: f64,
    /// `(x, y, yaw)` of the corner of cell (0, 0), m.
    #[pyo3(get)]
    origin: (f64, f64, f64),
}

#[pymethods]
impl Grid {
    /// The cells, `int8`, height x width.
    #[getter]
    fn grid<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i8>>> {
        let flat = PyArray1::from_slice(py, &self.cells);
        flat.reshape([self.height, self.width])
    }

    /// `(height, width)` in cells.
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.height, self.width)
    }

    fn __repr__(&self) -> String {
        format!(
            "<Grid {} x {} cells of {:.3} m, origin ({:.2}, {:.2})>",
            self.width, self.height, self.resolution, self.origin.0, self.origin.1
        )
    }

    /// The map as a picture, for Jupyter: free white, occupied black, unknown grey.
    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let png = crate::pictures::grid_png(&self.cells, self.width, self.height)?;
        Ok(PyBytes::new(py, &png))
    }
}

/// A `map` device.
#[pyclass(frozen, module = "player3")]
pub struct Map {
    pub core: DeviceCore,
}

#[pymethods]
impl Map {
    /// Fetches the whole grid (GIL released while the tiles come).
    fn read(&self, py: Python<'_>) -> PyResult<Grid> {
        let info = self.core.fetch(py, MapMessages::REQ_GET_INFO)?;
        let (width, height) = (info.width as usize, info.height as usize);
        let mut cells = vec![0i8; width * height];
        for row in (0..info.height).step_by(TILE as usize) {
            for col in (0..info.width).step_by(TILE as usize) {
                let ask = MapData {
                    col,
                    row,
                    width: TILE.min(info.width - col),
                    height: TILE.min(info.height - row),
                    ..MapData::default()
                };
                let reply = self.core.set(py, MapMessages::REQ_GET_DATA, ask)?;
                let tile = MapMessages::REQ_GET_DATA
                    .reply_of(&reply)
                    .map_err(|e| self.core.error(e, "map tile"))?;
                let tile_cells = tile.cells().map_err(|e| {
                    PyValueError::new_err(format!("{}: a bad map tile: {e}", self.core.label))
                })?;
                let tile_width = tile.width as usize;
                for (r, line) in tile_cells.chunks(tile_width.max(1)).enumerate() {
                    let start = (tile.row as usize + r) * width + tile.col as usize;
                    let end = (start + line.len()).min(cells.len());
                    if start < end {
                        cells[start..end].copy_from_slice(&line[..end - start]);
                    }
                }
            }
        }
        Ok(Grid {
            cells: Arc::new(cells),
            width,
            height,
            resolution: f64::from(info.scale),
            origin: (info.origin.px, info.origin.py, info.origin.pa),
        })
    }

    fn __repr__(&self) -> String {
        format!("<Map {} on {}>", self.core.label, self.core.link.place)
    }
}
