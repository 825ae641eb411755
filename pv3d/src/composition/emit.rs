//! Writing a composition back to XML: `--emit-config`, and saving the plugins' state.

use std::io::Write;
use std::path::Path;

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};

use super::instantiate::PluginInstance;
use super::model::Composition;
use super::relocate::relocate_file_parameters;
use super::xml_tree::{Element, Node};

const XINCLUDE_NS: &str = "http://www.w3.org/2001/XInclude";

/// A `<pv3d>` document holding the composition's servers, its extension elements, and the
/// given plugin instances written out in full (handlers already applied, each plugin's mask
/// the address of its device), ready to edit and run. It is meant to be written to
/// `written_to`: relative file parameters are rewritten to be read from there.
pub fn emit_document(
    composition: &Composition,
    instances: &[PluginInstance],
    written_to: &Path,
) -> String {
    let folder = written_to.parent().unwrap_or(Path::new(""));
    let mut root = Element::new("pv3d", super::error::SourcePos::generated());
    root.set_attr("xmlns:xi", XINCLUDE_NS);
    if !composition.clients.is_empty() {
        let mut handlers = Element::new("handlers", root.pos.clone());
        for client in &composition.clients {
            let mut c = Element::new("playerClient", root.pos.clone());
            c.set_attr("host", client.host.clone());
            c.set_attr("port", client.port.to_string());
            handlers.children.push(Node::Element(c));
        }
        root.children.push(Node::Element(handlers));
    }
    let mut enabled: Vec<&str> = Vec::new();
    for extension in &composition.extensions {
        if !enabled.contains(&extension.parser.as_str()) {
            enabled.push(&extension.parser);
            let mut add = Element::new("addParser", root.pos.clone());
            add.set_attr("element", extension.parser.clone());
            root.children.push(Node::Element(add));
        }
        root.children.push(Node::Element(extension.element.clone()));
    }
    // Extension elements were written above as they are; their plugin is made anew on load.
    for instance in instances {
        if !super::instantiate::is_extension_plugin(composition, instance) {
            let mut plugin = instance.element.clone();
            relocate_file_parameters(&mut plugin, folder);
            root.children.push(Node::Element(plugin));
        }
    }
    to_xml_string(&root)
}

/// Serialises an element tree with two-space indentation. Whitespace-only text is dropped and
/// re-created by the indenter, so emitting what was loaded is stable.
pub fn to_xml_string(root: &Element) -> String {
    let mut writer = Writer::new_with_indent(Vec::new(), b' ', 2);
    writer
        .write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))
        .expect("writing to memory");
    write_element(&mut writer, root);
    let mut out = writer.into_inner();
    out.write_all(b"\n").expect("writing to memory");
    String::from_utf8(out).expect("we only write UTF-8")
}

fn write_element(writer: &mut Writer<Vec<u8>>, element: &Element) {
    let mut start = BytesStart::new(element.name.as_str());
    for attr in &element.attributes {
        start.push_attribute((attr.name.as_str(), attr.value.as_str()));
    }
    let children: Vec<&Node> = element
        .children
        .iter()
        .filter(|n| !matches!(n, Node::Text(t) if t.trim().is_empty()))
        .collect();
    if children.is_empty() {
        writer
            .write_event(Event::Empty(start))
            .expect("writing to memory");
        return;
    }
    writer
        .write_event(Event::Start(start))
        .expect("writing to memory");
    for child in children {
        match child {
            Node::Element(e) => write_element(writer, e),
            Node::Text(t) => writer
                .write_event(Event::Text(BytesText::new(t.trim())))
                .expect("writing to memory"),
        }
    }
    writer
        .write_event(Event::End(BytesEnd::new(element.name.as_str())))
        .expect("writing to memory");
}
