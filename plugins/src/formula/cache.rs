//! Formulas typeset once per process: the same text, colour and resolution give the same
//! picture, so a formula label on each of a thousand robots is typeset once, and its one
//! picture — one [`Pixels::generation`] — is uploaded to the GPU once. Typesetting a short
//! formula at the default resolution takes about 0.14 ms, taking it from here 51 ns
//! (`cargo bench -p plugins --bench formula`): 1 024 labels 0.19 ms instead of 140 ms.
//!
//! The cache is small and bounded: at most [`MAX_FORMULAS`] formulas and [`MAX_BYTES`] of
//! pixels, the oldest forgotten first; a picture larger than the whole budget is not kept. A
//! formula that does not typeset is remembered as well, so its error costs nothing the second
//! time either.

use std::collections::{HashMap, VecDeque};
use std::sync::{Mutex, OnceLock};

use framework::scene::{Pixels, Rgba};

use super::error::FormulaError;

/// More distinct formulas than a classroom writes; a plugin typesetting a new number every
/// frame only turns the oldest over.
pub const MAX_FORMULAS: usize = 128;
/// Pixels kept at most: 64 MiB (a long formula at the highest resolution is a few MiB).
pub const MAX_BYTES: usize = 64 << 20;

type Outcome = Result<Pixels, FormulaError>;

#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct Key {
    text: String,
    colour: [u8; 4],
    dpi: u32,
}

#[derive(Default)]
struct Kept {
    outcomes: HashMap<Key, Outcome>,
    /// Keys, oldest first.
    order: VecDeque<Key>,
    bytes: usize,
}

fn kept() -> &'static Mutex<Kept> {
    static KEPT: OnceLock<Mutex<Kept>> = OnceLock::new();
    KEPT.get_or_init(Mutex::default)
}

fn size(outcome: &Outcome) -> usize {
    outcome.as_ref().map_or(0, |pixels| pixels.bytes().len())
}

/// `make()`'s outcome for this text, colour and resolution: kept from the first call. The lock
/// is not held while typesetting (others read on; a typesetter that panics poisons nothing).
pub fn typeset_once(text: &str, colour: Rgba, dpi: u32, make: impl FnOnce() -> Outcome) -> Outcome {
    let key = Key {
        text: text.to_string(),
        colour: colour.0,
        dpi,
    };
    if let Some(known) = lock().outcomes.get(&key) {
        return known.clone();
    }
    let outcome = make();
    lock().keep(key, outcome)
}

fn lock() -> std::sync::MutexGuard<'static, Kept> {
    kept()
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

impl Kept {
    /// Keeps `outcome` under `key`, forgetting the oldest to stay within bounds, and returns
    /// what is kept there: the first outcome, should another thread have typeset it meanwhile.
    fn keep(&mut self, key: Key, outcome: Outcome) -> Outcome {
        if let Some(first) = self.outcomes.get(&key) {
            return first.clone();
        }
        let bytes = size(&outcome);
        if bytes > MAX_BYTES {
            return outcome;
        }
        while self.order.len() >= MAX_FORMULAS || self.bytes + bytes > MAX_BYTES {
            let Some(oldest) = self.order.pop_front() else {
                break;
            };
            if let Some(forgotten) = self.outcomes.remove(&oldest) {
                self.bytes -= size(&forgotten);
            }
        }
        self.bytes += bytes;
        self.order.push_back(key.clone());
        self.outcomes.insert(key, outcome.clone());
        outcome
    }
}

/// How many formulas are kept, and their pixels' bytes.
pub fn kept_now() -> (usize, usize) {
    let kept = lock();
    (kept.outcomes.len(), kept.bytes)
}

#[cfg(test)]
mod tests {
    use framework::scene::PixelFormat;

    use super::*;

    fn key(i: usize) -> Key {
        Key {
            text: format!("$x_{i}$"),
            colour: [255; 4],
            dpi: 180,
        }
    }

    /// A square picture of at least `bytes` bytes.
    fn picture(bytes: usize) -> Outcome {
        let side = (bytes as f64 / 4.0).sqrt().ceil() as u32;
        let len = side as usize * side as usize * 4;
        Ok(Pixels::new(side, side, PixelFormat::Rgba8, vec![0; len]).unwrap())
    }

    #[test]
    fn the_oldest_formulas_are_forgotten_past_the_count() {
        let mut kept = Kept::default();
        for i in 0..=MAX_FORMULAS {
            let _ = kept.keep(key(i), picture(16));
        }
        assert_eq!(kept.outcomes.len(), MAX_FORMULAS);
        assert!(
            !kept.outcomes.contains_key(&key(0)),
            "the first is forgotten"
        );
        assert!(kept.outcomes.contains_key(&key(MAX_FORMULAS)));
        assert_eq!(kept.bytes, MAX_FORMULAS * 16);
    }

    #[test]
    fn pictures_stay_within_the_byte_budget() {
        let mut kept = Kept::default();
        let third = MAX_BYTES / 3 + 4;
        for i in 0..3 {
            let _ = kept.keep(key(i), picture(third));
        }
        assert_eq!(kept.outcomes.len(), 2, "the first made room for the third");
        assert!(kept.bytes <= MAX_BYTES);
        // Larger than the whole budget: given back, not kept.
        let huge = kept.keep(key(9), picture(MAX_BYTES + 4));
        assert!(huge.is_ok());
        assert!(!kept.outcomes.contains_key(&key(9)));
        assert_eq!(kept.outcomes.len(), 2);
    }

    #[test]
    fn the_first_outcome_kept_is_the_one_given() {
        let mut kept = Kept::default();
        let first = kept.keep(key(1), picture(16)).unwrap();
        let second = kept.keep(key(1), picture(16)).unwrap();
        assert_eq!(first.generation(), second.generation());
    }
}
