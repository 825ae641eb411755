//! The map plugin fed by a hand-answered device: it asks for the info, then for tiles within
//! Player's tile limit a few at a time, and lays the assembled grid on the ground at the
//! map's origin and resolution — with the obstacles grown by a robot's radius when asked,
//! and with a broken tile left unknown rather than failing the map.

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::plugin::Plugin;
use framework::scene::{ImageQuad, Kernel, PixelFormat};
use glam::Vec3;
use player_proto::DevAddr;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::map::{Map, MapData, MapInfo};
use player_proto::message::{Body, Message};
use player_proto::wire::{MsgType, Opaque};
use plugins::map::fetch::TILES_IN_FLIGHT;
use plugins::map::grid::{FREE_GREY, OCCUPIED_GREY, TILE_SIDE, UNKNOWN_GREY};
use support::{Harness, harness};

fn addr() -> DevAddr {
    "map:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_map".into(),
        id: "map".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "mapfile".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

fn info(width: u32, height: u32) -> MapInfo {
    MapInfo {
        scale: 0.1,
        width,
        height,
        origin: Pose2d {
            px: -5.0,
            py: -3.0,
            pa: 0.0,
        },
    }
}

/// The test map's cell at column `i`, row `j`: a wall along column 7, unknown below row 2,
/// free elsewhere.
fn cell(i: u32, j: u32) -> i8 {
    if i == 7 {
        1
    } else if j < 2 {
        0
    } else {
        -1
    }
}

/// Answers every tile request waiting, as a mapfile server would, except that the tile at
/// `broken` (column, row) arrives as bytes that are not zlib. Returns the rectangles asked.
fn serve_tiles(h: &Harness, answered: &mut usize, broken: Option<(u32, u32)>) -> Vec<MapData> {
    let kind = Map::REQ_GET_DATA.kind();
    let asked: Vec<MapData> = h
        .device
        .requests
        .lock()
        .unwrap()
        .iter()
        .filter(|(k, _)| *k == kind)
        .filter_map(|(_, body)| Map::REQ_GET_DATA.body_of(body).cloned())
        .collect();
    let pending: Vec<_> = {
        let mut all = h.device.pending.lock().unwrap();
        let (tiles, rest): (Vec<_>, Vec<_>) = all.drain(..).partition(|(k, _)| *k == kind);
        *all = rest;
        tiles
    };
    for (_, responder) in pending {
        let rect = &asked[*answered];
        *answered += 1;
        let cells: Vec<i8> = (0..rect.height)
            .flat_map(|j| (0..rect.width).map(move |i| (i, j)))
            .map(|(i, j)| cell(rect.col + i, rect.row + j))
            .collect();
        let mut tile = MapData::compress(rect.col, rect.row, rect.width, rect.height, 1, &cells);
        if broken == Some((rect.col, rect.row)) {
            tile.data = Opaque::from(vec![1, 2, 3]);
        }
        responder.answer(Ok(Message::typed(addr(), MsgType::Ack, Map::Tile(tile))));
    }
    asked
}

/// Runs the plugin until every tile was asked for and answered.
fn load(h: &mut Harness, plugin: &mut Box<dyn Plugin>, broken: Option<(u32, u32)>) -> Vec<MapData> {
    let mut answered = 0;
    let mut asked = Vec::new();
    for _ in 0..100 {
        plugin.run(&mut h.ctx());
        let in_flight = h.device.pending.lock().unwrap().len();
        assert!(
            in_flight <= TILES_IN_FLIGHT,
            "{in_flight} tiles asked at once"
        );
        asked = serve_tiles(h, &mut answered, broken);
    }
    asked
}

fn the_image(h: &Harness, plugin: &dyn Plugin) -> Option<ImageQuad> {
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    node.geometry.images.first().cloned()
}

fn answering_info(h: &Harness, info: MapInfo) {
    h.device.reply_to(
        Map::REQ_GET_INFO.kind(),
        Ok(Message::typed(addr(), MsgType::Ack, Map::Info(info))),
    );
}

#[test]
fn the_grid_lies_at_the_origin_at_its_resolution_from_tiles_within_the_limit() {
    let mut h = harness();
    answering_info(&h, info(1500, 700));
    let mut plugin = h.make(config(vec![])).unwrap();
    let asked = load(&mut h, &mut plugin, None);

    assert_eq!(asked.len(), 3 * 2, "1500 × 700 in tiles of {TILE_SIDE}");
    assert!(
        asked
            .iter()
            .all(|t| t.width <= TILE_SIDE && t.height <= TILE_SIDE)
    );
    let image = the_image(&h, plugin.as_ref()).expect("the map is drawn");
    assert_eq!(image.pixels.format(), PixelFormat::Gray8);
    assert_eq!((image.pixels.width(), image.pixels.height()), (1500, 700));
    assert!((image.size - glam::Vec2::new(150.0, 70.0)).length() < 1e-3);
    assert!(image.filters.is_empty());
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    let corner = node.transform.transform_point3(image.corner);
    assert!(
        (corner - Vec3::new(-5.0, -3.0, 0.0)).length() < 1e-5,
        "{corner}"
    );

    let grey = |i: u32, j: u32| image.pixels.bytes()[(j * 1500 + i) as usize];
    assert_eq!(grey(7, 300), OCCUPIED_GREY, "the wall");
    assert_eq!(grey(8, 1), UNKNOWN_GREY);
    assert_eq!(grey(1499, 699), FREE_GREY, "the last cell of the last tile");
}

#[test]
fn dilation_in_metres_grows_the_dark_obstacles() {
    let mut h = harness();
    answering_info(&h, info(50, 40));
    let mut dilate = Param::new("filter", "dilate");
    dilate.attributes = vec![("radius".into(), "0.25".into())];
    let mut plugin = h
        .make(config(vec![dilate, Param::new("filter", "sobel")]))
        .unwrap();
    load(&mut h, &mut plugin, None);
    let image = the_image(&h, plugin.as_ref()).unwrap();
    // 0.25 m at 0.1 m per cell: 3 cells, rounded up; obstacles are dark, so a minimum.
    assert_eq!(
        image.filters.0,
        [Kernel::Erode { radius: 3 }, Kernel::SobelEdges]
    );
}

#[test]
fn a_tile_that_does_not_inflate_stays_unknown_and_the_rest_is_drawn() {
    let mut h = harness();
    answering_info(&h, info(1000, 100));
    let mut plugin = h.make(config(vec![])).unwrap();
    load(&mut h, &mut plugin, Some((TILE_SIDE, 0)));
    let image = the_image(&h, plugin.as_ref()).expect("drawn without the broken tile");
    let grey = |i: u32, j: u32| image.pixels.bytes()[(j * 1000 + i) as usize];
    assert_eq!(grey(7, 50), OCCUPIED_GREY, "the first tile");
    assert_eq!(grey(900, 50), UNKNOWN_GREY, "the broken tile");
}

#[test]
fn a_map_that_claims_too_many_cells_is_refused_without_a_picture() {
    let mut h = harness();
    answering_info(&h, info(1_000_000, 1_000_000));
    let mut plugin = h.make(config(vec![])).unwrap();
    load(&mut h, &mut plugin, None);
    assert!(the_image(&h, plugin.as_ref()).is_none());
    let tiles = h
        .device
        .requests
        .lock()
        .unwrap()
        .iter()
        .filter(|(k, _)| *k == Map::REQ_GET_DATA.kind())
        .count();
    assert_eq!(tiles, 0, "no tile asked for a map that cannot be held");
}

#[test]
fn a_bad_filter_is_a_configuration_error() {
    let mut h = harness();
    let result = h.make(config(vec![Param::new("filter", "emboss")]));
    let err = result.err().expect("refused").to_string();
    assert!(err.contains("\"emboss\" is not a kernel"), "{err}");
    // A body that is not a map structure is not mistaken for one.
    assert!(Map::REQ_GET_DATA.body_of(&Body::Empty).is_none());
}

#[test]
fn the_map_answers_whether_a_point_is_free() {
    use framework::query::{BAD_ARGUMENTS, FAILED, Query, Target};
    let mut h = harness();
    answering_info(&h, info(50, 40));
    let mut plugin = h.make(config(vec![])).unwrap();
    let ask = |x: f32, y: f32| {
        Query::new(Target::Named("map".into()), "is point free")
            .with_attr("x", x)
            .with_attr("y", y)
    };
    let early = plugin.answer(&ask(0.0, 0.0), &mut h.ctx()).unwrap();
    assert_eq!(early.error, FAILED, "no grid yet");
    load(&mut h, &mut plugin, None);
    let state = |h: &mut Harness, plugin: &mut Box<dyn Plugin>, x, y| {
        let reply = plugin.answer(&ask(x, y), &mut h.ctx()).unwrap();
        assert!(reply.is_done(), "{reply:?}");
        reply.body.attr("state").unwrap().to_string()
    };
    // Column 7 is the wall, rows 0 and 1 unknown, at 0.1 m from (-5, -3).
    assert_eq!(state(&mut h, &mut plugin, -4.25, -2.0), "occupied");
    assert_eq!(state(&mut h, &mut plugin, -4.0, -2.0), "free");
    assert_eq!(state(&mut h, &mut plugin, -4.0, -2.95), "unknown");
    assert_eq!(state(&mut h, &mut plugin, 10.0, 0.0), "outside");
    let half = Query::new(Target::Named("map".into()), "is point free").with_attr("x", 1);
    assert_eq!(
        plugin.answer(&half, &mut h.ctx()).unwrap().error,
        BAD_ARGUMENTS
    );
}
