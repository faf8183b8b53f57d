//! Materials: glTF's metallic–roughness fields and the `KHR_materials_ior`, `_specular`,
//! `_transmission` and `_volume` extensions mapped to the chapter's material (the table in the
//! module's parent), and back; the exact parameters travel in `extras.shadelab`.

use super::extras::{self, Absorption, Flag, Ior, Mu, Named, Num, Phong, Rgb, Roughness, Thickness, Unit};
use super::scene_file::{Reader, num, rgb};
use super::{ATTENUATION_COLOR_MIN, DEFAULT_IOR, DIELECTRIC_MU_MAX, GltfError, dielectric_f0, m_from_roughness};
use crate::lighting::microfacet::{Distribution, Fresnel, Masking, Microfacet};
use crate::params::PhongExponent;
use crate::scene::{FresnelMix, Material, MetalRoughnessMap, NormalMap, OcclusionMap, Scene};
use gltf::json;
use gltf::json::validation::Checked;
use serde_json::{Value, json};

/// An index of refraction this close to glTF's default is not written (`KHR_materials_ior`
/// left out).
const IOR_DEFAULT_TOLERANCE: f64 = 1e-9;
/// μ channels this close are one grey μ (no `KHR_materials_specular` colour written).
const MU_GREY_TOLERANCE: f64 = 1e-12;

super::extras_struct! {
    /// `extras.shadelab` of a material: every parameter of the chapter's material, exactly (fields in
    /// the order they are checked).
    struct MaterialExtras {
        /// Diffuse colour C.
        #[serde(rename = "C")]
        color: Option<Rgb<Unit>>,
        m: Option<Num<Roughness>>,
        h: Option<Phong>,
        mu: Option<Rgb<Mu>>,
        r_s: Option<Num<Unit>>,
        r_d: Option<Num<Unit>>,
        r_a: Option<Num<Unit>>,
        /// Transmission t.
        t: Option<Num<Unit>>,
        /// Absorption a per channel.
        a: Option<Rgb<Absorption>>,
        /// Thickness d.
        d: Option<Num<Thickness>>,
        /// The part of μ the base colour sets (`Material::mu_tinted`).
        mu_t: Option<Rgb<Mu>>,
        /// Emission I_e, exactly (glTF's `emissiveFactor` is f32).
        #[serde(rename = "I_e")]
        emission: Option<Rgb<Unit>>,
        /// `M·F0` of a metallic–roughness texture (`MetalRoughnessMap::metallic_f0`).
        mf0: Option<Rgb<Mu>>,
        /// The refractive index v given directly (`Material::ior`); absent: from μ.
        ior: Option<Rgb<Ior>>,
        /// The Cook–Torrance terms D, G and F (`Material::microfacet`); each absent: the chapter's
        /// term when the material has `extras.shadelab`, else glTF's (docs/scene-files.md).
        distribution: Option<Named<Distribution>>,
        masking: Option<Named<Masking>>,
        fresnel: Option<Named<Fresnel>>,
        /// Phong's lobe normalized (`Material::phong_normalized`); written only when true.
        phong_normalized: Option<Flag>,
        /// The microfacet lobe's multiple-scattering compensation (`Microfacet::multiple_scattering`);
        /// written only when true.
        multiple_scattering: Option<Flag>,
        /// The diffuse weighted by the dielectric layer's Fresnel (`Microfacet::fresnel_mix`); absent:
        /// as `distribution`. Its layer's F0 and weight (`Material::fresnel_mix`), each written
        /// where it is not the default (0.04, 1); without `extras.shadelab` they come from the
        /// file's ior and specular extensions.
        fresnel_mix: Option<Flag>,
        mix_f0: Option<Num<Mu>>,
        mix_weight: Option<Num<Unit>>,
    }
}

impl Reader<'_> {
    /// Every material of the file, in order, with its base colour texture; the textures and
    /// properties not drawn yet are warned about.
    pub(super) async fn materials(&mut self, scene: &mut Scene) -> Result<(), GltfError> {
        let root = self.root;
        let mut unused: Vec<&str> = Vec::new();
        for (i, m) in root.materials.iter().enumerate() {
            let (mut mat, mf0) = self.material(i, m)?;
            let pbr = &m.pbr_metallic_roughness;
            let slot = |name: &str| format!("material {i}: {name}");
            if let Some(info) = &pbr.base_color_texture {
                mat.base_color_texture = self.texture_ref(scene, info, &slot("baseColorTexture")).await?;
            }
            if let Some(info) = &pbr.metallic_roughness_texture {
                mat.maps.metal_roughness = self
                    .texture_ref(scene, info, &slot("metallicRoughnessTexture"))
                    .await?
                    .map(|texture| MetalRoughnessMap { texture, metallic_f0: mf0 });
            }
            if let Some(o) = &m.occlusion_texture {
                let info = self.slot_info(
                    o.index,
                    o.tex_coord,
                    o.extensions.as_ref().map(|e| &e.others),
                    &slot("occlusionTexture"),
                )?;
                let strength = (o.strength.0 as f64).clamp(0.0, 1.0);
                if !o.strength.0.is_finite() {
                    return Err(self.cx.invalid(slot("occlusionTexture: strength is not finite")));
                }
                mat.maps.occlusion = self
                    .texture_ref(scene, &info, &slot("occlusionTexture"))
                    .await?
                    .map(|texture| OcclusionMap { texture, strength });
            }
            if let Some(nt) = &m.normal_texture {
                let info = self.slot_info(
                    nt.index,
                    nt.tex_coord,
                    nt.extensions.as_ref().map(|e| &e.others),
                    &slot("normalTexture"),
                )?;
                if !nt.scale.is_finite() {
                    return Err(self.cx.invalid(slot("normalTexture: scale is not finite")));
                }
                mat.maps.normal = self
                    .texture_ref(scene, &info, &slot("normalTexture"))
                    .await?
                    .map(|texture| NormalMap { texture, scale: nt.scale as f64 });
            }
            if let Some(info) = &m.emissive_texture {
                mat.maps.emissive = self.texture_ref(scene, info, &slot("emissiveTexture")).await?;
            }
            for (has, what) in [
                (
                    !matches!(m.alpha_mode, Checked::Valid(json::material::AlphaMode::Opaque)),
                    "alphaMode (drawn opaque)",
                ),
                (pbr.base_color_factor.0[3] < 1.0, "baseColorFactor alpha (drawn opaque)"),
            ] {
                if has && !unused.contains(&what) {
                    unused.push(what);
                }
            }
            scene.materials.push(mat);
            super::slices::slice_end().await;
        }
        if !unused.is_empty() {
            self.cx.warn(format!("material properties not drawn yet: {}", unused.join(", ")));
        }
        Ok(())
    }

    /// A `textureInfo` for the normal and occlusion slots (`what`), whose extensions the glTF crate
    /// keeps as plain JSON: their `KHR_texture_transform` read from it (a malformed one is an
    /// error), any other extension warned about.
    fn slot_info(
        &mut self,
        index: json::Index<json::Texture>,
        tex_coord: u32,
        others: Option<&serde_json::Map<String, Value>>,
        what: &str,
    ) -> Result<json::texture::Info, GltfError> {
        let mut texture_transform = None;
        for (name, v) in others.into_iter().flatten() {
            if name == "KHR_texture_transform" {
                let t = serde_json::from_value::<json::extensions::texture::TextureTransform>(v.clone())
                    .map_err(|e| self.cx.invalid(format!("{what}: KHR_texture_transform: {e}")))?;
                texture_transform = Some(t);
            } else {
                self.cx.warn(format!("{what}: extension {name} is not read"));
            }
        }
        let extensions = Some(json::extensions::texture::Info { texture_transform, others: Default::default() });
        Ok(json::texture::Info { index, tex_coord, extensions, extras: Default::default() })
    }

    /// Material `i` from its factors and extras, and its `M·F0` for a metallic–roughness texture.
    fn material(&self, i: usize, m: &json::Material) -> Result<(Material, [f64; 3]), GltfError> {
        let what = format!("material {i}");
        let pbr = &m.pbr_metallic_roughness;
        let finite = pbr.base_color_factor.0.iter().all(|c| c.is_finite())
            && pbr.metallic_factor.0.is_finite()
            && pbr.roughness_factor.0.is_finite();
        if !finite {
            return Err(self.cx.invalid(format!("{what}: a pbrMetallicRoughness factor is not finite")));
        }
        if m.emissive_factor.0.iter().any(|e| !e.is_finite()) {
            return Err(self.cx.invalid(format!("{what}: emissiveFactor is not finite")));
        }
        let mut mat = pbr_material(m);
        let mut mf0 = metallic_f0(m);
        mat.name = m.name.clone().unwrap_or(what.clone());
        let ex: MaterialExtras = extras::read(&self.cx, &m.extras, &what)?;
        let set = |field: &mut f64, v: Option<Num<Unit>>| {
            if let Some(v) = v {
                *field = v.0;
            }
        };
        if let Some(c) = ex.color {
            mat.color = c.0;
        }
        if let Some(v) = ex.m {
            mat.m = v.0;
        }
        if let Some(h) = ex.h {
            mat.h = h.0;
        }
        if let Some(v) = ex.mu {
            mat.mu = v.0;
            // A file with the exact μ states its tinted part too (none when it does not say), and
            // its refractive index when it is not μ's.
            mat.mu_tinted = ex.mu_t.map_or([0.0; 3], |t| t.0);
            mat.ior = ex.ior.map(|v| v.0);
        }
        set(&mut mat.r_s, ex.r_s);
        set(&mut mat.r_d, ex.r_d);
        set(&mut mat.r_a, ex.r_a);
        set(&mut mat.transmission, ex.t);
        if let Some(v) = ex.a {
            mat.absorption = v.0;
        }
        if let Some(v) = ex.d {
            mat.thickness = v.0;
        }
        if let Some(v) = ex.emission {
            mat.emission = v.0;
        }
        if let Some(v) = ex.mf0 {
            mf0 = v.0;
        }
        // A material that states the chapter's parameters keeps the chapter's terms; a plain
        // glTF material is drawn with the BRDF it was authored for (the glTF specification's).
        let terms = if extras::has_shadelab(&m.extras) { Microfacet::CHAPTER } else { Microfacet::GLTF };
        mat.microfacet = Microfacet {
            d: ex.distribution.map_or(terms.d, |n| n.0),
            g: ex.masking.map_or(terms.g, |n| n.0),
            f: ex.fresnel.map_or(terms.f, |n| n.0),
            multiple_scattering: ex.multiple_scattering.is_some_and(|f| f.0),
            fresnel_mix: ex.fresnel_mix.map_or(terms.fresnel_mix, |f| f.0),
        };
        // A material that states the chapter's parameters states its layer where it is not the
        // default one.
        if extras::has_shadelab(&m.extras) {
            mat.fresnel_mix = FresnelMix::default();
        }
        if let Some(v) = ex.mix_f0 {
            mat.fresnel_mix.f0 = v.0;
        }
        set(&mut mat.fresnel_mix.weight, ex.mix_weight);
        mat.phong_normalized = ex.phong_normalized.is_some_and(|f| f.0);
        Ok((mat, mf0))
    }
}

/// glTF's dielectric layer of a material: its index (`KHR_materials_ior`), and the factor and
/// colour of `KHR_materials_specular`, each read as its default where out of range.
fn dielectric_layer(m: &json::Material) -> (f64, f64, [f64; 3]) {
    let ext = m.extensions.as_ref();
    let ior = ext.and_then(|e| e.ior.as_ref()).map_or(DEFAULT_IOR, |i| i.ior.0 as f64);
    // KHR_materials_ior: ior ≥ 1, or 0 (F0 = 1); anything else is read as the default.
    let ior = if ior == 0.0 || (ior >= 1.0 && ior.is_finite()) { ior } else { DEFAULT_IOR };
    let (spec, spec_color) = ext
        .and_then(|e| e.specular.as_ref())
        .map_or((1.0, [1.0; 3]), |s| (s.specular_factor.0 as f64, s.specular_color_factor.0.map(f64::from)));
    let sane = |x: f64| if x.is_finite() { x.max(0.0) } else { 1.0 };
    (ior, sane(spec), spec_color.map(sane))
}

/// glTF's F0 of a material's dielectric part (ior and `KHR_materials_specular`).
fn material_f0(m: &json::Material) -> [f64; 3] {
    let (ior, spec, spec_color) = dielectric_layer(m);
    dielectric_f0(ior, spec, spec_color)
}

/// The layer of glTF's `fresnel_mix`: the largest channel of its F0 before the factor, which
/// weighs it apart (`weight·max(F)` in KHR_materials_specular), and that factor.
fn fresnel_mix_layer(m: &json::Material) -> FresnelMix {
    let (ior, spec, spec_color) = dielectric_layer(m);
    let f0 = dielectric_f0(ior, 1.0, spec_color).into_iter().fold(0.0, f64::max);
    FresnelMix { f0, weight: spec.min(1.0) }
}

/// `M·F0`: the share of μ the metallic factor took from the dielectric F0, which a
/// metallic–roughness texel's metal scale below 1 gives back.
fn metallic_f0(m: &json::Material) -> [f64; 3] {
    let metallic = (m.pbr_metallic_roughness.metallic_factor.0 as f64).clamp(0.0, 1.0);
    material_f0(m).map(|f| f * metallic)
}

/// glTF's default material: every property at its default (glTF 2.0 §3.9.6).
pub(super) fn json_default_material() -> json::Material {
    json::deserialize::from_str("{}").expect("every material property has a default")
}

/// The model's material from glTF's metallic–roughness fields and extensions (the mapping and
/// its reasons: the module's parent).
pub(super) fn pbr_material(m: &json::Material) -> Material {
    let pbr = &m.pbr_metallic_roughness;
    let base = [0, 1, 2].map(|c| (pbr.base_color_factor.0[c] as f64).clamp(0.0, 1.0));
    let metallic = (pbr.metallic_factor.0 as f64).clamp(0.0, 1.0);
    let roughness = (pbr.roughness_factor.0 as f64).clamp(0.0, 1.0);
    let ext = m.extensions.as_ref();
    let f0 = material_f0(m);
    let mu = [0, 1, 2].map(|c| (f0[c] * (1.0 - metallic) + base[c] * metallic).clamp(0.0, 1.0));
    let m_rough = m_from_roughness(roughness);
    let transmission =
        ext.and_then(|e| e.transmission.as_ref()).map_or(0.0, |t| (t.transmission_factor.0 as f64).clamp(0.0, 1.0));
    let (absorption, thickness) = ext.and_then(|e| e.volume.as_ref()).map_or(([0.0; 3], 0.0), |v| {
        let dist = v.attenuation_distance.0 as f64;
        let a = v.attenuation_color.0.map(|c| {
            let c = (c as f64).clamp(ATTENUATION_COLOR_MIN, 1.0);
            // Beer's law: c^(x/D) = e^(−a·x) with a = −ln(c)/D (docs/model.md §7); D = ∞ (the
            // default): none.
            if dist > 0.0 && dist.is_finite() { (-c.ln() / dist).min(crate::params::ABSORPTION.max) } else { 0.0 }
        });
        let d = v.thickness_factor.0 as f64;
        (a, if d.is_finite() { d.clamp(0.0, crate::params::THICKNESS.max) } else { 0.0 })
    });
    Material {
        name: String::new(),
        color: base.map(|c| c * (1.0 - metallic)),
        r_s: 1.0,
        r_d: 1.0,
        r_a: 1.0,
        m: m_rough,
        h: PhongExponent::from_m(m_rough),
        mu,
        transmission,
        // A transmitting material refracts with glTF's index as given (KHR_materials_ior).
        ior: (transmission > 0.0).then(|| ext.and_then(|e| e.ior.as_ref())).flatten().map(|i| {
            let v = i.ior.0 as f64;
            [if v.is_finite() { v.clamp(crate::params::IOR.min, crate::params::IOR.max) } else { DEFAULT_IOR }; 3]
        }),
        absorption,
        thickness,
        base_color_texture: None,
        mu_tinted: base.map(|c| c * metallic),
        emission: m.emissive_factor.0.map(|e| (e as f64).clamp(0.0, 1.0)),
        maps: Default::default(),
        microfacet: Default::default(),
        phong_normalized: false,
        fresnel_mix: fresnel_mix_layer(m),
    }
}

/// A material: PBR fields that approximate the model (the loader's mapping run backwards), and
/// the model's exact parameters in `extras.shadelab`; the extensions it uses are added to
/// `extensions_used`.
pub(super) fn write_material(m: &Material, extensions_used: &mut Vec<&'static str>) -> Value {
    let mut ext = serde_json::Map::new();
    let (base, metallic) = write_extensions(m, &mut ext, extensions_used);
    let ex = MaterialExtras {
        color: Some(m.color.into()),
        m: Some(m.m.into()),
        h: Some(Phong(m.h)),
        mu: Some(m.mu.into()),
        r_s: Some(m.r_s.into()),
        r_d: Some(m.r_d.into()),
        r_a: Some(m.r_a.into()),
        t: Some(m.transmission.into()),
        a: Some(m.absorption.into()),
        d: Some(m.thickness.into()),
        mu_t: Some(m.mu_tinted.into()),
        emission: (m.emission != [0.0; 3]).then(|| m.emission.into()),
        mf0: m.maps.metal_roughness.map(|mr| mr.metallic_f0.into()),
        ior: m.ior.map(Into::into),
        distribution: Some(Named(m.microfacet.d)),
        masking: Some(Named(m.microfacet.g)),
        fresnel: Some(Named(m.microfacet.f)),
        phong_normalized: m.phong_normalized.then_some(Flag(true)),
        multiple_scattering: m.microfacet.multiple_scattering.then_some(Flag(true)),
        fresnel_mix: m.microfacet.fresnel_mix.then_some(Flag(true)),
        mix_f0: (m.fresnel_mix.f0 != FresnelMix::default().f0).then(|| m.fresnel_mix.f0.into()),
        mix_weight: (m.fresnel_mix.weight != FresnelMix::default().weight).then(|| m.fresnel_mix.weight.into()),
    };
    let mut out = json!({
        "name": m.name,
        "pbrMetallicRoughness": {
            "baseColorFactor": [num(base[0]), num(base[1]), num(base[2]), 1.0],
            "metallicFactor": metallic,
            "roughnessFactor": num(m.m.clamp(0.0, 1.0).sqrt()),
        },
        "extras": extras::shadelab(&ex),
    });
    write_texture_slots(m, &mut out, extensions_used);
    if m.emission != [0.0; 3] {
        out["emissiveFactor"] = rgb(m.emission);
    }
    if !ext.is_empty() {
        out["extensions"] = Value::Object(ext);
    }
    out
}

/// The material's KHR_materials extensions into `ext` (named in `extensions_used`); the glTF base colour and metallic.
fn write_extensions(
    m: &Material,
    ext: &mut serde_json::Map<String, Value>,
    extensions_used: &mut Vec<&'static str>,
) -> ([f64; 3], f64) {
    let mu_max = m.mu.iter().fold(0.0f64, |a, b| a.max(*b));
    let (base, metallic) = if mu_max <= DIELECTRIC_MU_MAX {
        // A dielectric: μ through the index of refraction v = (1 + √μ)/(1 − √μ) (docs/model.md
        // §5) of its largest channel, the others by KHR_materials_specular's colour.
        let v = crate::brdf::fresnel_v_from_mu(mu_max);
        if (v - DEFAULT_IOR).abs() > IOR_DEFAULT_TOLERANCE {
            ext.insert("KHR_materials_ior".into(), json!({ "ior": num(v) }));
            extensions_used.push("KHR_materials_ior");
        }
        if m.mu.iter().any(|c| (c - mu_max).abs() > MU_GREY_TOLERANCE) && mu_max > 0.0 {
            ext.insert(
                "KHR_materials_specular".into(),
                json!({ "specularColorFactor": rgb(m.mu.map(|c| c / mu_max)) }),
            );
            extensions_used.push("KHR_materials_specular");
        }
        (m.color, 0.0)
    } else {
        // A metal: glTF's F0 is the base colour.
        (m.mu, 1.0)
    };
    if m.transmission > 0.0 {
        ext.insert("KHR_materials_transmission".into(), json!({ "transmissionFactor": num(m.transmission) }));
        extensions_used.push("KHR_materials_transmission");
    }
    if m.thickness > 0.0 || m.absorption.iter().any(|a| *a > 0.0) {
        // e^(−a·x) = c^(x/D) with D = 1: c = e^(−a) (docs/model.md §7).
        ext.insert(
            "KHR_materials_volume".into(),
            json!({
                "thicknessFactor": num(m.thickness),
                "attenuationDistance": 1.0,
                "attenuationColor": rgb(m.absorption.map(|a| (-a).exp())),
            }),
        );
        extensions_used.push("KHR_materials_volume");
    }
    (base, metallic)
}

/// The material's texture slots into `out`, the material's JSON (extensions they use named in `extensions_used`).
fn write_texture_slots(m: &Material, out: &mut Value, extensions_used: &mut Vec<&'static str>) {
    let info = super::textures::texture_info;
    if let Some(t) = &m.base_color_texture {
        out["pbrMetallicRoughness"]["baseColorTexture"] = info(t, extensions_used);
    }
    if let Some(mr) = &m.maps.metal_roughness {
        out["pbrMetallicRoughness"]["metallicRoughnessTexture"] = info(&mr.texture, extensions_used);
    }
    if let Some(o) = &m.maps.occlusion {
        let mut slot = info(&o.texture, extensions_used);
        slot["strength"] = num(o.strength);
        out["occlusionTexture"] = slot;
    }
    if let Some(t) = &m.maps.emissive {
        out["emissiveTexture"] = info(t, extensions_used);
    }
    if let Some(n) = &m.maps.normal {
        let mut slot = info(&n.texture, extensions_used);
        slot["scale"] = num(n.scale);
        out["normalTexture"] = slot;
    }
}
