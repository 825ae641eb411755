//! A small XML element tree that remembers where every element and attribute came from, so
//! that every configuration error can name file:line:column.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use quick_xml::events::{BytesStart, Event};
use quick_xml::reader::Reader;

use framework::query::MAX_ELEMENT_DEPTH;

use super::error::{ConfigError, SourcePos};

/// An attribute and where it was written.
#[derive(Debug, Clone, PartialEq)]
pub struct Attribute {
    pub name: String,
    pub value: String,
    pub pos: SourcePos,
}

/// A child of an element.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    Element(Element),
    /// Text content, entity references already resolved, surrounding whitespace kept.
    Text(String),
}

/// An XML element with its source position.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    /// The qualified name as written (`xi:include`, `plugin`).
    pub name: String,
    pub attributes: Vec<Attribute>,
    pub children: Vec<Node>,
    pub pos: SourcePos,
}

impl Element {
    pub fn new(name: &str, pos: SourcePos) -> Element {
        Element {
            name: name.to_string(),
            attributes: Vec::new(),
            children: Vec::new(),
            pos,
        }
    }

    pub fn attribute(&self, name: &str) -> Option<&Attribute> {
        self.attributes.iter().find(|a| a.name == name)
    }

    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attribute(name).map(|a| a.value.as_str())
    }

    /// Sets or replaces an attribute (position: the element's own).
    pub fn set_attr(&mut self, name: &str, value: impl Into<String>) {
        let value = value.into();
        match self.attributes.iter_mut().find(|a| a.name == name) {
            Some(a) => a.value = value,
            None => self.attributes.push(Attribute {
                name: name.to_string(),
                value,
                pos: self.pos.clone(),
            }),
        }
    }

    pub fn elements(&self) -> impl Iterator<Item = &Element> {
        self.children.iter().filter_map(|n| match n {
            Node::Element(e) => Some(e),
            Node::Text(_) => None,
        })
    }

    pub fn elements_mut(&mut self) -> impl Iterator<Item = &mut Element> {
        self.children.iter_mut().filter_map(|n| match n {
            Node::Element(e) => Some(e),
            Node::Text(_) => None,
        })
    }

    /// The first child element with this name.
    pub fn child(&self, name: &str) -> Option<&Element> {
        self.elements().find(|e| e.name == name)
    }

    /// All text directly inside this element, trimmed.
    pub fn text(&self) -> String {
        let mut text = String::new();
        for node in &self.children {
            if let Node::Text(t) = node {
                text.push_str(t);
            }
        }
        text.trim().to_string()
    }

    /// The element name without its namespace prefix.
    pub fn local_name(&self) -> &str {
        self.name.rsplit(':').next().unwrap_or(&self.name)
    }
}

/// Parses one file into its root element.
pub fn parse_file(path: &Path) -> Result<Element, ConfigError> {
    let text = std::fs::read_to_string(path).map_err(|e| ConfigError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    parse_str(&text, Arc::new(path.to_path_buf()))
}

/// Parses XML text; `file` is only used for positions.
pub fn parse_str(text: &str, file: Arc<PathBuf>) -> Result<Element, ConfigError> {
    // A byte-order mark is not part of the document (editors do not show it): the reader
    // skips it and counts its positions from after it, so the line index must too.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let lines = LineIndex::new(text);
    let pos_at = |offset: u64| lines.pos(&file, offset as usize);
    let mut reader = Reader::from_str(text);
    reader.config_mut().check_end_names = true;

    let mut stack: Vec<Element> = Vec::new();
    let mut root: Option<Element> = None;
    loop {
        let event_start = reader.buffer_position();
        let event = reader.read_event().map_err(|e| {
            ConfigError::at(
                pos_at(reader.error_position()),
                format!("malformed XML: {e}"),
            )
        })?;
        match event {
            Event::Start(start) => {
                if stack.len() >= MAX_ELEMENT_DEPTH {
                    return Err(ConfigError::at(
                        pos_at(event_start),
                        format!("elements nested more than {MAX_ELEMENT_DEPTH} deep"),
                    ));
                }
                let element = start_element(&start, pos_at(event_start), text, &lines, &file)?;
                stack.push(element);
            }
            Event::Empty(start) => {
                let element = start_element(&start, pos_at(event_start), text, &lines, &file)?;
                attach(&mut stack, &mut root, element, &pos_at(event_start))?;
            }
            Event::End(_) => {
                let element = stack.pop().ok_or_else(|| {
                    ConfigError::at(pos_at(event_start), "closing tag without an opening tag")
                })?;
                attach(&mut stack, &mut root, element, &pos_at(event_start))?;
            }
            Event::Text(t) => {
                let value = t.xml10_content();
                push_text(&mut stack, &value, &pos_at(event_start))?;
            }
            Event::GeneralRef(r) => {
                let name = r.into_inner();
                let value = resolve_entity(&name).ok_or_else(|| {
                    ConfigError::at(pos_at(event_start), format!("unknown entity &{name};"))
                })?;
                push_text(&mut stack, &value, &pos_at(event_start))?;
            }
            Event::CData(c) => {
                let value = c.xml10_content().into_owned();
                push_text(&mut stack, &value, &pos_at(event_start))?;
            }
            Event::Eof => break,
            // Declarations, comments, processing instructions and doctypes carry nothing.
            _ => {}
        }
    }
    if let Some(open) = stack.last() {
        return Err(ConfigError::at(
            open.pos.clone(),
            format!("<{}> is never closed", open.name),
        ));
    }
    root.ok_or_else(|| ConfigError::at(pos_at(0), "no root element"))
}

fn resolve_entity(name: &str) -> Option<String> {
    Some(match name {
        "lt" => "<".into(),
        "gt" => ">".into(),
        "amp" => "&".into(),
        "apos" => "'".into(),
        "quot" => "\"".into(),
        _ => {
            let code = if let Some(hex) = name.strip_prefix("#x") {
                u32::from_str_radix(hex, 16).ok()?
            } else {
                name.strip_prefix('#')?.parse().ok()?
            };
            char::from_u32(code)?.to_string()
        }
    })
}

fn push_text(stack: &mut [Element], value: &str, pos: &SourcePos) -> Result<(), ConfigError> {
    match stack.last_mut() {
        Some(parent) => {
            match parent.children.last_mut() {
                Some(Node::Text(t)) => t.push_str(value),
                _ => parent.children.push(Node::Text(value.to_string())),
            }
            Ok(())
        }
        None if value.trim().is_empty() => Ok(()),
        None => Err(ConfigError::at(
            pos.clone(),
            "text outside the root element",
        )),
    }
}

fn attach(
    stack: &mut [Element],
    root: &mut Option<Element>,
    element: Element,
    pos: &SourcePos,
) -> Result<(), ConfigError> {
    match stack.last_mut() {
        Some(parent) => parent.children.push(Node::Element(element)),
        None if root.is_none() => *root = Some(element),
        None => return Err(ConfigError::at(pos.clone(), "a second root element")),
    }
    Ok(())
}

fn start_element(
    start: &BytesStart<'_>,
    pos: SourcePos,
    text: &str,
    lines: &LineIndex,
    file: &Arc<PathBuf>,
) -> Result<Element, ConfigError> {
    let name = start.name().as_ref().to_string();
    let mut element = Element::new(&name, pos.clone());
    for attr in start.attributes() {
        let attr = attr.map_err(|e| ConfigError::at(pos.clone(), format!("bad attribute: {e}")))?;
        let key = attr.key.as_ref().to_string();
        let value = attr
            .normalized_value(quick_xml::XmlVersion::Implicit1_0)
            .map_err(|e| ConfigError::at(pos.clone(), format!("bad value of {key}: {e}")))?
            .into_owned();
        // Point at the attribute itself: find its name after the element's start.
        let start_offset = lines.offset(&pos);
        let attr_pos = text
            .get(start_offset..)
            .and_then(|rest| rest.find(&format!("{key}=")))
            .map(|rel| lines.pos(file, start_offset + rel))
            .unwrap_or_else(|| pos.clone());
        element.attributes.push(Attribute {
            name: key,
            value,
            pos: attr_pos,
        });
    }
    Ok(element)
}

/// Byte offsets of line starts, to turn an offset into line and column.
struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    fn new(text: &str) -> Self {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Self { starts }
    }

    fn pos(&self, file: &Arc<PathBuf>, offset: usize) -> SourcePos {
        let line = self.starts.partition_point(|&s| s <= offset);
        let col = offset - self.starts[line - 1] + 1;
        SourcePos {
            file: file.clone(),
            line,
            col,
        }
    }

    fn offset(&self, pos: &SourcePos) -> usize {
        self.starts[pos.line - 1] + pos.col - 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Element, ConfigError> {
        parse_str(text, Arc::new(PathBuf::from("t.xml")))
    }

    #[test]
    fn elements_attributes_text_and_positions() {
        let root = parse("<pv3d>\n  <plugin library=\"libpv3d_laser\" id=\"a&amp;b\">\n    <fill>1</fill>\n  </plugin>\n</pv3d>").unwrap();
        let plugin = root.child("plugin").unwrap();
        assert_eq!((plugin.pos.line, plugin.pos.col), (2, 3));
        assert_eq!(plugin.attr("id"), Some("a&b"));
        let id = plugin.attribute("id").unwrap();
        assert_eq!((id.pos.line, id.pos.col), (2, 35));
        assert_eq!(plugin.child("fill").unwrap().text(), "1");
    }

    #[test]
    fn elements_nested_past_the_limit_are_refused_where_the_limit_is_passed() {
        let deep = |levels: usize| "<a>\n".repeat(levels) + &"</a>".repeat(levels);
        assert!(parse(&deep(MAX_ELEMENT_DEPTH)).is_ok());
        let err = parse(&deep(100_000)).unwrap_err().to_string();
        let line = MAX_ELEMENT_DEPTH + 1;
        assert!(
            err.starts_with(&format!(
                "t.xml:{line}:1: elements nested more than 256 deep"
            )),
            "{err}"
        );
    }

    /// Found by the composition and command_grammar fuzz targets: a file starting with a
    /// byte-order mark put every position 3 bytes off, and finding an attribute sliced the
    /// text inside the mark (a panic).
    #[test]
    fn a_byte_order_mark_is_skipped_and_positions_are_as_an_editor_shows_them() {
        let root = parse("\u{feff}<pv3d>\n  <plugin library=\"libpv3d_laser\"/>\n</pv3d>").unwrap();
        let plugin = root.child("plugin").unwrap();
        assert_eq!((plugin.pos.line, plugin.pos.col), (2, 3));
        let library = plugin.attribute("library").unwrap();
        assert_eq!((library.pos.line, library.pos.col), (2, 11));
        assert!(parse("\u{feff}  <a b=\"1\"/>").is_ok());
        // The fuzzers' own inputs: an answer (these are broken XML: an error), not a panic.
        for seed in ["composition", "command_grammar"] {
            let path = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../fuzz/corpus")
                .join(seed)
                .join("byte-order-mark.xml");
            let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
            let _ = parse(&text);
        }
    }

    #[test]
    fn malformed_xml_names_the_place() {
        let err = parse("<pv3d>\n  <plugin>\n</pv3d>").unwrap_err();
        let text = err.to_string();
        assert!(text.starts_with("t.xml:3:"), "{text}");
    }
}
