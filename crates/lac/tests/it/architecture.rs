//! Claim: the crate's modules form the layers of docs/architecture.md, and no module uses one
//! above it or closes a cycle with its neighbours.
//!
//! Read from the source text: every `crate::…` path outside comments and unit tests names
//! the module it uses. A module is a top-level module of `src/` or, inside the `foundation`,
//! `family` and `curve` folders, one module of that folder. Paths through the crate root's
//! re-exports (`crate::Curve`) are refused outside tests, since they hide which layer they
//! reach.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The layers from the bottom up, each a list of path prefixes under `src/`.
const LAYERS: &[(&str, &[&str])] = &[
    ("foundations", &["foundation"]),
    ("families", &["family"]),
    ("segments", &["segment"]),
    ("curves and analysis", &["curve"]),
    ("replacement and paths", &["quasi", "path"]),
    ("fitting", &["fit"]),
    ("space curves and regions", &["space", "region"]),
];

/// Folders whose modules are units of their own (a layer made of several concepts).
const FOLDERS: &[&str] = &["foundation", "family", "curve"];

fn source_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            source_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The unit a path below `src/` (as module names) belongs to.
fn unit_of(parts: &[&str]) -> Option<String> {
    let first = *parts.first()?;
    if FOLDERS.contains(&first) {
        let second = parts.get(1)?;
        if *second == "mod" {
            return Some(first.to_string());
        }
        return Some(format!("{first}::{second}"));
    }
    Some(first.to_string())
}

fn layer_of(unit: &str) -> Option<usize> {
    let top = unit.split("::").next()?;
    LAYERS
        .iter()
        .position(|(_, prefixes)| prefixes.contains(&top))
}

/// The code of a file without its comments and its `#[cfg(test)]` module.
fn code(text: &str) -> String {
    let text = match text.find("#[cfg(test)]") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) => &line[..i],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every `crate::a::b` path in `code`, as its first two names (the second may be empty).
fn crate_paths(code: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let after = &rest[i + "crate::".len()..];
        let name = |s: &str| {
            s.chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect::<String>()
        };
        let first = name(after);
        let second = after[first.len()..]
            .strip_prefix("::")
            .map(name)
            .unwrap_or_default();
        // `use crate::{a, b}` is not used in this crate; a brace would be refused below.
        out.push((first, second));
        rest = after;
    }
    out
}

#[test]
fn every_module_uses_only_its_own_layer_and_those_below() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    source_files(&src, &mut files);
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut wrong = Vec::new();
    let mut units = BTreeSet::new();
    for file in &files {
        let relative = file.strip_prefix(&src).unwrap().with_extension("");
        let parts: Vec<&str> = relative
            .components()
            .map(|c| c.as_os_str().to_str().unwrap())
            .collect();
        if parts == ["lib"] {
            continue;
        }
        let unit = unit_of(&parts).unwrap();
        let Some(layer) = layer_of(&unit) else {
            wrong.push(format!("{}: in no layer", relative.display()));
            continue;
        };
        units.insert(unit.clone());
        for (first, second) in crate_paths(&code(&fs::read_to_string(file).unwrap())) {
            if first.is_empty() || first.starts_with(|c: char| c.is_uppercase()) {
                wrong.push(format!(
                    "{}: `crate::{first}` goes through the crate root; name the module",
                    relative.display()
                ));
                continue;
            }
            let target = if FOLDERS.contains(&first.as_str())
                && !second.is_empty()
                && second.starts_with(|c: char| c.is_lowercase())
            {
                format!("{first}::{second}")
            } else {
                first.clone()
            };
            let Some(target_layer) = layer_of(&target) else {
                wrong.push(format!(
                    "{}: uses `crate::{first}`, in no layer",
                    relative.display()
                ));
                continue;
            };
            if target_layer > layer {
                wrong.push(format!(
                    "{} ({}) uses {target} ({}), a layer above it",
                    relative.display(),
                    LAYERS[layer].0,
                    LAYERS[target_layer].0
                ));
            }
            if target != unit {
                edges.entry(unit.clone()).or_default().insert(target);
            }
        }
    }
    assert!(units.len() > 20, "only {} modules found", units.len());
    // A cycle among the units (within a layer, since the layers are ordered).
    fn visit(
        unit: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, bool>,
        stack: &mut Vec<String>,
        cycles: &mut Vec<String>,
    ) {
        match state.get(unit) {
            Some(true) => return,
            Some(false) => {
                let from = stack.iter().position(|u| u == unit).unwrap();
                cycles.push(format!("{} -> {unit}", stack[from..].join(" -> ")));
                return;
            }
            None => {}
        }
        state.insert(unit.to_string(), false);
        stack.push(unit.to_string());
        for next in edges.get(unit).into_iter().flatten() {
            visit(next, edges, state, stack, cycles);
        }
        stack.pop();
        state.insert(unit.to_string(), true);
    }
    let mut state = BTreeMap::new();
    let mut cycles = Vec::new();
    for unit in &units {
        visit(unit, &edges, &mut state, &mut Vec::new(), &mut cycles);
    }
    wrong.extend(cycles.into_iter().map(|c| format!("cycle: {c}")));
    assert!(wrong.is_empty(), "\n{}", wrong.join("\n"));
}
