//! What a world and its .cfg files ask that player-sim does not simulate, said once: the notes
//! ("ignored: <what> at file:line", one per place) grouped by what they ignore, with how many
//! places ask it, in one line.

/// One line saying what `notes` ignore and how often, in the order first met; `None` when
/// there are none. The places themselves are left out (a stock Stage world has dozens).
pub fn ignored_summary(notes: &[String]) -> Option<String> {
    let mut kinds: Vec<(&str, usize)> = Vec::new();
    for note in notes {
        let what = what_is_ignored(note);
        match kinds.iter_mut().find(|(w, _)| *w == what) {
            Some((_, count)) => *count += 1,
            None => kinds.push((what, 1)),
        }
    }
    if kinds.is_empty() {
        return None;
    }
    let list: Vec<String> = kinds
        .iter()
        .map(|&(what, n)| {
            if n == 1 {
                what.to_string()
            } else {
                format!("{what} (x{n})")
            }
        })
        .collect();
    Some(format!(
        "ignored, not simulated ({} in {} places): {}",
        plural(kinds.len(), "thing"),
        notes.len(),
        list.join("; ")
    ))
}

/// The `<what>` of "ignored: <what> at file:line" (the whole note when it is not one).
fn what_is_ignored(note: &str) -> &str {
    let body = note.strip_prefix("ignored: ").unwrap_or(note);
    match body.rsplit_once(" at ") {
        Some((what, place)) if place.rsplit_once(':').is_some_and(|(_, l)| is_line(l)) => what,
        _ => body,
    }
}

fn is_line(text: &str) -> bool {
    !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit())
}

fn plural(n: usize, word: &str) -> String {
    if n == 1 {
        format!("1 {word}")
    } else {
        format!("{n} {word}s")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_are_grouped_by_what_they_ignore_in_the_order_met() {
        let notes: Vec<String> = [
            "ignored: position property gui_nose at a.world:3",
            "ignored: world property laser_max at a.world:1",
            "ignored: position property gui_nose at pioneer.inc:40",
            "ignored: position property gui_nose at pioneer.inc:80",
            "ignored: driver \"vfh\" at a.cfg:12",
        ]
        .map(String::from)
        .to_vec();
        assert_eq!(
            ignored_summary(&notes).unwrap(),
            "ignored, not simulated (3 things in 5 places): position property gui_nose (x3); \
             world property laser_max; driver \"vfh\""
        );
        assert_eq!(ignored_summary(&[]), None);
    }

    #[test]
    fn a_what_holding_at_is_kept_whole() {
        let notes = vec![
            "ignored: a block not as tall as the rest of box at the door at b.world:7".to_string(),
            "something else at noon".to_string(),
        ];
        assert_eq!(
            ignored_summary(&notes).unwrap(),
            "ignored, not simulated (2 things in 2 places): a block not as tall as the rest \
             of box at the door; something else at noon"
        );
    }
}
