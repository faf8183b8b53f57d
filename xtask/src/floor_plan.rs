//! `docs/architecture.md` against the tree: each of the doc's sections that names a folder in
//! its heading (`### Model (`crates/shadelab-model/src/`)`) lists every `.rs` and `.wgsl` file
//! under that folder by its path relative to it, and every such path the doc names exists.

use std::path::Path;

/// The folders the floor plan must list whole.
pub const ROOTS: &[&str] = &[
    "crates/shadelab-model/src/",
    "crates/shadelab-render/src/",
    "crates/shadelab/src/",
    "crates/shadelab-web/src/",
    "shaders/",
    "xtask/src/",
    "tests/",
    "crates/shadelab/tests/",
    "fuzz/fuzz_targets/",
];

/// One section of the doc: the folder its heading names (if any) and its text, subsections
/// included.
#[derive(Debug)]
pub struct Section {
    pub root: Option<String>,
    pub text: String,
}

/// The doc's sections at every heading level; a section runs to the next heading of its level
/// or above, so it holds its subsections.
pub fn sections(doc: &str) -> Vec<Section> {
    let lines: Vec<&str> = doc.lines().collect();
    let level = |l: &str| l.starts_with('#').then(|| l.chars().take_while(|&c| c == '#').count());
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(lv) = level(line) else { continue };
        let end =
            lines[i + 1..].iter().position(|l| level(l).is_some_and(|m| m <= lv)).map_or(lines.len(), |p| i + 1 + p);
        let root = backticked(line).into_iter().find(|t| t.ends_with('/'));
        out.push(Section { root, text: lines[i..end].join("\n") });
    }
    out
}

/// The tokens between backticks on `text`'s lines.
pub fn backticked(text: &str) -> Vec<String> {
    text.lines().flat_map(|l| l.split('`').skip(1).step_by(2).map(str::to_string).collect::<Vec<_>>()).collect()
}

/// Every `.rs` and `.wgsl` file under `dir`, relative to it, sorted.
pub fn source_files(dir: &Path) -> Vec<String> {
    fn walk(dir: &Path, base: &Path, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, base, out);
            } else if path.extension().is_some_and(|e| e == "rs" || e == "wgsl") {
                out.push(path.strip_prefix(base).unwrap().to_string_lossy().replace('\\', "/"));
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, dir, &mut out);
    out.sort();
    out
}

/// What the doc gets wrong about the tree under `repo`: files a root's section does not list,
/// paths it names that do not exist, roots without exactly one section.
pub fn problems(doc: &str, repo: &Path) -> Vec<String> {
    let sections = sections(doc);
    let mut out = Vec::new();
    for root in ROOTS {
        let mine: Vec<&Section> = sections.iter().filter(|s| s.root.as_deref() == Some(root)).collect();
        let [section] = mine.as_slice() else {
            out.push(format!("`{root}` has {} sections; it needs one", mine.len()));
            continue;
        };
        let named = backticked(&section.text);
        for file in source_files(&repo.join(root)) {
            if !named.contains(&file) {
                out.push(format!("`{root}{file}` is not listed in the section of `{root}`"));
            }
        }
        for token in named.iter().filter(|t| (t.ends_with(".rs") || t.ends_with(".wgsl")) && !t.contains(' ')) {
            if !repo.join(root).join(token).is_file() && !repo.join(token).is_file() {
                out.push(format!("the section of `{root}` names `{token}`, which is not a file"));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_architecture_doc_lists_every_source_file_and_only_files() {
        let repo = crate::web::root();
        let doc = std::fs::read_to_string(repo.join("docs/architecture.md")).unwrap();
        let problems = problems(&doc, &repo);
        assert!(problems.is_empty(), "docs/architecture.md:\n  {}", problems.join("\n  "));
    }

    #[test]
    fn a_missing_or_a_gone_file_is_found() {
        let dir = std::env::temp_dir().join(format!("shadelab-floor-plan-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("shaders")).unwrap();
        std::fs::write(dir.join("shaders/a.wgsl"), "").unwrap();
        std::fs::write(dir.join("shaders/b.wgsl"), "").unwrap();
        let doc =
            "# Plan\n\n## Shaders (`shaders/`)\n\n### Terms\n\n- `a.wgsl`\n- `gone.wgsl`\n\n## Other\n\n`b.wgsl`\n";
        let found = problems(doc, &dir);
        let _ = std::fs::remove_dir_all(&dir);
        assert!(
            found.contains(&"`shaders/b.wgsl` is not listed in the section of `shaders/`".to_string()),
            "{found:?}"
        );
        assert!(
            found.contains(&"the section of `shaders/` names `gone.wgsl`, which is not a file".to_string()),
            "{found:?}"
        );
        assert!(!found.iter().any(|p| p.contains("a.wgsl")), "a listed file is fine: {found:?}");
        assert!(found.iter().any(|p| p.starts_with("`xtask/src/` has 0 sections")), "{found:?}");
    }
}
