//! The Rust tests of `cargo xtask test`: build every test binary once (`cargo test --no-run`),
//! then run each binary itself, timing it and each of its tests, so the summary can name the
//! steps' times and the slowest tests.
//!
//! A test's own time comes from libtest's `--report-time`. That flag is unstable, so the test
//! binaries (never the compiler: it would rebuild crates whose build scripts watch the variable)
//! run with `RUSTC_BOOTSTRAP=1`.

use crate::Count;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// One test binary cargo built: its package, its target, its path and its package's folder
/// (where cargo would run it: tests read paths relative to it).
#[derive(Debug, PartialEq)]
pub struct TestBinary {
    pub package: String,
    pub target: String,
    pub path: String,
    pub dir: String,
}

impl TestBinary {
    /// The name the summary gives it: `package` for a library's unit tests, else `package/target`.
    pub fn label(&self) -> String {
        if self.package.replace('-', "_") == self.target {
            self.package.clone()
        } else {
            format!("{}/{}", self.package, self.target)
        }
    }
}

/// One finished test and its time.
#[derive(Debug, PartialEq)]
pub struct TestTime {
    pub name: String,
    pub seconds: f64,
}

/// One step: its name, when it started (from the run's start) and how long it took.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    pub name: String,
    pub start: Duration,
    pub took: Duration,
}

/// Each step's wall time and every test's, for the summary.
pub struct Timings {
    pub since: Instant,
    pub steps: Vec<Step>,
    pub tests: Vec<TestTime>,
}

impl Default for Timings {
    fn default() -> Self {
        Timings::starting_at(Instant::now())
    }
}

impl Timings {
    /// Timings of a run that started at `since` (a thread's steps share the run's start).
    pub fn starting_at(since: Instant) -> Self {
        Timings { since, steps: Vec::new(), tests: Vec::new() }
    }

    /// Run `f` as the step `name`, recording when it started and its wall time.
    pub fn step<T>(&mut self, name: &str, f: impl FnOnce(&mut Self) -> T) -> T {
        let start = Instant::now();
        let out = f(self);
        self.steps.push(Step { name: name.to_string(), start: start - self.since, took: start.elapsed() });
        out
    }

    /// Add another thread's steps and tests.
    pub fn merge(&mut self, other: Timings) {
        self.steps.extend(other.steps);
        self.steps.sort_by_key(|s| s.start);
        self.tests.extend(other.tests);
    }

    /// The summary's lines: every step with its start and its time, the whole run's time (steps
    /// in the background overlap the others), then the slowest `n` tests.
    pub fn summary(&self, n: usize) -> Vec<String> {
        let mut lines = vec!["xtask: steps (start, time)".to_string()];
        let width = self.steps.iter().map(|s| s.name.chars().count()).max().unwrap_or(0);
        for s in &self.steps {
            lines.push(format!(
                "  {:<width$}  {:>7.1} s  {:>7.1} s",
                s.name,
                s.start.as_secs_f64(),
                s.took.as_secs_f64()
            ));
        }
        let total = self.steps.iter().map(|s| s.start + s.took).max().unwrap_or_default().as_secs_f64();
        lines.push(format!("  {:<width$}  {:>7.1} s  {total:>7.1} s", "the whole run", 0.0));
        let mut slowest: Vec<&TestTime> = self.tests.iter().collect();
        slowest.sort_by(|a, b| b.seconds.total_cmp(&a.seconds));
        lines.push(format!("xtask: the slowest {} of {} timed tests", n.min(slowest.len()), slowest.len()));
        for t in slowest.into_iter().take(n) {
            lines.push(format!("  {:>7.1} s  {}", t.seconds, t.name));
        }
        lines
    }
}

/// The executables of cargo's JSON messages whose profile is a test.
pub fn test_binaries(json_lines: &str) -> Vec<TestBinary> {
    let field = |line: &str, key: &str| -> Option<String> {
        let at = line.find(&format!("\"{key}\":\""))? + key.len() + 4;
        Some(line[at..at + line[at..].find('"')?].to_string())
    };
    json_lines
        .lines()
        .filter(|l| l.contains("\"reason\":\"compiler-artifact\""))
        .filter_map(|l| {
            let profile = &l[l.find("\"profile\":{")?..];
            if !profile[..profile.find('}')?].contains("\"test\":true") {
                return None;
            }
            let path = field(l, "executable")?;
            let manifest = field(l, "manifest_path")?;
            let dir = manifest.strip_suffix("/Cargo.toml").unwrap_or(&manifest).to_string();
            let target = field(&l[l.find("\"target\":")?..], "name")?;
            // "path+file:///…/crates/shadelab#0.1.0" or "path+file:///…#name@0.1.0"
            let id = field(l, "package_id")?;
            let tail = &id[id.rfind('/')? + 1..];
            let package = match tail.split_once('#') {
                Some((dir, version)) => version.split_once('@').map_or(dir, |(name, _)| name),
                None => tail,
            };
            Some(TestBinary { package: package.to_string(), target, path, dir })
        })
        .collect()
}

/// A finished test's name and seconds from libtest's `--report-time` line
/// (`test a::b ... ok <1.234s>`) or the browser tests' (`test web::c ... ok (1.2 s)`).
pub fn test_time(line: &str) -> Option<TestTime> {
    let rest = line.strip_prefix("test ")?;
    let (name, outcome) = rest.split_once(" ... ")?;
    let time = outcome.strip_prefix("ok ").or_else(|| outcome.strip_prefix("FAILED "))?.trim();
    let seconds = time
        .strip_prefix('<')
        .and_then(|t| t.strip_suffix("s>"))
        .or_else(|| time.strip_prefix('(').and_then(|t| t.strip_suffix(" s)")))?
        .parse()
        .ok()?;
    Some(TestTime { name: name.to_string(), seconds })
}

/// Build every test binary (`cargo test --no-run` with `cargo_args`); their paths.
pub fn build(cargo_args: &[String], env: &[(&str, &std::ffi::OsStr)]) -> Result<Vec<TestBinary>, String> {
    let mut cmd = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    cmd.args(["test", "--release", "--workspace", "--no-run", "--message-format", "json-render-diagnostics"]);
    cmd.args(cargo_args).envs(env.iter().copied()).stderr(Stdio::inherit());
    eprintln!("xtask: running {cmd:?}");
    let out = cmd.output().map_err(|e| format!("running cargo: {e}"))?;
    if !out.status.success() {
        return Err(format!("building the tests failed ({})", out.status));
    }
    Ok(test_binaries(&String::from_utf8_lossy(&out.stdout)))
}

/// Run each binary with `test_args`, passing its output through; count its results and time
/// each test. False when any binary failed or did not run.
pub fn run(
    binaries: &[TestBinary],
    test_args: &[String],
    env: &[(&str, &std::ffi::OsStr)],
    count: &mut Count,
    timings: &mut Timings,
) -> bool {
    let mut all_ok = true;
    for bin in binaries {
        let label = bin.label();
        let mut cmd = Command::new(&bin.path);
        cmd.current_dir(&bin.dir).args(["-Zunstable-options", "--report-time"]).args(test_args);
        cmd.envs(env.iter().copied()).env("RUSTC_BOOTSTRAP", "1");
        let start = Instant::now();
        let (ok, c) = crate::run_counting(&mut cmd, timings, &format!("{label}: "));
        // A binary that did not run, or stopped before its counts, still counts as a failure.
        count.passed += c.passed;
        count.failed += c.failed.max(u64::from(!ok && c.failed == 0));
        eprintln!("xtask: {label}: {} in {:.1} s", if ok { "ok" } else { "FAILED" }, start.elapsed().as_secs_f64());
        all_ok &= ok;
    }
    all_ok
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_binaries_are_read_from_cargo_messages() {
        let json = concat!(
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/crates/shadelab#0.1.0","manifest_path":"/w/crates/shadelab/Cargo.toml","target":{"kind":["test"],"name":"viewer","test":true},"profile":{"opt_level":"3","test":true},"executable":"/w/target/release/deps/viewer-1a2b","fresh":true}"#,
            "\n",
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/tests#shadelab-tests@0.1.0","target":{"kind":["lib"],"name":"shadelab_tests","test":true},"profile":{"opt_level":"3","test":false},"executable":null,"fresh":true}"#,
            "\n",
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/crates/shadelab-model#0.1.0","manifest_path":"/w/crates/shadelab-model/Cargo.toml","target":{"kind":["lib"],"name":"shadelab_model","test":true},"profile":{"opt_level":"3","test":true},"executable":"/w/target/release/deps/shadelab_model-9f","fresh":false}"#,
        );
        let bins = test_binaries(json);
        assert_eq!(bins.len(), 2, "{bins:?}");
        assert_eq!(bins[0].label(), "shadelab/viewer");
        assert_eq!(bins[0].path, "/w/target/release/deps/viewer-1a2b");
        assert_eq!(bins[0].dir, "/w/crates/shadelab");
        assert_eq!(bins[1].label(), "shadelab-model");
    }

    #[test]
    fn a_tests_time_is_read_from_either_format() {
        assert_eq!(test_time("test a::b ... ok <1.250s>"), Some(TestTime { name: "a::b".into(), seconds: 1.25 }));
        assert_eq!(test_time("test web::c ... ok (12.5 s)"), Some(TestTime { name: "web::c".into(), seconds: 12.5 }));
        assert_eq!(test_time("test a ... FAILED <0.5s>").map(|t| t.seconds), Some(0.5));
        assert_eq!(test_time("test a ... ignored"), None);
        assert_eq!(test_time("test result: ok. 3 passed"), None);
    }

    #[test]
    fn the_summary_lists_steps_and_the_slowest_tests() {
        let mut t = Timings::default();
        let s = |name: &str, start: u64, took: u64| Step {
            name: name.into(),
            start: Duration::from_secs(start),
            took: Duration::from_secs(took),
        };
        t.steps.push(s("build", 0, 10));
        t.steps.push(s("tests", 10, 5));
        let mut background = Timings::starting_at(t.since);
        background.steps.push(s("(background) web", 1, 12));
        t.merge(background);
        t.tests = (1..=12).map(|i| TestTime { name: format!("t{i}"), seconds: i as f64 }).collect();
        let lines = t.summary(10);
        assert!(lines[1].starts_with("  build") && lines[1].ends_with("0.0 s     10.0 s"), "{lines:?}");
        assert!(lines[2].starts_with("  (background) web"), "steps in the order they started: {lines:?}");
        assert!(lines[4].contains("the whole run") && lines[4].ends_with("15.0 s"), "{lines:?}");
        assert_eq!(lines[5], "xtask: the slowest 10 of 12 timed tests");
        assert!(lines[6].ends_with("t12") && lines[15].ends_with("t3"), "{lines:?}");
        assert_eq!(lines.len(), 16);
    }
}
