//! The libraries' module graphs: no cycle between modules (a parent and its own submodules aside),
//! and in `dof-core` and `dof` no module importing one from a layer above it
//! (`docs/architecture.md`, "Layers"). Read from the sources, so a new import that points uphill or
//! closes a cycle fails here, not in review.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module, as its path inside its crate (`["frame", "splat"]`; the crate root is `[]`).
type Module = Vec<String>;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("tests/ sits in the repository").to_path_buf()
}

/// Every `.rs` file under `src`, by the module it defines.
fn modules(src: &Path) -> BTreeMap<Module, PathBuf> {
    let mut out = BTreeMap::new();
    let mut stack = vec![src.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let rel = path.strip_prefix(src).expect("under src").with_extension("");
                let mut module: Module = rel.iter().map(|c| c.to_string_lossy().into_owned()).collect();
                if matches!(module.last().map(String::as_str), Some("mod" | "lib" | "main")) {
                    module.pop();
                }
                out.insert(module, path);
            }
        }
    }
    out
}

/// The length of the character literal that `s` starts with (`'x'`, `'"'`, `'\''`, `'\u{..}'`),
/// or `None` (not a quote, a lifetime, a label).
fn char_literal(s: &str) -> Option<usize> {
    let mut chars = s.char_indices();
    if chars.next()?.1 != '\'' {
        return None;
    }
    if chars.next()?.1 == '\\' {
        // An escape: the escaped character, then up to the closing quote.
        return s.get(3..)?.find('\'').map(|i| i + 4);
    }
    let (i, q) = chars.next()?;
    (q == '\'').then_some(i + 1)
}

/// The source without comments and without its `#[cfg(test)] mod …` blocks (tests may import
/// anything, and `super` inside them is one level deeper than the file).
fn code(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix("//") {
            rest = r.find('\n').map_or("", |n| &r[n..]);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.find("*/").map_or("", |n| &r[n + 2..]);
        } else if let Some(n) = char_literal(rest) {
            // A character literal ('"' would otherwise open a string).
            out.push_str("' '");
            rest = &rest[n..];
        } else if rest.starts_with('"') {
            // A string literal: kept out of the paths (it may hold "//" or "crate::").
            let bytes = rest.as_bytes();
            let mut i = 1;
            while i < bytes.len() && bytes[i] != b'"' {
                i += if bytes[i] == b'\\' { 2 } else { 1 };
            }
            out.push_str("\"\"");
            rest = rest.get(i + 1..).unwrap_or("");
        } else {
            let c = rest.chars().next().expect("not empty");
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    // Drop every `#[cfg(test)]` module from its opening brace to the matching close.
    while let Some(at) = out.find("#[cfg(test)]") {
        let after = &out[at + "#[cfg(test)]".len()..];
        let item = after.trim_start();
        let is_mod = item.starts_with("mod ") || item.starts_with("pub mod ") || item.starts_with("pub(crate) mod ");
        let Some(open) = after.find(['{', ';']).filter(|_| is_mod) else {
            out.replace_range(at..at + "#[cfg(test)]".len(), "");
            continue;
        };
        let start = at + "#[cfg(test)]".len() + open;
        let mut depth = 0usize;
        let mut end = out.len();
        for (i, c) in out[start..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = start + i + 1;
                        break;
                    }
                }
                ';' if depth == 0 => {
                    end = start + i + 1;
                    break;
                }
                _ => {}
            }
        }
        out.replace_range(at..end, "");
    }
    out
}

fn ident_len(s: &str) -> usize {
    s.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(s.len())
}

/// Every path that starts at `crate`, `super` or `self`, as its segments; a group
/// (`crate::a::{b, c::d}`) gives one path per member, its first segment only.
fn paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    for start in 0..code.len() {
        let word_start = start == 0 || !(bytes[start - 1].is_ascii_alphanumeric() || bytes[start - 1] == b'_');
        let rest = &code[start..];
        if !word_start || !(rest.starts_with("crate::") || rest.starts_with("super::") || rest.starts_with("self::")) {
            continue;
        }
        let mut segments = Vec::new();
        let mut at = start;
        loop {
            let n = ident_len(&code[at..]);
            if n == 0 || !code[at + n..].starts_with("::") {
                if n > 0 {
                    segments.push(code[at..at + n].to_string());
                }
                break;
            }
            segments.push(code[at..at + n].to_string());
            at += n + 2;
        }
        if code[at..].starts_with('{') {
            let mut depth = 0usize;
            let mut member = true;
            for (i, c) in code[at + 1..].char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => member = true,
                    c if member && (c.is_ascii_alphabetic() || c == '_') => {
                        let from = at + 1 + i;
                        let n = ident_len(&code[from..]);
                        let mut path = segments.clone();
                        path.push(code[from..from + n].to_string());
                        out.push(path);
                        member = false;
                    }
                    _ => {}
                }
            }
        } else {
            out.push(segments);
        }
    }
    out
}

/// The module a path names from `from`: its longest prefix that is a module of the crate.
fn resolve(from: &Module, path: &[String], mods: &BTreeMap<Module, PathBuf>) -> Module {
    let (mut full, mut rest): (Module, &[String]) = (from.clone(), path);
    if path.first().map(String::as_str) == Some("crate") {
        full.clear();
        rest = &path[1..];
    }
    while let Some(first) = rest.first() {
        match first.as_str() {
            "super" => {
                full.pop();
            }
            "self" => {}
            _ => break,
        }
        rest = &rest[1..];
    }
    full.extend(rest.iter().cloned());
    (0..=full.len()).rev().map(|n| full[..n].to_vec()).find(|m| mods.contains_key(m)).unwrap_or_default()
}

/// The crate's import edges between modules, leaving out a module and its own ancestors or
/// descendants (a parent declares its children and they use its items).
fn edges(src: &Path) -> BTreeSet<(Module, Module)> {
    let mods = modules(src);
    let mut out = BTreeSet::new();
    for (module, file) in &mods {
        let text = std::fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        for path in paths(&code(&text)) {
            let target = resolve(module, &path, &mods);
            let related = target.starts_with(module) || module.starts_with(&target);
            if !related {
                out.insert((module.clone(), target));
            }
        }
    }
    out
}

fn name(m: &Module) -> String {
    if m.is_empty() { "(crate root)".into() } else { m.join("::") }
}

/// The cycles of the graph, each as its modules (Tarjan's strongly connected components of more
/// than one module).
fn cycles(edges: &BTreeSet<(Module, Module)>) -> Vec<Vec<String>> {
    let mut next: BTreeMap<&Module, Vec<&Module>> = BTreeMap::new();
    for (a, b) in edges {
        next.entry(a).or_default().push(b);
        next.entry(b).or_default();
    }
    struct Walk<'a> {
        next: &'a BTreeMap<&'a Module, Vec<&'a Module>>,
        index: BTreeMap<&'a Module, usize>,
        low: BTreeMap<&'a Module, usize>,
        stack: Vec<&'a Module>,
        found: Vec<Vec<String>>,
    }
    impl<'a> Walk<'a> {
        fn visit(&mut self, v: &'a Module) {
            let i = self.index.len();
            self.index.insert(v, i);
            self.low.insert(v, i);
            self.stack.push(v);
            for &w in &self.next[v] {
                if !self.index.contains_key(w) {
                    self.visit(w);
                    let lw = self.low[w];
                    let lv = self.low.get_mut(v).expect("visited");
                    *lv = (*lv).min(lw);
                } else if self.stack.contains(&w) {
                    let iw = self.index[w];
                    let lv = self.low.get_mut(v).expect("visited");
                    *lv = (*lv).min(iw);
                }
            }
            if self.low[v] == self.index[v] {
                let at = self.stack.iter().rposition(|m| *m == v).expect("on the stack");
                let component: Vec<String> = self.stack.drain(at..).map(name).collect();
                if component.len() > 1 {
                    self.found.push(component);
                }
            }
        }
    }
    let mut walk = Walk { next: &next, index: BTreeMap::new(), low: BTreeMap::new(), stack: Vec::new(), found: Vec::new() };
    for &v in next.keys() {
        if !walk.index.contains_key(v) {
            walk.visit(v);
        }
    }
    walk.found
}

/// The edges of a cycle, for the message.
fn cycle_edges(edges: &BTreeSet<(Module, Module)>, cycle: &[String]) -> Vec<String> {
    edges
        .iter()
        .filter(|(a, b)| cycle.contains(&name(a)) && cycle.contains(&name(b)))
        .map(|(a, b)| format!("{} -> {}", name(a), name(b)))
        .collect()
}

const CRATES: [&str; 4] = ["shaders/src", "host/core/src", "host/src", "host/cli/src"];

#[test]
fn no_module_cycles_in_any_crate() {
    let mut found = Vec::new();
    for src in CRATES {
        let edges = edges(&repo().join(src));
        assert!(edges.len() > 10, "{src}: only {} import edges read; the scan is broken", edges.len());
        for cycle in cycles(&edges) {
            found.push(format!("{src}: {}", cycle_edges(&edges, &cycle).join(", ")));
        }
    }
    assert!(found.is_empty(), "module cycles:\n{}", found.join("\n"));
}

/// Each top-level module's layer (`docs/architecture.md`, "Layers", lower rows first); a module
/// may import from its own layer or below. Modules missing here fail the test, so a new one is
/// placed on purpose.
fn check_layers(src: &str, layers: &[&[&str]]) {
    let layer_of = |m: &Module| -> Option<usize> {
        let top = m.first().map(String::as_str).unwrap_or("");
        layers.iter().position(|row| row.contains(&top))
    };
    let mut uphill = Vec::new();
    for (a, b) in edges(&repo().join(src)) {
        if a.is_empty() || b.is_empty() {
            continue; // the crate root declares and re-exports
        }
        let la = layer_of(&a).unwrap_or_else(|| panic!("{src}: module {} has no layer in this test", name(&a)));
        let lb = layer_of(&b).unwrap_or_else(|| panic!("{src}: module {} has no layer in this test", name(&b)));
        if lb > la {
            uphill.push(format!("{} (layer {la}) -> {} (layer {lb})", name(&a), name(&b)));
        }
    }
    assert!(uphill.is_empty(), "{src}: imports from a higher layer:\n{}", uphill.join("\n"));
}

#[test]
fn core_imports_point_down() {
    check_layers(
        "host/core/src",
        &[&["error", "extent", "host_memory"], &["backend", "shaders", "lens"], &["ops", "aperture", "sampling"], &["frame"]],
    );
}

#[test]
fn library_imports_point_down() {
    check_layers(
        "host/src",
        &[
            // What `dof` re-exports from `dof-core`.
            &["dof_core", "backend", "error", "frame", "ops", "aperture", "lens", "shaders", "dof_shaders"],
            &["layers", "deep", "io", "metrics", "workload", "timing", "progress", "memory"],
            &["methods"],
            &["scene"],
            &["raster"],
            &["eval"],
            &["stress"],
        ],
    );
}

#[test]
fn the_scan_reads_groups_and_relative_paths() {
    let code = code("use crate::{a::B, c};\n// use crate::z;\nfn f() { super::d::e(); \"crate::y\"; }\n");
    let found = paths(&code);
    let expect: Vec<Vec<String>> = [vec!["crate", "a"], vec!["crate", "c"], vec!["super", "d", "e"]]
        .iter()
        .map(|p| p.iter().map(|s| s.to_string()).collect())
        .collect();
    assert_eq!(found, expect);
}
