//! The names a sentence may use, taken from the live world: robots as the scene draws them,
//! the zones' names, and the tags scene objects carry. Read again for every sentence, so a
//! robot that joined a moment ago can be commanded at once.

use framework::scene::Scene;

/// Tag every robot body carries (position2d's plugin sets it).
pub const ROBOT_TAG: &str = "robot";
/// A zone's object carries `zone:NAME`.
pub const ZONE_TAG_PREFIX: &str = "zone:";

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Vocabulary {
    pub robots: Vec<String>,
    pub zones: Vec<String>,
    pub tags: Vec<String>,
}

impl Vocabulary {
    /// The names in `scene`, each once, sorted.
    pub fn of_scene(scene: &Scene) -> Vocabulary {
        let mut vocabulary = Vocabulary::default();
        for (_, object) in scene.iter() {
            if object.has_tag(ROBOT_TAG) {
                vocabulary.robots.push(object.name.clone());
            }
            for tag in &object.tags {
                match tag.strip_prefix(ZONE_TAG_PREFIX) {
                    Some(zone) => vocabulary.zones.push(zone.to_string()),
                    // `id:7` and the like tell objects apart; nobody says them.
                    None if !tag.contains(':') => vocabulary.tags.push(tag.clone()),
                    None => {}
                }
            }
        }
        for list in [
            &mut vocabulary.robots,
            &mut vocabulary.zones,
            &mut vocabulary.tags,
        ] {
            list.sort();
            list.dedup();
        }
        vocabulary
    }
}
