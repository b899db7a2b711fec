//! The documentation's figures are what its "Made by" lines say they are.
//!
//! Every figure `docs/….svg` that README.md or a page `docs/*.md` shows is followed, in the
//! same document, by a line
//!
//! ```text
//! *Made by* `lac … -o docs/name.svg`.
//! ```
//!
//! (a pipe `lac … | lac … -o docs/name.svg` is fine; the path is the repository root's, on
//! every page). These tests run each such command with the `lac` just built, through `sh -c`
//! with the binary's directory first on `PATH`, in a scratch directory, and compare what it
//! writes with the committed file byte for byte. `make docs` runs them with
//! `LAC_WRITE_FIGURES=1`, which copies the new figures into `docs/` instead of failing, so the
//! *Made by* lines are the only place a figure's command is written.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Set (to anything) by `make docs`: write the figures instead of checking them.
const WRITE: &str = "LAC_WRITE_FIGURES";

/// The line that introduces a figure's command, and what closes it.
const MADE_BY: &str = "*Made by* `";
const CLOSE: &str = "`.";

/// One figure: the file it shows and the command that draws it.
struct Figure {
    /// Relative to the repository root, as the command writes it (`docs/segment.svg`).
    file: String,
    /// One `lac` command, or a pipe of them, run from the repository root.
    command: String,
}

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A document that may show figures: its path relative to the repository root and its text.
struct Document {
    path: PathBuf,
    text: String,
}

/// README.md and every `docs/*.md`, in a fixed order.
fn documents() -> Vec<Document> {
    let root = repo_root();
    let mut paths = vec![PathBuf::from("README.md")];
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|name| name.ends_with(".md"))
        .map(|name| Path::new("docs").join(name))
        .collect();
    pages.sort();
    paths.extend(pages);
    paths
        .into_iter()
        .map(|path| {
            let full = root.join(&path);
            let text = std::fs::read_to_string(&full)
                .unwrap_or_else(|e| panic!("{}: {e}", full.display()));
            Document { path, text }
        })
        .collect()
}

/// The "Made by" lines of `doc`, each with the file its last `-o` writes.
fn figures(doc: &Document) -> Vec<Figure> {
    let name = doc.path.display();
    doc.text
        .lines()
        .filter(|line| line.starts_with("*Made by*"))
        .map(|line| {
            let command = line
                .strip_prefix(MADE_BY)
                .and_then(|rest| rest.strip_suffix(CLOSE))
                .unwrap_or_else(|| {
                    panic!(
                        "{name}: write a figure's command as {MADE_BY}lac …{CLOSE}, not {line:?}"
                    )
                });
            for stage in command.split('|') {
                assert!(
                    stage.trim_start().starts_with("lac "),
                    "{name}: each stage of a figure's command runs `lac`: {command:?}"
                );
            }
            let words: Vec<&str> = command.split_whitespace().collect();
            let file = words
                .iter()
                .rposition(|w| *w == "-o")
                .and_then(|i| words.get(i + 1))
                .unwrap_or_else(|| panic!("{name}: {command:?} names no figure with -o FILE"));
            Figure {
                file: file.to_string(),
                command: command.to_string(),
            }
        })
        .collect()
}

/// Every figure of every document.
fn all_figures() -> Vec<Figure> {
    documents().iter().flat_map(figures).collect()
}

/// The SVG images `![…](…)` that `doc` shows, as paths from the repository root
/// (`docs/segment.svg`, whether README.md links `docs/segment.svg` or a page of `docs/`
/// links `segment.svg`).
fn shown(doc: &Document) -> Vec<String> {
    let dir = doc.path.parent().unwrap_or(Path::new(""));
    doc.text
        .split("![")
        .skip(1)
        .filter_map(|rest| rest.split_once("]("))
        .filter_map(|(_, rest)| rest.split(')').next())
        .filter(|target| target.ends_with(".svg"))
        .map(|target| {
            let mut parts: Vec<String> = Vec::new();
            for part in dir.join(target).components() {
                match part {
                    std::path::Component::ParentDir => {
                        assert!(
                            parts.pop().is_some(),
                            "{}: {target} is outside the repository",
                            doc.path.display()
                        );
                    }
                    std::path::Component::Normal(p) => parts.push(p.to_str().unwrap().to_string()),
                    _ => {}
                }
            }
            parts.join("/")
        })
        .collect()
}

/// What `figure`'s command writes, run in the scratch directory `dir` with the built `lac`
/// first on `PATH`.
fn draw(figure: &Figure, dir: &Path) -> Vec<u8> {
    let lac = Path::new(env!("CARGO_BIN_EXE_lac"));
    let mut path = vec![lac.parent().unwrap().to_path_buf()];
    path.extend(std::env::split_paths(
        &std::env::var_os("PATH").unwrap_or_default(),
    ));
    let path: OsString = std::env::join_paths(path).unwrap();
    let out = dir.join(&figure.file);
    std::fs::create_dir_all(out.parent().unwrap()).unwrap();
    let run = Command::new("sh")
        .arg("-c")
        .arg(&figure.command)
        .current_dir(dir)
        .env("PATH", path)
        .output()
        .expect("sh runs");
    assert!(
        run.status.success(),
        "`{}` failed ({}): {}",
        figure.command,
        run.status,
        String::from_utf8_lossy(&run.stderr)
    );
    std::fs::read(&out)
        .unwrap_or_else(|e| panic!("`{}` wrote no {} ({e})", figure.command, out.display()))
}

/// The 1-based number of the first line where `a` and `b` differ.
fn first_different_line(a: &[u8], b: &[u8]) -> usize {
    let same = a.iter().zip(b).take_while(|(x, y)| x == y).count();
    1 + a[..same].iter().filter(|&&c| c == b'\n').count()
}

#[test]
fn every_figure_the_documentation_shows_has_one_made_by_command_and_every_svg_in_docs_is_one() {
    let docs = documents();
    assert!(
        docs.iter().any(|d| d.path.starts_with("docs")),
        "no pages in docs/ were read"
    );
    let mut made = Vec::new();
    for doc in &docs {
        let mut here: Vec<String> = figures(doc).into_iter().map(|f| f.file).collect();
        let mut seen = shown(doc);
        here.sort();
        seen.sort();
        assert_eq!(
            here,
            seen,
            "{}: the figures made and the figures shown",
            doc.path.display()
        );
        made.extend(here);
    }
    let mut committed: Vec<String> = std::fs::read_dir(repo_root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|name| name.ends_with(".svg"))
        .map(|name| format!("docs/{name}"))
        .collect();
    made.sort();
    committed.sort();
    assert!(!made.is_empty(), "the documentation has no *Made by* lines");
    let mut unique = made.clone();
    unique.dedup();
    assert_eq!(made, unique, "two *Made by* commands write the same figure");
    // A figure not committed yet is reported by the next test (and written by `make docs`).
    let orphans: Vec<&String> = committed.iter().filter(|f| !made.contains(f)).collect();
    assert!(
        orphans.is_empty(),
        "no *Made by* line draws {orphans:?}: delete the file or show it with its *Made by* line"
    );
}

#[test]
fn every_committed_figure_is_what_its_made_by_command_draws_now() {
    let write = std::env::var_os(WRITE).is_some();
    let root = repo_root();
    let scratch = tempfile::tempdir().unwrap();
    let mut stale = Vec::new();
    for figure in all_figures() {
        let new = draw(&figure, scratch.path());
        let committed_path = root.join(&figure.file);
        let committed = std::fs::read(&committed_path).unwrap_or_default();
        if new == committed {
            continue;
        }
        if write {
            std::fs::write(&committed_path, &new).unwrap();
            eprintln!("wrote {}", figure.file);
        } else {
            stale.push(format!(
                "  {} (first difference on line {}), made by `{}`",
                figure.file,
                first_different_line(&new, &committed),
                figure.command
            ));
        }
    }
    assert!(
        stale.is_empty(),
        "these figures are not what their *Made by* commands draw now:\n{}\n\
         run `make docs` and commit the figures",
        stale.join("\n")
    );
}
