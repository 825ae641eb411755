//! `xi:include` resolution: an include is replaced by the root element of the file it names,
//! resolved relative to the including file, recursively, with loops refused.

use std::path::{Path, PathBuf};

use super::error::ConfigError;
use super::xml_tree::{Element, Node, parse_file};

/// The element name of an XInclude directive, with the prefix our files bind to XInclude.
const INCLUDE: &str = "xi:include";

/// Parses `path` and expands every `xi:include` inside it.
pub fn load_with_includes(path: &Path) -> Result<Element, ConfigError> {
    let mut chain = vec![canonical(path)];
    let mut root = parse_file(path)?;
    expand(&mut root, path, &mut chain)?;
    Ok(root)
}

fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}

fn expand(element: &mut Element, file: &Path, chain: &mut Vec<PathBuf>) -> Result<(), ConfigError> {
    for node in &mut element.children {
        let Node::Element(child) = node else { continue };
        if child.name == INCLUDE {
            *child = include(child, file, chain)?;
        } else {
            expand(child, file, chain)?;
        }
    }
    Ok(())
}

fn include(
    directive: &Element,
    file: &Path,
    chain: &mut Vec<PathBuf>,
) -> Result<Element, ConfigError> {
    let href = directive.attribute("href").ok_or_else(|| {
        ConfigError::at(
            directive.pos.clone(),
            "<xi:include> needs an href attribute naming the file to include",
        )
    })?;
    if let Some(parse) = directive.attr("parse").filter(|p| *p != "xml") {
        return Err(ConfigError::at(
            directive.pos.clone(),
            format!("<xi:include parse=\"{parse}\"> is not supported; only XML includes are"),
        ));
    }
    let target = file.parent().unwrap_or(Path::new(".")).join(&href.value);
    if !target.is_file() {
        return Err(ConfigError::at(
            href.pos.clone(),
            format!(
                "included file {:?} not found (looked for {})",
                href.value,
                target.display()
            ),
        ));
    }
    let key = canonical(&target);
    if let Some(first) = chain.iter().position(|p| *p == key) {
        let loop_path: Vec<String> = chain[first..]
            .iter()
            .chain(std::iter::once(&key))
            .map(|p| {
                p.file_name().map_or_else(
                    || p.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                )
            })
            .collect();
        return Err(ConfigError::at(
            href.pos.clone(),
            format!("include loop: {}", loop_path.join(" -> ")),
        ));
    }
    chain.push(key);
    let mut root = parse_file(&target)?;
    expand(&mut root, &target, chain)?;
    chain.pop();
    Ok(root)
}
