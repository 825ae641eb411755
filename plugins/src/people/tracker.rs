//! Keeping people's identities from scan to scan: a detection near where a person was is
//! that person again; one near nobody is someone new; a person not seen for some scans has
//! left. Identities are what reactions and "follow" hold on to.

use glam::Vec2;

/// A person being tracked, in the world frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    pub id: u32,
    pub at: Vec2,
    /// Scans in a row without a detection near it.
    missed: u32,
}

/// What changed with one scan.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Changes {
    pub appeared: Vec<u32>,
    pub left: Vec<u32>,
}

#[derive(Debug, Clone)]
pub struct Tracker {
    tracks: Vec<Track>,
    next_id: u32,
    /// A detection this close to a track is that track, m.
    match_distance: f32,
    /// A track missed this many scans in a row has left (a leg hidden behind the other for
    /// a scan or two must not make a person vanish and come back as someone else).
    keep_scans: u32,
}

impl Tracker {
    pub fn new(match_distance: f32, keep_scans: u32) -> Tracker {
        Tracker {
            tracks: Vec::new(),
            next_id: 1,
            match_distance,
            keep_scans,
        }
    }

    pub fn tracks(&self) -> &[Track] {
        &self.tracks
    }

    /// Matches the scan's detections to the tracks, nearest pairs first.
    pub fn update(&mut self, detections: &[Vec2]) -> Changes {
        let mut pairs: Vec<(f32, usize, usize)> = Vec::new();
        for (t, track) in self.tracks.iter().enumerate() {
            for (d, &at) in detections.iter().enumerate() {
                let distance = track.at.distance(at);
                if distance <= self.match_distance {
                    pairs.push((distance, t, d));
                }
            }
        }
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut track_seen = vec![false; self.tracks.len()];
        let mut detection_used = vec![false; detections.len()];
        for (_, t, d) in pairs {
            if !track_seen[t] && !detection_used[d] {
                track_seen[t] = true;
                detection_used[d] = true;
                self.tracks[t].at = detections[d];
                self.tracks[t].missed = 0;
            }
        }
        let mut changes = Changes::default();
        for (track, seen) in self.tracks.iter_mut().zip(&track_seen) {
            if !seen {
                track.missed += 1;
            }
        }
        let keep = self.keep_scans;
        self.tracks.retain(|t| {
            let stays = t.missed <= keep;
            if !stays {
                changes.left.push(t.id);
            }
            stays
        });
        for (d, &at) in detections.iter().enumerate() {
            if !detection_used[d] {
                let id = self.next_id;
                self.next_id += 1;
                self.tracks.push(Track { id, at, missed: 0 });
                changes.appeared.push(id);
            }
        }
        changes
    }
}
