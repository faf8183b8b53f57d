//! The WGSL sources under `shaders/`, compiled into the binary and assembled in dependency order.
//!
//! The renderer, the naga validation tests and the stability sweep all use these same files.

use shadelab_model::effects::EffectKey;

/// `(file name, source)` in the order they are concatenated.
pub const FILES: [(&str, &str); 4] = [
    ("common.wgsl", include_str!("../../../shaders/common.wgsl")),
    ("brdf.wgsl", include_str!("../../../shaders/brdf.wgsl")),
    ("lights.wgsl", include_str!("../../../shaders/lights.wgsl")),
    ("shading.wgsl", include_str!("../../../shaders/shading.wgsl")),
];

/// Keep or cut the `#if NAME` / `#else` / `#endif` blocks of a WGSL source: a block is kept when
/// `NAME` is among `defines`. Blocks nest. Cut lines become empty lines, so line numbers in
/// naga's messages stay those of the files. Any other line starting with `#` is an error.
pub fn preprocess(source: &str, defines: &[&str]) -> Result<String, String> {
    // Per open block: (this branch is kept, the enclosing block is kept, line of the #if).
    let mut stack: Vec<(bool, bool, usize)> = Vec::new();
    let mut out = String::with_capacity(source.len());
    for (i, line) in source.lines().enumerate() {
        let t = line.trim();
        let keeping = stack.last().is_none_or(|b| b.0 && b.1);
        if let Some(rest) = t.strip_prefix('#') {
            let mut words = rest.split_whitespace();
            match (words.next(), words.next(), words.next()) {
                (Some("if"), Some(name), None) => stack.push((defines.contains(&name), keeping, i + 1)),
                (Some("else"), None, None) => match stack.last_mut() {
                    Some(b) => b.0 = !b.0,
                    None => return Err(format!("line {}: #else without #if", i + 1)),
                },
                (Some("endif"), None, None) => {
                    if stack.pop().is_none() {
                        return Err(format!("line {}: #endif without #if", i + 1));
                    }
                }
                _ => return Err(format!("line {}: unknown directive '{t}' (allowed: #if NAME, #else, #endif)", i + 1)),
            }
            out.push('\n');
            continue;
        }
        if keeping {
            out.push_str(line);
        }
        out.push('\n');
    }
    match stack.last() {
        Some(b) => Err(format!("line {}: #if without #endif", b.2)),
        None => Ok(out),
    }
}

fn uber_defines() -> Vec<&'static str> {
    EffectKey::UBER.defines()
}

/// Constants, guards and the lighting terms with every effect, without bindings or entry points
/// (for compute passes that evaluate the terms directly).
pub fn terms_source() -> String {
    let raw = FILES[..3].iter().map(|(_, s)| *s).collect::<Vec<_>>().join("\n");
    preprocess(&raw, &uber_defines()).expect("the shipped WGSL preprocesses")
}

/// The stability sweep's kernel (`shaders/sweep.wgsl`), appended to the terms.
pub const SWEEP_KERNEL: &str = include_str!("../../../shaders/sweep.wgsl");

/// The sweep's compute module: the shipped terms followed by the kernel.
pub fn sweep_source() -> String {
    format!("{}\n{}", terms_source(), SWEEP_KERNEL)
}

/// The renderer's WGSL as shipped, before preprocessing.
pub fn raw_lighting_source() -> String {
    FILES.iter().map(|(_, s)| *s).collect::<Vec<_>>().join("\n")
}

/// The renderer module of one effect permutation: terms plus the shading entry points, holding
/// only the effects of `key`.
pub fn lighting_source_for(raw: &str, key: EffectKey) -> Result<String, String> {
    preprocess(raw, &key.defines())
}

/// The shipped renderer module with every effect (the "uber" permutation).
pub fn lighting_source() -> String {
    lighting_source_for(&raw_lighting_source(), EffectKey::UBER).expect("the shipped WGSL preprocesses")
}

/// Check a raw (unpreprocessed) renderer source: it preprocesses, and its permutation with every
/// effect and the one with none both validate in naga (hot reload runs this before using it).
pub fn validate_raw(raw: &str) -> Result<(), String> {
    for key in [EffectKey::UBER, EffectKey::NONE] {
        validate(&lighting_source_for(raw, key)?)?;
    }
    Ok(())
}

/// Parse and validate a WGSL module with naga; the error is naga's own message, with the
/// offending line shown.
pub fn validate(source: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
        .validate(&module)
        .map_err(|e| e.emit_to_string(source))?;
    Ok(())
}

/// The renderer's raw WGSL read from a folder holding the files of [`FILES`] (hot reload).
pub fn read_lighting_source(dir: &std::path::Path) -> std::io::Result<String> {
    let mut parts = Vec::new();
    for (name, _) in FILES {
        parts.push(std::fs::read_to_string(dir.join(name))?);
    }
    Ok(parts.join("\n"))
}

/// The newest modification time among those files (to notice an edit).
pub fn newest_change(dir: &std::path::Path) -> Option<std::time::SystemTime> {
    FILES.iter().filter_map(|(name, _)| std::fs::metadata(dir.join(name)).and_then(|m| m.modified()).ok()).max()
}

/// Entry points of a shading mode: (vertex, fragment).
pub fn entry_points(mode: shadelab_model::ShadingMode) -> (&'static str, &'static str) {
    use shadelab_model::ShadingMode::*;
    match mode {
        Flat => ("vs_flat", "fs_flat"),
        Gouraud => ("vs_gouraud", "fs_gouraud"),
        Phong => ("vs_phong", "fs_phong"),
    }
}

/// Entry points of the null-shader baseline (constant colour): (vertex, fragment).
pub const BASELINE_ENTRY_POINTS: (&str, &str) = ("vs_baseline", "fs_baseline");

/// The value of `globals.specular_model` (SPECULAR_PHONG or SPECULAR_COOK_TORRANCE) for a model.
pub fn specular_constant(model: shadelab_model::SpecularModel) -> u32 {
    match model {
        shadelab_model::SpecularModel::Phong => 0,
        shadelab_model::SpecularModel::CookTorrance => 1,
    }
}

#[cfg(test)]
mod tests {
    //! Plain unit tests (no GPU): every permutation validates in naga, the uniform structs'
    //! layouts and the numerical guards are the same in WGSL and Rust.
    use super::*;
    use crate::uniforms::{GlobalsUniform, LightUniform, ObjectUniform};
    use naga::valid::{Capabilities, ValidationFlags, Validator};
    use shadelab_model::effects::Effect;
    use shadelab_model::{ShadingMode, SpecularModel};
    use std::mem::offset_of;

    fn parse(src: &str) -> naga::Module {
        naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("{}", e.emit_to_string(src)))
    }

    fn validate(m: &naga::Module) -> naga::valid::ModuleInfo {
        Validator::new(ValidationFlags::all(), Capabilities::default()).validate(m).unwrap_or_else(|e| panic!("{e:?}"))
    }

    /// Every effect permutation (2^8) × every entry point validates in naga.
    #[test]
    fn every_permutation_validates_in_naga() {
        let raw = raw_lighting_source();
        for bits in 0..(1u32 << Effect::ALL.len()) {
            let mut key = EffectKey::UBER;
            for (i, e) in Effect::ALL.into_iter().enumerate() {
                if bits & (1 << i) == 0 {
                    key = key.without(e);
                }
            }
            let src = lighting_source_for(&raw, key).unwrap();
            let module = naga::front::wgsl::parse_str(&src)
                .unwrap_or_else(|e| panic!("{}: {}", key.label(), e.emit_to_string(&src)));
            validate(&module);
            let mut eps: Vec<(&str, &str)> = ShadingMode::ALL_MODES.into_iter().map(entry_points).collect();
            eps.push(BASELINE_ENTRY_POINTS);
            for (vs, fs) in eps {
                assert!(
                    module.entry_points.iter().any(|e| e.name == vs)
                        && module.entry_points.iter().any(|e| e.name == fs)
                );
            }
        }
        // The terms alone, and the sweep's compute module, are valid too.
        validate(&parse(&terms_source()));
        validate(&parse(&sweep_source()));
    }

    #[test]
    fn preprocessor_keeps_and_cuts_blocks() {
        let src = "a\n#if X\nb\n#if Y\nc\n#else\nd\n#endif\n#else\ne\n#endif\nf";
        let lines = |defs: &[&str]| -> Vec<String> {
            preprocess(src, defs).unwrap().lines().filter(|l| !l.is_empty()).map(String::from).collect()
        };
        assert_eq!(lines(&[]), ["a", "e", "f"]);
        assert_eq!(lines(&["X"]), ["a", "b", "d", "f"]);
        assert_eq!(lines(&["X", "Y"]), ["a", "b", "c", "f"]);
        assert_eq!(lines(&["Y"]), ["a", "e", "f"]);
        // Line numbers are kept.
        assert_eq!(preprocess(src, &[]).unwrap().lines().count(), src.lines().count());
        assert!(preprocess("#if X\n", &[]).unwrap_err().contains("line 1: #if without #endif"));
        assert!(preprocess("#endif\n", &[]).unwrap_err().contains("#endif without #if"));
        assert!(preprocess("#else\n", &[]).unwrap_err().contains("#else without #if"));
        assert!(preprocess("#ifdef X\n#endif", &[]).unwrap_err().contains("unknown directive"));
    }

    /// Functions reachable by calls from an entry point.
    fn reachable(module: &naga::Module, ep: &str) -> std::collections::HashSet<naga::Handle<naga::Function>> {
        fn walk(block: &naga::Block, out: &mut Vec<naga::Handle<naga::Function>>) {
            for st in block.iter() {
                match st {
                    naga::Statement::Call { function, .. } => out.push(*function),
                    naga::Statement::Block(b) => walk(b, out),
                    naga::Statement::If { accept, reject, .. } => {
                        walk(accept, out);
                        walk(reject, out);
                    }
                    naga::Statement::Loop { body, continuing, .. } => {
                        walk(body, out);
                        walk(continuing, out);
                    }
                    naga::Statement::Switch { cases, .. } => cases.iter().for_each(|c| walk(&c.body, out)),
                    _ => {}
                }
            }
        }
        let entry = module.entry_points.iter().find(|e| e.name == ep).unwrap();
        let mut todo = Vec::new();
        walk(&entry.function.body, &mut todo);
        let mut seen = std::collections::HashSet::new();
        while let Some(f) = todo.pop() {
            if seen.insert(f) {
                walk(&module.functions[f].body, &mut todo);
            }
        }
        seen
    }

    /// `(struct, member)` pairs read by the entry point or a function it reaches.
    fn members_read(module: &naga::Module, info: &naga::valid::ModuleInfo, ep: &str) -> Vec<(String, String)> {
        let mut out = Vec::new();
        let mut visit = |f: &naga::Function, fi: &naga::valid::FunctionInfo| {
            for (_, e) in f.expressions.iter() {
                if let naga::Expression::AccessIndex { base, index } = *e {
                    let mut ty = fi[base].ty.inner_with(&module.types);
                    if let naga::TypeInner::Pointer { base, .. } = ty {
                        ty = &module.types[*base].inner;
                    }
                    if let naga::TypeInner::Struct { members, .. } = ty {
                        let name = module.types.iter().find(|(_, t)| &t.inner == ty).and_then(|(_, t)| t.name.clone());
                        if let (Some(n), Some(m)) = (name, members.get(index as usize).and_then(|m| m.name.clone())) {
                            out.push((n, m));
                        }
                    }
                }
            }
        };
        let (i, entry) = module.entry_points.iter().enumerate().find(|(_, e)| e.name == ep).unwrap();
        visit(&entry.function, info.get_entry_point(i));
        for f in reachable(module, ep) {
            visit(&module.functions[f], &info[f]);
        }
        out
    }

    /// Uniform members only one effect reads.
    fn effect_members(e: Effect) -> &'static [(&'static str, &'static str)] {
        match e {
            Effect::Ambient => &[("Globals", "ambient")],
            Effect::DirectionalLights => &[("Light", "direction")],
            Effect::PointLights => &[("Light", "position")],
            Effect::FalloffQuadratic => &[("Light", "falloff_alpha")],
            Effect::FalloffLinear => &[("Light", "d0")],
            Effect::SpotLights => &[("Light", "spot_axis"), ("Light", "cos_inner"), ("Light", "cos_outer")],
            Effect::LightRange => &[("Light", "range")],
            Effect::SpecularCookTorrance => &[("Object", "mu")],
            // r_d, h and mirror are passed to light_contribution in every permutation (unused
            // there without the effect): their functions are the proof for these two.
            Effect::Diffuse | Effect::SpecularPhong => &[],
        }
    }

    /// The structural proof: in the module of a permutation without an effect, as naga sees it
    /// after specialization, no shading entry point reaches the effect's functions or reads the
    /// uniform members only it uses; with the effect, they do (so the check can fail).
    #[test]
    fn a_permutation_without_an_effect_has_no_code_for_it() {
        let raw = raw_lighting_source();
        let scene = shadelab_model::Scene::builtin("default").unwrap();
        let specialized = shadelab_model::effects::analyze(&scene, SpecularModel::Phong).key;
        for e in Effect::ALL {
            let mut keys = vec![(EffectKey::UBER, true), (EffectKey::UBER.without(e), false)];
            if specialized.has(e) {
                keys.push((specialized.without(e), false));
            }
            for (key, present) in keys {
                let src = lighting_source_for(&raw, key).unwrap();
                let module = parse(&src);
                let info = validate(&module);
                for shading in ShadingMode::ALL_MODES {
                    let (vs, fs) = entry_points(shading);
                    // Flat and Gouraud light in the vertex stage, Phong in the fragment stage.
                    let ep = if shading == ShadingMode::Phong { fs } else { vs };
                    let called: Vec<String> =
                        reachable(&module, ep).into_iter().filter_map(|f| module.functions[f].name.clone()).collect();
                    for f in e.functions() {
                        assert_eq!(called.iter().any(|c| c == f), present, "{} {ep}: call to {f}", key.label());
                    }
                    let read = members_read(&module, &info, ep);
                    for (st, m) in effect_members(e) {
                        let found = read.iter().any(|(a, b)| a == st && b == m);
                        assert_eq!(found, present, "{} {ep}: {st}.{m} read = {found}", key.label());
                    }
                }
            }
        }
    }

    /// (size, [(field, offset)]) of a WGSL struct as naga lays it out.
    fn wgsl_layout(module: &naga::Module, name: &str) -> (u32, Vec<(String, u32)>) {
        let ty = module.types.iter().find(|(_, t)| t.name.as_deref() == Some(name)).unwrap_or_else(|| panic!("{name}"));
        match &ty.1.inner {
            naga::TypeInner::Struct { members, span } => {
                (*span, members.iter().map(|m| (m.name.clone().unwrap(), m.offset)).collect())
            }
            _ => panic!("{name} is not a struct"),
        }
    }

    macro_rules! rust_layout {
        ($t:ty: $($f:ident),*) => {
            (size_of::<$t>() as u32, vec![$((stringify!($f).to_string(), offset_of!($t, $f) as u32)),*])
        };
    }

    #[test]
    fn uniform_layouts_match_wgsl() {
        let module = parse(&lighting_source());
        assert_eq!(
            wgsl_layout(&module, "Light"),
            rust_layout!(LightUniform: position, direction, radiance, kind, falloff_form, falloff_alpha, d0, spot_axis, cos_inner, cos_outer, range, _pad)
        );
        assert_eq!(
            wgsl_layout(&module, "Globals"),
            rust_layout!(GlobalsUniform: view_proj, camera_pos, ambient, light_count, flags, specular_model, _pad1, lights)
        );
        assert_eq!(
            wgsl_layout(&module, "Object"),
            rust_layout!(ObjectUniform: model, normal_matrix, color, mu, r_s, r_d, r_a, m, h, mirror, _pad0, _pad1)
        );
    }

    /// The value of a named `const` in the module, as f64.
    pub(crate) fn wgsl_constant(module: &naga::Module, name: &str) -> Option<f64> {
        let (_, c) = module.constants.iter().find(|(_, c)| c.name.as_deref() == Some(name))?;
        match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::F32(v)) => Some(v as f64),
            naga::Expression::Literal(naga::Literal::U32(v)) => Some(v as f64),
            naga::Expression::Literal(naga::Literal::AbstractFloat(v)) => Some(v),
            ref e => panic!("{name}: unexpected initializer {e:?}"),
        }
    }

    #[test]
    fn wgsl_guards_equal_rust_guards() {
        let module = parse(&terms_source());
        for (name, value) in shadelab_model::guards::ALL {
            let w = wgsl_constant(&module, name).unwrap_or_else(|| panic!("{name} missing from common.wgsl"));
            assert_eq!(w as f32, *value as f32, "{name}: WGSL {w} vs Rust {value}");
        }
        assert_eq!(wgsl_constant(&module, "MAX_LIGHTS"), Some(shadelab_model::scene::MAX_LIGHTS as f64));
        // globals.specular_model is compared with these constants.
        for (name, model) in
            [("SPECULAR_PHONG", SpecularModel::Phong), ("SPECULAR_COOK_TORRANCE", SpecularModel::CookTorrance)]
        {
            assert_eq!(wgsl_constant(&module, name), Some(specular_constant(model) as f64), "{name}");
        }
    }
}
