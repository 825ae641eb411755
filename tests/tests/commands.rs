//! Commands in words, end to end against player-sim over real TCP: "ROBOT go to charging"
//! drives the robot into the zone, "all robots stop" stops everyone, and a timed script
//! says its sentences in turn, naming file:line when one cannot be carried out.

use std::path::{Path, PathBuf};
use std::time::Duration;

use player_sim::serve::Running;
use pv3d::app::Viewer;
use pv3d::commands::{Script, Vocabulary};
use tests::{load, repo_root, run_for, run_until, serve, sim_pose};

/// The zone "charging": a 2 m square around (3, 2).
const CHARGING: (f64, f64, f64, f64) = (2.0, 4.0, 1.0, 3.0);

/// What the composition's reaction says when a robot drives into the charging zone.
const CHARGING_SAID: &str = "A robot is charging.";

fn in_charging(pose: (f64, f64, f64)) -> bool {
    (CHARGING.0..=CHARGING.1).contains(&pose.0) && (CHARGING.2..=CHARGING.3).contains(&pose.1)
}

/// Writes a two-robot world, its cfg and a composition with the zone, in a folder of its own.
fn commands_world(name: &str) -> (PathBuf, PathBuf) {
    commands_world_with(name, "")
}

/// The same, with more .cfg lines (speech devices).
fn commands_world_with(name: &str, cfg_lines: &str) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("pv3d-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let robots_inc = repo_root().join("stage-worlds/robots.inc");
    std::fs::write(
        dir.join("commands.world"),
        format!(
            "include \"{}\"\ninterval_sim 100\n\
             rover( name \"r0\" pose [ 0 0 0 0 ] color \"red\" )\n\
             rover( name \"r1\" pose [ 0 -2 0 0 ] color \"green\" )\n",
            robots_inc.display()
        ),
    )
    .unwrap();
    std::fs::write(
        dir.join("commands.cfg"),
        "driver ( name \"stage\" provides [ \"6665:simulation:0\" ] plugin \"stageplugin\" worldfile \"commands.world\" )\n\
         driver ( name \"stage\" provides [ \"6665:position2d:0\" ] model \"r0\" )\n\
         driver ( name \"stage\" provides [ \"6666:position2d:0\" ] model \"r1\" )\n"
            .to_string()
            + cfg_lines,
    )
    .unwrap();
    let (x0, x1, y0, y1) = CHARGING;
    std::fs::write(
        dir.join("commands.pv3d.xml"),
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?>
<pv3d>
  <handlers>
    <playerClient host="localhost" port="6665"/>
    <playerClient host="localhost" port="6666"/>
    <playerDeviceMask interface="position2d">
      <plugin library="libpv3d_position2d" id="robot">
        <playerDeviceMask interface="position2d" index="0"/>
      </plugin>
    </playerDeviceMask>
  </handlers>
  <addParser element="zone"/>
  <zone name="charging">{x0} {y0}  {x1} {y0}  {x1} {y1}  {x0} {y1}</zone>
  <addParser element="reaction"/>
  <reaction on="enter" zone="charging" tag="robot"><say>{CHARGING_SAID}</say></reaction>
</pv3d>
"#
        ),
    )
    .unwrap();
    (dir.join("commands.world"), dir.join("commands.pv3d.xml"))
}

/// The viewer against the served world, once both robots are drawn; and their names, r0's
/// first (robot bodies are named by their plugin ids).
fn ready(name: &str) -> (Viewer, Running, Vec<String>) {
    ready_with(commands_world(name))
}

fn ready_with((world, composition_file): (PathBuf, PathBuf)) -> (Viewer, Running, Vec<String>) {
    let mut composition = load(&[composition_file.to_str().unwrap()]);
    let running = serve(world.to_str().unwrap(), &mut composition, 4.0);
    let mut viewer = tests::viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    run_until(&mut viewer, "two robots", Duration::from_secs(10), |v| {
        Vocabulary::of_scene(v.scene()).robots.len() == 2
    });
    run_for(&mut viewer, Duration::from_millis(300));
    let vocabulary = Vocabulary::of_scene(viewer.scene());
    assert_eq!(vocabulary.zones, vec!["charging".to_string()]);
    // r1 starts 2 m below r0: the robot drawn lower is r1.
    let mut robots = vocabulary.robots.clone();
    let y = |name: &String| {
        let scene = viewer.scene();
        let (id, _) = scene.iter().find(|(_, o)| &o.name == name).unwrap();
        scene.world_transform(id).translation.y
    };
    robots.sort_by(|a, b| y(b).total_cmp(&y(a)));
    (viewer, running, robots)
}

#[test]
fn a_robot_told_to_go_to_a_zone_arrives_and_all_robots_stop() {
    let (mut viewer, running, robots) = ready("go-to-zone");
    let (r0, r1) = (&robots[0], &robots[1]);

    let reply = viewer.command(&format!("{r0} go to charging")).unwrap();
    assert_eq!(reply, format!("{r0}: going to zone charging"));
    // A zone is driven to its centre, not stopped short of like an object.
    run_until(
        &mut viewer,
        "r0 at charging's centre",
        Duration::from_secs(20),
        |_| {
            let (x, y, _) = sim_pose(&running, 0);
            (x - 3.0).hypot(y - 2.0) < 0.4
        },
    );
    assert!(!in_charging(sim_pose(&running, 1)), "r1 was not told");

    // Both set off for a far point; then everyone stops, and stays stopped.
    viewer
        .command(&format!("{r0} and {r1} go to -6 -6"))
        .unwrap();
    run_for(&mut viewer, Duration::from_millis(800));
    let moving = sim_pose(&running, 1);
    assert!(moving.0.hypot(moving.1 + 2.0) > 0.05, "r1 set off");
    assert_eq!(
        viewer.command("all robots stop").unwrap(),
        "all robots: stopping"
    );
    run_for(&mut viewer, Duration::from_millis(500));
    let stopped = [sim_pose(&running, 0), sim_pose(&running, 1)];
    run_for(&mut viewer, Duration::from_millis(1000));
    for (i, before) in stopped.iter().enumerate() {
        let after = sim_pose(&running, i);
        let moved = (after.0 - before.0).hypot(after.1 - before.1);
        assert!(moved < 0.02, "robot {i} still moving: {moved} m");
    }

    let refused = viewer.command("robot9 go to charging").unwrap_err();
    assert!(
        refused.starts_with("robot9 go to charging: no robot named robot9;"),
        "{refused}"
    );
    assert!(
        refused.contains(r0.as_str()) && refused.contains(r1.as_str()),
        "{refused}"
    );
}

#[test]
fn a_script_says_its_lines_in_time_and_names_the_line_of_an_error() {
    let (mut viewer, running, robots) = ready("script");
    let text = format!(
        "# two sentences, then a mistake\n0 {r1} go to charging\n\n0.2 robot9 stop\n",
        r1 = robots[1]
    );
    let script = Script::from_str(&text, Path::new("tour.txt")).unwrap();
    viewer.run_script(script);
    run_until(
        &mut viewer,
        "the script's error",
        Duration::from_secs(5),
        |v| v.replies().len() == 2,
    );
    assert!(viewer.replies()[0].is_ok(), "{:?}", viewer.replies());
    let error = viewer.replies()[1].clone().unwrap_err();
    assert!(
        error.starts_with("tour.txt:4: robot9 stop: no robot named robot9"),
        "{error}"
    );
    run_until(
        &mut viewer,
        "r1 in charging",
        Duration::from_secs(20),
        |_| in_charging(sim_pose(&running, 1)),
    );
}

#[test]
fn a_bad_script_is_refused_naming_its_line() {
    let e = Script::from_str("1 r0 stop\nsoon r0 stop\n", Path::new("s.txt")).unwrap_err();
    assert_eq!(
        e.to_string(),
        "s.txt:2: \"soon\" is not a number of seconds"
    );
    let e = Script::from_str("\n\n-1 r0 stop\n", Path::new("s.txt")).unwrap_err();
    assert!(e.to_string().starts_with("s.txt:3: seconds must be"), "{e}");
    let e = Script::from_str("5\n", Path::new("s.txt")).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("s.txt:1: expected <seconds> <sentence>"),
        "{e}"
    );
    let ok = Script::from_str("2 b stop # later\n1 a stop\n", Path::new("s.txt")).unwrap();
    let order: Vec<(&str, usize)> = ok
        .lines
        .iter()
        .map(|l| (l.sentence.as_str(), l.line))
        .collect();
    assert_eq!(order, vec![("a stop", 2), ("b stop", 1)]);
}

#[test]
fn sentences_heard_through_player_are_carried_out_and_the_replies_said() {
    let files = commands_world_with(
        "speech",
        "driver ( name \"sentences\" provides [ \"6665:speech_recognition:0\" ] file \"heard.txt\" )\n\
         driver ( name \"festival\" provides [ \"6665:speech:0\" ] log \"said.txt\" )\n",
    );
    let dir = files.0.parent().unwrap().to_path_buf();
    let said = dir.join("said.txt");
    let _ = std::fs::remove_file(&said);
    // Simulated seconds: the viewer is connected well before.
    std::fs::write(
        dir.join("heard.txt"),
        "3 all robots go to charging\n6 robot9 stop\n",
    )
    .unwrap();
    let (mut viewer, running, _) = ready_with(files);
    run_until(
        &mut viewer,
        "r0 in charging",
        Duration::from_secs(30),
        |_| in_charging(sim_pose(&running, 0)),
    );
    // Both replies, and the reaction's sentence when a robot arrives: all said through Player.
    run_until(
        &mut viewer,
        "both replies and the reaction said",
        Duration::from_secs(20),
        |_| {
            std::fs::read_to_string(&said).is_ok_and(|t| {
                t.lines().any(|l| l.starts_with("robot9 stop"))
                    && t.lines().any(|l| l == CHARGING_SAID)
            })
        },
    );
    let text = std::fs::read_to_string(&said).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "all robots: going to zone charging");
    let replies: Vec<&&str> = lines.iter().filter(|l| **l != CHARGING_SAID).collect();
    assert_eq!(replies.len(), 2, "{text}");
    assert!(
        replies[1].starts_with("robot9 stop: no robot named robot9"),
        "{text}"
    );
}
