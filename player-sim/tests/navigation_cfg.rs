//! Both halves of navigation.world's two-process setup read as one: the navigation .cfg's
//! `passthrough` devices are r0's own, its `mapfile` serves the floor bitmap, and amcl and
//! wavefront are read and reported as not served yet.

mod support;

use player_proto::wire::Interface;
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
    for (driver, line, serves) in [("amcl", 23, "localize"), ("wavefront", 38, "planner")] {
        let note = format!(
            "ignored: driver {driver:?} ({serves} and its devices are not served yet) at {}:{line}",
            nav.display()
        );
        assert!(ignored.contains(&note), "{note} not in {ignored:?}");
    }
    assert!(!served.iter().any(|d| d.interf == Interface::LOCALIZE));
    // Alone, the navigation half has nothing to pass through: an error at the passthrough.
    let err = from_cfg(&nav, &world, &mut Vec::new())
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with(&format!("{}:10:", nav.display())) && err.contains("passthrough"),
        "{err}"
    );
}
