//! The simulated camera through the real client over TCP: a first-person view in which a
//! coloured wall ahead fills the centre column, raw RGB888 or JPEG as the .cfg chooses.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use image::RgbaImage;
use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::camera::{COMPRESS_JPEG, COMPRESS_RAW, CameraData, FORMAT_RGB888};
use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::{Pose, World};

/// A 10 x 8 m room with blue walls; robot "eye" at the centre facing east (+x) with a camera;
/// a red panel 2 m ahead of it, 3 m wide. camera:0 raw, camera:1 through cameracompress.
fn world(dir: &Path) -> PathBuf {
    let room = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/bitmaps/room.png");
    let world = format!(
        "interval_sim 100\n\
         model( name \"room\" size [ 10 8 1.2 ] color \"blue\" bitmap \"{}\" )\n\
         model( name \"panel\" pose [ 2 0 0 0 ] size [ 0.2 3 0.6 ] color \"red\" )\n\
         position( name \"eye\" size [ 0.4 0.4 0.2 ]\n\
           camera( pose [ 0.2 0 0.1 0 ] resolution [ 80 60 ] fov [ 60 40 ] range [ 0.2 12 ] ) )\n",
        room.display()
    );
    let cfg = "driver ( name \"stage\" provides [ \"6665:simulation:0\" ] )\n\
               driver ( name \"stage\" provides [ \"6665:position2d:0\" \"6665:camera:0\" ] model \"eye\" )\n\
               driver ( name \"cameracompress\" requires [ \"6665:camera:0\" ] provides [ \"6665:camera:1\" ] image_quality 0.9 )\n";
    std::fs::write(dir.join("eye.cfg"), cfg).unwrap();
    let path = dir.join("eye.world");
    std::fs::write(&path, world).unwrap();
    path
}

fn start(path: &Path) -> Running {
    let world = World::load(path).unwrap();
    assert!(world.ignored.is_empty(), "{:?}", world.ignored);
    let mut ignored = Vec::new();
    let devices = from_cfg(&path.with_extension("cfg"), &world, &mut ignored).unwrap();
    let options = ServeOptions {
        speedup: 5.0,
        free_ports: true,
        ..ServeOptions::default()
    };
    serve(Simulation::new(world), devices, options).unwrap()
}

fn frame(client: &Client, index: u16) -> CameraData {
    let camera = client.camera(index);
    let driver = if index == 0 {
        "stage"
    } else {
        "cameracompress"
    };
    assert_eq!(camera.subscribe().unwrap(), driver);
    let deadline = Instant::now() + Duration::from_secs(5);
    loop {
        if let Some((data, _)) = camera.frame() {
            return data;
        }
        assert!(Instant::now() < deadline, "no frame from camera:{index}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// Is `p` mostly `channel` (0 red, 1 green, 2 blue)?
fn dominated_by(p: &image::Rgba<u8>, channel: usize) -> bool {
    let main = i32::from(p[channel]);
    (0..3)
        .filter(|&c| c != channel)
        .all(|c| main > 2 * i32::from(p[c]) + 20)
}

fn centre(image: &RgbaImage) -> image::Rgba<u8> {
    *image.get_pixel(image.width() / 2, image.height() / 2)
}

#[test]
fn a_camera_facing_a_red_panel_sees_red_in_its_centre_column_raw_and_jpeg() {
    let dir = tempfile::tempdir().unwrap();
    let sim = start(&world(dir.path()));
    let client = Client::connect(
        "127.0.0.1",
        sim.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();

    let raw = frame(&client, 0);
    assert_eq!(
        (raw.width, raw.height, raw.bpp, raw.format, raw.compression),
        (80, 60, 24, FORMAT_RGB888, COMPRESS_RAW)
    );
    assert_eq!(raw.image.len(), 80 * 60 * 3);
    let image = raw.to_rgba().unwrap();
    assert!(dominated_by(&centre(&image), 0), "{:?}", centre(&image));
    // The camera is 0.3 m up, the 0.6 m panel's face 1.7 m ahead: the panel spans rows 16-44
    // (focal length 30 / tan 20° = 82 px), the blue wall shows above it, the top row is sky and
    // the bottom row floor.
    let (top, bottom) = (image.get_pixel(40, 0), image.get_pixel(40, 59));
    assert!(
        !dominated_by(top, 0) && !dominated_by(bottom, 0),
        "{top:?} {bottom:?}"
    );
    assert!(top[2] > top[0], "sky is blueish: {top:?}");
    assert!(
        dominated_by(image.get_pixel(40, 14), 2),
        "{:?}",
        image.get_pixel(40, 14)
    );
    assert!(dominated_by(image.get_pixel(40, 17), 0) && dominated_by(image.get_pixel(40, 43), 0));
    // The 3 m panel's edges are 41° off the axis, beyond the 60° view: red across the width.
    assert!((0..80).all(|x| dominated_by(image.get_pixel(x, 30), 0)));

    let jpeg = frame(&client, 1);
    assert_eq!(
        (jpeg.width, jpeg.height, jpeg.compression),
        (80, 60, COMPRESS_JPEG)
    );
    assert!(jpeg.image.starts_with(&[0xFF, 0xD8]), "a JPEG file");
    assert!(jpeg.image.len() < raw.image.len());
    let decoded = jpeg.to_rgba().unwrap();
    assert!(dominated_by(&centre(&decoded), 0), "{:?}", centre(&decoded));
}

#[test]
fn turning_the_robot_shows_the_blue_wall_and_the_image_request_answers() {
    let dir = tempfile::tempdir().unwrap();
    let sim = start(&world(dir.path()));
    // Facing west the nearest thing is the room's blue wall, 5 m away.
    sim.sim.lock().unwrap().robots[0].pose = Pose {
        x: 0.0,
        y: 0.0,
        a: std::f64::consts::PI,
    };
    let client = Client::connect(
        "127.0.0.1",
        sim.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let asked = client.camera(0).request_image().unwrap();
    let image = asked.to_rgba().unwrap();
    assert!(dominated_by(&centre(&image), 2), "{:?}", centre(&image));
    // Farther walls look shorter: the 1.2 m wall 4.6 m away spans rows 14-35, sky above it.
    assert!(
        !dominated_by(image.get_pixel(40, 5), 2),
        "{:?}",
        image.get_pixel(40, 5)
    );
    assert!(
        dominated_by(image.get_pixel(40, 16), 2),
        "{:?}",
        image.get_pixel(40, 16)
    );
    assert!(
        !dominated_by(image.get_pixel(40, 40), 2),
        "{:?}",
        image.get_pixel(40, 40)
    );
}
