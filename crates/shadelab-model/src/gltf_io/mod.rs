//! Scenes in and out as glTF 2.0 (`.gltf` with embedded or external buffers, `.glb`).
//!
//! **Reading** parses the JSON with the `gltf` crate's data model (`gltf::json`), then checks
//! every index, every byte range and every count itself before it reads or allocates anything.
//! It does not call the crate's `validate()` nor `gltf::import`: in gltf 1.4.1 the validation
//! hook of a primitive indexes `root.accessors[...]` unchecked (an out-of-range `POSITION`
//! accessor panics), and `import` reads every buffer and image at its declared size. Bad input
//! is a [`GltfError`], one line that starts with the file's name, never a panic.
//!
//! **Writing** ([`save_scene`]) stores every object as a triangle mesh with normals, the
//! materials as glTF PBR fields that approximate the model, the lights as `KHR_lights_punctual`
//! and the camera, plus the chapter's exact parameters in `extras.shadelab` objects, so that
//! loading the file again gives the same scene.
//!
//! ## The material mapping (glTF metallic–roughness → the chapter's model)
//!
//! | glTF | model | why |
//! |---|---|---|
//! | `roughnessFactor` r | `m = r²` | glTF's perceptual roughness squared is the facet-slope RMS α (glTF 2.0 Appendix B), which Beckmann's `m` is too (docs/model.md §5) |
//! | — | `h = 2/m² − 2`, clamped to [1, `H_MAX`]; `m = 0` is the mirror (`PhongExponent::from_m`, the one h-from-m rule) | the usual Beckmann ↔ Phong lobe match (Walter et al. 2007, "Microfacet models for refraction", the Phong distribution), as the built-in scenes use |
//! | `baseColorFactor`, `metallicFactor` M | `C = baseColor·(1 − M)` | metals have no diffuse part (glTF 2.0 Appendix B, `c_diff = lerp(baseColor, 0, M)`) |
//! | the same, `KHR_materials_ior` v, `KHR_materials_specular` | `μ = lerp(F0, baseColor, M)`, `F0 = min(((v−1)/(v+1))²·specularColor, 1)·specular` | glTF's `F0` (Appendix B and the two extensions' specs); μ is the chapter's reflectance at normal incidence (docs/model.md §5), per channel |
//! | `KHR_materials_transmission` | `t` | the chapter's transparency (docs/model.md §2); stored, not rendered |
//! | `KHR_materials_volume` attenuation colour c, distance D, thickness | `a = −ln(c)/D`, `d` = thickness | glTF's Beer law `c^(x/D)` is the chapter's `e^(−a·x)` (docs/model.md §7); stored, not rendered |
//! | — | `r_s = r_d = r_a = 1` | glTF's base colour is already the whole albedo; with `I_L = E/π` (below) `r_d·C·(N·L)·I_L` is glTF's Lambert `(C/π)·E·(N·L)` |
//!
//! Lights: `I_L = intensity/π` (lux for directional lights, candela for point and spot lights,
//! so a white Lambert face facing a light of π lux shows 1, as in glTF viewers). A point or spot
//! light's falloff is `1/(1 + α d²)` with `α = 1` (`POINT_FALLOFF_ALPHA`): glTF's inverse square
//! beyond about one unit, yet finite at `d = 0`. A spot light keeps its cones (`innerConeAngle`,
//! `outerConeAngle`, `0 ≤ inner < outer ≤ π/2`, else an error) and shines along its node's −Z;
//! glTF's `range` ends a point or spot light with the extension's window `1 − (d/range)⁴`
//! (`brdf::window_range`; the chapter's falloffs have no end), and is ignored with a warning on a
//! directional light. More than `MAX_LIGHTS` lights: the first are kept, with a warning; none: a
//! default directional light, with a warning. Saving runs the mapping backwards
//! (`intensity = I_L·π`, divided by α for a quadratic point or spot light so that the far field
//! agrees) and writes the exact `I_L`, colour, α, falloff form, d0, cones and range in the light's
//! `extras.shadelab`.
//!
//! ## `extras.shadelab`
//!
//! | where | keys |
//! |---|---|
//! | material | `C`, `m`, `h` (number or `"mirror"`), `mu`, `mu_t` (the part of μ the base colour sets), `r_s`, `r_d`, `r_a`, `t`, `a`, `d` |
//! | `KHR_lights_punctual` light | `I_L`, `color`, `alpha`, `falloff_form` (`quadratic`/`linear`), `d0`, `position`, `direction`, `inner_cone`, `outer_cone`, `range` |
//! | scene | `ambient` (`I_amb`), `shading`, `specular` |
//! | mesh | `shape`, `tessellation` (an analytic shape; loaded back as it when the triangles still match) |
//! | node | `translation`, `rotation_y`, `scale` (exact f64 transform) |
//! | camera | `eye`, `target` (orbit pivot), `up`, `fov_y_deg`, `near`, `far`, `ymag` (orthographic) |
//!
//! Every key is optional and range-checked like the command line's flags; a value out of range is
//! an error. Placement values (node, light position/direction, camera) are used only when they
//! agree with the file's own f32 fields within 1e-5 (an edited file keeps its edit).
//!
//! ## Where each concept lives
//!
//! Each file holds one concept of the format, its reading and its writing side by side:
//! `scene_file.rs` the entry points ([`load_scene`], [`save_scene`], …), the glTF scene's own
//! fields and the order in which the others run; `container.rs` the GLB container, buffers
//! (BIN chunk, `data:` URIs, external files) and buffer views; `accessors.rs` typed element
//! arrays; `meshes.rs` primitives (lists, strips, fans) and analytic shapes; `nodes.rs` the node
//! hierarchy, world transforms and the objects placed on it; `materials.rs`, `lights.rs` and
//! `cameras.rs` those objects of the file; `slices.rs` the parse in slices a page runs between
//! its frames; `extras.rs` the field types of `extras.shadelab` and
//! their checked decoding (each concept declares its own `extras.shadelab` object as a serde
//! type, one field per key of the table above); `synthetic.rs` the generated benchmark meshes.

/// Declares an `extras.shadelab` struct: every field an `Option`, absent when read as `None`,
/// and left out when written as `None` (a key given as `null` is a bad value, not an absent one).
macro_rules! extras_struct {
    ($(#[$m:meta])* $vis:vis struct $name:ident { $($(#[$fm:meta])* $field:ident: $ty:ty,)* }) => {
        $(#[$m])*
        #[derive(Default, serde::Serialize, serde::Deserialize)]
        #[serde(default)]
        $vis struct $name {
            $($(#[$fm])* #[serde(skip_serializing_if = "Option::is_none")] $field: $ty,)*
        }
    };
}
use extras_struct;

mod accessors;
mod cameras;
mod confine;
mod container;
mod environment;
mod extras;
mod lights;
mod materials;
mod meshes;
mod nodes;
mod scene_file;
mod slices;
pub mod synthetic;
mod textures;

pub(crate) use container::glb_container;
pub use container::{Externals, percent_decode};
pub use scene_file::{
    load_scene, load_scene_from_bytes, load_scene_from_files, load_scene_from_slice, load_scene_with, save_scene,
    scene_to_glb, scene_to_gltf_json,
};
pub use slices::{ParseSource, SceneParse};
pub use textures::{MAX_IMAGE_FILE_BYTES, MAX_TEXTURE_BYTES, MAX_TEXTURE_SIDE};

use crate::params::{ShadingMode, SpecularModel};
use crate::scene::{Camera, Scene};

/// Most triangles a file may bring (every instance of a mesh counts): the memory budget of a
/// scene. `shadelab bench mesh` measured the peak of a whole run (load, GPU buffers, first frame)
/// on lavapipe, where the GPU's buffers are in the same memory, at about 180 bytes a triangle over
/// the program's own ~110 MiB for a file with normals and about 290 without (the crease-angle rule
/// works on a triangle soup): 16·10⁶ triangles are 3 to 5 GB, which an 8 GB machine still holds.
/// On a discrete GPU about 145 bytes a triangle of that is in its memory instead (smooth and
/// flat vertex buffers, indices). More is more likely a broken or hostile file (u8 indices name a
/// triangle per 3 bytes of file) than a scene; the limit is checked before anything is built.
pub const MAX_TRIANGLES: usize = 16_000_000;

/// Largest scene file or buffer read: 2 GiB. `MAX_TRIANGLES` triangles need at most ~1.3 GB
/// (3 unshared corners × (12 bytes of position + 12 of normal + 4 of index)), so a larger buffer
/// cannot be used, and reading it would only spend memory and time.
pub const MAX_FILE_BYTES: u64 = 1 << 31;

/// Most objects (mesh instances × primitives): each is one draw call and one 256-byte uniform
/// slot, so 16384 objects are 4 MiB of uniforms.
pub const MAX_OBJECTS: usize = 16_384;

/// Most morph-target offsets applied in one file (each target with a weight adds one offset per
/// vertex of its primitive): 3 × `MAX_TRIANGLES`, as many as the largest scene has corners. A few
/// dozen facial blend shapes on a 10⁵-vertex head stay far below; a hostile file naming one
/// large accessor as thousands of weighted targets would otherwise spend minutes adding them.
pub const MAX_MORPH_OFFSETS: usize = 3 * MAX_TRIANGLES;

/// Deepest node hierarchy followed. Character rigs reach ~100 levels; deeper is a broken file.
/// (The walk uses an explicit stack, so this bounds work, not the call stack.)
pub const MAX_NODE_DEPTH: usize = 256;

/// Ambient intensity `I_amb` of a file without `extras.shadelab.ambient`: the built-in scenes'.
pub const DEFAULT_AMBIENT: [f64; 3] = [0.12; 3];

/// glTF's default index of refraction (`KHR_materials_ior`): `((1.5 − 1)/(1.5 + 1))² = 0.04`.
pub const DEFAULT_IOR: f64 = 1.5;

/// Falloff `α` of a glTF point light: `1/(1 + d²)` ≈ glTF's `1/d²` beyond about one unit, and
/// finite at the light.
pub const POINT_FALLOFF_ALPHA: f64 = 1.0;

/// Smallest `KHR_materials_volume` attenuation colour channel used: `c = 0` would make `a`
/// infinite; `−ln(1e-6) ≈ 13.8`, so `e^(−a·D)` is 1e-6 at the attenuation distance.
pub const ATTENUATION_COLOR_MIN: f64 = 1e-6;

/// A μ at or below this in every channel is saved as a dielectric (`metallicFactor` 0, μ via
/// `KHR_materials_ior`); above, as a metal (`baseColorFactor` = μ). Dielectrics reach μ ≈ 0.17
/// (diamond, n = 2.42); metals start at ≈ 0.5 (iron).
pub const DIELECTRIC_MU_MAX: f64 = 0.2;

/// The shading mode and specular model a file asks for (`extras.shadelab` of the glTF scene):
/// not part of [`Scene`], they choose the pipeline.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SceneSettings {
    pub shading: Option<ShadingMode>,
    pub specular: Option<SpecularModel>,
}

/// A scene read from a file, with what the file asks for and what was ignored or changed.
#[derive(Clone, Debug)]
pub struct LoadedScene {
    pub scene: Scene,
    pub settings: SceneSettings,
    /// One line each: unsupported optional extensions, clamped values, defaults added.
    pub warnings: Vec<String>,
    /// Every camera of the file, in the order of the node hierarchy (depth first), with its name
    /// (the camera's, else its node's, else "camera N"). `scene.camera` is the first; none: the
    /// framing camera alone.
    pub cameras: Vec<(String, Camera)>,
}

/// A bad scene file: one line, starting with the file's name.
#[derive(Debug, thiserror::Error)]
pub enum GltfError {
    /// The file cannot be read.
    #[error("{file}: cannot read: {error}")]
    Read { file: String, error: std::io::Error },
    /// Not glTF at all, a broken GLB container or broken JSON.
    #[error("{file}: {detail}")]
    Format { file: String, detail: String },
    /// Well-formed JSON whose content is wrong: a missing or out-of-range index, a byte range past
    /// its buffer, an index past the vertex count, a non-finite position or transform.
    #[error("{file}: {detail}")]
    Invalid { file: String, detail: String },
    /// The file requires extensions this loader does not implement.
    #[error("{file}: requires unsupported extension(s): {extensions}")]
    UnsupportedRequired { file: String, extensions: String },
    /// More than the named limits ([`MAX_TRIANGLES`], [`MAX_OBJECTS`], [`MAX_NODE_DEPTH`]).
    #[error("{file}: {detail}")]
    TooLarge { file: String, detail: String },
    /// The file cannot be written.
    #[error("{file}: cannot write: {error}")]
    Write { file: String, error: std::io::Error },
}

/// The chapter's `m` from glTF's perceptual roughness (see the module's table).
pub fn m_from_roughness(roughness: f64) -> f64 {
    (roughness.clamp(0.0, 1.0)).powi(2)
}

/// glTF's dielectric `F0` (`KHR_materials_ior` v, `KHR_materials_specular` factor and colour).
pub fn dielectric_f0(ior: f64, specular_factor: f64, specular_color: [f64; 3]) -> [f64; 3] {
    let f0 = crate::presets::mu_from_ior(ior);
    specular_color.map(|c| (f0 * c).min(1.0) * specular_factor)
}

#[cfg(test)]
mod tests;
