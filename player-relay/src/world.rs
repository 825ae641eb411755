//! What the relay knows of a world it simulates itself (`--world`, `--demo`) and tells its
//! fronts: each port's robot's name, and the walls for the web page — its floorplan (bitmap
//! and blocks, as the simulation's wall grid holds them) and the boxes standing on the floor.
//! People's legs walk, so they are left to the lasers.

use std::collections::BTreeMap;
use std::path::Path;

use player_sim::served::{Source, devices_beside};
use player_sim::world::World;
use player_sim::worldfile::WorldFileError;
use player_web::walls::{Grid, Walls};

/// What the page draws of `world`.
pub fn walls(world: &World) -> Walls {
    let mut walls = Walls::default();
    if let Some(floor) = &world.floor {
        let (cell, origin) = (floor.cell, floor.origin);
        walls.add_grid(&Grid {
            width: floor.width,
            height: floor.height,
            cell,
            origin,
            wall: |col, row| {
                let x = origin.0 + (col as f64 + 0.5) * cell.0;
                let y = origin.1 + (row as f64 + 0.5) * cell.1;
                floor.occupied_at(x, y)
            },
        });
    }
    let legs: Vec<usize> = world.people.iter().flat_map(|p| p.legs).collect();
    for (_, obstacle) in (world.obstacles.iter().enumerate()).filter(|(i, _)| !legs.contains(i)) {
        let (pose, origin) = (obstacle.pose, obstacle.origin);
        let (c, s) = (pose.a.cos(), pose.a.sin());
        // The box's centre: its pose moved by its origin, in its own frame.
        let (cx, cy) = (
            pose.x + c * origin.x - s * origin.y,
            pose.y + s * origin.x + c * origin.y,
        );
        let (c, s) = ((pose.a + origin.a).cos(), (pose.a + origin.a).sin());
        let (hx, hy) = (obstacle.size[0] / 2.0, obstacle.size[1] / 2.0);
        let corner = |dx: f64, dy: f64| [cx + c * dx - s * dy, cy + s * dx + c * dy];
        walls.polygons.push(vec![
            corner(-hx, -hy),
            corner(hx, -hy),
            corner(hx, hy),
            corner(-hx, hy),
        ]);
    }
    walls
}

/// The name of the one model whose base (`position2d`) each configured port serves first; a
/// port serving several bases (Stage's one-port worlds) or none of its own (a map, navigation
/// drivers reaching a base through `passthrough`, listed after the base's own .cfg) gives no
/// name: those robots are their servers.
pub fn names(path: &Path, world: &World) -> Result<BTreeMap<u16, String>, WorldFileError> {
    let devices = devices_beside(path, world, &mut Vec::new())?;
    let mut home: BTreeMap<usize, u16> = BTreeMap::new();
    for device in &devices {
        if let Source::Position { robot } = device.source {
            home.entry(robot).or_insert(device.port);
        }
    }
    let mut bases: BTreeMap<u16, Vec<usize>> = BTreeMap::new();
    for (robot, port) in home {
        bases.entry(port).or_default().push(robot);
    }
    Ok(bases
        .into_iter()
        .filter_map(|(port, robots)| match robots.as_slice() {
            [robot] => Some((port, world.robots.get(*robot)?.name.clone())),
            _ => None,
        })
        .collect())
}
