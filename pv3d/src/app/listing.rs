//! Lists that stay usable at a thousand robots: the item tree's components and the status
//! panel's servers are found by typing (every word of the find text, in any case, must appear),
//! the selected robot and what runs on its server come first, and past a screenful the rest is
//! summarised instead of listed. GL-free and egui-free, so the rules are tested alone.

use std::collections::BTreeMap;

/// The item tree lists at most this many components; the others are summarised by kind.
pub const LISTED_AT_MOST: usize = 60;
/// From this many entries on, the item tree offers the find field.
pub const FIND_FROM: usize = 12;

/// What the lists know of one entry.
#[derive(Debug, Clone, Copy)]
pub struct Entry<'a> {
    /// What the entry is called where it is listed.
    pub title: &'a str,
    /// The Player server (host, port) it belongs to, if any.
    pub server: Option<(&'a str, u16)>,
}

/// Which entries to list, in which order, and how many found ones were left out.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Listing {
    /// Indices into the entries, in the order to show them.
    pub shown: Vec<usize>,
    /// Entries the find text matches (shown or not).
    pub found: usize,
}

impl Listing {
    /// Found entries not shown for want of room.
    pub fn left_out(&self) -> usize {
        self.found - self.shown.len()
    }
}

/// Whether `text` holds every word of `find`, ignoring case. An empty find holds everywhere.
pub fn matches(find: &str, text: &str) -> bool {
    let text = text.to_lowercase();
    find.split_whitespace()
        .all(|word| text.contains(&word.to_lowercase()))
}

/// The text an entry is found by: its title and its server's host:port.
fn searchable(entry: &Entry<'_>) -> String {
    match entry.server {
        Some((host, port)) => format!("{} {host}:{port}", entry.title),
        None => entry.title.to_string(),
    }
}

/// Orders `entries`: the `selected` one first, then the others on its server, then the rest,
/// each group in its own order; keeps those `find` matches; lists at most `at_most`.
pub fn list(entries: &[Entry<'_>], selected: Option<usize>, find: &str, at_most: usize) -> Listing {
    let selected_server = selected.and_then(|i| entries.get(i)).and_then(|e| e.server);
    let rank = |i: usize| -> u8 {
        if Some(i) == selected {
            0
        } else if selected_server.is_some() && entries[i].server == selected_server {
            1
        } else {
            2
        }
    };
    // Nothing typed finds everything: no entry's text is made (a thousand a frame).
    let typed = !find.trim().is_empty();
    let mut found: Vec<usize> = (0..entries.len())
        .filter(|&i| !typed || matches(find, &searchable(&entries[i])))
        .collect();
    // Stable: each group keeps the composition's order.
    found.sort_by_key(|&i| rank(i));
    let count = found.len();
    found.truncate(at_most);
    Listing {
        shown: found,
        found: count,
    }
}

/// "2 048 components: 1 024 laser, 1 024 position2d": how many of each kind, most first.
pub fn summary<'a>(kinds: impl IntoIterator<Item = &'a str>, noun: &str) -> String {
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    let mut total = 0;
    for kind in kinds {
        *counts.entry(kind).or_default() += 1;
        total += 1;
    }
    let mut by_count: Vec<(&str, usize)> = counts.into_iter().collect();
    by_count.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
    let parts: Vec<String> = by_count
        .iter()
        .map(|(kind, n)| format!("{} {kind}", thousands(*n)))
        .collect();
    format!("{} {noun}: {}", thousands(total), parts.join(", "))
}

/// 1024 as "1 024", as the rest of the viewer writes large counts.
pub fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(' ');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn swarm(robots: u16) -> Vec<(String, u16)> {
        (0..robots)
            .flat_map(|r| {
                let port = 7000 + r;
                [
                    (format!("Robot robot{r}"), port),
                    (format!("Laser laser:0@127.0.0.1:{port}"), port),
                ]
            })
            .collect()
    }

    fn entries(items: &[(String, u16)]) -> Vec<Entry<'_>> {
        items
            .iter()
            .map(|(title, port)| Entry {
                title,
                server: Some(("127.0.0.1", *port)),
            })
            .collect()
    }

    #[test]
    fn a_thousand_robots_list_a_screenful_and_count_the_rest() {
        let items = swarm(1024);
        let listing = list(&entries(&items), None, "", LISTED_AT_MOST);
        assert_eq!(listing.shown.len(), LISTED_AT_MOST);
        assert_eq!(listing.found, 2048);
        assert_eq!(listing.left_out(), 2048 - LISTED_AT_MOST);
        assert_eq!(listing.shown[..3], [0, 1, 2], "in the composition's order");
    }

    #[test]
    fn the_selected_robot_and_its_server_come_first() {
        let items = swarm(1024);
        let all = entries(&items);
        // robot700 is entry 1400, its laser 1401.
        let listing = list(&all, Some(1400), "", LISTED_AT_MOST);
        assert_eq!(listing.shown[..3], [1400, 1401, 0]);
    }

    #[test]
    fn typing_finds_by_every_word_in_any_case() {
        let items = swarm(1024);
        let all = entries(&items);
        let robot = list(&all, None, "ROBOT1000", LISTED_AT_MOST);
        assert_eq!(robot.shown, [2000]);
        let by_port = list(&all, None, "laser 127.0.0.1:7005", LISTED_AT_MOST);
        assert_eq!(by_port.shown, [11], "the laser on port 7005 only");
        let lasers = list(&all, None, "laser", LISTED_AT_MOST);
        assert_eq!((lasers.found, lasers.shown.len()), (1024, LISTED_AT_MOST));
        assert!(list(&all, None, "sonar", LISTED_AT_MOST).shown.is_empty());
        assert!(matches("", "anything") && matches("  ", "anything"));
    }

    #[test]
    fn a_summary_counts_each_kind_most_first() {
        let kinds = std::iter::repeat_n("laser", 1024)
            .chain(std::iter::repeat_n("position2d", 1024))
            .chain(["ground"]);
        assert_eq!(
            summary(kinds, "components"),
            "2 049 components: 1 024 laser, 1 024 position2d, 1 ground"
        );
        assert_eq!(thousands(7), "7");
        assert_eq!(thousands(1_000_000), "1 000 000");
    }
}
