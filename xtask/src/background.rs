//! What `cargo xtask test` builds beside the tests: the web site (the wasm build and
//! wasm-bindgen) and the fuzz targets. They share nothing with the native build, so they run on a
//! thread of their own from the start, every command at the lowest CPU priority (`nice -n 19`):
//! they take only the cores the native build and the tests leave idle, and the tests run as fast
//! as they would alone. Their output goes to a log, printed when a step fails.

use crate::suite::Timings;
use std::cell::RefCell;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc::Receiver;
use std::thread::JoinHandle;
use std::time::Instant;

thread_local! {
    /// The log of the thread that runs in the background; `None` on every other thread.
    static LOG: RefCell<Option<File>> = const { RefCell::new(None) };
}

/// On the background thread, `cmd` at the lowest priority with its output appended to the log
/// (which also gets `note`); on any other thread `None`, and `note` goes to stderr.
pub fn niced(cmd: &Command, note: &str) -> Option<Command> {
    LOG.with(|log| {
        let log = log.borrow();
        let Some(file) = log.as_ref() else {
            eprintln!("{note}");
            return None;
        };
        let _ = writeln!(&*file, "{note}");
        let mut niced = Command::new("nice");
        niced.arg("-n").arg("19").arg(cmd.get_program()).args(cmd.get_args());
        for (k, v) in cmd.get_envs() {
            match v {
                Some(v) => niced.env(k, v),
                None => niced.env_remove(k),
            };
        }
        if let Some(dir) = cmd.get_current_dir() {
            niced.current_dir(dir);
        }
        let to_log = || file.try_clone().map(Stdio::from).unwrap_or_else(|_| Stdio::null());
        niced.stdout(to_log()).stderr(to_log());
        Some(niced)
    })
}

/// The background's work: the site's outcome as soon as it is built (the browser tests need
/// nothing more), then the whole thread's with the fuzz targets'.
pub struct Background {
    pub site: Receiver<Result<(), String>>,
    pub rest: JoinHandle<Prepared>,
    pub log: PathBuf,
}

/// What the background built besides the site: the fuzz targets' outcome, and its steps' times.
pub struct Prepared {
    pub fuzz_targets: Result<(), String>,
    pub timings: Timings,
}

/// Start building the site into `site` (with its node tools in `node_dir`), then the fuzz targets.
pub fn start(site: PathBuf, node_dir: PathBuf, since: Instant) -> Background {
    let log = crate::web::root().join("target/xtask-background.log");
    let (send, receive) = std::sync::mpsc::channel();
    let log_path = log.clone();
    let rest = std::thread::spawn(move || {
        let _ = std::fs::create_dir_all(log.parent().unwrap());
        if let Ok(file) = File::create(&log) {
            LOG.with(|l| *l.borrow_mut() = Some(file));
        }
        let mut timings = Timings::starting_at(since);
        let built = timings.step("(background) browser tools and web build", |_| {
            crate::web_test::ensure_browser_tools(&node_dir).and_then(|()| crate::web::build_site(&site))
        });
        let _ = send.send(built);
        let fuzz_targets = timings.step("(background) fuzz targets: build", |_| crate::fuzz::build());
        Prepared { fuzz_targets, timings }
    });
    Background { site: receive, rest, log: log_path }
}

/// The log's last `lines` lines, to show with a failure.
pub fn tail(log: &Path, lines: usize) -> String {
    let text = std::fs::read_to_string(log).unwrap_or_default();
    let all: Vec<&str> = text.lines().collect();
    all[all.len().saturating_sub(lines)..].join("\n")
}
