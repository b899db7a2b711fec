//! Lists the page's files (everything under `web/` but `index.html` and the README) for
//! `src/assets.rs`, so that a new module of the page is served without naming it anywhere.

use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::{env, fs};

fn files_under(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .expect("web/ is readable")
        .map(|e| e.expect("a web/ entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            files_under(&path, out);
        } else {
            out.push(path);
        }
    }
}

fn main() {
    let web = Path::new(&env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("web");
    println!("cargo:rerun-if-changed=web");
    let mut files = Vec::new();
    files_under(&web, &mut files);
    let mut list = String::from("&[\n");
    for path in files {
        let name = path
            .strip_prefix(&web)
            .expect("under web/")
            .to_string_lossy()
            .replace('\\', "/");
        let media_type = match path.extension().and_then(|e| e.to_str()) {
            Some("js") => "text/javascript; charset=utf-8",
            Some("css") => "text/css; charset=utf-8",
            Some("svg") => "image/svg+xml",
            // index.html is the page itself; notes for developers are not served.
            _ => continue,
        };
        writeln!(
            list,
            "    ({name:?}, include_str!({:?}), {media_type:?}),",
            path.display()
        )
        .expect("writing to a string");
    }
    list.push_str("]\n");
    let out = Path::new(&env::var("OUT_DIR").expect("cargo sets it")).join("assets.rs");
    fs::write(out, list).expect("OUT_DIR is writable");
}
