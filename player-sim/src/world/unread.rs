//! What of a world player-sim does not read, noted once at each place that asks it ("ignored:
//! <what> at file:line"): properties no part of player-sim reads, parts of models it does not
//! simulate, blocks it cannot slice by height. `ignored.rs` sums the notes up in one line.

use super::properties::READ;
use super::{Model, World, blocks};
use crate::worldfile::Pos;

impl World {
    pub(super) fn ignore(&mut self, what: &str, pos: &Pos) {
        let note = format!("ignored: {what} at {}:{}", pos.file, pos.line);
        if self.ignored_seen.insert(note.clone()) {
            tracing::debug!("{note}");
            self.ignored.push(note);
        }
    }

    pub(super) fn note_unread(&mut self, model: &Model) {
        for p in &model.properties {
            if !READ.contains(&p.name.as_str()) {
                self.ignore(&format!("{} property {}", model.declared, p.name), &p.pos);
            }
        }
        for block in blocks::partial_height_blocks(model) {
            self.ignore(
                &format!(
                    "a block not as tall as the rest of {} (solid at every height to collisions and cameras)",
                    model.declared
                ),
                &block.pos,
            );
        }
        // Sensors are read by the ranger and block() shapes by every model; nothing else is.
        for part in &model.parts {
            let read: &[&str] = match part.kind.as_str() {
                // A sensor's colour only tints its beams in Stage's GUI.
                "sensor" if model.kind == "ranger" => &[
                    "pose",
                    "size",
                    "range",
                    "fov",
                    "samples",
                    "color",
                    "color_rgba",
                    "noise",
                ],
                "block" => &["points", "z"],
                _ => {
                    self.ignore(&format!("{}() in {}", part.kind, model.declared), &part.pos);
                    continue;
                }
            };
            for p in &part.properties {
                let indexed_point = part.kind == "block" && p.name.starts_with("point[");
                if !read.contains(&p.name.as_str()) && !indexed_point {
                    self.ignore(&format!("{} property {}", part.kind, p.name), &p.pos);
                }
            }
            for inner in &part.children {
                self.ignore(&format!("{}() in {}", inner.kind, part.kind), &inner.pos);
            }
        }
    }
}
