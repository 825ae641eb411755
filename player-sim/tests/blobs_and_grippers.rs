//! Stage's blobfinder and gripper as a Player client meets them over TCP, in navigation.world:
//! r2 (port 6668) sees the red puck between its paddles as a blob, closes on it, carries it
//! away, and puts it down again when it opens.

mod support;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Duration;

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::blobfinder::BlobfinderData;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::gripper::{
    CMD_CLOSE, CMD_OPEN, Gripper, GripperData, STATE_CLOSED, STATE_OPEN,
};
use player_proto::interfaces::simulation::{Simulation as SimMsg, SimulationPose2d};
use player_proto::message::{Body, Message};
use player_proto::wire::{BANNER_LEN, DevAddr, Interface, MsgType, PlayerString};
use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;
use support::wait_for;

const COLLECTOR_PORT: u16 = 6668;
const SIMULATION_PORT: u16 = 6666;
const RED: u32 = 0xff_00_00;
const WAIT: Duration = Duration::from_secs(10);

fn start() -> Running {
    let world_file = support::worlds().join("navigation.world");
    let world = World::load(&world_file).unwrap();
    let devices = from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        speedup: 10.0,
        free_ports: true,
        ..ServeOptions::default()
    };
    serve(Simulation::new(world), devices, options).unwrap()
}

/// Sends a gripper command as libplayerc does: a CMD with no body.
fn gripper_command(port: u16, subtype: u8) {
    let mut socket = TcpStream::connect(("127.0.0.1", port)).unwrap();
    let mut banner = [0u8; BANNER_LEN];
    socket.read_exact(&mut banner).unwrap();
    let to = DevAddr {
        host: 0,
        robot: u32::from(port),
        interf: Interface::GRIPPER,
        index: 0,
    };
    let command = Message::new(to, MsgType::Cmd, subtype, Body::Empty);
    socket.write_all(&command.to_bytes()).unwrap();
}

fn puck_x(sim: &Client) -> f64 {
    let ask = SimulationPose2d {
        name: PlayerString::new("p0"),
        pose: Pose2d::default(),
    };
    let reply = sim
        .request_with(
            sim.addr(Interface::SIMULATION, 0),
            SimMsg::REQ_GET_POSE2D,
            ask,
        )
        .unwrap();
    SimMsg::REQ_GET_POSE2D.reply_of(&reply).unwrap().pose.px
}

#[test]
fn the_blobfinder_sees_the_red_puck_ahead() {
    let running = start();
    let port = running.port(COLLECTOR_PORT).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    let finder = client.addr(Interface::BLOBFINDER, 0);
    assert_eq!(client.subscribe(finder).unwrap(), "stage");
    let (seen, _) = wait_for("blobs", WAIT, || client.latest_of::<BlobfinderData>(finder));
    assert_eq!((seen.width, seen.height), (80, 60));
    let puck = seen
        .blobs
        .iter()
        .find(|b| b.color == RED)
        .unwrap_or_else(|| panic!("no red blob in {seen:?}"));
    // Straight ahead: in the middle of the image, and near (the puck's face is 0.15 m away).
    assert!(
        puck.left < 40 && puck.right > 40 && puck.x.abs_diff(40) <= 1,
        "{puck:?}"
    );
    assert!((puck.range - 0.15).abs() < 0.02, "{puck:?}");
    assert!(
        puck.top < puck.bottom && puck.bottom <= 60 && puck.area > 0,
        "{puck:?}"
    );
}

#[test]
fn the_gripper_closes_on_the_puck_carries_it_and_puts_it_down() {
    let running = start();
    let port = running.port(COLLECTOR_PORT).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    let sim = Client::connect(
        "127.0.0.1",
        running.port(SIMULATION_PORT).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let gripper = client.addr(Interface::GRIPPER, 0);
    assert_eq!(client.subscribe(gripper).unwrap(), "stage");
    let geometry = client.fetch(gripper, Gripper::REQ_GET_GEOM).unwrap();
    assert_eq!(geometry.num_beams, 2);
    assert_eq!((geometry.outer_size.sl, geometry.outer_size.sw), (0.2, 0.3));
    let state = |want: u8| {
        wait_for(&format!("gripper state {want}"), WAIT, || {
            client
                .latest_of::<GripperData>(gripper)
                .filter(|(d, _)| d.state == want)
        })
        .0
    };
    // Open, with the puck across both beams.
    assert_eq!(state(STATE_OPEN).beams, 0x0c);
    let base = client.position2d(0);
    base.subscribe().unwrap();
    let start_x = puck_x(&sim);

    gripper_command(port, CMD_CLOSE);
    let closed = state(STATE_CLOSED);
    // Held at the gripper's centre, as Stage holds it: across the inner beam only.
    assert_eq!(closed.beams, 0x04);
    base.set_velocity(-0.3, 0.0, 0.0);
    wait_for("the puck carried back", WAIT, || {
        (puck_x(&sim) < start_x - 0.3).then_some(())
    });
    base.set_velocity(0.0, 0.0, 0.0);

    gripper_command(port, CMD_OPEN);
    state(STATE_OPEN);
    let dropped_at = puck_x(&sim);
    base.set_velocity(-0.3, 0.0, 0.0);
    wait_for("the robot backing away", WAIT, || {
        base.state()
            .filter(|(s, _)| s.pos.px < dropped_at - 1.0)
            .map(|_| ())
    });
    assert_eq!(puck_x(&sim), dropped_at, "an open gripper leaves the puck");
    let empty = state(STATE_OPEN);
    assert_eq!(empty.beams, 0, "nothing between the paddles");
}
