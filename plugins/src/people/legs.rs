//! Finding people in one laser scan: the readings break into clusters where neighbouring
//! returns are far apart; a cluster as wide as a leg is a leg, and two legs close enough to
//! belong to one person are that person. Optionally a single cluster as wide as a body
//! (legs together, a long coat) counts too — off by default, since a robot is that wide.
//! Pure geometry, in the laser's frame, so that it is tested on made-up scans.

use glam::Vec2;

/// The detector's thresholds, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegParams {
    /// Neighbouring returns farther apart than this start a new cluster.
    pub cluster_gap: f32,
    pub min_leg_width: f32,
    pub max_leg_width: f32,
    /// The largest distance between two legs' centres that still makes one person.
    pub max_leg_gap: f32,
    /// A single cluster this wide is a person too, when `Some((min, max))`.
    pub body_width: Option<(f32, f32)>,
}

impl Default for LegParams {
    fn default() -> LegParams {
        LegParams {
            cluster_gap: 0.1,
            min_leg_width: 0.05,
            max_leg_width: 0.25,
            max_leg_gap: 0.5,
            body_width: None,
        }
    }
}

/// One scan, as bearings and ranges.
#[derive(Debug, Clone, Copy)]
pub struct Scan<'a> {
    pub ranges: &'a [f32],
    /// Bearing of the first reading, rad.
    pub first: f32,
    /// Angle between readings, rad.
    pub step: f32,
    /// Readings at or beyond this saw nothing, m.
    pub max_range: f32,
}

/// A run of neighbouring returns.
#[derive(Debug, Clone, PartialEq)]
pub struct Cluster {
    pub centre: Vec2,
    /// Its extent across the beams, with one beam's footprint added (a single return
    /// still covers the gap to its neighbours).
    pub width: f32,
    /// Whether it stands in front of what lies beside it (the readings on either side see
    /// nothing, or something farther): a leg does, a stretch of wall seen edge-on does not.
    pub in_front: bool,
}

/// Whether a reading is a return (not "nothing seen", not garbage).
fn is_return(range: f32, max_range: f32) -> bool {
    range.is_finite() && range > 0.0 && (max_range <= 0.0 || range < max_range)
}

/// The scan's clusters, in bearing order.
pub fn clusters(scan: &Scan<'_>, gap: f32) -> Vec<Cluster> {
    let mut out = Vec::new();
    let mut run: Vec<(Vec2, f32)> = Vec::new();
    // Whether the reading at `index` (if any) is nothing, or farther than `range` by a gap.
    let behind = |index: Option<usize>, range: f32| {
        index
            .and_then(|i| scan.ranges.get(i))
            .is_none_or(|&r| !is_return(r, scan.max_range) || r > range + gap)
    };
    let finish = |run: &mut Vec<(Vec2, f32)>, out: &mut Vec<Cluster>, end: usize| {
        if let (Some(&(a, _)), Some(&(b, _))) = (run.first(), run.last()) {
            let n = run.len() as f32;
            let mean_range = run.iter().map(|(_, r)| r).sum::<f32>() / n;
            let nearest = run.iter().map(|(_, r)| *r).fold(f32::INFINITY, f32::min);
            let centre = run.iter().map(|(p, _)| *p).sum::<Vec2>() / n;
            let start = end - run.len();
            out.push(Cluster {
                centre,
                width: a.distance(b) + mean_range * scan.step.abs(),
                in_front: behind(start.checked_sub(1), nearest) && behind(Some(end), nearest),
            });
        }
        run.clear();
    };
    for (i, &range) in scan.ranges.iter().enumerate() {
        if !is_return(range, scan.max_range) {
            finish(&mut run, &mut out, i);
            continue;
        }
        let bearing = scan.first + scan.step * i as f32;
        let point = Vec2::from_angle(bearing) * range;
        if run
            .last()
            .is_some_and(|(last, _)| last.distance(point) > gap)
        {
            finish(&mut run, &mut out, i);
        }
        run.push((point, range));
    }
    finish(&mut run, &mut out, scan.ranges.len());
    out
}

/// Where the people are in this scan, in the laser's frame. Only clusters in front of
/// their surroundings count: the sparse returns of a wall seen edge-on are as narrow as
/// legs, but each has a nearer stretch of wall beside it.
pub fn people(scan: &Scan<'_>, params: &LegParams) -> Vec<Vec2> {
    let found: Vec<Cluster> = clusters(scan, params.cluster_gap)
        .into_iter()
        .filter(|c| c.in_front)
        .collect();
    let legs: Vec<Vec2> = found
        .iter()
        .filter(|c| (params.min_leg_width..=params.max_leg_width).contains(&c.width))
        .map(|c| c.centre)
        .collect();
    let mut people = pair_legs(&legs, params.max_leg_gap);
    if let Some((min, max)) = params.body_width {
        people.extend(
            found
                .iter()
                .filter(|c| c.width > params.max_leg_width && (min..=max).contains(&c.width))
                .map(|c| c.centre),
        );
    }
    people
}

/// Pairs legs, nearest pairs first, each leg in one pair at most; a person stands between
/// the two. A leg with no partner near enough is left out.
fn pair_legs(legs: &[Vec2], max_gap: f32) -> Vec<Vec2> {
    let mut pairs: Vec<(f32, usize, usize)> = Vec::new();
    for i in 0..legs.len() {
        for j in i + 1..legs.len() {
            let d = legs[i].distance(legs[j]);
            if d <= max_gap {
                pairs.push((d, i, j));
            }
        }
    }
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut used = vec![false; legs.len()];
    let mut people = Vec::new();
    for (_, i, j) in pairs {
        if !used[i] && !used[j] {
            used[i] = true;
            used[j] = true;
            people.push((legs[i] + legs[j]) / 2.0);
        }
    }
    people
}
