//! `<reaction>`: what the world does on its own when something happens — the paper's
//! "launching components that handle particular situations". Enabled with
//! `<addParser element="reaction"/>`:
//!
//! ```xml
//! <reaction on="enter" zone="keep out" tag="person|robot">
//!   <query to="robot1">stop</query>
//!   <say>Someone walked into the keep-out area</say>
//!   <command>robot2 go to charging</command>
//!   <load><plugin library="libpv3d_grid" id="alarm grid"/></load>
//! </reaction>
//! ```
//!
//! `on` is `appear` or `leave` (an object with one of the `tag`s comes into or goes out of
//! the scene) or `enter` or `exit` (it goes into or out of the named `zone`, or any zone
//! without one), or `tagged` or `untagged` (it gains or loses one of the `tag`s: device
//! awareness, as a robot is tagged `stalled`, `stale` or `link down`). `tag` lists tags
//! separated by `|`. The actions run in order: a `<query>`
//! (as in [`framework::query`]), a sentence to `<say>`, a `<command>` in words (the command
//! line's grammar), a `<plugin>` to `<load>` (bound to a device of the robot the event is
//! about when its mask fits one).

use framework::query::{Query, XmlElement};

use super::error::ConfigError;
use super::xml_tree::{Element, Node};

/// The library name `<reaction>` elements are gathered under (the viewer runs them; no
/// plugin of that name exists).
pub const REACTIONS_LIBRARY: &str = "libpv3d_reactions";

/// What a reaction waits for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Trigger {
    Appear,
    Leave,
    Enter,
    Exit,
    /// An object carries one of the tags it did not carry at the last look (new objects
    /// included): a robot's `stalled`, `stale`, `link down`.
    Tagged,
    /// An object still in the scene no longer carries one of the tags.
    Untagged,
}

impl Trigger {
    const ALL: [(&str, Trigger); 6] = [
        ("appear", Trigger::Appear),
        ("leave", Trigger::Leave),
        ("enter", Trigger::Enter),
        ("exit", Trigger::Exit),
        ("tagged", Trigger::Tagged),
        ("untagged", Trigger::Untagged),
    ];

    pub fn name(self) -> &'static str {
        Trigger::ALL
            .iter()
            .find(|(_, t)| *t == self)
            .map_or("?", |(n, _)| n)
    }

    /// Whether it is about zones (and so needs the zones asked).
    pub fn is_zone(self) -> bool {
        matches!(self, Trigger::Enter | Trigger::Exit)
    }
}

/// One thing a reaction does.
#[derive(Debug, Clone, PartialEq)]
pub enum ReactionAction {
    Query(Query),
    Say(String),
    /// A sentence for the command grammar, as if typed on the command line.
    Command(String),
    /// A `<plugin>` element to make and add.
    Load(Element),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Reaction {
    pub on: Trigger,
    /// Any of these tags on the object (empty: any object with a tag).
    pub tags: Vec<String>,
    pub zone: Option<String>,
    pub actions: Vec<ReactionAction>,
    /// `file:line:col`, for the log.
    pub origin: String,
}

/// The framework's plain element for a composition element (positions dropped).
pub fn plain_element(element: &Element) -> XmlElement {
    XmlElement {
        name: element.name.clone(),
        attributes: element
            .attributes
            .iter()
            .map(|a| (a.name.clone(), a.value.clone()))
            .collect(),
        text: element.text(),
        children: element.elements().map(plain_element).collect(),
    }
}

/// Reads one `<reaction>`; every error names file:line:column.
pub fn parse_reaction(element: &Element) -> Result<Reaction, ConfigError> {
    let at = |e: &Element, message: String| ConfigError::at(e.pos.clone(), message);
    let on_text = element.attr("on").ok_or_else(|| {
        at(
            element,
            "<reaction> needs on=\"appear|leave|enter|exit|tagged|untagged\"".into(),
        )
    })?;
    let on = Trigger::ALL
        .iter()
        .find(|(name, _)| *name == on_text.trim())
        .map(|(_, t)| *t)
        .ok_or_else(|| {
            at(
                element,
                format!("<reaction on={on_text:?}>: expected appear, leave, enter, exit, tagged or untagged"),
            )
        })?;
    let tags = element
        .attr("tag")
        .map(|t| {
            t.split('|')
                .map(str::trim)
                .filter(|t| !t.is_empty())
                .map(str::to_string)
                .collect()
        })
        .unwrap_or_default();
    let zone = element.attr("zone").map(|z| z.trim().to_string());
    if zone.is_some() && !on.is_zone() {
        return Err(at(
            element,
            format!("zone= only goes with on=\"enter\" or on=\"exit\", not {on_text:?}"),
        ));
    }
    let mut actions = Vec::new();
    for child in element.elements() {
        actions.push(match child.name.as_str() {
            "query" => ReactionAction::Query(
                Query::from_element(plain_element(child)).map_err(|e| at(child, e.to_string()))?,
            ),
            "say" if !child.text().is_empty() => ReactionAction::Say(child.text()),
            "say" => return Err(at(child, "<say> needs a sentence".into())),
            "command" if !child.text().is_empty() => ReactionAction::Command(child.text()),
            "command" => return Err(at(child, "<command> needs a sentence".into())),
            "load" => {
                let plugin = child
                    .elements()
                    .find(|e| e.name == "plugin")
                    .ok_or_else(|| at(child, "<load> needs a <plugin> inside".into()))?;
                ReactionAction::Load(plugin.clone())
            }
            other => {
                return Err(at(
                    child,
                    format!("unknown action <{other}> in <reaction>; expected query, say, command or load"),
                ));
            }
        });
    }
    if actions.is_empty() {
        return Err(at(
            element,
            "<reaction> does nothing: add <query>, <say>, <command> or <load>".into(),
        ));
    }
    Ok(Reaction {
        on,
        tags,
        zone,
        actions,
        origin: element.pos.to_string(),
    })
}

/// The reactions gathered in an instance of [`REACTIONS_LIBRARY`].
pub fn parse_reactions(gathered: &Element) -> Result<Vec<Reaction>, ConfigError> {
    gathered
        .children
        .iter()
        .filter_map(|n| match n {
            Node::Element(e) if e.name == "reaction" => Some(e),
            _ => None,
        })
        .map(parse_reaction)
        .collect()
}
