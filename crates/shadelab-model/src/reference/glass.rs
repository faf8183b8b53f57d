//! The reference's Whitted-style tracer through transparent objects (docs/transparency.md). At
//! every interface: Snell's law, the chapter's exact Fresnel factor per channel and total
//! internal reflection; inside: Beer–Lambert over the exact path; both the reflected and the
//! refracted ray are followed, to `GLASS_MAX_DEPTH` interfaces. The leaves a path ends on are
//! the shaded scene, or 1 for the energy check (no path returns more light than it received).

use super::intersect::{SurfaceHit, glass_exit, trace};
use super::{Context, Shaded};
use crate::lighting::transmission::{absorption_exact, fresnel_dielectric, reflect_about, refract_snell};
use crate::scene::{BACKGROUND, Material};
use glam::{DVec3, DVec4};
use std::cell::{Cell, RefCell};

/// Interfaces a path crosses or reflects off before the tracer stops: 12 takes a ray through
/// four spheres in a row, or around a slab's total internal reflection five times.
pub const GLASS_MAX_DEPTH: u32 = 12;
/// A path carrying less than this share of the pixel's light is not followed: the light it drops
/// is under 1e-4 of the pixel's, below an 8-bit step (1/255).
pub const GLASS_MIN_WEIGHT: f64 = 1e-4;
/// A ray leaving a surface starts this far along its direction, relative to the scene's size,
/// so that it does not meet the surface it leaves through rounding: far above f64's rounding,
/// far below a pixel's footprint.
pub const SECONDARY_RAY_OFFSET: f64 = 1e-7;

/// What a path ends on.
pub(super) trait Leaves {
    /// An opaque surface, seen from `from`.
    fn opaque(&self, ctx: &Context, hit: &SurfaceHit, from: DVec3) -> [f64; 3];
    /// Nothing: the ray leaves the scene along unit `dir`.
    fn background(&self, ctx: &Context, dir: DVec3) -> [f64; 3];
    /// A glass surface's own light from the lights (its diffuse, ambient and specular terms with
    /// `material`), seen from `eye`.
    fn glass_surface(&self, ctx: &Context, hit: &SurfaceHit, eye: DVec4, material: &Material) -> Shaded;
}

/// The image's leaves: the scene shaded as the reference shades it.
pub(super) struct SceneLeaves {
    tinted: RefCell<Vec<Material>>,
}

impl SceneLeaves {
    pub fn new(ctx: &Context) -> SceneLeaves {
        SceneLeaves { tinted: RefCell::new(ctx.scene.materials.clone()) }
    }
}

impl Leaves for SceneLeaves {
    fn opaque(&self, ctx: &Context, hit: &SurfaceHit, from: DVec3) -> [f64; 3] {
        ctx.shade_hit(hit, from.extend(1.0), &mut self.tinted.borrow_mut(), None, None, None).lit
    }
    fn background(&self, ctx: &Context, dir: DVec3) -> [f64; 3] {
        glass_miss(ctx, dir)
    }
    fn glass_surface(&self, ctx: &Context, hit: &SurfaceHit, eye: DVec4, material: &Material) -> Shaded {
        ctx.shade_hit(hit, eye, &mut self.tinted.borrow_mut(), None, Some(material), None)
    }
}

/// What a ray through glass that meets nothing sees along unit `dir`, as the glass pass: the
/// environment where it is the background, else the scene's background (in a term view too).
pub(super) fn glass_miss(ctx: &Context, dir: DVec3) -> [f64; 3] {
    ctx.env_background(dir).unwrap_or(BACKGROUND)
}

/// The tracer: a context, its leaves, and the light of the paths it stopped (the energy check's
/// allowance).
pub(super) struct Tracer<'a, L: Leaves> {
    pub ctx: &'a Context<'a>,
    pub leaves: &'a L,
    /// The largest channel weight of the paths not followed, summed.
    pub lost: Cell<f64>,
    offset: f64,
}

fn scale(w: [f64; 3], k: f64) -> [f64; 3] {
    w.map(|x| x * k)
}

fn heaviest(w: [f64; 3]) -> f64 {
    w.into_iter().fold(0.0, f64::max)
}

impl<'a, L: Leaves> Tracer<'a, L> {
    pub fn new(ctx: &'a Context<'a>, leaves: &'a L) -> Self {
        Tracer { ctx, leaves, lost: Cell::new(0.0), offset: SECONDARY_RAY_OFFSET * ctx.rays.scale }
    }

    fn drop_path(&self, w: [f64; 3]) {
        self.lost.set(self.lost.get() + heaviest(w));
    }

    /// The light that comes back along the ray from `o` along unit `dir`, carrying weight `w` of
    /// the pixel's light; `channel`: the one channel a dispersing path follows.
    pub fn radiance(&self, o: DVec3, dir: DVec3, depth: u32, w: [f64; 3], channel: Option<usize>) -> [f64; 3] {
        let ctx = self.ctx;
        let Some(hit) = trace(ctx.scene, ctx.geo, o + dir * self.offset, dir) else {
            return self.leaves.background(ctx, dir);
        };
        if ctx.scene.drawn_as_glass(hit.object) {
            return self.glass_color(&hit, dir, o.extend(1.0), depth, w, channel).lit;
        }
        self.leaves.opaque(ctx, &hit, o)
    }

    /// A transparent surface hit along `dir`, seen from `eye`: its own light with C·(1 − τ), and
    /// τ of the light the reflected and the refracted paths bring, split by Fresnel.
    pub fn glass_color(
        &self,
        hit: &SurfaceHit,
        dir: DVec3,
        eye: DVec4,
        depth: u32,
        w: [f64; 3],
        channel: Option<usize>,
    ) -> Shaded {
        let ctx = self.ctx;
        let mat = &ctx.scene.materials[ctx.scene.objects[hit.object].material];
        if channel.is_none() && mat.disperses() {
            // Each channel bends by its own index: three paths, one channel each.
            let per = [0, 1, 2].map(|c| self.glass_color(hit, dir, eye, depth, w, Some(c)));
            return Shaded {
                lit: [per[0].lit[0], per[1].lit[1], per[2].lit[2]],
                unshadowed: [per[0].unshadowed[0], per[1].unshadowed[1], per[2].unshadowed[2]],
                hidden: per[0].hidden | per[1].hidden | per[2].hidden,
            };
        }
        let tau = mat.transmission;
        let surface_mat = Material { color: mat.color.map(|c| c * (1.0 - tau)), ..mat.clone() };
        let surface = self.leaves.glass_surface(ctx, hit, eye, &surface_mat);
        // The outward normal faces the incoming ray.
        let n1 = if hit.normal.dot(dir) > 0.0 { -hit.normal } else { hit.normal };
        let v = mat.refractive_index()[channel.unwrap_or(0)];
        let f1 = fresnel_dielectric(-dir.dot(n1), v);
        let p1 = hit.point;
        let wr = scale(w, tau * f1);
        let mirror = if depth + 1 < GLASS_MAX_DEPTH && heaviest(wr) >= GLASS_MIN_WEIGHT {
            self.radiance(p1, reflect_about(dir, n1), depth + 1, wr, channel)
        } else {
            self.drop_path(wr);
            [0.0; 3]
        };
        let inside = match refract_snell(dir, n1, 1.0 / v) {
            Some(t1) => self.glass_path(hit.object, mat, v, p1, t1, depth + 1, scale(w, tau * (1.0 - f1)), channel),
            None => [0.0; 3],
        };
        let through: [f64; 3] = std::array::from_fn(|i| tau * (f1 * mirror[i] + (1.0 - f1) * inside[i]));
        Shaded {
            lit: std::array::from_fn(|i| surface.lit[i] + through[i]),
            unshadowed: std::array::from_fn(|i| surface.unshadowed[i] + through[i]),
            hidden: surface.hidden,
        }
    }

    /// The light that comes back along the path inside object `obj` from `p` along unit `t`:
    /// absorbed over the exact length to the exit, then split there into the refracted ray out and
    /// the reflected ray back in (all of it back in under total internal reflection).
    #[allow(clippy::too_many_arguments)]
    fn glass_path(
        &self,
        obj: usize,
        mat: &Material,
        v: f64,
        p: DVec3,
        t: DVec3,
        depth: u32,
        w: [f64; 3],
        channel: Option<usize>,
    ) -> [f64; 3] {
        if depth >= GLASS_MAX_DEPTH || heaviest(w) < GLASS_MIN_WEIGHT {
            self.drop_path(w);
            return [0.0; 3];
        }
        let ctx = self.ctx;
        // A mesh's exit is searched past the point the path starts on.
        let Some((p2, n2)) = glass_exit(ctx.scene, ctx.geo, obj, p + t * self.offset, t) else {
            self.drop_path(w);
            return [0.0; 3];
        };
        let d = (p2 - p).length();
        let a: [f64; 3] = std::array::from_fn(|i| absorption_exact(mat.absorption[i] * d));
        let f2 = fresnel_dielectric(t.dot(n2), 1.0 / v);
        let wa: [f64; 3] = std::array::from_fn(|i| w[i] * a[i]);
        let out = match refract_snell(t, -n2, v) {
            Some(t2) if f2 < 1.0 => self.radiance(p2, t2, depth + 1, scale(wa, 1.0 - f2), channel),
            _ => [0.0; 3],
        };
        let back = if f2 > 0.0 {
            self.glass_path(obj, mat, v, p2, reflect_about(t, n2), depth + 1, scale(wa, f2), channel)
        } else {
            [0.0; 3]
        };
        std::array::from_fn(|i| a[i] * ((1.0 - f2) * out[i] + f2 * back[i]))
    }
}

impl Context<'_> {
    /// A transparent object's pixel: the primary ray along `dir` hits it at `hit`.
    pub fn glass(&self, hit: &SurfaceHit, dir: DVec3, eye: DVec4) -> Shaded {
        let leaves = SceneLeaves::new(self);
        Tracer::new(self, &leaves).glass_color(hit, dir, eye, 0, [1.0; 3], None)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::SpecularModel;
    use crate::reference::Geometry;
    use crate::reference::shadow_rays::ShadowRays;
    use crate::scene::{Object, Scene, Shape, Transform};

    /// Every leaf returns 1 and glass has no light of its own: what a pixel returns is the share
    /// of its light the paths carried out.
    struct Furnace;
    impl Leaves for Furnace {
        fn opaque(&self, _: &Context, _: &SurfaceHit, _: DVec3) -> [f64; 3] {
            [1.0; 3]
        }
        fn background(&self, _: &Context, _: DVec3) -> [f64; 3] {
            [1.0; 3]
        }
        fn glass_surface(&self, _: &Context, _: &SurfaceHit, _: DVec4, _: &Material) -> Shaded {
            Shaded::default()
        }
    }

    fn glass_scene(shape: Shape, ior: [f64; 3], absorption: [f64; 3]) -> Scene {
        let mut s = Scene::builtin("sphere").unwrap();
        s.objects = vec![Object {
            name: "glass".into(),
            shape,
            tessellation: 16,
            transform: Transform { rotation_y: 0.4, ..Transform::new(DVec3::ZERO, DVec3::new(1.0, 0.7, 0.9)) },
            material: 0,
        }];
        s.materials = vec![Material { transmission: 1.0, ior: Some(ior), absorption, ..Material::default() }];
        s
    }

    /// No path returns more light than it received: with every leaf 1, a pixel through glass
    /// returns at most 1, and without absorption all of it less what the tracer stopped; with
    /// absorption strictly less. Every shape, indices from 1 to 3, dispersing too, rays from every
    /// side, through the critical angles.
    #[test]
    fn no_path_returns_more_light_than_it_received() {
        let mut checked = 0;
        for shape in [Shape::Sphere, Shape::Cube, Shape::Cylinder, Shape::Pyramid, Shape::Plane] {
            for ior in [[1.0; 3], [1.5; 3], [2.4; 3], [3.0; 3], [1.45, 1.5, 1.6]] {
                for absorb in [[0.0; 3], [0.3, 1.0, 4.0]] {
                    let scene = glass_scene(shape, ior, absorb);
                    let geo = Geometry::new(&scene);
                    let rays = ShadowRays::new(&scene, &geo);
                    let ctx = Context {
                        scene: &scene,
                        geo: &geo,
                        rays: &rays,
                        specular: SpecularModel::Phong,
                        exact: true,
                        env: None,
                        env_use: super::super::EnvUse::Sh,
                        area_error: Default::default(),
                        areas: Vec::new(),
                    };
                    for k in 0..200 {
                        // Rays from a sphere of radius 4 around the object, aimed at points inside it.
                        let (u, w) = ((k as f64 * 0.618034).fract(), (k as f64 * 0.414214).fract());
                        let (theta, phi) = ((1.0 - 2.0 * u).acos(), std::f64::consts::TAU * w);
                        let o = DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin()) * 4.0;
                        let aim = DVec3::new(
                            (k % 7) as f64 / 7.0 - 0.5,
                            (k % 5) as f64 / 5.0 - 0.5,
                            (k % 3) as f64 / 3.0 - 0.5,
                        );
                        let dir = (aim * 0.9 - o).normalize();
                        let Some(hit) = trace(&scene, &geo, o, dir) else { continue };
                        let tracer = Tracer::new(&ctx, &Furnace);
                        let out = tracer.glass_color(&hit, dir, o.extend(1.0), 0, [1.0; 3], None).lit;
                        let lost = tracer.lost.get();
                        for (c, x) in out.into_iter().enumerate() {
                            assert!(
                                x.is_finite() && x <= 1.0 + 1e-12,
                                "{shape:?} ior {ior:?}: channel {c} returns {x}"
                            );
                            if absorb == [0.0; 3] {
                                assert!(x >= 1.0 - lost - 1e-9, "{shape:?} ior {ior:?}: {x} + lost {lost} < 1");
                            } else if shape != Shape::Plane && c == 2 {
                                // The strongest absorber keeps under 1 (the plane has no inside).
                                assert!(x < 1.0, "{shape:?}: absorption took nothing ({x})");
                            }
                        }
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 3000, "{checked} rays hit glass");
    }

    /// Total internal reflection keeps light in: a ray entering a cube's top face steeply enough
    /// meets a side face beyond the critical angle and carries none out there, and with every
    /// leaf 1 no light is lost to it.
    #[test]
    fn total_internal_reflection_reflects_everything() {
        use crate::lighting::transmission::{SHAPE_CUBE, shape_exit};
        // Inside a cube of index 1.5, a direction 60° from a side's normal is past asin(1/1.5) = 41.8°.
        let d = DVec3::new(60f64.to_radians().cos(), -60f64.to_radians().sin(), 0.0);
        let (t, n) = shape_exit(SHAPE_CUBE, DVec3::new(0.9, 0.95, 0.0), d).unwrap();
        assert!(t > 0.0 && n == DVec3::X);
        assert!(refract_snell(d, -n, 1.5).is_none());
        assert_eq!(fresnel_dielectric(d.dot(n), 1.0 / 1.5), 1.0);
    }
}
