//! The README's figures are what its "Made by" lines say they are.
//!
//! Every figure `docs/….svg` that README.md shows is followed by a line
//!
//! ```text
//! *Made by* `lac … -o docs/name.svg`.
//! ```
//!
//! (a pipe `lac … | lac … -o docs/name.svg` is fine). These tests run each such command with
//! the `lac` just built, through `sh -c` with the binary's directory first on `PATH`, in a
//! scratch directory, and compare what it writes with the committed file byte for byte.
//! `make docs` runs them with `LAC_WRITE_FIGURES=1`, which copies the new figures into `docs/`
//! instead of failing, so the README lines are the only place a figure's command is written.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Set (to anything) by `make docs`: write the figures instead of checking them.
const WRITE: &str = "LAC_WRITE_FIGURES";

/// The line that introduces a figure's command, and what closes it.
const MADE_BY: &str = "*Made by* `";
const CLOSE: &str = "`.";

/// One README figure: the file it shows and the command that draws it.
struct Figure {
    /// Relative to the repository root, as the command writes it (`docs/segment.svg`).
    file: String,
    /// One `lac` command, or a pipe of them, run from the repository root.
    command: String,
}

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn readme() -> String {
    let path = repo_root().join("README.md");
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The "Made by" lines of `readme`, each with the file its last `-o` writes.
fn figures(readme: &str) -> Vec<Figure> {
    readme
        .lines()
        .filter(|line| line.starts_with("*Made by*"))
        .map(|line| {
            let command = line
                .strip_prefix(MADE_BY)
                .and_then(|rest| rest.strip_suffix(CLOSE))
                .unwrap_or_else(|| {
                    panic!(
                        "README: write a figure's command as {MADE_BY}lac …{CLOSE}, not {line:?}"
                    )
                });
            for stage in command.split('|') {
                assert!(
                    stage.trim_start().starts_with("lac "),
                    "README: each stage of a figure's command runs `lac`: {command:?}"
                );
            }
            let words: Vec<&str> = command.split_whitespace().collect();
            let file = words
                .iter()
                .rposition(|w| *w == "-o")
                .and_then(|i| words.get(i + 1))
                .unwrap_or_else(|| panic!("README: {command:?} names no figure with -o FILE"));
            Figure {
                file: file.to_string(),
                command: command.to_string(),
            }
        })
        .collect()
}

/// The images `![…](docs/…)` that `readme` shows.
fn shown(readme: &str) -> Vec<String> {
    readme
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .filter(|target| target.starts_with("docs/"))
        .map(str::to_string)
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
fn every_figure_the_readme_shows_has_one_made_by_command_and_every_svg_in_docs_is_one() {
    let readme = readme();
    let mut made: Vec<String> = figures(&readme).into_iter().map(|f| f.file).collect();
    let mut shown = shown(&readme);
    let mut committed: Vec<String> = std::fs::read_dir(repo_root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|name| name.ends_with(".svg"))
        .map(|name| format!("docs/{name}"))
        .collect();
    for list in [&mut made, &mut shown, &mut committed] {
        list.sort();
    }
    assert!(!made.is_empty(), "README has no *Made by* lines");
    let mut unique = made.clone();
    unique.dedup();
    assert_eq!(made, unique, "two *Made by* commands write the same figure");
    assert_eq!(
        made, shown,
        "README: the figures made and the figures shown"
    );
    // A figure not committed yet is reported by the next test (and written by `make docs`).
    let orphans: Vec<&String> = committed.iter().filter(|f| !made.contains(f)).collect();
    assert!(
        orphans.is_empty(),
        "no *Made by* line draws {orphans:?}: delete the file or add its README lines"
    );
}

#[test]
fn every_committed_figure_is_what_its_made_by_command_draws_now() {
    let write = std::env::var_os(WRITE).is_some();
    let root = repo_root();
    let scratch = tempfile::tempdir().unwrap();
    let mut stale = Vec::new();
    for figure in figures(&readme()) {
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
        "these README figures are not what their *Made by* commands draw now:\n{}\n\
         run `make docs` and commit the figures",
        stale.join("\n")
    );
}
