//! Scenes: analytic shapes with transforms, materials, lights and a camera.
//!
//! Shapes stay analytic here (the f64 reference ray-casts them exactly); `mesh` tessellates them
//! for the rasterizer. Materials, the camera and the built-in scenes have their own files under
//! `scene/`; lights are declared with their f64 terms in `lighting/lights.rs`.

mod builtin;
mod camera;
mod cornell;
pub(crate) mod material;
mod texture;

pub use crate::lighting::lights::{LIGHT_STAND_OFF, Light, MAX_LIGHTS, SPOT_OUTER_CONE_DEFAULT};
pub use builtin::{
    BUILTIN_SCENES, PENUMBRA_LIGHT_HEIGHT, PENUMBRA_LIGHT_SIZE, PENUMBRA_PLATE_HALF, PENUMBRA_PLATE_HEIGHT,
    default_scene, penumbra_scene, single_shape_scene,
};
pub use camera::{COMPOSED_ASPECT, Camera};
pub use cornell::{
    CORNELL_FALLOFF, CORNELL_GREEN, CORNELL_LIGHT_CENTER, CORNELL_LIGHT_SIZE, CORNELL_RADIANCE, CORNELL_RED,
    CORNELL_ROOM, CORNELL_WHITE, cornell_scene,
};
pub use material::{
    FresnelMix, Material, MaterialMaps, MetalRoughnessMap, NormalMap, OcclusionMap, SurfacePoint, emitted,
    metallic_scaled, normal_mapped, occluded, phong_h_from_m, roughness_scaled, tinted_surface, vertex_tint,
};
pub use texture::{
    ColorSpace, Filter, Level, MipCache, Sampler, Texture, TextureRef, UvFootprint, UvTransform, Wrap, linear_to_srgb,
    srgb_to_linear, texture_uv,
};

use crate::lighting::microfacet::Microfacet;
use crate::params::*;
use crate::shadow_settings::{ShadowFilter, ShadowSettings};
use glam::{DMat3, DMat4, DVec3};

/// Analytic shapes, each in its own unit box `[-1, 1]³` of object space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shape {
    /// Radius 1 about the origin.
    Sphere,
    /// Radius 1 around the y axis, `y ∈ [-1, 1]`, with caps.
    Cylinder,
    /// `[-1, 1]³`.
    Cube,
    /// `y = 0`, `x, z ∈ [-1, 1]`, facing +y.
    Plane,
    /// Square base `[-1, 1]²` at `y = -1`, apex at `(0, 1, 0)` (the chapter's figure 7.3).
    Pyramid,
    /// A triangle mesh from a scene file: `Scene::meshes[i]` (keeps `Shape` `Copy + Hash`).
    Mesh(usize),
}

impl Shape {
    /// The shape's code in the analytic exit (`lighting::transmission::SHAPE_…`).
    pub fn exit_code(self) -> u32 {
        use crate::lighting::transmission::*;
        match self {
            Shape::Sphere => SHAPE_SPHERE,
            Shape::Cylinder => SHAPE_CYLINDER,
            Shape::Cube => SHAPE_CUBE,
            Shape::Plane => SHAPE_PLANE,
            Shape::Pyramid => SHAPE_PYRAMID,
            Shape::Mesh(_) => SHAPE_MESH,
        }
    }

    pub const ALL: [Shape; 5] = [Shape::Sphere, Shape::Cylinder, Shape::Cube, Shape::Plane, Shape::Pyramid];
    pub fn name(self) -> &'static str {
        match self {
            Shape::Sphere => "sphere",
            Shape::Cylinder => "cylinder",
            Shape::Cube => "cube",
            Shape::Plane => "plane",
            Shape::Pyramid => "pyramid",
            Shape::Mesh(_) => "mesh",
        }
    }
}

/// Object-to-world transform: scale, then rotation about y, then translation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub translation: DVec3,
    /// Rotation about the y axis, radians.
    pub rotation_y: f64,
    pub scale: DVec3,
}

impl Transform {
    pub fn new(translation: DVec3, scale: DVec3) -> Self {
        Transform { translation, rotation_y: 0.0, scale }
    }
    pub fn matrix(&self) -> DMat4 {
        DMat4::from_translation(self.translation)
            * DMat4::from_rotation_y(self.rotation_y)
            * DMat4::from_scale(self.scale)
    }
    /// The matrix that carries object-space normals to world space: `(R S)^-T = R S^-1`.
    pub fn normal_matrix(&self) -> DMat3 {
        DMat3::from_rotation_y(self.rotation_y) * DMat3::from_diagonal(self.scale.recip())
    }
}

/// One object: a shape, its tessellation for the rasterizer, a transform and a material.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub name: String,
    pub shape: Shape,
    /// Segments around (sphere, cylinder) or subdivisions per edge (cube, plane, pyramid).
    pub tessellation: u32,
    pub transform: Transform,
    /// Index into `Scene::materials`.
    pub material: usize,
}

/// A whole scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub name: String,
    pub objects: Vec<Object>,
    pub materials: Vec<Material>,
    pub lights: Vec<Light>,
    /// Scene-wide ambient intensity `I_amb` per channel (docs/model.md §3).
    pub ambient: [f64; 3],
    pub camera: Camera,
    /// Triangle meshes from a scene file, indexed by `Shape::Mesh(i)`; shared by the scene's
    /// copies (`mesh::Meshes`).
    pub meshes: crate::mesh::Meshes,
    /// The illumination model the scene is lit with (docs/model.md §3a).
    pub illumination: crate::params::IlluminationModel,
    /// The materials' textures, indexed by `TextureRef::texture`.
    pub textures: Vec<Texture>,
    /// How transparent objects absorb: exactly, or by the chapter's rule per object
    /// (docs/transparency.md).
    pub absorption: crate::lighting::transmission::AbsorptionChoice,
    /// What a ray that meets nothing sees: [`BACKGROUND`]; `None` in a term view (`Term::apply`),
    /// where such pixels are black with alpha 0, so that the term images add up to the whole
    /// image everywhere once the background is composited under them.
    pub background: Option<[f64; 3]>,
    /// The environment light, one at most (docs/environment.md); it adds to `I_amb`.
    pub environment: Option<crate::lighting::env_map::Environment>,
}

/// Background colour (linear RGB): dark enough for highlights to stand out, not black, so a blank
/// image is told from a dark one.
pub const BACKGROUND: [f64; 3] = [0.03, 0.035, 0.045];

/// What the command line or the viewer overrides in a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overrides {
    pub m: Option<f64>,
    pub h: Option<PhongExponent>,
    pub mu: Option<[f64; 3]>,
    /// Every material's transmission share `1 − t` (docs/model.md §2).
    pub transmission: Option<f64>,
    /// Every material's refractive index per channel, within `params::IOR`.
    pub ior: Option<[f64; 3]>,
    /// Every material's absorption coefficient per channel, within `params::ABSORPTION`.
    pub absorption_coef: Option<[f64; 3]>,
    /// How transparent objects absorb (`--absorption`).
    pub absorption: Option<crate::lighting::transmission::AbsorptionChoice>,
    pub falloff_alpha: Option<f64>,
    pub falloff_form: Option<FalloffForm>,
    pub d0: Option<f64>,
    pub light: Option<LightKind>,
    /// Every area light's width and height in metres (a disk's or sphere's diameter), within
    /// `lights::LIGHT_SIZE`.
    pub light_size: Option<f64>,
    /// Every area light drawn as this many point sources (0: its exact area form), within
    /// `lights::AREA_POINTS`.
    pub area_points: Option<u32>,
    /// How every area light's specular is drawn (`--area-specular`).
    pub area_specular: Option<crate::params::AreaSpecular>,
    /// Every light casts shadows (`Some(true)`) or none does (`Some(false)`).
    pub shadows: Option<bool>,
    /// Every light's shadow map side, within `shadows::SHADOW_RESOLUTION` (clamped into it).
    pub shadow_resolution: Option<u32>,
    pub shadow_filter: Option<ShadowFilter>,
    /// Every light's PCSS taps per pass, within `shadows::PCSS_TAPS`.
    pub pcss_taps: Option<u32>,
    /// Every directional light may use cascades (`Some(true)`) or keeps one map (`Some(false)`).
    pub shadow_cascades: Option<bool>,
    /// The illumination model (`--model`, with the specular model it fixes kept elsewhere).
    pub illumination: Option<crate::params::IlluminationModel>,
    /// Every material's three microfacet terms (`--microfacet chapter|gltf`), before the terms
    /// given one by one.
    pub microfacet: Option<Microfacet>,
    pub distribution: Option<crate::lighting::microfacet::Distribution>,
    pub masking: Option<crate::lighting::microfacet::Masking>,
    pub fresnel: Option<crate::lighting::microfacet::Fresnel>,
    /// Every material's Phong lobe normalized (`--phong-normalized on|off`).
    pub phong_normalized: Option<bool>,
    /// Every material's microfacet lobe compensated for multiple scattering
    /// (`--multiple-scattering on|off`), after `microfacet`.
    pub multiple_scattering: Option<bool>,
    /// Every material's diffuse weighted by its dielectric layer's Fresnel (`--fresnel-mix
    /// on|off`), after `microfacet`.
    pub fresnel_mix: Option<bool>,
}

/// The microfacet overrides on one material's terms: the preset, then each term given.
fn apply_terms(t: &mut Microfacet, o: &Overrides) {
    if let Some(preset) = o.microfacet {
        *t = preset;
    }
    t.d = o.distribution.unwrap_or(t.d);
    t.g = o.masking.unwrap_or(t.g);
    t.f = o.fresnel.unwrap_or(t.f);
    t.multiple_scattering = o.multiple_scattering.unwrap_or(t.multiple_scattering);
    t.fresnel_mix = o.fresnel_mix.unwrap_or(t.fresnel_mix);
}

impl Overrides {
    /// What choosing `choice` changes in a scene: its illumination model, and for the four-term
    /// sum the chapter's falloff `1/(d + d0)` on every point and spot light (equation (1)).
    pub fn for_model(choice: crate::params::ModelChoice) -> Overrides {
        let (model, _) = choice.split();
        Overrides {
            illumination: Some(model),
            falloff_form: (model == crate::params::IlluminationModel::Sum).then_some(FalloffForm::Linear),
            ..Default::default()
        }
    }
}

impl Scene {
    /// A scene named `name` with nothing in it yet, lit by the ambient `ambient` and seen by
    /// `camera`: the chapter's Phong model, no meshes, textures or environment, and the default
    /// background (a scene file keeps none, so a saved scene loads with the same).
    pub fn empty(name: String, ambient: [f64; 3], camera: Camera) -> Scene {
        Scene {
            name,
            objects: Vec::new(),
            materials: Vec::new(),
            lights: Vec::new(),
            ambient,
            camera,
            meshes: Default::default(),
            illumination: Default::default(),
            textures: Vec::new(),
            absorption: Default::default(),
            background: Some(BACKGROUND),
            environment: None,
        }
    }

    /// Whether object `i` is drawn by the glass pass: its material transmits, and the model is
    /// not the four-term sum (which draws transmission as its own `I_t` term).
    pub fn drawn_as_glass(&self, i: usize) -> bool {
        self.illumination != crate::params::IlluminationModel::Sum
            && self.objects.get(i).and_then(|o| self.materials.get(o.material)).is_some_and(|m| m.transmits())
    }

    /// Turn every light's cast shadows on or off (tests that compare the lighting terms alone
    /// switch them off; `render --shadows`).
    pub fn set_shadows(&mut self, on: bool) {
        for l in &mut self.lights {
            l.shadow.casts = on;
        }
    }

    /// Apply command-line or panel overrides to every material and light.
    pub fn apply(&mut self, o: &Overrides) {
        if let Some(model) = o.illumination {
            self.illumination = model;
        }
        if let Some(a) = o.absorption {
            self.absorption = a;
        }
        for mat in &mut self.materials {
            if let Some(m) = o.m {
                mat.m = m;
            }
            if let Some(h) = o.h {
                mat.h = h;
            }
            if let Some(mu) = o.mu {
                mat.mu = mu;
            }
            if let Some(t) = o.transmission {
                mat.transmission = t;
            }
            if let Some(v) = o.ior {
                mat.ior = Some(v);
            }
            if let Some(a) = o.absorption_coef {
                mat.absorption = a;
            }
            apply_terms(&mut mat.microfacet, o);
            mat.phong_normalized = o.phong_normalized.unwrap_or(mat.phong_normalized);
        }
        for light in &mut self.lights {
            if let Some(kind) = o.light {
                light.set_kind(kind);
            }
            if let Some(w) = o.light_size {
                light.size = [w; 2];
            }
            if let Some(k) = o.area_points {
                light.area_points = k;
            }
            if let Some(s) = o.area_specular {
                light.area_specular = s;
            }
            if let Some(a) = o.falloff_alpha {
                light.falloff_alpha = a;
            }
            if let Some(f) = o.falloff_form {
                light.falloff_form = f;
            }
            if let Some(d0) = o.d0 {
                light.d0 = d0;
            }
            if let Some(on) = o.shadows {
                light.shadow.casts = on;
            }
            if let Some(r) = o.shadow_resolution {
                light.shadow = ShadowSettings { resolution: r, ..light.shadow }.clamped();
            }
            if let Some(f) = o.shadow_filter {
                light.shadow.filter = f;
            }
            if let Some(n) = o.pcss_taps {
                light.shadow = ShadowSettings { pcss_taps: n, ..light.shadow }.clamped();
            }
            if let Some(c) = o.shadow_cascades {
                light.shadow.cascades = c;
            }
        }
    }

    /// Object `o`'s base colour texture, when its material has one that exists.
    pub fn base_color_texture(&self, o: &Object) -> Option<TextureRef> {
        let r = self.materials.get(o.material)?.base_color_texture?;
        (r.texture < self.textures.len()).then_some(r)
    }

    /// Total triangle count once tessellated.
    pub fn triangle_count(&self) -> usize {
        self.objects.iter().map(|o| self.object_triangle_count(o)).sum()
    }

    /// Triangles of one object: its tessellation, or its mesh's count.
    pub fn object_triangle_count(&self, o: &Object) -> usize {
        match o.shape {
            Shape::Mesh(i) => self.meshes.get(i).map_or(0, |m| m.triangle_count()),
            shape => crate::mesh::triangle_count(shape, o.tessellation),
        }
    }

    /// The GPU-ready meshes of an object: the analytic shape tessellated, or `Scene::meshes[i]`
    /// built (the file's normals, else the crease-angle rule). A mesh index past `meshes` or a
    /// non-finite position (which the loader already refuses) gives an empty mesh.
    pub fn mesh_data(&self, o: &Object) -> crate::mesh::MeshData {
        match o.shape {
            Shape::Mesh(i) => self.meshes.get(i).and_then(|m| m.build().ok()).unwrap_or_default(),
            shape => crate::mesh::tessellate(shape, o.tessellation),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_scenes_exist_and_fit_the_light_slots() {
        for name in BUILTIN_SCENES {
            let s = Scene::builtin(name).unwrap();
            assert!(!s.objects.is_empty() && s.lights.len() <= MAX_LIGHTS);
            for o in &s.objects {
                assert!(o.material < s.materials.len());
            }
        }
        assert!(Scene::builtin("nope").is_none());
    }

    #[test]
    fn camera_ray_through_centre_looks_at_target() {
        let c = builtin::default_camera();
        let (_, d) = c.ray(50, 50, 101, 101);
        assert!((d - (c.target - c.eye).normalize()).length() < 1e-12);
        // The ray's direction projects back to the pixel centre it came from.
        let p = c.eye + d * 3.0;
        let clip = c.projection(2.0) * c.view() * p.extend(1.0);
        let (_, d2) = c.ray(0, 0, 200, 100);
        let q = c.eye + d2 * 3.0;
        let clip2 = c.projection(2.0) * c.view() * q.extend(1.0);
        assert!((clip.x / clip.w).abs() < 1e-12);
        assert!((clip2.x / clip2.w - (-1.0 + 1.0 / 200.0)).abs() < 1e-9);
        assert!((clip2.y / clip2.w - (1.0 - 1.0 / 100.0)).abs() < 1e-9);
    }

    #[test]
    fn overrides_change_every_material_and_light() {
        let mut s = default_scene();
        s.apply(&Overrides {
            m: Some(0.0),
            light: Some(LightKind::Point),
            falloff_alpha: Some(2.0),
            ..Default::default()
        });
        assert!(s.materials.iter().all(|m| m.m == 0.0));
        assert!(s.lights.iter().all(|l| l.kind == LightKind::Point && l.falloff_alpha == 2.0));
    }

    #[test]
    fn shadow_overrides_change_every_light() {
        let mut s = default_scene();
        assert!(s.lights.len() > 1);
        let o = Overrides {
            shadows: Some(false),
            shadow_resolution: Some(512),
            shadow_filter: Some(ShadowFilter::Poisson),
            shadow_cascades: Some(false),
            ..Default::default()
        };
        s.apply(&o);
        let want = ShadowSettings {
            casts: false,
            resolution: 512,
            filter: ShadowFilter::Poisson,
            cascades: false,
            ..Default::default()
        };
        assert!(s.lights.iter().all(|l| l.shadow == want), "{:?}", s.lights);
        // Only what is given changes; a resolution outside the range is held to it.
        s.apply(&Overrides { shadows: Some(true), shadow_resolution: Some(1 << 20), ..Default::default() });
        let want = ShadowSettings { casts: true, resolution: 4096, ..want };
        assert!(s.lights.iter().all(|l| l.shadow == want), "{:?}", s.lights);
    }
}
