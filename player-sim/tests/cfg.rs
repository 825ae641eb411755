//! What the Player .cfg decides: a device the model does not have is refused with the .cfg's
//! position, and a laser can be reported under another driver name (`report_as`), so that a
//! viewer's `laser:sicklms200:*` masks match the simulated robot as they would a real one.

use std::path::{Path, PathBuf};

use player_proto::client::{Client, ClientOptions};
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::{Source, from_cfg};
use player_sim::sim::Simulation;
use player_sim::world::World;

fn multirobot() -> World {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/multirobot.world");
    World::load(&path).unwrap()
}

fn cfg(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("test.cfg");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn providing_more_fiducials_rangers_or_cameras_than_the_model_has_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let world = multirobot();
    for (provides, what) in [
        (
            r#""6665:fiducial:0" "6665:fiducial:1""#,
            "1 fiducial finder",
        ),
        (
            r#""6665:ranger:0" "6665:ranger:1" "6665:ranger:2""#,
            "2 ranger",
        ),
        (r#""6666:camera:0""#, "0 camera"),
    ] {
        let model = if provides.contains("6666") {
            "r1"
        } else {
            "r0"
        };
        let path = cfg(
            dir.path(),
            &format!(
                "# one too many\ndriver ( name \"stage\" provides [ {provides} ] model \"{model}\" )\n"
            ),
        );
        let err = from_cfg(&path, &world, &mut Vec::new())
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with(&format!("{}:2:", path.display())) && err.contains(what),
            "{err}"
        );
    }
    // Exactly as many as the model has is fine (a space inside the quotes too, as Player reads
    // Stage's autolab.cfg).
    let path = cfg(
        dir.path(),
        "driver ( name \"stage\" provides [ \"6665:fiducial:0\" \"6665:camera:0 \" ] model \"r0\" )\n",
    );
    let served = from_cfg(&path, &world, &mut Vec::new()).unwrap();
    assert_eq!(served.len(), 2);
    assert_eq!(
        served[0].source,
        Source::Fiducial {
            robot: 0,
            finder: 0
        }
    );
}

#[test]
fn a_laser_can_be_reported_as_a_sicklms200() {
    let dir = tempfile::tempdir().unwrap();
    let world = multirobot();
    let path = cfg(
        dir.path(),
        "driver ( name \"stage\" provides [ \"6665:position2d:0\" \"6665:ranger:0\" ] model \"r0\" )\n\
         driver ( name \"rangertolaser\" requires [ \"6665:ranger:0\" ] provides [ \"6665:laser:0\" ] report_as \"sicklms200\" )\n",
    );
    let devices = from_cfg(&path, &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        speedup: 5.0,
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
    assert_eq!(client.laser(0).subscribe().unwrap(), "sicklms200");
    assert_eq!(
        client.ranger(0).subscribe().unwrap(),
        "stage",
        "only the laser is renamed"
    );
    assert_eq!(client.position2d(0).subscribe().unwrap(), "stage");
}
