//! From syntax to models: includes read (relative to the including file, loops refused),
//! `define`d types expanded with inheritance (the base's properties and children first, then
//! the define's, then the instance's, later ones winning).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::worldfile::{Block, Item, Pos, Property, WorldFileError, parse_text};

/// Model types Stage itself provides; everything else must be `define`d.
pub const BUILTIN: &[&str] = &[
    "model",
    "position",
    "ranger",
    "fiducial",
    "camera",
    "blobfinder",
    "gripper",
    "actuator",
    "blinkenlight",
    // player-sim's own: a walking person (see `person.rs`).
    "person",
];

/// Defines one model may be expanded through at once (its base chain and the defines of the
/// models inside it). Stage's own files use a handful; more is a mistake in the file.
const MAX_DEFINE_DEPTH: usize = 32;
/// Models one instance may expand to, with everything inside it. A robot is a few; defines
/// that each hold two of the next would double with every level, to billions.
const MAX_MODELS_PER_INSTANCE: usize = 10_000;

/// Where the expansion of one instance stands.
#[derive(Default)]
struct Expansion<'t> {
    /// The defines being expanded, outermost first: a define met again inside itself is a
    /// cycle.
    within: Vec<&'t str>,
    /// Models made so far.
    models: usize,
}

/// Parts of a model that are not models themselves; `define`s may build on them too (Stage's
/// own `pioneer.inc` defines its sonar transducers with `define p2dxsonar sensor`).
pub const PARTS: &[&str] = &["sensor", "block"];

/// A model with its type expanded: `kind` is the builtin type at the root of its `define`s.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// The builtin type (`position`, `ranger`, …).
    pub kind: String,
    /// The type as written (`pioneer2dx`).
    pub declared: String,
    pub properties: Vec<Property>,
    /// Nested models (sensors on a robot).
    pub children: Vec<Model>,
    /// Nested non-model blocks (`sensor(...)`, `block(...)`).
    pub parts: Vec<Block>,
    pub pos: Pos,
}

impl Model {
    pub fn get(&self, name: &str) -> Option<&Property> {
        self.properties.iter().rev().find(|p| p.name == name)
    }
}

/// Every item of a world file and its includes, in order.
pub fn read_with_includes(path: &Path) -> Result<Vec<Item>, WorldFileError> {
    let mut chain = Vec::new();
    read(path, &mut chain, None)
}

fn read(
    path: &Path,
    chain: &mut Vec<PathBuf>,
    from: Option<&Pos>,
) -> Result<Vec<Item>, WorldFileError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| match from {
        Some(pos) => WorldFileError::at(
            &pos.file,
            pos.line,
            pos.col,
            format!("cannot include {name}: {e}"),
        ),
        None => WorldFileError::at(&name, 1, 1, format!("cannot read: {e}")),
    })?;
    let key = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
    if chain.contains(&key) {
        let pos = from.expect("only an include can loop");
        return Err(WorldFileError::at(
            &pos.file,
            pos.line,
            pos.col,
            format!("include loop through {name}"),
        ));
    }
    chain.push(key);
    let mut out = Vec::new();
    for item in parse_text(&text, &name)? {
        match item {
            Item::Include {
                path: included,
                pos,
            } => {
                let target = path.parent().unwrap_or(Path::new(".")).join(&included);
                out.extend(read(&target, chain, Some(&pos))?);
            }
            other => out.push(other),
        }
    }
    chain.pop();
    Ok(out)
}

/// The `define`s of a world.
#[derive(Debug, Default)]
pub struct Types {
    defines: HashMap<String, (String, Block)>,
}

impl Types {
    pub fn add(&mut self, name: String, base: String, body: Block) {
        self.defines.insert(name, (base, body));
    }

    pub fn is_model_type(&self, kind: &str) -> bool {
        BUILTIN.contains(&kind)
            || (self.defines.contains_key(kind) && self.part_root(kind).is_none())
    }

    /// The part (`sensor`, `block`) a `define` builds on, if it builds on one.
    fn part_root(&self, kind: &str) -> Option<&'static str> {
        PARTS
            .iter()
            .find(|part| self.derives_from(kind, part))
            .copied()
    }

    /// A part written with a `define`d name, as the part it builds on: the defines'
    /// properties (the base's first) then the instance's, later ones winning.
    fn expand_part(&self, block: &Block, root: &'static str) -> Block {
        let mut chain = Vec::new();
        let mut at = block.kind.as_str();
        while let Some((base, body)) = self.defines.get(at).filter(|_| at != root) {
            chain.push(body);
            at = base;
            if chain.len() > 32 {
                break;
            }
        }
        let mut part = Block {
            kind: root.to_string(),
            properties: Vec::new(),
            children: Vec::new(),
            pos: block.pos.clone(),
        };
        for body in chain.iter().rev().copied().chain([block]) {
            part.properties.extend(body.properties.iter().cloned());
            part.children.extend(body.children.iter().cloned());
        }
        part
    }

    /// Is `kind` `ancestor`, or `define`d from it at any depth?
    pub fn derives_from(&self, kind: &str, ancestor: &str) -> bool {
        let mut at = kind;
        for _ in 0..=32 {
            if at == ancestor {
                return true;
            }
            match self.defines.get(at) {
                Some((base, _)) => at = base,
                None => return false,
            }
        }
        false
    }

    /// Expands an instance block into a model.
    pub fn instantiate(&self, block: &Block) -> Result<Model, WorldFileError> {
        self.instantiate_within(block, &mut Expansion::default())
    }

    /// `instantiate`, as part of `expanding`. A define's body may hold instances of other
    /// defines, which hold others: a define met again inside itself, through its base or
    /// through a child, would expand for ever, and defines holding several of the next grow
    /// exponentially.
    fn instantiate_within<'t>(
        &'t self,
        block: &Block,
        expanding: &mut Expansion<'t>,
    ) -> Result<Model, WorldFileError> {
        expanding.models += 1;
        if expanding.models > MAX_MODELS_PER_INSTANCE {
            return Err(WorldFileError::at(
                &block.pos.file,
                block.pos.line,
                block.pos.col,
                format!(
                    "{} expands to more than {MAX_MODELS_PER_INSTANCE} models: defines that \
                     hold several of each other?",
                    block.kind
                ),
            ));
        }
        let mut model = self.expand_type(&block.kind, &block.pos, expanding)?;
        model.declared = block.kind.clone();
        model.pos = block.pos.clone();
        self.overlay(&mut model, block, expanding)?;
        Ok(model)
    }

    fn expand_type<'t>(
        &'t self,
        kind: &str,
        pos: &Pos,
        expanding: &mut Expansion<'t>,
    ) -> Result<Model, WorldFileError> {
        if BUILTIN.contains(&kind) {
            return Ok(Model {
                kind: kind.to_string(),
                declared: kind.to_string(),
                properties: Vec::new(),
                children: Vec::new(),
                parts: Vec::new(),
                pos: pos.clone(),
            });
        }
        let at = |message: String| WorldFileError::at(&pos.file, pos.line, pos.col, message);
        let Some((name, (base, body))) = self.defines.get_key_value(kind) else {
            return Err(at(format!(
                "unknown model type {kind:?} (not built in, not defined; a missing include?)"
            )));
        };
        if expanding.within.contains(&name.as_str()) {
            return Err(at(format!(
                "{kind} is defined through itself: {} -> {kind}",
                expanding.within.join(" -> ")
            )));
        }
        if expanding.within.len() >= MAX_DEFINE_DEPTH {
            return Err(at(format!(
                "define chain through {kind} is more than {MAX_DEFINE_DEPTH} defines deep"
            )));
        }
        expanding.within.push(name);
        let mut model = self.expand_type(base, &body.pos, expanding)?;
        self.overlay(&mut model, body, expanding)?;
        expanding.within.pop();
        Ok(model)
    }

    fn overlay<'t>(
        &'t self,
        model: &mut Model,
        block: &Block,
        expanding: &mut Expansion<'t>,
    ) -> Result<(), WorldFileError> {
        model.properties.extend(block.properties.iter().cloned());
        for child in &block.children {
            if let Some(root) = self.part_root(&child.kind) {
                model.parts.push(self.expand_part(child, root));
            } else if self.is_model_type(&child.kind) {
                model
                    .children
                    .push(self.instantiate_within(child, expanding)?);
            } else {
                model.parts.push(child.clone());
            }
        }
        Ok(())
    }
}
