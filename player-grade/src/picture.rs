//! `path.png`: the world from above — its walls and obstacles, the zones and targets of the
//! checks (green where the check passed, red where it failed), the other robots' paths in grey
//! and the graded robot's path in blue, from a ring at its start to a dot at its end, with a
//! cross where it first stalled.

use image::{Rgb, RgbImage};
use player_sim::world::World;

use crate::checks::{Check, Rule, Verdict};
use crate::trace::Trace;
use crate::zone::Zone;

/// The picture's longer side, pixels.
const SIDE: u32 = 640;
const MARGIN: f64 = 0.5;

const FLOOR: Rgb<u8> = Rgb([250, 250, 247]);
const WALL: Rgb<u8> = Rgb([40, 40, 48]);
const OBSTACLE: Rgb<u8> = Rgb([120, 110, 100]);
const PATH: Rgb<u8> = Rgb([30, 90, 220]);
const OTHERS: Rgb<u8> = Rgb([170, 170, 175]);
const PASSED: Rgb<u8> = Rgb([40, 160, 70]);
const FAILED: Rgb<u8> = Rgb([210, 50, 50]);

/// World metres to pixels.
struct View {
    x0: f64,
    y1: f64,
    scale: f64,
    width: u32,
    height: u32,
}

impl View {
    fn pixel(&self, x: f64, y: f64) -> (f64, f64) {
        ((x - self.x0) * self.scale, (self.y1 - y) * self.scale)
    }

    fn world(&self, px: u32, py: u32) -> (f64, f64) {
        (
            self.x0 + (f64::from(px) + 0.5) / self.scale,
            self.y1 - (f64::from(py) + 0.5) / self.scale,
        )
    }
}

/// The picture of `trace` in `world`, with `checks` and their verdicts.
pub fn draw(world: &World, trace: &Trace, checks: &[Check], verdicts: &[Verdict]) -> RgbImage {
    let view = frame(world, trace, checks);
    let mut image = RgbImage::from_pixel(view.width, view.height, FLOOR);
    if let Some(floor) = &world.floor {
        for py in 0..view.height {
            for px in 0..view.width {
                let (x, y) = view.world(px, py);
                if floor.occupied_at(x, y) {
                    image.put_pixel(px, py, WALL);
                }
            }
        }
    }
    for obstacle in &world.obstacles {
        let (hl, hw) = (obstacle.size[0] / 2.0, obstacle.size[1] / 2.0);
        let (s, c) = obstacle.pose.a.sin_cos();
        let corner = |u: f64, v: f64| {
            view.pixel(
                obstacle.pose.x + u * c - v * s,
                obstacle.pose.y + u * s + v * c,
            )
        };
        let corners = [
            corner(-hl, -hw),
            corner(hl, -hw),
            corner(hl, hw),
            corner(-hl, hw),
        ];
        for i in 0..4 {
            line(&mut image, corners[i], corners[(i + 1) % 4], OBSTACLE, 2.0);
        }
    }
    for (check, verdict) in checks.iter().zip(verdicts) {
        let colour = if verdict.passed() { PASSED } else { FAILED };
        match &check.rule {
            Rule::Reach { zone, .. } | Rule::EndIn(zone) | Rule::Avoid(zone) => {
                outline(&mut image, &view, zone, colour);
            }
            Rule::Follow { target, .. } => {
                let path: Vec<(f64, f64)> = trace
                    .samples
                    .iter()
                    .map(|s| view.pixel(s.poses[*target].0, s.poses[*target].1))
                    .collect();
                polyline(&mut image, &path, colour, 2.0);
            }
            _ => {}
        }
    }
    for other in (0..trace.names.len()).filter(|&r| r != trace.robot) {
        let path: Vec<(f64, f64)> = trace
            .samples
            .iter()
            .map(|s| view.pixel(s.poses[other].0, s.poses[other].1))
            .collect();
        polyline(&mut image, &path, OTHERS, 1.0);
    }
    let path: Vec<(f64, f64)> = trace.path().map(|(_, x, y)| view.pixel(x, y)).collect();
    polyline(&mut image, &path, PATH, 2.5);
    if let (Some(&start), Some(&end)) = (path.first(), path.last()) {
        ring(&mut image, start, 6.0, PATH);
        disc(&mut image, end, 5.0, PATH);
    }
    if let Some((_, x, y)) = trace.first_stall() {
        let (cx, cy) = view.pixel(x, y);
        line(
            &mut image,
            (cx - 7.0, cy - 7.0),
            (cx + 7.0, cy + 7.0),
            FAILED,
            2.5,
        );
        line(
            &mut image,
            (cx - 7.0, cy + 7.0),
            (cx + 7.0, cy - 7.0),
            FAILED,
            2.5,
        );
    }
    image
}

/// What the picture shows: the floor's extent, else the paths and zones, with a margin.
fn frame(world: &World, trace: &Trace, checks: &[Check]) -> View {
    let mut low = (f64::INFINITY, f64::INFINITY);
    let mut high = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut take = |x: f64, y: f64| {
        if x.is_finite() && y.is_finite() {
            low = (low.0.min(x), low.1.min(y));
            high = (high.0.max(x), high.1.max(y));
        }
    };
    if let Some(floor) = &world.floor {
        take(floor.origin.0, floor.origin.1);
        take(
            floor.origin.0 + floor.width as f64 * floor.cell.0,
            floor.origin.1 + floor.height as f64 * floor.cell.1,
        );
    }
    for sample in &trace.samples {
        for &(x, y, _) in &sample.poses {
            take(x, y);
        }
    }
    for check in checks {
        if let Rule::Reach { zone, .. } | Rule::EndIn(zone) | Rule::Avoid(zone) = &check.rule {
            let (low, high) = zone.bounds();
            take(low.0, low.1);
            take(high.0, high.1);
        }
    }
    if !low.0.is_finite() {
        (low, high) = ((-1.0, -1.0), (1.0, 1.0));
    }
    let (x0, y0) = (low.0 - MARGIN, low.1 - MARGIN);
    let (x1, y1) = (high.0 + MARGIN, high.1 + MARGIN);
    let scale = f64::from(SIDE) / (x1 - x0).max(y1 - y0);
    View {
        x0,
        y1,
        scale,
        width: (((x1 - x0) * scale).ceil() as u32).clamp(1, SIDE),
        height: (((y1 - y0) * scale).ceil() as u32).clamp(1, SIDE),
    }
}

fn outline(image: &mut RgbImage, view: &View, zone: &Zone, colour: Rgb<u8>) {
    match *zone {
        Zone::Circle { x, y, radius } => {
            let centre = view.pixel(x, y);
            ring(image, centre, radius * view.scale, colour);
        }
        Zone::Box {
            xmin,
            xmax,
            ymin,
            ymax,
        } => {
            let corners = [
                view.pixel(xmin, ymin),
                view.pixel(xmax, ymin),
                view.pixel(xmax, ymax),
                view.pixel(xmin, ymax),
            ];
            for i in 0..4 {
                line(image, corners[i], corners[(i + 1) % 4], colour, 2.0);
            }
        }
    }
}

fn polyline(image: &mut RgbImage, points: &[(f64, f64)], colour: Rgb<u8>, width: f64) {
    for pair in points.windows(2) {
        line(image, pair[0], pair[1], colour, width);
    }
}

fn ring(image: &mut RgbImage, centre: (f64, f64), radius: f64, colour: Rgb<u8>) {
    let steps = (radius * 8.0).clamp(16.0, 720.0) as usize;
    let points: Vec<(f64, f64)> = (0..=steps)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / steps as f64;
            (centre.0 + radius * a.cos(), centre.1 + radius * a.sin())
        })
        .collect();
    polyline(image, &points, colour, 2.0);
}

fn disc(image: &mut RgbImage, centre: (f64, f64), radius: f64, colour: Rgb<u8>) {
    stamp(image, centre, radius, colour);
}

/// A line `width` pixels wide: discs stamped along it.
fn line(image: &mut RgbImage, a: (f64, f64), b: (f64, f64), colour: Rgb<u8>, width: f64) {
    let length = (b.0 - a.0).hypot(b.1 - a.1);
    if !length.is_finite() {
        return;
    }
    let steps = (length * 2.0).ceil().clamp(1.0, 20_000.0) as usize;
    for i in 0..=steps {
        let t = i as f64 / steps as f64;
        stamp(
            image,
            (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t),
            width / 2.0,
            colour,
        );
    }
}

fn stamp(image: &mut RgbImage, centre: (f64, f64), radius: f64, colour: Rgb<u8>) {
    let r = radius.max(0.5);
    let (w, h) = (i64::from(image.width()), i64::from(image.height()));
    let (x0, x1) = ((centre.0 - r).floor() as i64, (centre.0 + r).ceil() as i64);
    let (y0, y1) = ((centre.1 - r).floor() as i64, (centre.1 + r).ceil() as i64);
    for py in y0.max(0)..=y1.min(h - 1) {
        for px in x0.max(0)..=x1.min(w - 1) {
            let (dx, dy) = (px as f64 + 0.5 - centre.0, py as f64 + 0.5 - centre.1);
            if dx * dx + dy * dy <= r * r {
                image.put_pixel(px as u32, py as u32, colour);
            }
        }
    }
}
