//! What the open pages show, and so what the relay must subscribe to for them.
//!
//! Every page shows every robot's pose (its row and its body on the map): while any page is
//! open, every robot's position2d devices are looked at. A robot's drawn sensors (lasers,
//! rangers, sonars, fiducials, maps, localize, planner) are looked at only while some page
//! has the robot in view, and a page has at most [`SENSORS_IN_VIEW`] robots' sensors: zoomed
//! out over more robots than that, a 181-beam scan is a few pixels wide, so the page draws
//! bodies only, and the relay does not pay for scans nobody can read. A page says which
//! robots are in its view (`FromPage::Show`); one that has not said yet (a page just opened,
//! or a client that never says) is shown the first [`SENSORS_IN_VIEW`] robots by name.
//! Devices the page does not draw (cameras, power, …) are not looked at: their rows say
//! "not shown".

use std::collections::{BTreeSet, HashMap};

use player_front::Device;
use player_proto::wire::Interface;

/// The most robots whose sensors one page is sent.
pub const SENSORS_IN_VIEW: usize = 64;

/// The interfaces the page draws; other devices' data is only counted in the rows. A camera's
/// frames would cost every page megabytes a second for nothing drawn.
pub const DRAWN: &[Interface] = &[
    Interface::POSITION2D,
    Interface::LASER,
    Interface::RANGER,
    Interface::SONAR,
    Interface::FIDUCIAL,
    Interface::MAP,
    Interface::LOCALIZE,
    Interface::PLANNER,
];

/// One open page's view: the robots it has in view, or `None` before it said.
type View = Option<BTreeSet<String>>;

/// The open pages' views, by page.
#[derive(Debug, Default, Clone)]
pub struct Views {
    pages: HashMap<u64, View>,
}

impl Views {
    /// A page opened; until it says, it shows the first robots by name.
    pub fn opened(&mut self, page: u64) {
        self.pages.insert(page, None);
    }

    pub fn closed(&mut self, page: u64) {
        self.pages.remove(&page);
    }

    /// The page has `robots` in view (at most [`SENSORS_IN_VIEW`] of them are kept). False
    /// for a page that is not open.
    pub fn show(&mut self, page: u64, robots: &[String]) -> bool {
        match self.pages.get_mut(&page) {
            Some(view) => {
                *view = Some(robots.iter().take(SENSORS_IN_VIEW).cloned().collect());
                true
            }
            None => false,
        }
    }

    /// Whether some page shows `device` of `robot`, the robot being the `rank`-th by name.
    pub fn shows(&self, robot: &str, rank: usize, device: Device) -> bool {
        if device.0 == Interface::POSITION2D {
            return !self.pages.is_empty();
        }
        if !DRAWN.contains(&device.0) {
            return false;
        }
        self.pages.values().any(|view| match view {
            Some(robots) => robots.contains(robot),
            None => rank < SENSORS_IN_VIEW,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LASER: Device = (Interface::LASER, 0);
    const BASE: Device = (Interface::POSITION2D, 0);
    const CAMERA: Device = (Interface::CAMERA, 0);

    #[test]
    fn with_no_page_nothing_is_shown() {
        let views = Views::default();
        assert!(!views.shows("r0", 0, BASE));
        assert!(!views.shows("r0", 0, LASER));
    }

    #[test]
    fn every_pose_is_shown_and_sensors_only_of_the_robots_in_view() {
        let mut views = Views::default();
        views.opened(1);
        assert!(views.shows("r900", 900, BASE), "every robot's pose");
        assert!(
            views.shows("r0", 0, LASER),
            "the first robots before the page says"
        );
        assert!(!views.shows("r900", 900, LASER));
        assert!(
            !views.shows("r0", 0, CAMERA),
            "nothing the page does not draw"
        );
        assert!(views.show(1, &["r900".to_string()]));
        assert!(views.shows("r900", 900, LASER));
        assert!(!views.shows("r0", 0, LASER));
        views.closed(1);
        assert!(!views.shows("r900", 900, BASE));
        assert!(!views.show(1, &[]), "a closed page shows nothing");
    }

    #[test]
    fn a_page_gets_the_sensors_of_at_most_so_many_robots() {
        let mut views = Views::default();
        views.opened(1);
        let all: Vec<String> = (0..1000).map(|i| format!("r{i:04}")).collect();
        views.show(1, &all);
        let shown = all
            .iter()
            .enumerate()
            .filter(|(rank, r)| views.shows(r, *rank, LASER))
            .count();
        assert_eq!(shown, SENSORS_IN_VIEW);
    }
}
