//! File parameters of a composition written somewhere else than where it was read.
//!
//! A plugin reads a relative file parameter (a ground's bitmap, a robot's skin) against the
//! folder of the file its `<plugin>` element was written in. When pv3d writes the composition
//! to another folder (`--emit-config`, `--save-to`), every parameter that names a file that
//! way is rewritten relative to the written file, so the written file runs where it lies.
//! Which parameters are files is not a list kept here: a parameter is one when its text, read
//! against the plugin's folder, names an existing file — new plugins' files follow for free.
//! Absolute paths are the author's choice and are kept.

use std::path::{Component, Path, PathBuf};

use super::xml_tree::{Element, Node};

/// The folder a plugin's relative file parameters are read against.
pub fn plugin_folder(plugin: &Element) -> PathBuf {
    plugin
        .pos
        .file
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default()
}

/// Rewrites the plugin's relative file parameters for a file written into `folder`.
pub fn relocate_file_parameters(plugin: &mut Element, folder: &Path) {
    let from = plugin_folder(plugin);
    let Some(to) = real_folder(folder) else {
        tracing::warn!(
            "cannot resolve {}: file parameters are written as they were",
            folder.display()
        );
        return;
    };
    for parameter in plugin.elements_mut() {
        let text = parameter.text();
        if text.is_empty() || text.contains('\n') || Path::new(&text).is_absolute() {
            continue;
        }
        let Ok(file) = from.join(&text).canonicalize() else {
            continue;
        };
        if !file.is_file() {
            continue;
        }
        let moved = relative_path(&file, &to).display().to_string();
        parameter.children.retain(|n| !matches!(n, Node::Text(_)));
        parameter.children.insert(0, Node::Text(moved));
    }
}

/// `folder` with symbolic links and `..` resolved, as the files it is compared with are;
/// `""` is the working folder.
fn real_folder(folder: &Path) -> Option<PathBuf> {
    let folder = if folder.as_os_str().is_empty() {
        Path::new(".")
    } else {
        folder
    };
    folder.canonicalize().ok()
}

/// The path of `file` seen from `folder` (both absolute and resolved).
fn relative_path(file: &Path, folder: &Path) -> PathBuf {
    let file_parts: Vec<Component> = file.components().collect();
    let folder_parts: Vec<Component> = folder.components().collect();
    let common = file_parts
        .iter()
        .zip(&folder_parts)
        .take_while(|(a, b)| a == b)
        .count();
    let mut path = PathBuf::new();
    for _ in common..folder_parts.len() {
        path.push("..");
    }
    for part in &file_parts[common..] {
        path.push(part);
    }
    path
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::composition::parse_str;

    #[test]
    fn paths_between_folders() {
        let rel = |file: &str, folder: &str| {
            relative_path(Path::new(file), Path::new(folder))
                .display()
                .to_string()
        };
        assert_eq!(rel("/a/b/c.png", "/a/b"), "c.png");
        assert_eq!(rel("/a/b/c.png", "/a/x/y"), "../../b/c.png");
        assert_eq!(rel("/a/b/c.png", "/"), "a/b/c.png");
    }

    #[test]
    fn only_parameters_naming_files_move() {
        let dir = tempfile::tempdir().unwrap();
        let input = dir.path().join("in");
        let output = dir.path().join("out/deeper");
        std::fs::create_dir_all(input.join("skins")).unwrap();
        std::fs::create_dir_all(&output).unwrap();
        std::fs::write(input.join("skins/rover.obj"), "").unwrap();
        let mut plugin = parse_str(
            "<plugin library=\"l\"><skinFile>skins/rover.obj</skinFile>\
             <trailLength>200</trailLength><missing>gone.png</missing>\
             <absolute>/etc/hostname</absolute></plugin>",
            Arc::new(input.join("c.xml")),
        )
        .unwrap();
        relocate_file_parameters(&mut plugin, &output);
        let text = |name: &str| plugin.child(name).unwrap().text();
        assert_eq!(text("skinFile"), "../../in/skins/rover.obj");
        assert_eq!(text("trailLength"), "200");
        assert_eq!(text("missing"), "gone.png");
        assert_eq!(text("absolute"), "/etc/hostname");
    }
}
