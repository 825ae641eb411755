//! What player-sim must reach against Stage's golden readings (tests/golden.rs): issue #34's
//! tolerances, or, in a world whose gap is still open, the figures it reached when measured,
//! with why it does not reach more. A gap closed moves its world off the list.

/// Least share (%) of beams within 5 cm of Stage's, laser and sonar, and most share off by
/// more than 0.5 m.
#[derive(Debug)]
pub struct Floor {
    pub laser_within_5cm: f64,
    pub laser_off_half_m: f64,
    pub sonar_within_5cm: f64,
}

/// Issue #34's tolerances.
const TOLERANCES: Floor = Floor {
    laser_within_5cm: 98.0,
    laser_off_half_m: 0.1,
    sonar_within_5cm: 95.0,
};

/// The worlds whose gaps are still open, with what player-sim reaches there and why not more.
/// A world not listed must meet [`TOLERANCES`].
const GAPS: &[(&str, Floor, &str)] = &[
    (
        "classroom",
        Floor {
            laser_within_5cm: 98.7,
            laser_off_half_m: 0.6,
            sonar_within_5cm: 95.0,
        },
        "the robots' lidar heads are met on their cells of Stage's raster now (1.18 % off \
         before); what remains are beams grazing those cells or the walls': Stage walks a ray \
         in whole cells from where it starts and jumps across empty 32-cell regions, so its path \
         can pass a cell beside the one player-sim's ray enters",
    ),
    (
        "oneport",
        Floor {
            laser_within_5cm: 99.1,
            laser_off_half_m: 0.17,
            sonar_within_5cm: 95.0,
        },
        "the other robot's lidar head is met on its cells of Stage's raster now (0.33 % off \
         before); what remains are beams grazing cells, whose path differs from Stage's walk \
         by a cell",
    ),
    (
        "autolab",
        Floor {
            laser_within_5cm: 99.1,
            laser_off_half_m: 0.14,
            sonar_within_5cm: 95.0,
        },
        "beams grazing the cells of a wall's corner or another robot: Stage walks a ray in \
         whole cells from where it starts and jumps across empty 32-cell regions, so its \
         path can pass a cell beside the one player-sim's ray enters",
    ),
    (
        "mbicp",
        Floor {
            laser_within_5cm: 98.0,
            laser_off_half_m: 0.1,
            sonar_within_5cm: 66.6,
        },
        "its ranger's range and field of view",
    ),
    (
        "pioneer_flocking",
        Floor {
            laser_within_5cm: 98.0,
            laser_off_half_m: 0.1,
            sonar_within_5cm: 92.15,
        },
        "sonar: resolution 0.1 (10 cm cells): the other robots are met on their cells as in \
         Stage, but at cells this coarse the path of Stage's walk (whole cells from where the \
         ray starts) decides which of a robot's cells a sonar's single beam enters",
    ),
    (
        "pioneer_follow",
        Floor {
            laser_within_5cm: 98.35,
            laser_off_half_m: 0.14,
            sonar_within_5cm: 95.0,
        },
        "beams grazing corners of the cave's cells",
    ),
    (
        "pioneer_walle",
        Floor {
            laser_within_5cm: 98.35,
            laser_off_half_m: 0.21,
            sonar_within_5cm: 95.0,
        },
        "beams grazing corners of the cave's cells",
    ),
    (
        "sensor_noise_demo",
        Floor {
            laser_within_5cm: 43.35,
            laser_off_half_m: 0.14,
            sonar_within_5cm: 95.0,
        },
        "Stage's readings carry its sensor's noise (Gaussian, sd 0.1 m): compared with \
         player-sim's exact readings, only the beams whose draw was small are within 5 cm (the \
         noise's spread is checked apart: Stage 100.9 mm, player-sim 100.3 mm); the cave bitmap",
    ),
    (
        "sensor_noise_module_demo",
        Floor {
            laser_within_5cm: 98.35,
            laser_off_half_m: 0.14,
            sonar_within_5cm: 95.0,
        },
        "beams grazing corners of the cave's cells",
    ),
    (
        "simple",
        Floor {
            laser_within_5cm: 98.1,
            laser_off_half_m: 0.14,
            sonar_within_5cm: 95.0,
        },
        "beams grazing corners of the cave's cells",
    ),
    (
        "uoa_robotics_lab",
        Floor {
            laser_within_5cm: 96.3,
            laser_off_half_m: 2.78,
            sonar_within_5cm: 96.3,
        },
        "its furniture (chairs' 3 cm legs, a table's poles, the cabinet's posts) is met on \
         its cells of Stage's 2 cm raster now (9.91 % off before, sonar 88.2 %); what remains \
         are beams passing within a cell of a leg, which Stage's walk (whole cells from where \
         the ray starts, jumps across empty regions) enters or misses where player-sim's ray \
         does the opposite: one or two beams a leg",
    ),
];

/// What `name` must meet.
pub fn floor_of(name: &str) -> &'static Floor {
    GAPS.iter()
        .find(|(n, _, _)| *n == name)
        .map_or(&TOLERANCES, |(_, floor, _)| floor)
}
