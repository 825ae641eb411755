//! A model `define`d through itself — its base, or a model inside it, being itself at some
//! remove — is refused where it is used, naming the cycle; before, expanding it recursed until
//! the stack overflowed (found by the stage_world fuzz target). Defines that hold several of
//! each other, level after level, are refused before they expand to billions of models.

use std::path::{Path, PathBuf};

use player_sim::world::World;

fn load(dir: &Path, text: &[u8]) -> Result<World, String> {
    let path = dir.join("cycle.world");
    std::fs::write(&path, text).unwrap();
    World::load(&path).map_err(|e| e.to_string())
}

#[test]
fn a_define_holding_an_instance_of_itself_is_refused_with_the_cycle() {
    let dir = tempfile::tempdir().unwrap();
    let direct = load(dir.path(), b"define crate model ( crate( ) )\ncrate( )\n").unwrap_err();
    // Where the define names itself.
    assert!(direct.contains("cycle.world:1:22: "), "{direct}");
    assert!(
        direct.contains("crate is defined through itself: crate -> crate"),
        "{direct}"
    );

    let mutual = b"define shelf model ( box( ) )\ndefine box model ( shelf( ) )\nshelf( )\n";
    let error = load(dir.path(), mutual).unwrap_err();
    assert!(error.contains("shelf -> box -> shelf"), "{error}");

    let bases = b"define a b ( )\ndefine b a ( )\na( )\n";
    let error = load(dir.path(), bases).unwrap_err();
    assert!(error.contains("a -> b -> a"), "{error}");
}

#[test]
fn defines_that_double_with_every_level_are_refused_before_they_fill_the_memory() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("define d0 model ( size [ 0.1 0.1 0.1 ] )\n");
    for level in 1..=20 {
        let below = level - 1;
        text += &format!("define d{level} model ( d{below}( ) d{below}( ) )\n");
    }
    text += "d20( )\n";
    let error = load(dir.path(), text.as_bytes()).unwrap_err();
    assert!(
        error.contains("expands to more than 10000 models"),
        "{error}"
    );
}

#[test]
fn the_same_define_used_twice_side_by_side_is_no_cycle() {
    let dir = tempfile::tempdir().unwrap();
    let text = b"define wheel model ( size [ 0.1 0.1 0.1 ] )\n\
                 define cart model ( wheel( pose [ 0.2 0 0 0 ] ) wheel( pose [ -0.2 0 0 0 ] ) )\n\
                 cart( name \"c1\" )\ncart( name \"c2\" )\n";
    load(dir.path(), text).unwrap();
}

#[test]
fn the_fuzzers_input_is_refused_not_a_stack_overflow() {
    let seed: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz/corpus/stage_world/define-through-itself.world");
    let dir = tempfile::tempdir().unwrap();
    let error = load(dir.path(), &std::fs::read(seed).unwrap()).unwrap_err();
    assert!(
        error.contains("cycle.world:14:1: puck is defined through itself"),
        "{error}"
    );
}
