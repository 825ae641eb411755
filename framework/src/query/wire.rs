//! Queries and replies as XML text: what compositions, scripts and other processes send.
//! A malformed text is an [`XmlError`] with the line and column, never a panic.

use quick_xml::events::{BytesStart, Event};
use quick_xml::reader::Reader;

use super::{MAX_ELEMENT_DEPTH, Query, Reply, Target, XmlElement};

/// Text that is not a query or reply, and where.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{line}:{column}: {message}")]
pub struct XmlError {
    pub line: usize,
    pub column: usize,
    pub message: String,
}

/// An element that cannot be a query, and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum NotAQuery {
    #[error("expected <query>, found <{0}>")]
    Element(String),
    #[error("<query> has no to attribute (a plugin id, a library name, or *)")]
    NoTarget,
    #[error("<query> has no name attribute and no text saying what is asked")]
    NoName,
}

/// The line and column (both from 1) of a byte offset in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..text.floor_char_boundary(offset.min(text.len()))];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

fn error_at(text: &str, offset: u64, message: impl Into<String>) -> XmlError {
    let (line, column) = line_column(text, usize::try_from(offset).unwrap_or(usize::MAX));
    XmlError {
        line,
        column,
        message: message.into(),
    }
}

fn start_of(start: &BytesStart<'_>, text: &str, offset: u64) -> Result<XmlElement, XmlError> {
    let mut element = XmlElement::new(start.name().as_ref().to_string());
    for attribute in start.attributes() {
        let attribute =
            attribute.map_err(|e| error_at(text, offset, format!("bad attribute: {e}")))?;
        let key = attribute.key.as_ref().to_string();
        let value = attribute
            .normalized_value(quick_xml::XmlVersion::Implicit1_0)
            .map_err(|e| error_at(text, offset, format!("bad value of {key}: {e}")))?;
        element.attributes.push((key, value.into_owned()));
    }
    Ok(element)
}

fn entity(name: &str) -> Option<char> {
    match name {
        "lt" => Some('<'),
        "gt" => Some('>'),
        "amp" => Some('&'),
        "apos" => Some('\''),
        "quot" => Some('"'),
        _ => {
            let code = match name.strip_prefix("#x") {
                Some(hex) => u32::from_str_radix(hex, 16).ok()?,
                None => name.strip_prefix('#')?.parse().ok()?,
            };
            char::from_u32(code)
        }
    }
}

/// Parses one element (with its children) from `text`.
pub fn parse_element(text: &str) -> Result<XmlElement, XmlError> {
    let mut reader = Reader::from_str(text);
    reader.config_mut().check_end_names = true;
    let mut open: Vec<XmlElement> = Vec::new();
    let mut root = None;
    loop {
        let at = reader.buffer_position();
        let event = reader
            .read_event()
            .map_err(|e| error_at(text, reader.error_position(), format!("malformed XML: {e}")))?;
        let finished = match event {
            Event::Start(start) => {
                if open.len() >= MAX_ELEMENT_DEPTH {
                    return Err(error_at(
                        text,
                        at,
                        format!("elements nested more than {MAX_ELEMENT_DEPTH} deep"),
                    ));
                }
                open.push(start_of(&start, text, at)?);
                None
            }
            Event::Empty(start) => Some(start_of(&start, text, at)?),
            Event::End(_) => open.pop(),
            Event::Text(t) => {
                let value = t.xml10_content();
                push_text(&mut open, &value, text, at)?;
                None
            }
            Event::GeneralRef(r) => {
                let name = r.as_ref().to_string();
                let c = entity(&name)
                    .ok_or_else(|| error_at(text, at, format!("unknown entity &{name};")))?;
                push_text(&mut open, &c.to_string(), text, at)?;
                None
            }
            Event::CData(c) => {
                push_text(&mut open, &c.xml10_content(), text, at)?;
                None
            }
            Event::Eof => break,
            _ => None,
        };
        if let Some(element) = finished {
            match open.last_mut() {
                Some(parent) => parent.children.push(element),
                None if root.is_none() => root = Some(element),
                None => return Err(error_at(text, at, "a second root element")),
            }
        }
    }
    if let Some(unclosed) = open.last() {
        return Err(error_at(
            text,
            text.len() as u64,
            format!("<{}> is never closed", unclosed.name),
        ));
    }
    let mut root = root.ok_or_else(|| error_at(text, 0, "no element"))?;
    trim_texts(&mut root);
    Ok(root)
}

fn push_text(open: &mut [XmlElement], value: &str, text: &str, at: u64) -> Result<(), XmlError> {
    match open.last_mut() {
        Some(parent) => {
            parent.text.push_str(value);
            Ok(())
        }
        None if value.trim().is_empty() => Ok(()),
        None => Err(error_at(text, at, "text outside the element")),
    }
}

fn trim_texts(element: &mut XmlElement) {
    element.text = element.text.trim().to_string();
    element.children.iter_mut().for_each(trim_texts);
}

fn escape(text: &str) -> String {
    quick_xml::escape::escape(text).into_owned()
}

/// Writes an element on one line.
pub fn print_element(element: &XmlElement) -> String {
    let mut out = String::new();
    write_element(element, &mut out);
    out
}

fn write_element(element: &XmlElement, out: &mut String) {
    out.push('<');
    out.push_str(&element.name);
    for (k, v) in &element.attributes {
        out.push_str(&format!(" {k}=\"{}\"", escape(v)));
    }
    if element.text.is_empty() && element.children.is_empty() {
        out.push_str("/>");
        return;
    }
    out.push('>');
    out.push_str(&escape(&element.text));
    for child in &element.children {
        write_element(child, out);
    }
    out.push_str(&format!("</{}>", element.name));
}

impl Query {
    /// Reads `<query to=".." name="..">body</query>`; without `name`, the text is the name
    /// (`<query to="robot1">stop</query>`).
    pub fn parse(text: &str) -> Result<Query, XmlError> {
        Query::from_element(parse_element(text)?).map_err(|e| XmlError {
            line: 1,
            column: 1,
            message: e.to_string(),
        })
    }

    /// A query from an already parsed `<query>` element (a composition's, a script's).
    pub fn from_element(mut element: XmlElement) -> Result<Query, NotAQuery> {
        if element.name != "query" {
            return Err(NotAQuery::Element(element.name));
        }
        let to = element
            .attr("to")
            .map(Target::parse)
            .ok_or(NotAQuery::NoTarget)?;
        let name = match element.attr("name") {
            Some(name) => name.to_string(),
            None => std::mem::take(&mut element.text),
        };
        if name.trim().is_empty() {
            return Err(NotAQuery::NoName);
        }
        element.attributes.retain(|(k, _)| k != "to" && k != "name");
        Ok(Query {
            to,
            name: name.trim().to_string(),
            body: element,
        })
    }

    /// The query as XML text.
    pub fn to_xml(&self) -> String {
        let mut element = self.body.clone();
        element.name = "query".into();
        let mut attributes = vec![
            ("to".to_string(), self.to.to_string()),
            ("name".to_string(), self.name.clone()),
        ];
        attributes.append(&mut element.attributes);
        element.attributes = attributes;
        print_element(&element)
    }
}

impl Reply {
    /// Reads `<reply error="N">body</reply>`; the body is its first child element, or an
    /// empty `<message>` holding the reply's text.
    pub fn parse(text: &str) -> Result<Reply, XmlError> {
        let bad = |message: String| XmlError {
            line: 1,
            column: 1,
            message,
        };
        let mut element = parse_element(text)?;
        if element.name != "reply" {
            return Err(bad(format!("expected <reply>, found <{}>", element.name)));
        }
        let error = element
            .attr("error")
            .ok_or_else(|| bad("<reply> has no error attribute".into()))?;
        let error = error
            .trim()
            .parse()
            .map_err(|_| bad(format!("error={error:?} of <reply> is not an integer")))?;
        let body = if element.children.is_empty() {
            XmlElement::new("message").with_text(element.text)
        } else {
            element.children.swap_remove(0)
        };
        Ok(Reply { error, body })
    }

    /// The reply as XML text.
    pub fn to_xml(&self) -> String {
        print_element(
            &XmlElement::new("reply")
                .with_attr("error", self.error)
                .with_child(self.body.clone()),
        )
    }
}
