//! pv3d against a Player server over real TCP whose `map` device answers the info and tile
//! requests as Player's mapfile does (tiles compressed): the screenshot shows the grid on the
//! ground — free space light, the unknown strip grey, the walls dark — with the template's
//! defaults, and a composition that dilates the walls shows them thicker.

use std::process::Command;

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::map::{Map, MapData, MapInfo};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply, Server, ServerConfig};

const WIDTH: u32 = 800;
const HEIGHT: u32 = 600;
const SCALE: f32 = 0.05;

/// Walls around and down the middle, an unknown strip on the left, free elsewhere.
fn cell(i: u32, j: u32) -> i8 {
    let wall = i == 100 || i == WIDTH - 1 || j == 0 || j == HEIGHT - 1 || (i == 450 && j < 400);
    if wall {
        1
    } else if i < 100 {
        0
    } else {
        -1
    }
}

struct Mapfile;

impl Device for Mapfile {
    fn driver_name(&self) -> &str {
        "mapfile"
    }

    fn on_request(&mut self, request: &Message) -> Reply {
        let info = MapInfo {
            scale: SCALE,
            width: WIDTH,
            height: HEIGHT,
            origin: Pose2d::new(-20.0, -15.0, 0.0),
        };
        if Map::REQ_GET_INFO.kind().matches(&request.header) {
            return Reply::Ack(Map::REQ_GET_INFO.to_body(info));
        }
        let Some(asked) = Map::REQ_GET_DATA.body_of(&request.body) else {
            return Reply::Nack;
        };
        let (w, h) = (
            asked.width.min(WIDTH.saturating_sub(asked.col)),
            asked.height.min(HEIGHT.saturating_sub(asked.row)),
        );
        let cells: Vec<i8> = (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| cell(asked.col + i, asked.row + j))
            .collect();
        Reply::Ack(Body::Map(Map::Tile(MapData::compress(
            asked.col, asked.row, w, h, 1, &cells,
        ))))
    }
}

/// Screenshots `composition` (with `{port}` replaced by the server's) after a second.
fn screenshot(composition: &str, name: &str) -> image::RgbaImage {
    let mut config = ServerConfig::default();
    let robot = config.robot(0);
    config.device(robot, "map:0".parse().unwrap(), Mapfile);
    let server = Server::start(config).unwrap();
    let port = server.port(0);
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("map.xml");
    let templates = concat!(env!("CARGO_MANIFEST_DIR"), "/../configs/templates");
    let text = composition
        .replace("{port}", &port.to_string())
        .replace("{templates}", templates);
    std::fs::write(&file, text).unwrap();
    let png = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let out = Command::new(env!("CARGO_BIN_EXE_pv3d"))
        .arg(&file)
        .args([
            "--headless",
            "--after",
            "1.5",
            "--size",
            "800x600",
            "--screenshot",
        ])
        .arg(&png)
        .output()
        .unwrap();
    server.shutdown();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && !stderr.contains("ERROR"),
        "{stderr}"
    );
    image::open(&png).unwrap().to_rgba8()
}

/// Pixels of a grey in `grey` within the 3D view (right of the item tree, above the status).
fn count(image: &image::RgbaImage, grey: std::ops::RangeInclusive<u8>) -> usize {
    let (left, top, right, bottom) = map_area(image);
    image
        .enumerate_pixels()
        .filter(|(x, y, _)| (left..=right).contains(x) && (top..=bottom).contains(y))
        .filter(|(_, _, p)| is_grey(p, &grey))
        .count()
}

fn is_grey(p: &image::Rgba<u8>, grey: &std::ops::RangeInclusive<u8>) -> bool {
    grey.contains(&p[0]) && p[0] == p[1] && p[1] == p[2]
}

/// The map's part of the view: the box round its free and unknown cells, widened by a few
/// pixels for the outer walls, so that widgets floating over the view (the command line) are
/// not counted.
fn map_area(image: &image::RgbaImage) -> (u32, u32, u32, u32) {
    const WALL_MARGIN: u32 = 12;
    let (free, unknown) = (225..=245, 140..=160);
    let (mut left, mut top, mut right, mut bottom) = (u32::MAX, u32::MAX, 0, 0);
    for (x, y, p) in image.enumerate_pixels() {
        if x <= VIEW_LEFT || y >= VIEW_BOTTOM {
            continue;
        }
        // The rows from the free cells alone: a hint's grey text below the map is not map.
        if is_grey(p, &free) {
            (top, bottom) = (top.min(y), bottom.max(y));
        }
        if is_grey(p, &free) || is_grey(p, &unknown) {
            (left, right) = (left.min(x), right.max(x));
        }
    }
    (
        left.saturating_sub(WALL_MARGIN).max(VIEW_LEFT),
        top.saturating_sub(WALL_MARGIN),
        right + WALL_MARGIN,
        (bottom + WALL_MARGIN).min(VIEW_BOTTOM),
    )
}

/// Where the 3D view lies in an 800 × 600 screenshot.
const VIEW_LEFT: u32 = 240;
const VIEW_BOTTOM: u32 = 550;

const TEMPLATE: &str = r#"<pv3d xmlns:xi="http://www.w3.org/2001/XInclude">
  <handlers>
    <playerClient host="127.0.0.1" port="{port}"/>
    <playerDeviceMask interface="map"><xi:include href="{templates}/map.pv3d.xml"/></playerDeviceMask>
  </handlers>
</pv3d>"#;

#[test]
fn the_grid_from_a_live_server_is_drawn_free_unknown_and_occupied() {
    let image = screenshot(TEMPLATE, "map_live.png");
    let free = count(&image, 225..=245);
    let unknown = count(&image, 140..=160);
    let occupied = count(&image, 15..=35);
    // The 40 × 30 m map fills most of the 800 × 600 view once framed.
    assert!(free > 100_000, "free: {free} pixels");
    assert!(unknown > 10_000, "unknown: {unknown} pixels");
    // The middle wall, 20 m long, and the outer walls: zoomed out, each at least a pixel wide.
    assert!(occupied > 1000, "walls: {occupied} pixels");
    assert!(
        unknown < free / 2,
        "the unknown strip is a quarter of the free space at most"
    );

    let dilated = TEMPLATE.replace(
        r#"<xi:include href="{templates}/map.pv3d.xml"/>"#,
        r#"<plugin library="libpv3d_map" id="cspace"><filter radius="0.3">dilate</filter></plugin>"#,
    );
    let grown = screenshot(&dilated, "map_live_dilated.png");
    let grown_walls = count(&grown, 15..=35);
    assert!(
        grown_walls > occupied * 4,
        "walls grown by 0.3 m: {grown_walls} pixels, {occupied} before"
    );
}
