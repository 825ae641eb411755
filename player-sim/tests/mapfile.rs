//! The `mapfile` driver against the real one: the map player-sim serves for the navigation
//! captures' .cfg (`captures/nav/world/nav_a.cfg`: its image, resolution 0.1, no origin) has the
//! info, whole-map cells and sub-tile cells that real Player sent in `map_info_data.jsonl`, and
//! the vector request is NACKed as Player NACKs it.

mod support;

use std::path::{Path, PathBuf};

use player_proto::capture::{Direction, parse_capture, stream};
use player_proto::client::{Client, ClientOptions, RequestError};
use player_proto::interfaces::map::{Map, MapData, MapInfo};
use player_proto::message::{Body, Message};
use player_proto::wire::{FrameDecoder, Interface, MsgType};
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;

fn captures() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures/nav");
    assert!(dir.is_dir(), "missing {}", dir.display());
    dir
}

/// The messages of one direction of a capture.
fn messages(name: &str, dir: Direction) -> Vec<Message> {
    let text = std::fs::read_to_string(captures().join(name)).unwrap();
    let bytes = stream(&parse_capture(&text).unwrap(), dir);
    let mut frames = FrameDecoder::default();
    frames.extend(&bytes);
    if dir == Direction::ServerToClient {
        frames.take_banner().unwrap().unwrap();
    }
    let mut out = Vec::new();
    while let Some(frame) = frames.next_frame().unwrap() {
        out.push(Message::decode(frame.header, frame.body).unwrap());
    }
    out
}

/// What real Player answered: the info, then the tiles in the order they were asked.
fn captured() -> (MapInfo, Vec<MapData>) {
    let replies = messages("map_info_data.jsonl", Direction::ServerToClient);
    let acks = replies
        .iter()
        .filter(|m| m.header.msg_type == MsgType::Ack && m.header.addr.interf == Interface::MAP);
    let (mut info, mut tiles) = (None, Vec::new());
    for ack in acks {
        match &ack.body {
            Body::Map(Map::Info(i)) => info = Some(*i),
            Body::Map(Map::Tile(t)) => tiles.push(t.clone()),
            _ => {}
        }
    }
    (info.expect("a GET_INFO reply"), tiles)
}

#[test]
fn the_served_map_matches_what_player_sent_for_the_capture_world() {
    let (info, tiles) = captured();
    assert_eq!(tiles.len(), 2, "the whole map and the sub-tile");
    let dir = tempfile::tempdir().unwrap();
    let world_file = support::write(dir.path(), "empty.world", "interval_sim 100\n");
    let image = captures().join("world/bitmaps/nav_a.png");
    // nav_a.cfg's mapfile lines, the image named by its absolute path.
    let cfg = support::write(
        dir.path(),
        "map.cfg",
        &format!(
            "driver\n(\n  name \"mapfile\"\n  provides [ \"map:0\" ]\n  filename \"{}\"\n  \
             resolution 0.1\n  negate 0\n)\n",
            image.display()
        ),
    );
    let world = World::load(&world_file).unwrap();
    let devices = from_cfg(&cfg, &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        free_ports: true,
        ..ServeOptions::default()
    };
    let running = serve(Simulation::new(world), devices, options).unwrap();
    let client = Client::connect(
        "127.0.0.1",
        running.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let map = client.addr(Interface::MAP, 0);
    assert_eq!(client.subscribe(map).unwrap(), "mapfile");
    assert_eq!(client.fetch(map, Map::REQ_GET_INFO).unwrap(), info);
    for expected in &tiles {
        let asked = MapData {
            col: expected.col,
            row: expected.row,
            width: expected.width,
            height: expected.height,
            ..MapData::default()
        };
        let reply = client.request_with(map, Map::REQ_GET_DATA, asked).unwrap();
        let tile = Map::REQ_GET_DATA.reply_of(&reply).unwrap();
        assert_eq!(
            (tile.col, tile.row, tile.width, tile.height, tile.data_range),
            (
                expected.col,
                expected.row,
                expected.width,
                expected.height,
                expected.data_range
            )
        );
        assert_eq!(&tile.data[..2], &[0x78, 0x9c], "zlib, as Player compresses");
        assert_eq!(tile.cells().unwrap(), expected.cells().unwrap());
    }
    let vector = client.request(map, Map::REQ_GET_VECTOR.subtype(), Body::Empty);
    assert!(matches!(vector, Err(RequestError::Nack(_))), "{vector:?}");
}

#[test]
fn a_broken_mapfile_block_is_an_error_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let world_file = support::write(dir.path(), "empty.world", "interval_sim 100\n");
    let world = World::load(&world_file).unwrap();
    for (block, line, says) in [
        (
            "driver ( name \"mapfile\" provides [ \"map:0\" ]\n filename \"missing.png\" resolution 0.1 )",
            2,
            "cannot read map image",
        ),
        (
            "driver ( name \"mapfile\" provides [ \"map:0\" ] filename \"m.png\" )",
            1,
            "needs a resolution",
        ),
        (
            "driver ( name \"mapfile\" provides [ \"map:0\" ] filename \"m.png\"\n resolution -1 )",
            2,
            "positive",
        ),
    ] {
        let cfg = support::write(dir.path(), "bad.cfg", &format!("{block}\n"));
        let err = from_cfg(&cfg, &world, &mut Vec::new())
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with(&format!("{}:{line}:", cfg.display())) && err.contains(says),
            "{err}"
        );
    }
}
