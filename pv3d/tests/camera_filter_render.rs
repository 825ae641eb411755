//! A camera's window shows its frame through the chain chosen for that camera: the plugin asks
//! for the frame to be filtered, the viewer runs the chain on the GPU and hands the result back.
//! A single white pixel dilated by one becomes a 3 × 3 white square.

use framework::PluginConfig;
use framework::config::Param;
use framework::testing::Harness;
use player_proto::interfaces::camera::{COMPRESS_RAW, Camera, CameraData, FORMAT_RGB888};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use pv3d::headless::HeadlessGl;
use pv3d::render::{PictureFilters, SceneBatch};

const SIDE: u32 = 5;

#[test]
fn the_camera_window_gets_the_filtered_frame() {
    let mut h = Harness::with_registry(plugins::standard_plugins());
    let mut dilate = Param::new("filter", "dilate");
    dilate.attributes = vec![("radius".into(), "1".into())];
    let config = PluginConfig {
        library: "libpv3d_camera".into(),
        params: vec![dilate],
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    };
    let mut plugin = h.make(config).unwrap();
    // Black, with one white pixel in the middle (row 2, column 2), RGB888 top row first.
    let mut rgb = vec![0u8; (SIDE * SIDE * 3) as usize];
    let middle = ((2 * SIDE + 2) * 3) as usize;
    rgb[middle..middle + 3].copy_from_slice(&[255, 255, 255]);
    let frame = CameraData {
        width: SIDE,
        height: SIDE,
        bpp: 24,
        format: FORMAT_RGB888,
        fdiv: 0,
        compression: COMPRESS_RAW,
        image: rgb.into(),
    };
    let addr: DevAddr = "camera:0".parse().unwrap();
    h.device
        .push(Message::typed(addr, MsgType::Data, Camera::State(frame)));
    plugin.run(&mut h.ctx());

    let mut batch = SceneBatch::default();
    batch.rebuild(&h.scene, None);
    assert_eq!(batch.filtered.len(), 1, "the frame is asked to be filtered");
    let gl = HeadlessGl::new(8, 8).expect("headless GL (Mesa EGL)");
    gl.bind();
    let mut filters = PictureFilters::new();
    filters.run(&gl.gl, &batch.filtered);
    let result = batch.filtered[0]
        .output
        .latest()
        .expect("the filtered frame came back");
    filters.destroy(&gl.gl);
    assert_eq!((result.width(), result.height()), (SIDE, SIDE));
    let white = |x: u32, y: u32| result.bytes()[((y * SIDE + x) * 4) as usize] > 200;
    for y in 0..SIDE {
        for x in 0..SIDE {
            let inside = (1..=3).contains(&x) && (1..=3).contains(&y);
            assert_eq!(white(x, y), inside, "({x}, {y})");
        }
    }
}
