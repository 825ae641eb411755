//! Both halves of navigation.world's two-process setup read as one: the navigation .cfg's
//! `passthrough` devices are r0's own, its `mapfile` serves the floor bitmap, amcl localizes
//! r0 and wavefront drives it.

mod support;

use player_proto::wire::Interface;
use player_sim::nav::PoseInput;
use player_sim::served::{Source, from_cfg, from_cfgs};
use player_sim::world::World;

#[test]
fn the_navigation_half_reaches_r0_and_serves_the_map() {
    let dir = support::worlds();
    let world = World::load(&dir.join("navigation.world")).unwrap();
    let (stage, nav) = (dir.join("navigation.cfg"), dir.join("navigation-nav.cfg"));
    let mut ignored = Vec::new();
    let served = from_cfgs(&[&stage, &nav], &world, &mut ignored).unwrap();
    let on = |port: u16, interf: Interface, index: u16| {
        served
            .iter()
            .find(|d| (d.port, d.interf, d.index) == (port, interf, index))
            .unwrap_or_else(|| panic!("{port}:{interf}:{index} not served"))
    };
    let passed = on(6665, Interface::POSITION2D, 0);
    assert_eq!(passed.driver, "passthrough");
    assert_eq!(passed.source, on(6666, Interface::POSITION2D, 0).source);
    assert_eq!(
        on(6665, Interface::LASER, 0).source,
        Source::Laser {
            robot: 0,
            ranger: 0
        }
    );
    let Source::Map(map) = &on(6665, Interface::MAP, 0).source else {
        panic!("map:0 is not a map");
    };
    assert_eq!((map.0.width, map.0.height), (160, 120));
    assert_eq!(map.0.origin, (-8.0, -6.0));
    // The map and the floorplan are the same walls: r0's start is free, the border occupied.
    assert_eq!(map.0.cell(15, 15), Some(-1));
    assert_eq!(map.0.cell(0, 0), Some(1));
    let Source::Localize(amcl) = &on(6665, Interface::LOCALIZE, 0).source else {
        panic!("localize:0 is not a localizer");
    };
    assert_eq!(on(6665, Interface::LOCALIZE, 0).driver, "amcl");
    assert_eq!(amcl.spec.robot, 0);
    assert_eq!(amcl.spec.particles, 100);
    assert!((amcl.spec.update_angle - 15f64.to_radians()).abs() < 1e-12);
    let init = amcl.spec.init_pose.unwrap();
    assert_eq!((init.x, init.y), (-6.5, -4.5));
    assert_eq!(
        on(6665, Interface::POSITION2D, 1).source,
        Source::Estimate(amcl.clone())
    );
    let Source::Planner(wavefront) = &on(6665, Interface::PLANNER, 0).source else {
        panic!("planner:0 is not a planner");
    };
    assert_eq!(wavefront.spec.robot, 0);
    assert_eq!(wavefront.spec.input, PoseInput::Localizer(amcl.id));
    assert_eq!(wavefront.spec.safety_dist, 0.15);
    assert_eq!(wavefront.spec.settings.dist_eps, 0.5);
    assert!(wavefront.spec.settings.replan_dist < 0.0);
    // What is not simulated is said, once per block.
    let note = format!(
        "ignored: amcl options init_pose_var, laser_max_beams, pf_max_samples (not simulated) \
         at {}:24",
        nav.display()
    );
    assert!(ignored.contains(&note), "{note} not in {ignored:?}");
    // Alone, the navigation half has nothing to pass through: an error at the passthrough.
    let err = from_cfg(&nav, &world, &mut Vec::new())
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with(&format!("{}:11:", nav.display())) && err.contains("passthrough"),
        "{err}"
    );
}
