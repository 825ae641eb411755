//! The camera plugin: frames are decoded once per new frame (raw and JPEG), republished
//! frames are not decoded again, the rate and age are measured, bad frames are reported, and
//! the window hands egui a texture of the frame's size — all without OpenGL.

mod support;

use std::sync::Arc;
use std::time::{Duration, Instant};

use framework::PluginConfig;
use framework::config::DeviceRef;
use framework::device::Stamped;
use player_proto::interfaces::camera::{
    COMPRESS_JPEG, COMPRESS_RAW, Camera, CameraData, FORMAT_MONO8, FORMAT_RGB888,
};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use plugins::camera::frames::{CameraFrames, Offered};
use support::harness;

fn addr() -> DevAddr {
    "camera:0".parse().unwrap()
}

fn rgb_frame(width: u32, height: u32, fill: [u8; 3]) -> CameraData {
    CameraData {
        width,
        height,
        bpp: 24,
        format: FORMAT_RGB888,
        fdiv: 0,
        compression: COMPRESS_RAW,
        image: fill.repeat((width * height) as usize).into(),
    }
}

fn sample(frame: CameraData, seq: u64, received: Instant) -> Stamped {
    Stamped {
        message: Arc::new(Message::typed(addr(), MsgType::Data, Camera::State(frame))),
        received,
        server_time: 0.0,
        seq,
    }
}

#[test]
fn a_raw_frame_is_decoded_once_and_a_republished_one_not_at_all() {
    let t0 = Instant::now();
    let mut frames = CameraFrames::default();
    let red = sample(rgb_frame(4, 2, [255, 0, 0]), 1, t0);
    assert_eq!(frames.offer(&red), Offered::Decoded);
    assert_eq!(frames.offer(&red), Offered::Seen, "same seq: nothing new");
    let image = frames.image().unwrap().clone();
    assert_eq!((image.width(), image.height()), (4, 2));
    assert_eq!(image.get_pixel(3, 1).0, [255, 0, 0, 255]);
    assert_eq!(frames.version(), 1);

    // Stage republishes the same pixels under a new sequence number.
    let again = sample(
        rgb_frame(4, 2, [255, 0, 0]),
        2,
        t0 + Duration::from_millis(100),
    );
    assert_eq!(frames.offer(&again), Offered::Unchanged);
    assert_eq!(frames.version(), 1, "not decoded again");
    assert!(Arc::ptr_eq(frames.image().unwrap(), &image));

    let blue = sample(
        rgb_frame(4, 2, [0, 0, 255]),
        3,
        t0 + Duration::from_millis(200),
    );
    assert_eq!(frames.offer(&blue), Offered::Decoded);
    assert_eq!(frames.version(), 2);
    assert_eq!(frames.image().unwrap().get_pixel(0, 0).0, [0, 0, 255, 255]);
}

#[test]
fn rate_and_age_follow_the_arrivals() {
    let t0 = Instant::now();
    let mut frames = CameraFrames::default();
    assert_eq!(frames.rate(t0), None);
    assert_eq!(frames.summary(t0), "no frame yet");
    // Eleven frames 100 ms apart: 10 fps.
    for i in 0..11u8 {
        let at = t0 + Duration::from_millis(100 * u64::from(i));
        frames.offer(&sample(rgb_frame(2, 2, [i, i, i]), u64::from(i) + 1, at));
    }
    let last = t0 + Duration::from_millis(1000);
    let rate = frames.rate(last).unwrap();
    assert!((rate - 10.0).abs() < 0.01, "{rate}");
    let now = last + Duration::from_millis(500);
    assert_eq!(frames.age(now), Some(Duration::from_millis(500)));
    assert_eq!(frames.summary(now), "2×2, 10.0 fps, 0.5 s old");
    // Long after the camera stopped, there is no rate to speak of.
    assert_eq!(frames.rate(last + Duration::from_secs(10)), None);

    // The viewer saw only every third message (seq 1, 4, 7 over 0.2 s): the camera still sends
    // 30 frames per second.
    let mut skipped = CameraFrames::default();
    for (i, seq) in [1u64, 4, 7].into_iter().enumerate() {
        let at = t0 + Duration::from_millis(100 * i as u64);
        skipped.offer(&sample(rgb_frame(2, 2, [seq as u8; 3]), seq, at));
    }
    let rate = skipped.rate(t0 + Duration::from_millis(200)).unwrap();
    assert!((rate - 30.0).abs() < 0.01, "{rate}");
}

#[test]
fn jpeg_frames_decode_and_bad_frames_say_why_keeping_the_last_good_one() {
    let mut jpeg = Vec::new();
    let picture = image::RgbImage::from_pixel(16, 8, image::Rgb([0, 200, 0]));
    picture
        .write_to(
            &mut std::io::Cursor::new(&mut jpeg),
            image::ImageFormat::Jpeg,
        )
        .unwrap();
    let frame = CameraData {
        width: 16,
        height: 8,
        bpp: 24,
        format: FORMAT_RGB888,
        fdiv: 0,
        compression: COMPRESS_JPEG,
        image: jpeg.into(),
    };
    let t0 = Instant::now();
    let mut frames = CameraFrames::default();
    assert_eq!(frames.offer(&sample(frame, 1, t0)), Offered::Decoded);
    let green = frames.image().unwrap().get_pixel(8, 4).0;
    assert!(
        green[1] > 180 && green[0] < 30 && green[2] < 30,
        "{green:?}"
    );

    // A frame whose header claims more pixels than it carries.
    let short = CameraData {
        width: 640,
        height: 480,
        bpp: 8,
        format: FORMAT_MONO8,
        fdiv: 0,
        compression: COMPRESS_RAW,
        image: vec![0; 10].into(),
    };
    let Offered::Failed(reason) = frames.offer(&sample(short, 2, t0)) else {
        panic!("a short frame decoded");
    };
    assert!(reason.contains("needs 307200 bytes"), "{reason}");
    assert_eq!(
        frames.image().unwrap().width(),
        16,
        "the last good frame stays"
    );
    assert!(frames.summary(t0).contains("newest frame not shown"));
}

#[test]
fn the_plugin_shows_the_frame_as_a_texture_of_its_size_without_gl() {
    let config = PluginConfig {
        library: "libpv3d_camera".into(),
        id: "camera".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "stage".into(),
        }),
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    };
    let mut h = harness();
    let Ok(mut plugin) = h.make(config) else {
        panic!("default config refused");
    };
    h.device.push(Message::typed(
        addr(),
        MsgType::Data,
        Camera::State(rgb_frame(40, 30, [9, 9, 9])),
    ));
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "the scene does not change"
    );

    // A headless egui pass: no viewport support, so the window is embedded.
    let egui_ctx = egui::Context::default();
    let output = egui_ctx.run_ui(egui::RawInput::default(), |ui| {
        plugin.windows(ui.ctx(), &mut h.ctx());
    });
    let sizes: Vec<[usize; 2]> = output
        .textures_delta
        .set
        .values()
        .flatten()
        .map(|delta| match &delta.image {
            egui::ImageData::Color(image) => image.size,
        })
        .collect();
    output.drop_without_applying_deltas();
    assert!(sizes.contains(&[40, 30]), "{sizes:?}");
    assert_eq!(plugin.save().param("showWindow").unwrap().text, "1");
}
