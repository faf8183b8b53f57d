//! The sweep's inputs: its axes (geometries, m, h, μ, d, α), their full product and the table
//! the kernel reads them from.

use glam::DVec3;
use shadelab_model::guards::{D0_MIN, H_MAX};
use shadelab_model::{Light, Scene};

/// One geometry: a (possibly zero or non-unit) normal, and unit view and light vectors, in f32
/// as the GPU gets them.
#[derive(Clone, Copy, Debug)]
pub struct Geometry {
    pub n: [f32; 3],
    pub v: [f32; 3],
    pub l: [f32; 3],
    pub label: &'static str,
}

/// One shadow projection the sweep maps points through: a light's view-projection as the GPU gets
/// it (f32), the world size of its texel and whether it is perspective.
#[derive(Clone, Copy, Debug)]
pub struct ShadowCase {
    pub matrix: [[f32; 4]; 4],
    pub texel_world: f32,
    pub perspective: bool,
    pub label: &'static str,
}

impl ShadowCase {
    fn new(p: &shadelab_model::shadows::ShadowProjection, face: usize, label: &'static str) -> ShadowCase {
        ShadowCase {
            matrix: p.matrices[face].as_mat4().to_cols_array_2d(),
            texel_world: p.texel_world as f32,
            perspective: p.perspective,
            label,
        }
    }

    /// The matrix as the f64 side reads it: the f32 values the GPU multiplies by.
    pub fn dmat4(&self) -> glam::DMat4 {
        glam::Mat4::from_cols_array_2d(&self.matrix).as_dmat4()
    }
}

/// The hard shadow projections (docs/model.md §9): grazing light, a light at the scene's centre
/// or far outside it (near ≈ far), a scene of zero size and one of 10⁶, the widest spot cone, a
/// cascade.
fn shadow_cases() -> Vec<ShadowCase> {
    use shadelab_model::shadows::{cascade_count, cascade_projection, scene_bounds, shadow_projection};
    let o = DVec3::ZERO;
    let grazing = Light::directional(DVec3::new(1.0, -1e-7, 0.3), [1.0; 3], 1.0);
    let down = Light::directional(DVec3::NEG_Y, [1.0; 3], 1.0);
    let at_centre = Light::point(o, [1.0; 3], 1.0, 0.0);
    let far = Light::point(DVec3::new(1e6, 0.0, 0.0), [1.0; 3], 1.0, 0.0);
    let spot = Light::spot(o, DVec3::new(0.2, -1.0, 0.1), [1.0; 3], 1.0, 0.0, (1.4, 89f64.to_radians()));
    let field = Scene::builtin("field").expect("built-in");
    let (centre, radius) = scene_bounds(&field).expect("objects");
    let cascades =
        cascade_projection(&field.lights[0], &field, 16.0 / 9.0, (centre, radius), 2048, cascade_count(&field));
    vec![
        ShadowCase::new(&shadow_projection(&grazing, o, 1.0, 2048), 0, "directional, grazing 1e-7"),
        ShadowCase::new(&shadow_projection(&down, o, 1e6, 256), 0, "directional, scene radius 1e6"),
        ShadowCase::new(&shadow_projection(&down, o, 0.0, 4096), 0, "directional, scene of zero size"),
        ShadowCase::new(&shadow_projection(&at_centre, o, 1.0, 2048), 0, "point at the centre, +x face"),
        ShadowCase::new(&shadow_projection(&at_centre, o, 0.0, 2048), 3, "point, zero-size scene (near ≈ far)"),
        ShadowCase::new(&shadow_projection(&far, o, 1.0, 1024), 1, "point 1e6 away (near ≈ far)"),
        ShadowCase::new(&shadow_projection(&spot, o, 10.0, 2048), 0, "spot, widest cone"),
        ShadowCase::new(&cascades, 0, "first cascade of 'field'"),
    ]
}

/// The sweep's axes; the combinations are their full product.
pub struct SweepInputs {
    pub geometry: Vec<Geometry>,
    pub m: Vec<f32>,
    /// (h, mirror)
    pub h: Vec<(f32, bool)>,
    pub mu: Vec<[f32; 3]>,
    pub d: Vec<f32>,
    /// (α of the quadratic falloff, d0 of the linear one)
    pub alpha: Vec<(f32, f32)>,
    /// The shadow projections; combination (geometry g, m index i) uses case (g + i) mod count.
    pub shadow: Vec<ShadowCase>,
}

fn unit(v: DVec3) -> [f32; 3] {
    v.normalize().as_vec3().to_array()
}

fn dir(theta_deg: f64, phi_deg: f64) -> DVec3 {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    DVec3::new(t.sin() * p.cos(), t.cos(), t.sin() * p.sin())
}

/// Grazing light and view at angles approaching 90° from both sides, onto `g`.
fn push_grazing(g: &mut Vec<Geometry>) {
    let y = [0.0f32, 1.0, 0.0];
    for (k, eps) in [1e-7f64, 1e-5, 1e-3, -1e-7, -1e-5].into_iter().enumerate() {
        let t = 90.0 - eps.to_degrees();
        let labels = [
            "grazing light +1e-7",
            "grazing light +1e-5",
            "grazing light +1e-3",
            "grazing light −1e-7",
            "grazing light −1e-5",
        ];
        g.push(Geometry { n: y, v: unit(dir(20.0, 0.0)), l: unit(dir(t, 180.0)), label: labels[k] });
        let labels = [
            "grazing view +1e-7",
            "grazing view +1e-5",
            "grazing view +1e-3",
            "grazing view −1e-7",
            "grazing view −1e-5",
        ];
        g.push(Geometry { n: y, v: unit(dir(t, 0.0)), l: unit(dir(20.0, 180.0)), label: labels[k] });
        g.push(Geometry { n: y, v: unit(dir(t, 0.0)), l: unit(dir(t, 180.0)), label: "both grazing, mirror" });
    }
}

/// Views exactly and nearly in the light's mirror direction, onto `g`.
fn push_mirror(g: &mut Vec<Geometry>) {
    let y = [0.0f32, 1.0, 0.0];
    for theta in [0.5, 10.0, 45.0, 80.0, 89.9] {
        g.push(Geometry { n: y, v: unit(dir(theta, 0.0)), l: unit(dir(theta, 180.0)), label: "mirror direction" });
        for off in [1e-4, 1e-3, 0.08, 1.0] {
            g.push(Geometry {
                n: y,
                v: unit(dir(theta + off, 0.0)),
                l: unit(dir(theta, 180.0)),
                label: "near mirror direction",
            });
        }
    }
}

/// A deterministic spread over the sphere (normals tilted too) onto `g`, up to 150 in all.
fn push_spread(g: &mut Vec<Geometry>) {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    while g.len() < 150 {
        let n = dir(rnd() * 60.0, rnd() * 360.0);
        let v = dir(rnd() * 180.0, rnd() * 360.0);
        let l = dir(rnd() * 180.0, rnd() * 360.0);
        g.push(Geometry { n: unit(n), v: unit(v), l: unit(l), label: "spread" });
    }
}

impl SweepInputs {
    /// The hard cases of docs/model.md §9 plus a deterministic spread of ordinary directions.
    pub fn standard() -> SweepInputs {
        let y = [0.0f32, 1.0, 0.0];
        let mut g = vec![
            Geometry { n: y, v: y, l: y, label: "normal incidence" },
            Geometry { n: y, v: unit(dir(30.0, 0.0)), l: [1.0, 0.0, 0.0], label: "light exactly at 90°" },
            Geometry { n: y, v: [1.0, 0.0, 0.0], l: unit(dir(30.0, 180.0)), label: "view exactly at 90°" },
            Geometry { n: y, v: [0.0, 0.0, 1.0], l: [1.0, 0.0, 0.0], label: "light and view at 90°" },
            Geometry { n: y, v: [-1.0, 0.0, 0.0], l: [1.0, 0.0, 0.0], label: "L = −V at 90°" },
            Geometry { n: y, v: unit(dir(40.0, 180.0) * -1.0), l: unit(dir(40.0, 180.0)), label: "L = −V" },
            Geometry { n: y, v: unit(dir(120.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "back-facing view" },
            Geometry { n: y, v: unit(dir(30.0, 0.0)), l: unit(dir(120.0, 180.0)), label: "light below horizon" },
            Geometry { n: [0.0; 3], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "zero normal" },
            Geometry { n: [0.0, 1e-3, 0.0], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "short normal" },
            Geometry { n: [0.0, 1e-12, 0.0], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "tiny normal" },
            Geometry { n: [0.0, 1e3, 0.0], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "long normal" },
            Geometry {
                n: [0.3, 2.0, -0.5],
                v: unit(dir(10.0, 45.0)),
                l: unit(dir(50.0, 200.0)),
                label: "non-unit normal",
            },
        ];
        push_grazing(&mut g);
        push_mirror(&mut g);
        push_spread(&mut g);
        SweepInputs {
            geometry: g,
            m: vec![0.0, 1e-6, 1e-3, 0.01, 0.05, 0.2, 0.5, 1.0],
            h: vec![
                (1.0, false),
                (2.0, false),
                (20.0, false),
                (1e3, false),
                (1e6, false),
                (1e9, false),
                (H_MAX as f32, true),
            ],
            mu: vec![[0.0; 3], [1e-6, 0.02, 0.04], [0.5; 3], [1.0, 0.766, 0.336], [1.0; 3]],
            d: vec![0.0, 1e-6, 1e-4, 0.01, 1.0, 100.0, 1e4],
            alpha: vec![(0.0, D0_MIN as f32), (1e-3, 0.01), (1.0, 1.0), (1e3, 10.0), (1e6, 1e3)],
            shadow: shadow_cases(),
        }
    }

    pub fn combinations(&self) -> usize {
        self.geometry.len() * self.m.len() * self.h.len() * self.mu.len() * self.d.len() * self.alpha.len()
    }

    /// The axes' indices of a combination (the kernel's decomposition).
    pub(super) fn split(&self, idx: usize) -> [usize; 6] {
        let mut r = idx;
        let ai = r % self.alpha.len();
        r /= self.alpha.len();
        let di = r % self.d.len();
        r /= self.d.len();
        let ui = r % self.mu.len();
        r /= self.mu.len();
        let hi = r % self.h.len();
        r /= self.h.len();
        let mi = r % self.m.len();
        [r / self.m.len(), mi, hi, ui, di, ai]
    }

    /// The shadow case of the combination with geometry `gi` and m index `mi`.
    pub fn shadow_case(&self, gi: usize, mi: usize) -> &ShadowCase {
        &self.shadow[(gi + mi) % self.shadow.len()]
    }

    /// A combination's inputs in words.
    pub fn describe(&self, idx: usize) -> String {
        let [gi, mi, hi, ui, di, ai] = self.split(idx);
        let g = &self.geometry[gi];
        let h = if self.h[hi].1 { "mirror".to_string() } else { format!("{:e}", self.h[hi].0) };
        format!(
            "{}: n={:?} v={:?} l={:?} m={:e} h={} μ={:?} d={:e} α={:e} d0={:e}; shadow: {}",
            g.label,
            g.n,
            g.v,
            g.l,
            self.m[mi],
            h,
            self.mu[ui],
            self.d[di],
            self.alpha[ai].0,
            self.alpha[ai].1,
            self.shadow_case(gi, mi).label
        )
    }

    pub(super) fn table(&self) -> Vec<[f32; 4]> {
        let mut t = geometry_rows(&self.geometry);
        t.extend(self.m.iter().map(|&m| [m, 0.0, 0.0, 0.0]));
        t.extend(self.h.iter().map(|&(h, mirror)| [h, mirror as u32 as f32, 0.0, 0.0]));
        t.extend(self.mu.iter().map(|mu| [mu[0], mu[1], mu[2], 0.0]));
        t.extend(self.d.iter().map(|&d| [d, 0.0, 0.0, 0.0]));
        t.extend(self.alpha.iter().map(|&(a, d0)| [a, d0, 0.0, 0.0]));
        for c in &self.shadow {
            t.extend(c.matrix);
            t.push([c.texel_world, c.perspective as u32 as f32, 0.0, 0.0]);
        }
        t
    }
}

/// The kernels' first rows: each geometry's n, v and l.
pub(super) fn geometry_rows(geometry: &[Geometry]) -> Vec<[f32; 4]> {
    geometry.iter().flat_map(|g| [g.n, g.v, g.l].map(|v| [v[0], v[1], v[2], 0.0])).collect()
}
