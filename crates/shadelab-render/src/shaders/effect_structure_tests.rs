//! Tests that the WGSL holds the declared effects (`shadelab_model::effects::DECLARED`) and only
//! them: every define is a block in the WGSL and back, every permutation validates, and a
//! permutation without an effect has none of the functions or uniform members declared for it.

use super::tests::parse;
use super::validated_before;
use super::*;
use crate::sweep::{SWEEP_KERNEL, sweep_source};
use naga::valid::{Capabilities, ValidationFlags, Validator};
use shadelab_model::effects::{DECLARED, Effect};
use shadelab_model::{ShadingMode, SpecularModel};
use std::collections::{BTreeSet, HashSet};

fn validate(m: &naga::Module) -> naga::valid::ModuleInfo {
    Validator::new(ValidationFlags::all(), Capabilities::default()).validate(m).unwrap_or_else(|e| panic!("{e:?}"))
}

/// Every simulated effect's define opens a block (`#if EFFECT_…`) in the WGSL, and every block
/// the WGSL opens is a declared define.
#[test]
fn wgsl_blocks_are_the_declared_defines() {
    let raw = raw_lighting_source();
    let in_wgsl: BTreeSet<&str> =
        raw.lines().filter_map(|l| l.trim().strip_prefix("#if ")).flat_map(|n| n.trim().split("||")).collect();
    // The effects' defines, and the one derived from them (texture coordinates).
    let declared: BTreeSet<&str> =
        DECLARED.iter().filter_map(|d| d.define).chain([shadelab_model::effects::TEXTURE_COORDS]).collect();
    assert_eq!(in_wgsl, declared, "the WGSL's #if names against the declared defines");
    for d in DECLARED {
        assert_eq!(d.define.is_some(), Effect::ALL.contains(&d.effect), "{}", d.effect);
    }
    // The sweep's kernel is appended after preprocessing: it holds no blocks.
    assert!(SWEEP_KERNEL.lines().all(|l| !l.trim_start().starts_with('#')));
    let env_kernel = crate::sweep::environment::ENV_SWEEP_KERNEL;
    assert!(env_kernel.lines().all(|l| !l.trim_start().starts_with('#')));
}

/// The effects whose code is nested inside `EFFECT_CAST_SHADOWS` and reads nothing outside the
/// shadow code: the filters and the cascades.
const INSIDE_SHADOWS: [Effect; 4] =
    [Effect::ShadowFilterHard, Effect::ShadowFilterPcf, Effect::ShadowFilterPoisson, Effect::ShadowCascades];

/// The area lights' ways (area_lights.wgsl, area_points.wgsl, ltc.wgsl): reached only on the
/// point lights' path, so their subsets are validated on a few bases rather than multiplying the
/// rest.
const AREA: [Effect; 3] = [Effect::AreaLights, Effect::AreaPoints, Effect::AreaLtc];

/// The effects of a surface's texture and vertex colours (surface.wgsl), independent of the rest.
const SURFACE: [Effect; 7] = [
    Effect::NormalTexture,
    Effect::BaseColorTexture,
    Effect::VertexColors,
    Effect::MetalRoughnessTexture,
    Effect::OcclusionTexture,
    Effect::Emission,
    Effect::EmissiveTexture,
];

/// The transparent objects' effects (transmission.wgsl, glass.wgsl): only the glass pass's entry
/// points reach them, so their subsets are validated on a few bases.
const GLASS: [Effect; 3] = [Effect::Transmission, Effect::Refraction, Effect::Absorption];

/// The microfacet terms (microfacet.wgsl): reached only through Cook–Torrance's specular, so
/// their subsets are validated on a few bases.
const MICROFACET: [Effect; shadelab_model::effects::MICROFACET_EFFECTS.len()] =
    shadelab_model::effects::MICROFACET_EFFECTS;

/// Phong's normalization: one factor inside Phong specular's branch, validated on a few bases
/// rather than doubling the product of the rest.
const PHONG_OPTIONS: [Effect; 1] = [Effect::PhongNormalized];

/// The microfacet lobe's compensation (a factor inside Cook–Torrance's specular and a table read
/// in `shade`) and the Fresnel-weighted diffuse (a factor on the diffuse), validated on a few
/// bases.
const MS_OPTIONS: [Effect; 2] = [Effect::MultipleScattering, Effect::FresnelMix];

/// The environment's occlusion (one factor inside its diffuse term) and its background (a pass of
/// its own that reads the levels), validated on a few bases rather than multiplying the rest.
const ENV_OPTIONS: [Effect; 2] = [Effect::EnvironmentOcclusion, Effect::EnvironmentBackground];

/// The keys of every subset of `effects`.
fn subsets(effects: &[Effect]) -> Vec<EffectKey> {
    (0..1u32 << effects.len())
        .map(|bits| effects.iter().enumerate().filter(|(i, _)| bits & (1 << i) != 0).map(|(_, e)| *e).collect())
        .collect()
}

fn union(a: EffectKey, b: EffectKey) -> EffectKey {
    b.effects().into_iter().fold(a, |k, e| k.with(e))
}

/// Every subset of `group` on each of `bases` (each base without `group`'s own effects first).
fn subsets_on(group: &[Effect], bases: &[EffectKey]) -> Vec<EffectKey> {
    let subsets = subsets(group);
    bases
        .iter()
        .flat_map(|&base| {
            let base = group.iter().fold(base, |k, &e| k.without(e));
            subsets.iter().map(move |&k| union(k, base))
        })
        .collect()
}

/// Every permutation validates in naga with every entry point: all 2^n subsets of the effects
/// outside the shadow, area and surface code (with the shadow sub-effects all on), and every
/// subset of the shadow sub-effects, the area effects and the surface effects on a few bases (their code is nested in the shadow block, so the full product
/// would only repeat these).
#[test]
fn every_permutation_validates_in_naga() {
    let raw = raw_lighting_source();
    let keys = permutation_keys();
    // Keys whose effects are nested in an effect that is off preprocess to the same source:
    // each distinct source (with the two entry points a key decides) is validated once, which
    // checks what every key would. Sources are compared by hash, so they need not all be held;
    // the keys are preprocessed and hashed on every core, in order.
    let raw = &raw;
    let hashed = on_every_core(&keys, |key| {
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        std::hash::Hash::hash(&lighting_source_for(raw, key).unwrap(), &mut hasher);
        let decided = (key.has(Effect::Transmission), key.has(Effect::EnvironmentBackground));
        (std::hash::Hasher::finish(&hasher), decided)
    });
    let mut seen = HashSet::new();
    let distinct: Vec<(EffectKey, ModuleHash)> =
        keys.into_iter().zip(hashed).filter(|(_, h)| seen.insert(*h)).collect();
    // A module an earlier run checked, with the same source, entry points, naga and checks, is
    // not checked again (validated_before.rs); a fresh build checks every one.
    let (todo, passed) = not_checked_before(&distinct);
    // On every core: parsing and validating each module is most of the suite's longest test.
    on_every_core(&todo, |key| permutation_is_valid(key, &lighting_source_for(raw, key).unwrap()));
    validated_before::store(&passed);
    // The terms alone, and the sweep's compute module, are valid too.
    validate(&parse(&terms_source()));
    validate(&parse(&sweep_source()));
    validate(&parse(&crate::sweep::environment::env_sweep_source()));
}

/// A lighting module's source hash and what its key decides (transmission, the background).
type ModuleHash = (u64, (bool, bool));

/// The keys of `distinct` whose checks no earlier run passed, and every key's check (the record
/// once all of them pass).
fn not_checked_before(distinct: &[(EffectKey, ModuleHash)]) -> (Vec<EffectKey>, HashSet<u64>) {
    let digest = validated_before::checks_digest(include_str!("effect_structure_tests.rs"));
    let check = |(key, module): &(EffectKey, ModuleHash)| {
        // The entry points' names the check compares with, whether the key needs them or not.
        let names = (crate::environment_gpu::BACKGROUND_ENTRY_POINTS, crate::glass_pass::GLASS_ENTRY_POINTS);
        validated_before::check_hash(digest, (module, required_entry_points(*key), names))
    };
    let before = validated_before::load();
    let todo: Vec<EffectKey> = distinct.iter().filter(|k| !before.contains(&check(k))).map(|(k, _)| *k).collect();
    eprintln!(
        "{} distinct modules: {} checked now, {} passed the same checks in an earlier run",
        distinct.len(),
        todo.len(),
        distinct.len() - todo.len()
    );
    (todo, distinct.iter().map(check).collect())
}

/// The effect keys the permutations' test covers (many preprocess to the same module).
fn permutation_keys() -> Vec<EffectKey> {
    let outside: Vec<Effect> = Effect::ALL
        .into_iter()
        .filter(|e| {
            let groups =
                [&INSIDE_SHADOWS[..], &SURFACE, &AREA, &GLASS, &MICROFACET, &PHONG_OPTIONS, &MS_OPTIONS, &ENV_OPTIONS];
            !groups.iter().any(|group| group.contains(e))
        })
        .collect();
    let all_inside: EffectKey = INSIDE_SHADOWS.into_iter().collect();
    let mut keys: Vec<EffectKey> = subsets(&outside).into_iter().map(|k| union(k, all_inside)).collect();
    let bases: [EffectKey; 3] = [
        EffectKey::UBER,
        [Effect::CastShadows, Effect::DirectionalLights].into_iter().collect(),
        [Effect::CastShadows, Effect::PointLights, Effect::SpotLights].into_iter().collect(),
    ];
    keys.extend(subsets_on(&INSIDE_SHADOWS, &bases));
    // The area effects on every other effect, none, a shadowed point light, and the chapter's
    // other models (each sample of the light loop goes through them).
    let area_bases: [EffectKey; 4] = [
        EffectKey::UBER,
        EffectKey::NONE,
        [Effect::PointLights, Effect::CastShadows, Effect::ShadowFilterPcf, Effect::ShadowFilterPcss]
            .into_iter()
            .collect(),
        [Effect::PointLights, Effect::LambertRule, Effect::FourTermSum, Effect::TransmittedTerm].into_iter().collect(),
    ];
    keys.extend(subsets_on(&AREA, &area_bases));
    // The surface effects touch only surface.wgsl and Phong shading's interpolants: each of
    // their subsets with every other effect on, and with none.
    keys.extend(subsets_on(&SURFACE, &[EffectKey::UBER, EffectKey::NONE]));
    // The glass effects on every other effect, none, shadows with a point light, the surface
    // effects, and an area light (the glass pass shades its surface with the whole light loop).
    let glass_bases: [EffectKey; 5] = [
        EffectKey::UBER,
        EffectKey::NONE,
        [Effect::PointLights, Effect::CastShadows, Effect::ShadowFilterPcf].into_iter().collect(),
        SURFACE.into_iter().collect(),
        [Effect::PointLights, Effect::AreaLights, Effect::SpecularCookTorrance].into_iter().collect(),
    ];
    keys.extend(subsets_on(&GLASS, &glass_bases));
    // The microfacet terms on every other effect, on Cook–Torrance alone, and with glass (whose
    // Fresnel is the exact F's function).
    let microfacet_bases: [EffectKey; 3] = [
        EffectKey::UBER,
        [Effect::PointLights, Effect::SpecularCookTorrance].into_iter().collect(),
        [Effect::DirectionalLights, Effect::SpecularCookTorrance, Effect::Transmission].into_iter().collect(),
    ];
    keys.extend(subsets_on(&MICROFACET, &microfacet_bases));
    // Phong's normalization on every other effect, on Phong specular alone, and on none.
    let phong_bases: [EffectKey; 3] =
        [EffectKey::UBER, [Effect::PointLights, Effect::SpecularPhong].into_iter().collect(), EffectKey::NONE];
    keys.extend(subsets_on(&PHONG_OPTIONS, &phong_bases));
    // Both on every other effect, on glTF's terms with the diffuse, and on none.
    let ms_bases: [EffectKey; 3] = [
        EffectKey::UBER,
        [
            Effect::PointLights,
            Effect::Diffuse,
            Effect::SpecularCookTorrance,
            Effect::DistributionGgx,
            Effect::MaskingSmithCorrelated,
            Effect::FresnelSchlick,
        ]
        .into_iter()
        .collect(),
        EffectKey::NONE,
    ];
    keys.extend(subsets_on(&MS_OPTIONS, &ms_bases));
    // These on every other effect, on the environment's diffuse alone, and on none.
    let env_bases: [EffectKey; 3] =
        [EffectKey::UBER, [Effect::DirectionalLights, Effect::EnvironmentSh].into_iter().collect(), EffectKey::NONE];
    keys.extend(subsets_on(&ENV_OPTIONS, &env_bases));
    keys
}

/// `f` of every key, the keys cut into one run a core, the results in the keys' order.
fn on_every_core<T: Send>(keys: &[EffectKey], f: impl Fn(EffectKey) -> T + Sync) -> Vec<T> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let chunk = keys.len().div_ceil(threads).max(1);
    let f = &f;
    std::thread::scope(|scope| {
        let parts: Vec<_> = keys
            .chunks(chunk)
            .map(|part| scope.spawn(move || part.iter().map(|&k| f(k)).collect::<Vec<T>>()))
            .collect();
        parts.into_iter().flat_map(|p| p.join().expect("a permutation's check panicked")).collect()
    })
}

/// `src`, the lighting module of `key`, parses and validates, and holds the entry points of every
/// shading mode, the baseline's, and the glass pass's and the background's where `key` has them.
fn permutation_is_valid(key: EffectKey, src: &str) {
    let module =
        naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("{}: {}", key.label(), e.emit_to_string(src)));
    validate(&module);
    let background = module.entry_points.iter().any(|e| e.name == crate::environment_gpu::BACKGROUND_ENTRY_POINTS.1);
    assert_eq!(background, key.has(Effect::EnvironmentBackground), "{}: the background's entry point", key.label());
    let glass = module.entry_points.iter().any(|e| e.name == crate::glass_pass::GLASS_ENTRY_POINTS.1);
    assert_eq!(glass, key.has(Effect::Transmission), "{}: the glass pass's entry point", key.label());
    for (vs, fs) in required_entry_points(key) {
        assert!(module.entry_points.iter().any(|e| e.name == vs) && module.entry_points.iter().any(|e| e.name == fs));
    }
}

/// The entry points `key`'s module must hold: every shading mode's, the baseline's, and the glass
/// pass's where it has transmission.
fn required_entry_points(key: EffectKey) -> Vec<(&'static str, &'static str)> {
    let mut eps: Vec<(&str, &str)> = ShadingMode::ALL_MODES.into_iter().map(entry_points).collect();
    eps.push(BASELINE_ENTRY_POINTS);
    if key.has(Effect::Transmission) {
        eps.extend([crate::glass_pass::GLASS_ENTRY_POINTS, crate::glass_pass::BACK_ENTRY_POINTS]);
    }
    eps
}

/// Functions reachable by calls from an entry point.
fn reachable(module: &naga::Module, ep: &str) -> HashSet<naga::Handle<naga::Function>> {
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
    let mut seen = HashSet::new();
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

/// The structural proof: in the module of a permutation without an effect, as naga sees it
/// after specialization, no shading entry point reaches the functions declared for the effect or
/// reads the uniform members declared for it; with the effect, they do (so the check can fail).
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
                let (_, fs) = entry_points(shading);
                // Flat and Gouraud light in their compute passes, Phong in the fragment stage.
                let ep = match shading {
                    ShadingMode::Flat => crate::lighting_pass::FLAT_ENTRY_POINT,
                    ShadingMode::Gouraud => crate::lighting_pass::GOURAUD_ENTRY_POINT,
                    ShadingMode::Phong => fs,
                };
                // A per-vertex mode tints C in its fragment stage: both stages count. The glass
                // pass shades per pixel in every mode: its stage counts for Phong shading and, in
                // the other modes, for the glass effects.
                let mut eps = if ep == fs { vec![ep] } else { vec![ep, fs] };
                let glass_ep = crate::glass_pass::GLASS_ENTRY_POINTS.1;
                if module.entry_points.iter().any(|x| x.name == glass_ep)
                    && (shading == ShadingMode::Phong || GLASS.contains(&e))
                {
                    eps.push(glass_ep);
                }
                // The background is its own pass: its stage counts for its effect.
                let background_ep = crate::environment_gpu::BACKGROUND_ENTRY_POINTS.1;
                if e == Effect::EnvironmentBackground && module.entry_points.iter().any(|x| x.name == background_ep) {
                    eps.push(background_ep);
                }
                let called: Vec<String> = eps
                    .iter()
                    .flat_map(|ep| reachable(&module, ep))
                    .filter_map(|f| module.functions[f].name.clone())
                    .collect();
                // The metallic–roughness and occlusion textures vary per-pixel lighting: the
                // per-vertex modes never reach them, even in a permutation that has them.
                let present =
                    present && (shading == ShadingMode::Phong || !crate::program::PER_PIXEL_LIGHTING.contains(&e));
                for f in e.functions() {
                    assert_eq!(called.iter().any(|c| c == f), present, "{} {ep}: call to {f}", key.label());
                }
                let read: Vec<(String, String)> = eps.iter().flat_map(|ep| members_read(&module, &info, ep)).collect();
                for (st, m) in e.members() {
                    let found = read.iter().any(|(a, b)| a == st && b == m);
                    assert_eq!(found, present, "{} {ep}: {st}.{m} read = {found}", key.label());
                }
            }
        }
    }
}

/// The exact F declares no function (the glass shares `fresnel_dielectric`), so its own check: in
/// an opaque Cook–Torrance permutation, the specular reaches `fresnel_dielectric` exactly when
/// the exact F is in, and `fresnel_schlick` exactly when Schlick's is.
#[test]
fn the_exact_fresnel_is_reached_only_with_its_effect() {
    let raw = raw_lighting_source();
    let base: EffectKey =
        [Effect::PointLights, Effect::SpecularCookTorrance, Effect::DistributionGgx].into_iter().collect();
    for (exact, schlick) in [(true, false), (false, true), (true, true), (false, false)] {
        let mut key = base;
        if exact {
            key = key.with(Effect::FresnelExact);
        }
        if schlick {
            key = key.with(Effect::FresnelSchlick);
        }
        let module = parse(&lighting_source_for(&raw, key).unwrap());
        let (_, fs) = entry_points(ShadingMode::Phong);
        let called: Vec<String> =
            reachable(&module, fs).into_iter().filter_map(|f| module.functions[f].name.clone()).collect();
        assert_eq!(called.iter().any(|f| f == "fresnel_dielectric"), exact, "{}", key.label());
        assert_eq!(called.iter().any(|f| f == "fresnel_schlick"), schlick, "{}", key.label());
        assert!(called.iter().any(|f| f == "d_ggx") && !called.iter().any(|f| f == "d_beckmann"), "{}", key.label());
    }
}

/// Cast shadows beyond functions and members: a permutation without them has no shadow-map
/// binding (no global in @group(2) or @group(3), no depth texture, no comparison sampler), no
/// depth-compare sample and no shadow-pass entry point; with them it has all of these.
#[test]
fn a_permutation_without_cast_shadows_has_no_shadow_bindings() {
    let raw = raw_lighting_source();
    for (key, present) in
        [(EffectKey::UBER, true), (EffectKey::UBER.without(Effect::CastShadows), false), (EffectKey::NONE, false)]
    {
        let module = parse(&lighting_source_for(&raw, key).unwrap());
        // Flat shading's per-face bindings (@group(3), 1–3) are in every permutation, the glass
        // pass's (8–11) in every permutation with transparent objects.
        let groups: Vec<u32> = module
            .global_variables
            .iter()
            .filter_map(|(_, g)| g.binding.as_ref())
            .filter(|b| !(b.group == 3 && ((1..=3).contains(&b.binding) || (8..=11).contains(&b.binding))))
            .map(|b| b.group)
            .collect();
        assert_eq!(groups.iter().any(|g| *g >= 2), present, "{}: groups {groups:?}", key.label());
        assert_eq!(groups.iter().max().copied().unwrap_or(0) <= 1, !present, "{}", key.label());
        let depth = module.types.iter().any(|(_, t)| {
            matches!(t.inner, naga::TypeInner::Image { class: naga::ImageClass::Depth { .. }, .. })
                || matches!(t.inner, naga::TypeInner::Sampler { comparison: true })
        });
        assert_eq!(depth, present, "{}: depth texture or comparison sampler", key.label());
        let compares = module
            .functions
            .iter()
            .flat_map(|(_, f)| f.expressions.iter())
            .chain(module.entry_points.iter().flat_map(|e| e.function.expressions.iter()))
            .any(|(_, e)| matches!(e, naga::Expression::ImageSample { depth_ref: Some(_), .. }));
        assert_eq!(compares, present, "{}: depth-compare samples", key.label());
        assert_eq!(module.entry_points.iter().any(|e| e.name == "vs_shadow"), present, "{}", key.label());
    }
}

/// Flat and Gouraud shading evaluate the model in their lighting passes only: `cs_flat` and
/// `cs_gouraud` reach `shade`, their vertex and fragment stages (both interpolations) do not.
#[test]
fn per_vertex_modes_shade_in_their_lighting_passes_only() {
    use crate::lighting_pass::{FLAT_ENTRY_POINT, GOURAUD_ENTRY_POINT};
    let module = parse(&lighting_source_for(&raw_lighting_source(), EffectKey::UBER).unwrap());
    let calls = |ep: &str| -> bool {
        reachable(&module, ep).into_iter().any(|f| module.functions[f].name.as_deref() == Some("shade"))
    };
    assert!(calls(FLAT_ENTRY_POINT) && calls(GOURAUD_ENTRY_POINT));
    for shading in [ShadingMode::Flat, ShadingMode::Gouraud] {
        for interpolation in [shadelab_model::Interpolation::Perspective, shadelab_model::Interpolation::Screen] {
            let (vs, fs) = crate::shaders::entry_points_with(shading, interpolation);
            assert!(!calls(vs) && !calls(fs), "{vs} or {fs} shades");
        }
    }
    let (_, phong) = entry_points(ShadingMode::Phong);
    assert!(calls(phong), "the check can fail: Phong shading shades in its fragment stage");
}

/// The texture coordinates belong to no one texture: a permutation holds them (the transform,
/// the guarded sample, the interpolant) exactly when it samples some texture.
#[test]
fn texture_coordinates_only_where_a_texture_is_sampled() {
    use shadelab_model::effects::TEXTURE_EFFECTS;
    let raw = raw_lighting_source();
    let without = EffectKey::UBER.without_all(&TEXTURE_EFFECTS);
    let mut keys = vec![(EffectKey::UBER, true), (without, false), (EffectKey::NONE, false)];
    keys.extend(TEXTURE_EFFECTS.map(|e| (without.with(e), true)));
    for (key, present) in keys {
        let module = parse(&lighting_source_for(&raw, key).unwrap());
        let has = |name: &str| module.functions.iter().any(|(_, f)| f.name.as_deref() == Some(name));
        assert_eq!(has("texture_uv") && has("sample_slot"), present, "{}", key.label());
        let interpolant = module.types.iter().any(|(_, t)| match &t.inner {
            naga::TypeInner::Struct { members, .. } => members.iter().any(|m| m.name.as_deref() == Some("uv")),
            _ => false,
        });
        assert_eq!(interpolant, present, "{}: a uv interpolant", key.label());
    }
}
