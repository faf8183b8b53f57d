//! The WGSL preprocessor: `#if` blocks cut one effect permutation out of the shipped sources, and
//! named blocks let a list of optional fields or copies be written once and inserted where needed.

use std::collections::HashMap;

/// Keep or cut the `#if NAME` / `#else` / `#endif` blocks of a WGSL source: a block is kept when
/// `NAME` is among `defines` (`#if A||B`: when either is). Blocks nest. `#block NAME` … `#endblock`
/// (at the top level) names its lines, and `#insert NAME` after it stands for them, with their
/// `#if`s decided there. Cut lines become empty lines and an insert's lines are joined onto its one
/// line, so line numbers in naga's messages stay those of the files. Any other line starting with
/// `#` is an error.
pub fn preprocess(source: &str, defines: &[&str]) -> Result<String, String> {
    run(source, defines, &mut HashMap::new())
}

/// [`preprocess`] with the named blocks already known (an insert's lines may insert blocks).
fn run(source: &str, defines: &[&str], blocks: &mut HashMap<String, Vec<String>>) -> Result<String, String> {
    // Per open `#if`: (this branch is kept, the enclosing block is kept, line of the #if).
    let mut stack: Vec<(bool, bool, usize)> = Vec::new();
    // The named block being read: (name, its lines, line of the #block).
    let mut open: Option<(&str, Vec<String>, usize)> = None;
    let mut out = String::with_capacity(source.len());
    for (i, line) in source.lines().enumerate() {
        let at = i + 1;
        let t = line.trim();
        if let Some((name, lines, _)) = &mut open {
            match t {
                "#endblock" => {
                    blocks.insert(name.to_string(), std::mem::take(lines));
                    open = None;
                }
                _ if t.starts_with("#block") => return Err(format!("line {at}: #block inside block {name}")),
                _ => lines.push(line.to_string()),
            }
            out.push('\n');
            continue;
        }
        let keeping = stack.last().is_none_or(|b| b.0 && b.1);
        if let Some(rest) = t.strip_prefix('#') {
            let mut words = rest.split_whitespace();
            match (words.next(), words.next(), words.next()) {
                // `#if A||B`: kept when any of the names is defined.
                (Some("if"), Some(names), None) => {
                    stack.push((names.split("||").any(|n| defines.contains(&n)), keeping, at))
                }
                (Some("else"), None, None) => match stack.last_mut() {
                    Some(b) => b.0 = !b.0,
                    None => return Err(format!("line {at}: #else without #if")),
                },
                (Some("endif"), None, None) => {
                    if stack.pop().is_none() {
                        return Err(format!("line {at}: #endif without #if"));
                    }
                }
                (Some("block"), Some(name), None) if stack.is_empty() => open = Some((name, Vec::new(), at)),
                (Some("block"), Some(_), None) => return Err(format!("line {at}: #block inside #if")),
                (Some("endblock"), None, None) => return Err(format!("line {at}: #endblock without #block")),
                (Some("insert"), Some(name), None) => {
                    // Out of the map while it expands, so that a block inserting itself is an error.
                    let (key, lines) = blocks
                        .remove_entry(name)
                        .ok_or_else(|| format!("line {at}: #insert of unknown block {name}"))?;
                    let text = expand(&lines.join("\n"), defines, blocks);
                    blocks.insert(key, lines);
                    if keeping {
                        out += &text.map_err(|e| format!("line {at}: in block {name}: {e}"))?;
                    }
                }
                _ => {
                    return Err(format!(
                        "line {at}: unknown directive '{t}' (allowed: #if NAME, #else, #endif, #block NAME, \
                         #endblock, #insert NAME)"
                    ));
                }
            }
            out.push('\n');
            continue;
        }
        if keeping {
            out.push_str(line);
        }
        out.push('\n');
    }
    if let Some((name, _, at)) = open {
        return Err(format!("line {at}: #block {name} without #endblock"));
    }
    match stack.last() {
        Some(b) => Err(format!("line {}: #if without #endif", b.2)),
        None => Ok(out),
    }
}

/// A named block's kept lines on one line: comments dropped (they would run to the line's end).
fn expand(text: &str, defines: &[&str], blocks: &mut HashMap<String, Vec<String>>) -> Result<String, String> {
    let kept = run(text, defines, blocks)?;
    let code = kept.lines().map(|l| l.split("//").next().unwrap_or("").trim()).filter(|l| !l.is_empty());
    Ok(code.collect::<Vec<_>>().join(" "))
}
