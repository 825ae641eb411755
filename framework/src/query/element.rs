//! The XML a query or a reply carries: a plain element tree, owned, with no positions (a
//! query may be built in code as often as parsed).

use super::argument_error::ArgumentError;

/// Elements inside elements, at most, in any XML the viewer reads (compositions, queries,
/// replies). Real ones are a few deep; every level is a call in whatever walks the tree
/// (includes, printing, even dropping it), so a file of nothing but `<a><a><a>…` would end
/// the program with a stack overflow instead of an error.
pub const MAX_ELEMENT_DEPTH: usize = 256;

/// An element: its name, attributes in order, text and child elements.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct XmlElement {
    pub name: String,
    pub attributes: Vec<(String, String)>,
    /// The element's own text, trimmed (mixed content is not kept apart).
    pub text: String,
    pub children: Vec<XmlElement>,
}

impl XmlElement {
    pub fn new(name: impl Into<String>) -> XmlElement {
        XmlElement {
            name: name.into(),
            ..XmlElement::default()
        }
    }

    /// The same element with an attribute, for building replies in one expression.
    pub fn with_attr(mut self, name: &str, value: impl ToString) -> XmlElement {
        self.set_attr(name, value.to_string());
        self
    }

    /// The same element with text.
    pub fn with_text(mut self, text: impl Into<String>) -> XmlElement {
        self.text = text.into();
        self
    }

    /// The same element with a child.
    pub fn with_child(mut self, child: XmlElement) -> XmlElement {
        self.children.push(child);
        self
    }

    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }

    pub fn set_attr(&mut self, name: &str, value: String) {
        match self.attributes.iter_mut().find(|(k, _)| k == name) {
            Some((_, v)) => *v = value,
            None => self.attributes.push((name.to_string(), value)),
        }
    }

    pub fn child(&self, name: &str) -> Option<&XmlElement> {
        self.children.iter().find(|c| c.name == name)
    }

    /// The element's text, trimmed.
    pub fn text(&self) -> String {
        self.text.trim().to_string()
    }

    /// A numeric attribute, with an error naming it and the element when it is missing or
    /// not a number.
    pub fn number(&self, name: &str) -> Result<f64, ArgumentError> {
        let text = self.attr(name).ok_or_else(|| ArgumentError::Missing {
            element: self.name.clone(),
            attribute: name.to_string(),
        })?;
        text.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| ArgumentError::NotANumber {
                element: self.name.clone(),
                attribute: name.to_string(),
                text: text.to_string(),
            })
    }
}
