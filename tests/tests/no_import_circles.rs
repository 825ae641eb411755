//! No crate of the workspace has a circle in its module graph: if `a` uses `b`, nothing in `b`
//! (or in what `b` uses) uses `a`. The workspace keeps its module graph one-way; when two modules
//! come to need each other, the item they share moves down into its own module that both use.
//!
//! A module is a `.rs` file under a crate's `src` (`a/b.rs` is `a::b`; `mod.rs`, `lib.rs` and
//! `main.rs` stand for their folder). A file uses module `m` when, outside `//` comments,
//! `pub(in ...)` restrictions and a `#[cfg(test)] mod tests { ... }` block (taken to run to the
//! end of the file), it names a path `crate::m...`, names `m...` inside `use crate::{...};`, or
//! names `super::m...` (each `super::` one level up from the file's module); a path counts for
//! the longest leading part of it that is a module. Inline `mod` blocks are not modules here.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

type Module = Vec<String>;
type Graph = BTreeMap<Module, BTreeSet<Module>>;
/// A circle: each of its modules with the modules of the circle that it uses.
type Circle = BTreeMap<String, Vec<String>>;

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

fn starts(t: &[char], i: usize, s: &str) -> bool {
    s.chars().enumerate().all(|(k, c)| t.get(i + k) == Some(&c))
}

/// The identifier path (`a::b::c`) from `i`, which must start a word, and where it ends.
fn path_at(t: &[char], mut i: usize) -> (Vec<String>, usize) {
    let mut path = Vec::new();
    loop {
        let start = i;
        while i < t.len() && is_word(t[i]) {
            i += 1;
        }
        path.push(t[start..i].iter().collect());
        if !(starts(t, i, "::") && t.get(i + 2).is_some_and(|&c| is_word(c))) {
            return (path, i);
        }
        i += 2;
    }
}

/// The text that counts: no `//` comments, no `pub(in ...)`, no trailing `#[cfg(test)] mod tests`.
fn cleaned(text: &str) -> Vec<char> {
    let mut t: String = text
        .split('\n')
        .map(|line| line.find("//").map_or(line, |k| &line[..k]))
        .collect::<Vec<_>>()
        .join("\n");
    let mut from = 0;
    while let Some(k) = t[from..].find("pub(in ").map(|k| from + k) {
        let Some(close) = t[k..].find(')') else { break };
        t.replace_range(k..k + close + 1, "pub");
        from = k + "pub".len();
    }
    let tests = t.match_indices("#[cfg(test)]").map(|(k, _)| k).find(|&k| {
        let rest = t[k + "#[cfg(test)]".len()..].trim_start();
        rest.strip_prefix("mod tests")
            .is_some_and(|rest| rest.trim_start().starts_with('{'))
    });
    if let Some(k) = tests {
        t.truncate(k);
    }
    t.chars().collect()
}

/// The module paths (as written, before resolving to a module) that file `t` of module `m` names.
fn named_paths(t: &[char], m: &Module) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let word_starts = |i: usize| i == 0 || !is_word(t[i - 1]);
    let mut i = 0;
    while i < t.len() {
        // `crate::a::b`
        if word_starts(i) && starts(t, i, "crate::") && t.get(i + 7).is_some_and(|&c| is_word(c)) {
            let (path, end) = path_at(t, i + 7);
            paths.push(path);
            i = end;
        } else {
            i += 1;
        }
    }
    let mut i = 0;
    while i < t.len() {
        // `use crate::{a::b, c}`: every path inside the braces, nested ones too.
        let open = i + "use crate::{".len();
        let semi = (word_starts(i) && starts(t, i, "use crate::{"))
            .then(|| t[open..].iter().position(|&c| c == ';').map(|k| open + k))
            .flatten()
            .filter(|&s| s > open && t[s - 1] == '}');
        let Some(semi) = semi else {
            i += 1;
            continue;
        };
        let mut j = open;
        while j < semi - 1 {
            if is_word(t[j]) {
                let (path, end) = path_at(t, j);
                paths.push(path);
                j = end;
            } else {
                j += 1;
            }
        }
        i = semi + 1;
    }
    let mut i = 0;
    while i < t.len() {
        // `super::super::a::b`; as the script's regex, `super::super::{..}` names `super::super`.
        let mut j = i;
        let mut ups = 0;
        while word_starts(i) && starts(t, j, "super::") {
            ups += 1;
            j += "super::".len();
        }
        let rest = if ups > 0 && j < t.len() && is_word(t[j]) {
            Some(path_at(t, j))
        } else if ups > 1 {
            ups -= 1;
            Some((vec!["super".to_string()], j - 2))
        } else {
            None
        };
        let Some((rest, end)) = rest else {
            i += 1;
            continue;
        };
        let mut path = m[..m.len().saturating_sub(ups)].to_vec();
        path.extend(rest);
        paths.push(path);
        i = end;
    }
    paths
}

fn rs_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if entry.file_type().is_ok_and(|t| t.is_dir()) {
            rs_files(&path, out);
        } else if path.to_string_lossy().ends_with(".rs") {
            out.push(path);
        }
    }
}

/// Each module of the crate whose sources are `src`, with the other modules it uses.
fn graph(src: &Path) -> Graph {
    let mut files: BTreeMap<Module, Vec<PathBuf>> = BTreeMap::new();
    let mut all = Vec::new();
    rs_files(src, &mut all);
    for file in all {
        let rel = file.strip_prefix(src).unwrap().with_extension("");
        let mut m: Module = rel.iter().map(|c| c.to_string_lossy().into()).collect();
        if ["mod", "lib", "main"].contains(&m[m.len() - 1].as_str()) {
            m.pop();
        }
        files.entry(m).or_default().push(file);
    }
    let mut edges = Graph::new();
    for (m, fs) in &files {
        let uses = edges.entry(m.clone()).or_default();
        for file in fs {
            let text = String::from_utf8_lossy(&fs::read(file).unwrap()).into_owned();
            for p in named_paths(&cleaned(&text), m) {
                let longest = (1..=p.len()).rev().find(|&k| files.contains_key(&p[..k]));
                if let Some(k) = longest
                    && p[..k] != m[..]
                {
                    uses.insert(p[..k].to_vec());
                }
            }
        }
    }
    edges
}

/// Tarjan's strongly connected components.
#[derive(Default)]
struct Tarjan<'g> {
    index: BTreeMap<&'g Module, (usize, usize)>,
    stack: Vec<&'g Module>,
    found: Vec<Vec<&'g Module>>,
}

impl<'g> Tarjan<'g> {
    fn visit(&mut self, graph: &'g Graph, v: &'g Module) {
        let n = self.index.len();
        self.index.insert(v, (n, n));
        self.stack.push(v);
        for w in &graph[v] {
            let low = match self.index.get(w) {
                None => {
                    self.visit(graph, w);
                    self.index[w].1
                }
                Some(&(i, _)) if self.stack.contains(&w) => i,
                Some(_) => continue,
            };
            let entry = self.index.get_mut(v).unwrap();
            entry.1 = entry.1.min(low);
        }
        if self.index[v].0 == self.index[v].1 {
            let at = self.stack.iter().rposition(|&w| w == v).unwrap();
            let component = self.stack.split_off(at);
            if component.len() > 1 {
                self.found.push(component);
            }
        }
    }
}

fn name(m: &Module) -> String {
    if m.is_empty() {
        "lib".to_string()
    } else {
        m.join("/")
    }
}

/// The circles among the modules of the crate whose sources are `src`.
fn circles_in(src: &Path) -> Vec<Circle> {
    let graph = graph(src);
    let mut tarjan = Tarjan::default();
    for v in graph.keys() {
        if !tarjan.index.contains_key(v) {
            tarjan.visit(&graph, v);
        }
    }
    tarjan
        .found
        .iter()
        .map(|component| {
            let inside = |w: &&Module| component.contains(w);
            component
                .iter()
                .map(|&v| (name(v), graph[v].iter().filter(inside).map(name).collect()))
                .collect()
        })
        .collect()
}

/// Every `src` folder with a `Cargo.toml` beside it under `dir`, skipping build output.
fn crate_sources(dir: &Path, out: &mut Vec<PathBuf>) {
    if dir.file_name().is_some_and(|n| n == "src") && dir.with_file_name("Cargo.toml").exists() {
        out.push(dir.to_path_buf());
    }
    for entry in fs::read_dir(dir).into_iter().flatten().flatten() {
        let skip = ["target", "node_modules", ".git"]
            .iter()
            .any(|s| entry.file_name() == *s);
        if !skip && entry.file_type().is_ok_and(|t| t.is_dir()) {
            crate_sources(&entry.path(), out);
        }
    }
}

#[test]
fn no_crate_has_a_module_import_circle() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut sources = Vec::new();
    crate_sources(&root, &mut sources);
    assert!(
        sources.contains(&root.join("player-sim/src")),
        "{sources:?}"
    );
    let mut report = String::new();
    for src in &sources {
        for circle in circles_in(src) {
            let shown = src.strip_prefix(&root).unwrap().display();
            report += &format!("{shown}: {:?}\n", circle.keys().collect::<Vec<_>>());
            for (m, uses) in &circle {
                report += &format!("    {m} -> {uses:?}\n");
            }
        }
    }
    assert!(
        report.is_empty(),
        "module import circles (a module uses one that, directly or not, uses it back):\n{report}\
         Undo one by moving the item the modules share down into its own module that they both use, \
         so the graph stays one-way."
    );
}

/// A throwaway crate under the temp folder; returns its `src`.
fn fake_crate(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("no_import_circles_{}_{name}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(dir.join("src")).unwrap();
    fs::write(dir.join("Cargo.toml"), "[package]\nname = \"fake\"\n").unwrap();
    for (path, text) in files {
        fs::write(dir.join("src").join(path), text).unwrap();
    }
    dir.join("src")
}

#[test]
fn a_planted_circle_is_found_and_one_way_uses_are_not() {
    let circle = fake_crate(
        "circle",
        &[
            ("lib.rs", "mod a;\nmod b;\n"),
            ("a.rs", "use crate::b::X;\npub struct Y(X);\n"),
            ("b.rs", "use super::a::Y;\npub struct X;\nfn f(_: Y) {}\n"),
        ],
    );
    let expected: Circle = [("a", ["b"]), ("b", ["a"])]
        .into_iter()
        .map(|(m, uses)| (m.to_string(), uses.map(String::from).to_vec()))
        .collect();
    assert_eq!(circles_in(&circle), vec![expected]);

    let one_way = fake_crate(
        "one_way",
        &[
            ("lib.rs", "mod a;\nmod b;\n"),
            ("a.rs", "use crate::{b::X, c};\npub struct Y(X);\n"),
            (
                "b.rs",
                "// uses crate::a::Y\npub(in crate::a) struct X;\n\
                 #[cfg(test)]\nmod tests {\n    use super::super::a::Y;\n    use crate::a;\n}\n",
            ),
        ],
    );
    let (a, b) = (vec!["a".to_string()], vec!["b".to_string()]);
    let uses = graph(&one_way);
    assert_eq!(uses[&a], BTreeSet::from([b.clone()]), "{uses:?}");
    assert!(uses[&b].is_empty(), "{uses:?}");
    assert!(circles_in(&one_way).is_empty());
    for src in [circle, one_way] {
        let _ = fs::remove_dir_all(src.parent().unwrap());
    }
}
