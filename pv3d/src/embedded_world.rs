//! A Stage world served in-process (player-sim as a library) on free local ports, and the
//! composition pointed at it over real TCP: `pv3d --world stage-worlds/swarm.world` shows any
//! world file with no Player server installed, and `--demo` is this with the multirobot world.

use std::path::Path;

use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::devices_beside;
use player_sim::sim::Simulation;
use player_sim::sim::body_at;
use player_sim::world::ignored_summary;
use player_sim::world::{BoxObstacle, Floorplan, Polygon, World, placed};

use crate::composition::{ClientDecl, Composition, Element, Node, SourcePos};

/// Why a world could not be served.
#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    #[error(transparent)]
    World(#[from] player_sim::worldfile::WorldFileError),
    #[error("cannot serve the world: {0}")]
    Serve(#[from] player_proto::server::ServerError),
}

/// Serves a Stage world (with the `.cfg` beside it, and its navigation half `<world>-nav.cfg`
/// when there is one) on free ports. Every Player client of the
/// composition whose port the world configures is pointed at the port it got; a composition
/// that names no server gets one for every served port, so masks alone show every robot. A
/// ground plugin without a bitmap gets the world's floorplan.
pub fn serve_world(
    world_file: &Path,
    composition: &mut Composition,
    options: ServeOptions,
) -> Result<Running, WorldError> {
    let world = World::load(world_file)?;
    let mut ignored = world.ignored.clone();
    // The .cfg files beside the world, as player-sim reads them (one port per robot when there
    // are none, or when they name models the world lacks).
    let devices = devices_beside(world_file, &world, &mut ignored)?;
    for note in &ignored {
        tracing::debug!("{note}");
    }
    if let Some(summary) = ignored_summary(&ignored) {
        tracing::info!("{}: {summary}", world_file.display());
    }
    let floorplan = world.floorplan.clone();
    let blocks = (world.floor_blocks.clone(), world.floor_height);
    // People's legs move: drawn once, where they stood at the start, they would mislead.
    let legs: Vec<usize> = world.people.iter().flat_map(|p| p.legs).collect();
    let obstacles: Vec<Obstacle> = world
        .obstacles
        .iter()
        .enumerate()
        .filter(|(i, _)| !legs.contains(i))
        .flat_map(|(_, o)| obstacle_walls(o))
        .collect();
    let options = ServeOptions {
        free_ports: true,
        ..options
    };
    let running = serve(Simulation::new(world), devices, options)?;
    point_clients_at(composition, &running.ports);
    if let Some(floorplan) = &floorplan {
        give_ground_the_floorplan(composition, floorplan);
    }
    give_ground_the_block_walls(composition, &blocks.0, blocks.1, &obstacles);
    Ok(running)
}

/// `ports`: (configured, actually served) pairs. A composition that names servers chose its
/// robots (the paper's three of five): only those are pointed at the world. One that names
/// none gets every robot.
fn point_clients_at(composition: &mut Composition, ports: &[(u16, u16)]) {
    let every_robot = composition.clients.is_empty();
    for &(configured, actual) in ports {
        match composition
            .clients
            .iter_mut()
            .find(|c| c.port == configured)
        {
            Some(client) => {
                client.host = "127.0.0.1".into();
                client.port = actual;
            }
            None if every_robot => composition.clients.push(ClientDecl {
                host: "127.0.0.1".into(),
                port: actual,
                pos: SourcePos::generated(),
            }),
            None => {}
        }
    }
}

fn give_ground_the_floorplan(composition: &mut Composition, floorplan: &Floorplan) {
    let grounds = composition
        .plugins
        .iter_mut()
        .filter(|p| p.attr("library") == Some("libpv3d_ground") && p.child("bitmap").is_none());
    for ground in grounds {
        let params = [
            // Absolute: the ground resolves a relative path against its composition's folder.
            (
                "bitmap",
                std::path::absolute(&floorplan.bitmap)
                    .unwrap_or_else(|_| floorplan.bitmap.clone())
                    .display()
                    .to_string(),
            ),
            (
                "bitmapSize",
                format!("{} {}", floorplan.size[0], floorplan.size[1]),
            ),
            (
                "bitmapCentre",
                format!("{} {}", floorplan.centre[0], floorplan.centre[1]),
            ),
            ("wallHeight", floorplan.height.to_string()),
        ];
        for (name, value) in params {
            if ground.child(name).is_none() {
                let mut element = Element::new(name, SourcePos::generated());
                element.children.push(Node::Text(value));
                ground.children.push(Node::Element(element));
            }
        }
    }
}

/// An obstacle's outline on the ground, with its height and colour.
struct Obstacle {
    outline: Polygon,
    height: f64,
    color: [u8; 3],
}

/// A box (or the blocks it is drawn with) where the simulator has it.
fn obstacle_walls(o: &BoxObstacle) -> Vec<Obstacle> {
    let body = body_at(o.pose, o.origin);
    let (hx, hy) = (o.size[0] / 2.0, o.size[1] / 2.0);
    let outlines = if o.shape.is_empty() {
        vec![placed(&[[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]], body)]
    } else {
        o.shape.iter().map(|p| placed(p, body)).collect()
    };
    outlines
        .into_iter()
        .map(|outline| Obstacle {
            outline,
            height: o.size[2],
            color: o.color,
        })
        .collect()
}

/// Floorplans drawn with Stage `block`s, and the world's obstacles: each polygon becomes a
/// `<wall>` of every ground that has none of its own.
fn give_ground_the_block_walls(
    composition: &mut Composition,
    walls: &[Polygon],
    height: f64,
    obstacles: &[Obstacle],
) {
    if walls.is_empty() && obstacles.is_empty() {
        return;
    }
    let corners = |polygon: &Polygon| -> String {
        let corners: Vec<String> = polygon.iter().map(|[x, y]| format!("{x} {y}")).collect();
        corners.join("  ")
    };
    let grounds = composition
        .plugins
        .iter_mut()
        .filter(|p| p.attr("library") == Some("libpv3d_ground") && p.child("wall").is_none());
    for ground in grounds {
        for wall in walls {
            let mut element = Element::new("wall", SourcePos::generated());
            element.children.push(Node::Text(corners(wall)));
            ground.children.push(Node::Element(element));
        }
        for obstacle in obstacles {
            let mut element = Element::new("wall", SourcePos::generated());
            let [r, g, b] = obstacle.color;
            element.set_attr("height", obstacle.height.to_string());
            element.set_attr("color", format!("#{r:02x}{g:02x}{b:02x}"));
            element
                .children
                .push(Node::Text(corners(&obstacle.outline)));
            ground.children.push(Node::Element(element));
        }
        if ground.child("wallHeight").is_none() {
            let mut element = Element::new("wallHeight", SourcePos::generated());
            element.children.push(Node::Text(height.to_string()));
            ground.children.push(Node::Element(element));
        }
    }
}
