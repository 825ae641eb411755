//! `player3`: the Player client (player-proto) and simulator (player-sim) for Python.
//!
//! A thin layer: connections, subscriptions, reconnection and decoding are player-proto's
//! client; this crate turns its typed readings into Python objects and numpy arrays, waits
//! with the GIL released, and maps its errors to Python exceptions.

mod camera;
mod errors;
mod link;
mod map;
mod navigation;
mod pictures;
mod position;
mod rangers;
mod readable;
mod robot;
mod robot_table;
mod scan;
mod sensors;
mod waiting;
mod world;

use pyo3::prelude::*;

#[pymodule]
fn _player3(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    m.add_function(wrap_pyfunction!(robot::connect, m)?)?;
    m.add_function(wrap_pyfunction!(world::simulate, m)?)?;
    m.add_class::<robot::Robot>()?;
    m.add_class::<robot::Device>()?;
    m.add_class::<world::World>()?;
    m.add_class::<position::Position2d>()?;
    m.add_class::<scan::Scan>()?;
    m.add_class::<rangers::Laser>()?;
    m.add_class::<rangers::Ranger>()?;
    m.add_class::<rangers::Sonar>()?;
    m.add_class::<sensors::Fiducial>()?;
    m.add_class::<sensors::Marker>()?;
    m.add_class::<sensors::Blobfinder>()?;
    m.add_class::<sensors::Blob>()?;
    m.add_class::<sensors::Bumper>()?;
    m.add_class::<sensors::Power>()?;
    m.add_class::<sensors::Battery>()?;
    m.add_class::<sensors::Gripper>()?;
    m.add_class::<sensors::GripperState>()?;
    m.add_class::<camera::Camera>()?;
    m.add_class::<map::Map>()?;
    m.add_class::<map::Grid>()?;
    m.add_class::<navigation::Localize>()?;
    m.add_class::<navigation::Estimate>()?;
    m.add_class::<navigation::Planner>()?;
    m.add_class::<navigation::PlanState>()?;
    m.add_class::<navigation::Speech>()?;
    Ok(())
}
