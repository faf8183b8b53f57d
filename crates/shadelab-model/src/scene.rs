//! Scenes: analytic shapes with transforms, materials, lights and a camera.
//!
//! Shapes stay analytic here (the f64 reference ray-casts them exactly); `mesh` tessellates them
//! for the rasterizer.

use crate::params::*;
use glam::{DMat3, DMat4, DVec3, Mat4};

/// Surface material of the chapter's model (spec §3, §5).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    /// Surface colour `C`, linear RGB in [0, 1].
    pub color: [f64; 3],
    /// Specular share `r_s`.
    pub r_s: f64,
    /// Diffuse share `r_d`.
    pub r_d: f64,
    /// Ambient reflectance `r_a`.
    pub r_a: f64,
    /// Beckmann roughness `m` (Cook–Torrance).
    pub m: f64,
    /// Phong exponent `h` (Phong specular).
    pub h: PhongExponent,
    /// Normal-incidence reflectance `μ` per channel (Cook–Torrance Fresnel).
    pub mu: [f64; 3],
    /// Transparency `t` in [0, 1] (spec §2, glTF `KHR_materials_transmission`). Stored, not
    /// rendered yet.
    pub transmission: f64,
    /// Absorption coefficient `a` per channel, per unit length, of `I_Td = I_T0·e^(−a·d)` (spec §7,
    /// from glTF `KHR_materials_volume`). Stored, not rendered yet.
    pub absorption: [f64; 3],
    /// Thickness `d` of the material for that absorption (spec §7). Stored, not rendered yet.
    pub thickness: f64,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            name: "default".into(),
            color: [0.8, 0.8, 0.8],
            r_s: 1.0,
            r_d: 0.8,
            r_a: 0.8,
            m: 0.3,
            h: PhongExponent::Finite(20.0),
            mu: [0.04; 3],
            transmission: 0.0,
            absorption: [0.0; 3],
            thickness: 0.0,
        }
    }
}

/// A light source (spec §6).
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    /// Position (point lights).
    pub position: DVec3,
    /// Direction the light travels (directional lights); `L = −direction`.
    pub direction: DVec3,
    /// Linear RGB colour.
    pub color: [f64; 3],
    /// Intensity `I_L` (multiplies the colour).
    pub intensity: f64,
    /// Falloff form of point lights.
    pub falloff_form: FalloffForm,
    /// `α` of `1/(1 + α d²)`.
    pub falloff_alpha: f64,
    /// `d0` of `1/(d + d0)`.
    pub d0: f64,
    /// Spot lights: half-angles of the inner cone (full light) and of the outer cone (no light
    /// beyond), radians, `0 ≤ inner < outer ≤ π/2` (glTF `innerConeAngle`, `outerConeAngle`).
    /// The axis is `direction`.
    pub inner_cone: f64,
    pub outer_cone: f64,
    /// Point and spot lights: the distance at which the light ends (glTF `range`), reached
    /// smoothly by [`crate::brdf::window_range`]; `None`: it never ends.
    pub range: Option<f64>,
}

/// glTF's default outer cone of a spot light (π/4), also the cone a light gets when it is made
/// a spot light.
pub const SPOT_OUTER_CONE_DEFAULT: f64 = std::f64::consts::FRAC_PI_4;

impl Light {
    pub fn directional(direction: DVec3, color: [f64; 3], intensity: f64) -> Self {
        Light {
            kind: LightKind::Directional,
            position: -direction.normalize() * LIGHT_STAND_OFF,
            direction: direction.normalize(),
            color,
            intensity,
            falloff_form: FalloffForm::Quadratic,
            falloff_alpha: 0.0,
            d0: 1.0,
            inner_cone: 0.0,
            outer_cone: SPOT_OUTER_CONE_DEFAULT,
            range: None,
        }
    }
    pub fn point(position: DVec3, color: [f64; 3], intensity: f64, falloff_alpha: f64) -> Self {
        Light {
            kind: LightKind::Point,
            position,
            direction: (-position).normalize_or(DVec3::NEG_Y),
            color,
            intensity,
            falloff_form: FalloffForm::Quadratic,
            falloff_alpha,
            d0: 1.0,
            inner_cone: 0.0,
            outer_cone: SPOT_OUTER_CONE_DEFAULT,
            range: None,
        }
    }
    /// A spot light at `position` shining along `direction`, with cones `inner < outer` (radians).
    pub fn spot(
        position: DVec3,
        direction: DVec3,
        color: [f64; 3],
        intensity: f64,
        falloff_alpha: f64,
        (inner_cone, outer_cone): (f64, f64),
    ) -> Self {
        Light {
            kind: LightKind::Spot,
            direction: direction.normalize_or(DVec3::NEG_Y),
            inner_cone,
            outer_cone,
            ..Light::point(position, color, intensity, falloff_alpha)
        }
    }
}

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

/// The aspect ratio the built-in scenes are composed for.
pub const COMPOSED_ASPECT: f64 = 16.0 / 9.0;

/// A perspective camera; the GPU renderer and the f64 reference use the same one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub eye: DVec3,
    pub target: DVec3,
    pub up: DVec3,
    /// Vertical field of view, degrees.
    pub fov_y_deg: f64,
    pub near: f64,
    pub far: f64,
}

impl Camera {
    pub fn view(&self) -> DMat4 {
        DMat4::look_at_rh(self.eye, self.target, self.up)
    }
    pub fn projection(&self, aspect: f64) -> DMat4 {
        DMat4::perspective_rh(self.fov_y_deg.to_radians(), aspect, self.near, self.far)
    }
    /// The same camera with its vertical field of view widened, for images narrower than the
    /// 16:9 the built-in scenes are composed for, so that the whole width still shows.
    pub fn fitted(&self, aspect: f64) -> Camera {
        if aspect >= COMPOSED_ASPECT || aspect <= 0.0 {
            return *self;
        }
        let half = (self.fov_y_deg.to_radians() * 0.5).tan() * COMPOSED_ASPECT / aspect;
        Camera { fov_y_deg: (2.0 * half.atan()).to_degrees().min(120.0), ..*self }
    }

    /// World → clip (wgpu conventions: depth in [0, 1], y up), for the GPU.
    pub fn view_proj(&self, width: u32, height: u32) -> Mat4 {
        (self.projection(width as f64 / height as f64) * self.view()).as_mat4()
    }
    /// The world-space ray through the centre of pixel `(x, y)` (y down) of a `width × height`
    /// image: the same pixel centres the rasterizer samples.
    pub fn ray(&self, x: u32, y: u32, width: u32, height: u32) -> (DVec3, DVec3) {
        let ndc_x = (x as f64 + 0.5) / width as f64 * 2.0 - 1.0;
        let ndc_y = 1.0 - (y as f64 + 0.5) / height as f64 * 2.0;
        let aspect = width as f64 / height as f64;
        let t = (self.fov_y_deg.to_radians() * 0.5).tan();
        let forward = (self.target - self.eye).normalize();
        let right = forward.cross(self.up).normalize();
        let up = right.cross(forward);
        let dir = (forward + right * (ndc_x * t * aspect) + up * (ndc_y * t)).normalize();
        (self.eye, dir)
    }
}

/// A whole scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub name: String,
    pub objects: Vec<Object>,
    pub materials: Vec<Material>,
    pub lights: Vec<Light>,
    /// Scene-wide ambient intensity `I_amb` per channel (spec §3).
    pub ambient: [f64; 3],
    pub camera: Camera,
    /// Triangle meshes from a scene file, indexed by `Shape::Mesh(i)`.
    pub meshes: Vec<crate::mesh::TriangleMesh>,
}

/// Background colour (linear RGB): dark enough for highlights to stand out, not black, so a blank
/// image is told from a dark one.
pub const BACKGROUND: [f64; 3] = [0.03, 0.035, 0.045];

/// How far from the origin a directional light is placed when it becomes a point light: twice as
/// far as any built-in object but the ground (all within 3 of the origin), so it lights them from
/// about the same direction as before.
pub const LIGHT_STAND_OFF: f64 = 6.0;

/// Most lights a scene may hold (the GPU uniform has this many slots).
pub const MAX_LIGHTS: usize = 8;

/// Names of the scenes compiled into the binary.
pub const BUILTIN_SCENES: &[&str] = &["default", "sphere", "cylinder", "pyramid", "cube"];

/// What the command line or the viewer overrides in a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overrides {
    pub m: Option<f64>,
    pub h: Option<PhongExponent>,
    pub mu: Option<[f64; 3]>,
    pub falloff_alpha: Option<f64>,
    pub falloff_form: Option<FalloffForm>,
    pub d0: Option<f64>,
    pub light: Option<LightKind>,
}

impl Scene {
    /// A built-in scene by name (see [`BUILTIN_SCENES`]).
    pub fn builtin(name: &str) -> Option<Scene> {
        match name {
            "default" => Some(default_scene()),
            "sphere" => Some(single_shape_scene("sphere", Shape::Sphere, 16)),
            "cylinder" => Some(single_shape_scene("cylinder", Shape::Cylinder, 16)),
            "pyramid" => Some(single_shape_scene("pyramid", Shape::Pyramid, 1)),
            "cube" => Some(single_shape_scene("cube", Shape::Cube, 1)),
            _ => None,
        }
    }

    /// Apply command-line or panel overrides to every material and light.
    pub fn apply(&mut self, o: &Overrides) {
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
        }
        for light in &mut self.lights {
            if let Some(kind) = o.light {
                light.set_kind(kind);
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
        }
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

impl Light {
    /// Turn the light into another kind, keeping where it shines from: a directional light
    /// becomes a point or spot light `LIGHT_STAND_OFF` units back along its direction from the
    /// origin (a spot keeps the direction as its axis); a point light becomes a directional light
    /// or a spot light along the line from it to the origin; a spot light keeps its position
    /// (point) or its axis (directional).
    pub fn set_kind(&mut self, kind: LightKind) {
        use LightKind::*;
        match (self.kind, kind) {
            (Directional, Point | Spot) => self.position = -self.direction * LIGHT_STAND_OFF,
            (Point, Directional | Spot) => self.direction = (-self.position).normalize_or(DVec3::NEG_Y),
            _ => {}
        }
        self.kind = kind;
    }
}

/// The Phong exponent that gives a lobe about as wide as Beckmann roughness `m`
/// (`h = 2/m² − 2`, the usual Beckmann–Phong correspondence), rounded.
fn h_like_m(m: f64) -> PhongExponent {
    PhongExponent::Finite((2.0 / (m * m) - 2.0).max(1.0).round())
}

fn default_camera() -> Camera {
    Camera {
        eye: DVec3::new(0.0, 2.1, 5.2),
        target: DVec3::new(0.0, 0.35, -0.4),
        up: DVec3::Y,
        fov_y_deg: 40.0,
        near: 0.1,
        far: 50.0,
    }
}

fn default_lights() -> Vec<Light> {
    vec![
        Light::directional(DVec3::new(-0.55, -1.0, -0.7), [1.0, 0.97, 0.92], 0.75),
        Light::point(DVec3::new(-2.2, 2.4, 2.4), [0.92, 0.96, 1.0], 1.1, 0.06),
    ]
}

fn ground() -> (Object, Material) {
    (
        Object {
            name: "ground".into(),
            shape: Shape::Plane,
            tessellation: 16,
            transform: Transform::new(DVec3::ZERO, DVec3::new(5.0, 1.0, 3.6)),
            material: 0,
        },
        Material {
            name: "ground".into(),
            color: [0.32, 0.32, 0.3],
            r_s: 0.25,
            r_d: 0.8,
            r_a: 0.8,
            m: 0.5,
            h: PhongExponent::Finite(6.0),
            mu: [0.04; 3],
            ..Material::default()
        },
    )
}

/// The default scene: a row of red plastic spheres going from sharp to rough (m increasing, h
/// decreasing alike), a gold cylinder and a stone pyramid on a ground plane, with a directional
/// key light and a point light.
pub fn default_scene() -> Scene {
    let (ground_obj, ground_mat) = ground();
    let mut objects = vec![ground_obj];
    let mut materials = vec![ground_mat];
    for (i, m) in [0.08, 0.15, 0.25, 0.4, 0.7].into_iter().enumerate() {
        materials.push(Material {
            name: format!("plastic m={m}"),
            color: [0.75, 0.12, 0.08],
            r_s: 1.0,
            r_d: 0.8,
            r_a: 0.8,
            m,
            h: h_like_m(m),
            mu: [0.04; 3],
            ..Material::default()
        });
        objects.push(Object {
            name: format!("sphere {}", i + 1),
            shape: Shape::Sphere,
            tessellation: 16,
            transform: Transform::new(DVec3::new(-2.0 + i as f64, 0.42, 0.7), DVec3::splat(0.42)),
            material: materials.len() - 1,
        });
    }
    materials.push(Material {
        name: "gold".into(),
        color: [1.0, 0.766, 0.336],
        r_s: 1.0,
        r_d: 0.25,
        r_a: 0.5,
        m: 0.2,
        h: h_like_m(0.2),
        // Gold's reflectance at normal incidence (linear sRGB), Filament's material table.
        mu: [1.0, 0.766, 0.336],
        ..Material::default()
    });
    objects.push(Object {
        name: "cylinder".into(),
        shape: Shape::Cylinder,
        tessellation: 16,
        transform: Transform::new(DVec3::new(-1.5, 0.7, -1.1), DVec3::new(0.45, 0.7, 0.45)),
        material: materials.len() - 1,
    });
    materials.push(Material {
        name: "stone".into(),
        color: [0.82, 0.8, 0.74],
        r_s: 0.4,
        r_d: 0.85,
        r_a: 0.8,
        m: 0.3,
        h: h_like_m(0.3),
        mu: [0.05; 3],
        ..Material::default()
    });
    objects.push(Object {
        name: "pyramid".into(),
        shape: Shape::Pyramid,
        tessellation: 1,
        transform: Transform {
            translation: DVec3::new(1.5, 0.65, -1.1),
            rotation_y: 30f64.to_radians(),
            scale: DVec3::splat(0.65),
        },
        material: materials.len() - 1,
    });
    Scene {
        name: "default".into(),
        objects,
        materials,
        lights: default_lights(),
        ambient: [0.12; 3],
        camera: default_camera(),
        meshes: Vec::new(),
    }
}

/// One shape on the ground, lit by the default lights: the scenes the reference knows exactly.
pub fn single_shape_scene(name: &str, shape: Shape, tessellation: u32) -> Scene {
    let (ground_obj, ground_mat) = ground();
    let material = Material {
        name: "blue plastic".into(),
        color: [0.15, 0.3, 0.8],
        m: 0.2,
        h: h_like_m(0.2),
        ..Material::default()
    };
    let (translation, scale, rotation_y) = match shape {
        Shape::Cylinder => (DVec3::new(0.0, 0.9, 0.0), DVec3::new(0.7, 0.9, 0.7), 0.0),
        Shape::Pyramid => (DVec3::new(0.0, 0.9, 0.0), DVec3::splat(0.9), 30f64.to_radians()),
        Shape::Cube => (DVec3::new(0.0, 0.7, 0.0), DVec3::splat(0.7), 30f64.to_radians()),
        _ => (DVec3::new(0.0, 1.0, 0.0), DVec3::splat(1.0), 0.0),
    };
    Scene {
        name: name.into(),
        objects: vec![
            ground_obj,
            Object {
                name: name.into(),
                shape,
                tessellation,
                transform: Transform { translation, rotation_y, scale },
                material: 1,
            },
        ],
        materials: vec![ground_mat, material],
        lights: default_lights(),
        ambient: [0.12; 3],
        camera: Camera { eye: DVec3::new(0.0, 2.2, 4.6), target: DVec3::new(0.0, 0.8, 0.0), ..default_camera() },
        meshes: Vec::new(),
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
        let c = default_camera();
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
}
