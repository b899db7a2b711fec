//! `lac serve`: the interactive editor (the `lac-serve` crate) on a local port.

use std::net::SocketAddr;
use std::process::{Command, Stdio};

use clap::Args;
use lac_io::json::ErrorBody;

/// Arguments of `lac serve`.
#[derive(Debug, Args)]
pub(crate) struct ServeArgs {
    /// The port to listen on (0: any free port; the URL printed says which)
    #[arg(long, value_name = "P", default_value_t = 8787)]
    pub(crate) port: u16,

    /// Open the editor in the default web browser
    #[arg(long)]
    pub(crate) open: bool,

    /// The address to listen on; anything but a loopback address needs --allow-remote
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1")]
    pub(crate) host: std::net::IpAddr,

    /// Allow a non-loopback --host: anyone who can reach the port can use the editor's API
    #[arg(long)]
    pub(crate) allow_remote: bool,
}

/// Run `lac serve`: bind, print the URL (and open it with `--open`), serve until
/// interrupted.
pub(crate) fn run(args: &ServeArgs) -> Result<(), ErrorBody> {
    let addr = SocketAddr::new(args.host, args.port);
    lac_serve::run(
        addr,
        args.allow_remote,
        lac_serve::Limits::default(),
        |bound| {
            let url = format!("http://{bound}/");
            println!("lac editor: {url}  (Ctrl-C stops it)");
            if args.open {
                if let Err(why) = open_browser(&url) {
                    eprintln!("could not open a browser ({why}); open {url} yourself");
                }
            }
        },
    )
}

/// Ask the desktop to open `url`, without waiting for the browser; why not, when it cannot
/// (no display on Linux, no opener, an opener that fails: reported from a thread, since the
/// server is running by then).
fn open_browser(url: &str) -> Result<(), String> {
    let mut command = if cfg!(target_os = "macos") {
        Command::new("open")
    } else if cfg!(target_os = "windows") {
        let mut c = Command::new("cmd");
        c.args(["/C", "start", ""]);
        c
    } else {
        let display = ["DISPLAY", "WAYLAND_DISPLAY"]
            .iter()
            .any(|name| std::env::var_os(name).is_some_and(|v| !v.is_empty()));
        if !display {
            return Err("no display: neither DISPLAY nor WAYLAND_DISPLAY is set".to_string());
        }
        Command::new("xdg-open")
    };
    let mut child = command
        .arg(url)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("{}: {e}", command.get_program().to_string_lossy()))?;
    let url = url.to_string();
    std::thread::spawn(move || {
        if let Ok(status) = child.wait() {
            if !status.success() {
                eprintln!("could not open a browser (the opener exited with {status}); open {url} yourself");
            }
        }
    });
    Ok(())
}
