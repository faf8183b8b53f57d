//! CPU twins of the WGSL uniform structs (`#[repr(C)]` + bytemuck), and their packing from the
//! scene. The test `uniform_layouts_match_wgsl` holds every size and field offset equal to naga's
//! layout. A light is packed in one place, [`LightUniform::new`], from the values the model
//! derives for the GPU and the f64 reference alike (`lighting/lights.rs`).

use bytemuck::{Pod, Zeroable};
use shadelab_model::lighting::area::{AreaShape, disk_polygon_scale};
use shadelab_model::lighting::ms_table::MS_TABLE_VEC4S;
use shadelab_model::scene::MAX_LIGHTS;
use shadelab_model::scene::UvTransform;
use shadelab_model::shadows::MAX_SHADOW_LAYERS;
use shadelab_model::{Light, Object, Scene, SpecularModel};

#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct LightUniform {
    pub position: [f32; 4],
    pub direction: [f32; 4],
    pub radiance: [f32; 4],
    pub kind: u32,
    pub falloff_form: u32,
    pub falloff_alpha: f32,
    pub d0: f32,
    pub spot_axis: [f32; 4],
    pub cos_inner: f32,
    pub cos_outer: f32,
    /// 0: the light never ends.
    pub range: f32,
    pub _pad: f32,
    /// xyz: a flat area light's unit normal, the way it emits (`Light::spot_axis`).
    pub normal: [f32; 4],
    /// xyz: a flat area light's unit tangent (`Light::area_tangent`).
    pub tangent: [f32; 4],
    /// A rectangle's half-sizes; a disk's radius and its equal-area polygon's circumradius; a
    /// sphere's radius in `half_x`.
    pub half_x: f32,
    pub half_y: f32,
    /// 0: an area light's exact form; k: k point sources (`Light::area_points`).
    pub area_points: u32,
    /// `AreaSpecular::code`: an area light's specular at its representative point or by LTC.
    pub area_specular: u32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GlobalsUniform {
    pub view_proj: [[f32; 4]; 4],
    pub camera_pos: [f32; 4],
    pub ambient: [f32; 4],
    pub light_count: u32,
    pub flags: u32,
    /// `SpecularModel::code`: SPECULAR_PHONG or SPECULAR_COOK_TORRANCE.
    pub specular_model: u32,
    pub illumination: u32,
    pub lights: [LightUniform; MAX_LIGHTS],
    /// The environment's nine SH coefficients ([`env_sh`]); zero without one.
    pub env_sh: [[f32; 4]; 9],
    /// The occlusion grid's placement (`OcclusionGrid::gpu_placement`); zero without one, set by
    /// the frame, which bakes the grid once per change of the geometry.
    pub env_occlusion: [[f32; 4]; 2],
    /// The inverse of `view_proj`, for the background's ray through each pixel.
    pub inv_view_proj: [[f32; 4]; 4],
}

/// `types.wgsl`'s `Tables` (@group(0) @binding(3)): the constant tables, written once per
/// device by the renderer ([`TablesUniform::new`]), so the globals written on each change stay
/// small.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct TablesUniform {
    /// The multiple-scattering compensation's table (`ms_table::ms_table_vec4s`); the split
    /// sum reads it too (its E).
    pub ms_albedo: [[f32; 4]; MS_TABLE_VEC4S],
    /// The split sum's B table (`environment::env_split_b_vec4s`).
    pub env_split_b: [[f32; 4]; shadelab_model::lighting::environment::ENV_SPLIT_B_VEC4S],
    /// The LTC table (`ltc_table::LTC_TABLE`), one node a slot.
    pub ltc: [[f32; 4]; shadelab_model::lighting::ltc::LTC_TABLE_VEC4S],
}

impl TablesUniform {
    /// The tables, as the shaders read them.
    pub fn new() -> Self {
        TablesUniform {
            ms_albedo: shadelab_model::lighting::ms_table::ms_table_vec4s(),
            env_split_b: shadelab_model::lighting::environment::env_split_b_vec4s(),
            ltc: shadelab_model::lighting::ltc_table::LTC_TABLE,
        }
    }
}

impl Default for TablesUniform {
    fn default() -> Self {
        Self::new()
    }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct ObjectUniform {
    pub model: [[f32; 4]; 4],
    pub normal_matrix: [[f32; 4]; 4],
    pub color: [f32; 4],
    pub mu: [f32; 4],
    pub r_s: f32,
    pub r_d: f32,
    pub r_a: f32,
    pub m: f32,
    pub h: f32,
    pub mirror: u32,
    pub transmission: f32,
    /// `KHR_texture_transform` rotation of the base colour texture.
    pub uv_rotation: f32,
    /// The part of μ the base colour sets (`Material::mu_tinted`).
    pub mu_tinted: [f32; 4],
    /// The texture transform's offset (xy) and scale (zw).
    pub uv_offset_scale: [f32; 4],
    /// `MetalRoughnessMap::metallic_f0`.
    pub metallic_f0: [f32; 4],
    /// Emission I_e.
    pub emission: [f32; 4],
    /// The metallic–roughness, occlusion and emissive textures' transforms: offset (xy) and
    /// scale (zw) each; their rotations are `uv_rotations`.
    pub metal_roughness_uv: [f32; 4],
    pub occlusion_uv: [f32; 4],
    pub emissive_uv: [f32; 4],
    /// Rotations of the metallic–roughness, occlusion, emissive and normal textures (x, y, z, w).
    pub uv_rotations: [f32; 4],
    /// Which slots' textures the material has (`textures::MAP_BITS`).
    pub maps: u32,
    pub occlusion_strength: f32,
    /// The normal texture's `scale`.
    pub normal_scale: f32,
    /// 1: Phong's lobe normalized (`Material::phong_normalized`).
    pub phong_normalized: u32,
    /// The normal texture's transform: offset (xy) and scale (zw); its rotation is `uv_rotations.w`.
    pub normal_uv: [f32; 4],
    /// World to object space (the glass pass's analytic exit).
    pub inverse_model: [[f32; 4]; 4],
    /// The refractive index v per channel (rgb); w: 1 where the channels differ (disperse).
    pub ior: [f32; 4],
    /// The absorption coefficient a per channel per world unit (rgb).
    pub absorption: [f32; 4],
    /// `Shape::exit_code`; `SHAPE_MESH` reads the back faces.
    pub exit_shape: u32,
    /// `AbsorptionForm::code` of the form the object absorbs in (`effects::absorption_form`).
    pub absorption_form: u32,
    /// `effects::longest_chord`: the path-length view's white.
    pub longest_chord: f32,
    /// `Microfacet::code`: the material's D, G and F.
    pub microfacet: u32,
    /// The Fresnel-weighted diffuse's layer (`Material::fresnel_mix`): its F0 and weight (xy).
    pub fresnel_mix: [f32; 4],
}

/// One light's shadow map as `shadows.wgsl`'s `ShadowLight` reads it (zeroed: no shadow).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct ShadowLightUniform {
    pub first_layer: u32,
    /// 0: no shadow; 1: directional or spot; 6: a point light's faces.
    pub layers: u32,
    /// `ShadowFilter::code`.
    pub shadow_filter: u32,
    pub perspective: u32,
    pub texel_world: f32,
    pub uv_scale: f32,
    pub texel_uv: f32,
    /// `Light::penumbra_size` (PCSS; 0 for a light without an area).
    pub light_size: f32,
    /// The map's depth range along its view axis (PCSS linearizes the stored depth with it).
    pub near: f32,
    pub far: f32,
    /// Cube lights: the cubes from `first_layer` on (an area light drawn as points has one per
    /// point source, as many as fit); 1 otherwise.
    pub cubes: u32,
    /// `ShadowSettings::pcss_taps`.
    pub pcss_taps: u32,
}

/// `shadows.wgsl`'s `Shadows` (@group(2) @binding(0)): each layer's light view-projection and
/// each light's map. Bound only in permutations with cast shadows; the shadow pass reads the
/// same buffer's matrices as `ShadowCasters`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct ShadowsUniform {
    pub matrices: [[[f32; 4]; 4]; MAX_SHADOW_LAYERS as usize],
    pub lights: [ShadowLightUniform; MAX_LIGHTS],
}

/// `flags` bit: paint non-finite pixels magenta.
pub const FLAG_DEBUG_NONFINITE: u32 = 1;
/// `flags` bits 1–2: the glass view (`GlassView::code`, glass.wgsl's `GLASS_VIEW_SHIFT`).
pub const GLASS_VIEW_SHIFT: u32 = 1;

fn rgb(c: [f64; 3], w: f32) -> [f32; 4] {
    [c[0] as f32, c[1] as f32, c[2] as f32, w]
}

impl LightUniform {
    /// One light as `lights.wgsl`'s `Light` reads it.
    pub fn new(l: &Light) -> Self {
        let (cos_inner, cos_outer) = l.cone_cosines();
        let (half_x, half_y) = match l.area_light().map(|a| a.shape) {
            Some(AreaShape::Rect { half_x, half_y }) => (half_x, half_y),
            Some(AreaShape::Disk { radius }) => (radius, radius * disk_polygon_scale()),
            Some(AreaShape::Sphere { radius }) => (radius, radius),
            None => (0.0, 0.0),
        };
        LightUniform {
            position: l.position.as_vec3().extend(1.0).to_array(),
            direction: l.direction.as_vec3().extend(0.0).to_array(),
            radiance: rgb(l.radiance(), 1.0),
            kind: l.kind.code(),
            falloff_form: l.falloff_form.code(),
            falloff_alpha: l.falloff_alpha as f32,
            d0: l.d0 as f32,
            spot_axis: l.spot_axis().as_vec3().extend(0.0).to_array(),
            cos_inner: cos_inner as f32,
            cos_outer: cos_outer as f32,
            range: l.range.unwrap_or(0.0) as f32,
            _pad: 0.0,
            normal: l.spot_axis().as_vec3().extend(0.0).to_array(),
            tangent: l.area_tangent().as_vec3().extend(0.0).to_array(),
            half_x: half_x as f32,
            half_y: half_y as f32,
            area_points: if l.drawn_as_points() { l.area_points } else { 0 },
            area_specular: l.area_specular.code(),
        }
    }
}

/// The built-in background (`scene::BACKGROUND`), the same as the f64 reference's: what a scene
/// pass clears to before its uniforms were written.
pub const CLEAR_COLOR: wgpu::Color = wgpu::Color {
    r: shadelab_model::scene::BACKGROUND[0],
    g: shadelab_model::scene::BACKGROUND[1],
    b: shadelab_model::scene::BACKGROUND[2],
    a: 1.0,
};

/// What the scene pass clears to: the scene's background, opaque; without one (a term view)
/// transparent black, so the term images add up on every pixel.
pub fn clear_color(scene: &Scene) -> wgpu::Color {
    match scene.background {
        Some([r, g, b]) => wgpu::Color { r, g, b, a: 1.0 },
        None => wgpu::Color::TRANSPARENT,
    }
}

/// An environment's nine SH terms as `globals.env_sh` holds them.
pub fn env_sh(env: &shadelab_model::lighting::env_map::Environment, lights: &[Light]) -> [[f32; 4]; 9] {
    env.sh(lights).map(|c| rgb(c, 0.0))
}

impl GlobalsUniform {
    /// The globals of `scene`; `env_sh` its environment's SH terms ([`env_sh`]), which the frame
    /// keeps between writes since a large map's projection reads every texel.
    pub fn new(
        scene: &Scene,
        width: u32,
        height: u32,
        flags: u32,
        specular: SpecularModel,
        env_sh: [[f32; 4]; 9],
    ) -> Self {
        let mut lights = [LightUniform::zeroed(); MAX_LIGHTS];
        for (slot, l) in lights.iter_mut().zip(&scene.lights) {
            *slot = LightUniform::new(l);
        }
        GlobalsUniform {
            view_proj: scene.camera.view_proj(width, height).to_cols_array_2d(),
            camera_pos: scene.camera.eye_h().as_vec4().to_array(),
            ambient: rgb(scene.ambient, 1.0),
            light_count: scene.lights.len().min(MAX_LIGHTS) as u32,
            flags,
            specular_model: specular.code(),
            illumination: scene.illumination.code(),
            lights,
            env_sh,
            env_occlusion: [[0.0; 4]; 2],
            // Inverted in f64: the far plane's points are large, f32's inverse loses them.
            inv_view_proj: {
                let c = &scene.camera;
                (c.projection(f64::from(width) / f64::from(height.max(1))) * c.view())
                    .inverse()
                    .as_mat4()
                    .to_cols_array_2d()
            },
        }
    }
}

impl ObjectUniform {
    /// Object `object` (number `index`) of `scene` with its material's parameters and textures.
    pub fn new(scene: &Scene, index: usize, object: &Object) -> Self {
        let material = &scene.materials[object.material];
        let nm = glam::DMat4::from_mat3(object.transform.normal_matrix());
        let t = material.base_color_texture.map(|r| r.transform).unwrap_or_default();
        let maps = &material.maps;
        let transforms = [
            maps.metal_roughness.map(|r| r.texture.transform),
            maps.occlusion.map(|r| r.texture.transform),
            maps.emissive.map(|r| r.transform),
            maps.normal.map(|r| r.texture.transform),
        ]
        .map(Option::unwrap_or_default);
        let offset_scale = |t: &UvTransform| [t.offset[0], t.offset[1], t.scale[0], t.scale[1]].map(|x| x as f32);
        let slots = crate::textures::object_slots(scene, object);
        ObjectUniform {
            model: object.transform.matrix().as_mat4().to_cols_array_2d(),
            normal_matrix: nm.as_mat4().to_cols_array_2d(),
            color: rgb(material.color, 1.0),
            mu: rgb(material.mu, 0.0),
            r_s: material.r_s as f32,
            r_d: material.r_d as f32,
            r_a: material.r_a as f32,
            m: material.m as f32,
            h: material.h.value() as f32,
            mirror: material.h.is_mirror() as u32,
            transmission: material.transmission as f32,
            uv_rotation: t.rotation as f32,
            mu_tinted: rgb(material.mu_tinted, 0.0),
            uv_offset_scale: offset_scale(&t),
            metallic_f0: rgb(maps.metal_roughness.map_or([0.0; 3], |m| m.metallic_f0), 0.0),
            emission: rgb(material.emission, 0.0),
            metal_roughness_uv: offset_scale(&transforms[0]),
            occlusion_uv: offset_scale(&transforms[1]),
            emissive_uv: offset_scale(&transforms[2]),
            uv_rotations: [transforms[0].rotation, transforms[1].rotation, transforms[2].rotation, 0.0]
                .map(|x| x as f32),
            maps: slots.iter().zip(crate::textures::MAP_BITS).filter(|(s, _)| s.is_some()).map(|(_, b)| b).sum(),
            occlusion_strength: maps.occlusion.map_or(0.0, |o| o.strength) as f32,
            normal_scale: maps.normal.map_or(1.0, |n| n.scale) as f32,
            phong_normalized: material.phong_normalized as u32,
            normal_uv: offset_scale(&transforms[3]),
            inverse_model: object.transform.matrix().inverse().as_mat4().to_cols_array_2d(),
            ior: rgb(material.refractive_index(), if material.disperses() { 1.0 } else { 0.0 }),
            absorption: rgb(material.absorption, 0.0),
            exit_shape: object.shape.exit_code(),
            absorption_form: shadelab_model::effects::absorption_form(scene, index).code(),
            longest_chord: shadelab_model::effects::longest_chord(scene, index) as f32,
            microfacet: material.microfacet.code(),
            fresnel_mix: [material.fresnel_mix.f0 as f32, material.fresnel_mix.weight as f32, 0.0, 0.0],
        }
    }
}
