//! The reference renderer: rays cast through the same pixel centres as the rasterizer, hitting
//! the *analytic* shapes (exact normals, no tessellation), shaded by the f64 model. The ground
//! truth for tests and for the accuracy study.

use crate::lighting::common::safe_normalize;
use crate::lighting::shading::shade;
use crate::mesh::{TriangleMesh, face_normal};
use crate::params::SpecularModel;
use crate::scene::{BACKGROUND, Object, Scene, Shape};
use glam::{DMat4, DVec3};

/// A linear RGB image in f64, rows top to bottom.
#[derive(Clone, Debug)]
pub struct ReferenceImage {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<[f64; 3]>,
    /// Index of the object seen at each pixel (`None`: background).
    pub object: Vec<Option<usize>>,
}

impl ReferenceImage {
    pub fn get(&self, x: u32, y: u32) -> [f64; 3] {
        self.pixels[(y * self.width + x) as usize]
    }
    pub fn object_at(&self, x: u32, y: u32) -> Option<usize> {
        self.object[(y * self.width + x) as usize]
    }
}

/// Rays starting closer than this (in object-space ray parameter) do not count as hits: the
/// camera is outside every shape.
const RAY_T_MIN: f64 = 1e-9;

/// A ray counts as parallel to a plane, or to a triangle's plane, when the dot product deciding
/// the hit is smaller than this: only an exactly parallel ray gets there, and the division by it
/// would overflow.
const PARALLEL_DENOM_MIN: f64 = 1e-300;

/// A hit: ray parameter and object-space unit normal.
type Hit = (f64, DVec3);

/// Intersect a ray with a convex polyhedron `{x : n·x ≤ d for all planes}`.
fn convex(o: DVec3, dir: DVec3, planes: &[(DVec3, f64)]) -> Option<Hit> {
    let (mut t_in, mut t_out, mut n_in) = (f64::NEG_INFINITY, f64::INFINITY, DVec3::ZERO);
    for &(n, d) in planes {
        let denom = n.dot(dir);
        let dist = d - n.dot(o);
        if denom.abs() < PARALLEL_DENOM_MIN {
            if dist < 0.0 {
                return None;
            }
            continue;
        }
        let t = dist / denom;
        if denom < 0.0 {
            if t > t_in {
                t_in = t;
                n_in = n;
            }
        } else if t < t_out {
            t_out = t;
        }
    }
    (t_in <= t_out && t_in > RAY_T_MIN).then(|| (t_in, n_in.normalize()))
}

fn solve_quadratic(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (t0, t1) = (q / a, c / q);
    Some((t0.min(t1), t0.max(t1)))
}

/// Intersect a ray (object space, `dir` not necessarily unit) with a unit shape. A
/// `Shape::Mesh` has no analytic form and is not hit here: [`trace`] intersects its triangles.
fn intersect_shape(shape: Shape, o: DVec3, dir: DVec3) -> Option<Hit> {
    match shape {
        Shape::Mesh(_) => None,
        Shape::Sphere => {
            let (t0, t1) = solve_quadratic(dir.dot(dir), 2.0 * o.dot(dir), o.dot(o) - 1.0)?;
            let t = if t0 > RAY_T_MIN { t0 } else { t1 };
            (t > RAY_T_MIN).then(|| (t, (o + dir * t).normalize()))
        }
        Shape::Cylinder => {
            let mut best: Option<Hit> = None;
            let mut consider = |h: Hit| {
                if h.0 > RAY_T_MIN && best.is_none_or(|b| h.0 < b.0) {
                    best = Some(h);
                }
            };
            let (a, b, c) =
                (dir.x * dir.x + dir.z * dir.z, 2.0 * (o.x * dir.x + o.z * dir.z), o.x * o.x + o.z * o.z - 1.0);
            if let Some((t0, t1)) = solve_quadratic(a, b, c) {
                for t in [t0, t1] {
                    let p = o + dir * t;
                    if p.y.abs() <= 1.0 {
                        consider((t, DVec3::new(p.x, 0.0, p.z).normalize()));
                    }
                }
            }
            if dir.y != 0.0 {
                for y in [-1.0, 1.0] {
                    let t = (y - o.y) / dir.y;
                    let p = o + dir * t;
                    if p.x * p.x + p.z * p.z <= 1.0 {
                        consider((t, DVec3::new(0.0, y, 0.0)));
                    }
                }
            }
            best
        }
        Shape::Cube => convex(
            o,
            dir,
            &[
                (DVec3::X, 1.0),
                (DVec3::NEG_X, 1.0),
                (DVec3::Y, 1.0),
                (DVec3::NEG_Y, 1.0),
                (DVec3::Z, 1.0),
                (DVec3::NEG_Z, 1.0),
            ],
        ),
        Shape::Plane => {
            if dir.y == 0.0 {
                return None;
            }
            let t = -o.y / dir.y;
            let p = o + dir * t;
            (t > RAY_T_MIN && p.x.abs() <= 1.0 && p.z.abs() <= 1.0).then_some((t, DVec3::Y))
        }
        Shape::Pyramid => {
            // Sides through the apex (0, 1, 0) and a base edge at e·x = 1, y = −1:
            // 2 e·x + y ≤ 1; the base: −y ≤ 1.
            let k = 5f64.sqrt();
            let side = |e: DVec3| ((e * 2.0 + DVec3::Y) / k, 1.0 / k);
            convex(
                o,
                dir,
                &[side(DVec3::X), side(DVec3::NEG_X), side(DVec3::Z), side(DVec3::NEG_Z), (DVec3::NEG_Y, 1.0)],
            )
        }
    }
}

/// Intersect a ray (object space) with a file's triangle mesh by brute force (Möller–Trumbore,
/// every triangle: fine for the small meshes the reference is used on). The normal is the
/// file's corner normals interpolated, or the face normal; it faces the ray's origin side as the
/// face's winding says (no flipping).
fn intersect_mesh(mesh: &TriangleMesh, o: DVec3, dir: DVec3) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for k in 0..mesh.triangle_count() {
        let t = &mesh.triangle(k);
        let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
        let p = dir.cross(e2);
        let det = e1.dot(p);
        if det.abs() < PARALLEL_DENOM_MIN {
            continue;
        }
        let s = o - t[0];
        let u = s.dot(p) / det;
        let q = s.cross(e1);
        let v = dir.dot(q) / det;
        let tt = e2.dot(q) / det;
        if !(0.0..=1.0).contains(&u) || v < 0.0 || u + v > 1.0 || tt <= RAY_T_MIN || best.is_some_and(|b| tt >= b.0) {
            continue;
        }
        let face = face_normal(t).unwrap_or(DVec3::Y);
        let n = match mesh.corner_normals(k) {
            Some(c) => safe_normalize(c[0] * (1.0 - u - v) + c[1] * u + c[2] * v, face),
            None => face,
        };
        best = Some((tt, n));
    }
    best
}

/// The nearest hit of a world ray among the scene's objects: (object index, world point, world
/// unit normal).
fn trace(scene: &Scene, inverses: &[DMat4], o: DVec3, dir: DVec3) -> Option<(usize, DVec3, DVec3)> {
    let mut best: Option<(f64, usize, DVec3)> = None;
    for (i, (obj, inv)) in scene.objects.iter().zip(inverses).enumerate() {
        let (lo, ld) = (inv.transform_point3(o), inv.transform_vector3(dir));
        let hit = match obj.shape {
            Shape::Mesh(m) => scene.meshes.get(m).and_then(|mesh| intersect_mesh(mesh, lo, ld)),
            shape => intersect_shape(shape, lo, ld),
        };
        if let Some((t, n)) = hit
            && best.is_none_or(|b| t < b.0)
        {
            best = Some((t, i, n));
        }
    }
    best.map(|(t, i, n)| {
        let obj: &Object = &scene.objects[i];
        (i, o + dir * t, (obj.transform.normal_matrix() * n).normalize())
    })
}

/// Render the scene by ray casting in f64 at any resolution.
pub fn render_reference(scene: &Scene, specular: SpecularModel, width: u32, height: u32) -> ReferenceImage {
    let inverses: Vec<DMat4> = scene.objects.iter().map(|o| o.transform.matrix().inverse()).collect();
    let mut pixels = Vec::with_capacity((width * height) as usize);
    let mut object = Vec::with_capacity((width * height) as usize);
    for y in 0..height {
        for x in 0..width {
            let (o, dir) = scene.camera.ray(x, y, width, height);
            match trace(scene, &inverses, o, dir) {
                Some((i, p, n)) => {
                    let mat = &scene.materials[scene.objects[i].material];
                    pixels.push(shade(p, n, scene.camera.eye, mat, &scene.lights, scene.ambient, specular));
                    object.push(Some(i));
                }
                None => {
                    pixels.push(BACKGROUND);
                    object.push(None);
                }
            }
        }
    }
    ReferenceImage { width, height, pixels, object }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::triangles;

    /// Every analytic shape agrees with its own tessellation: rays that hit a fine mesh's
    /// triangle hit the shape at nearly the same distance.
    #[test]
    fn analytic_shapes_match_their_tessellation() {
        for shape in Shape::ALL {
            let tris = triangles(shape, 64);
            for (k, t) in tris.iter().enumerate().step_by(97) {
                let c = (t[0] + t[1] + t[2]) / 3.0;
                let from = c * 3.0 + DVec3::new(0.1, 2.5, 0.2) * if shape == Shape::Plane { 1.0 } else { 0.0 };
                let dir = c - from;
                let hit = intersect_shape(shape, from, dir);
                let (t_hit, _) = hit.unwrap_or_else(|| panic!("{shape:?} triangle {k} missed"));
                assert!((t_hit - 1.0).abs() < 0.01, "{shape:?} triangle {k}: t = {t_hit}");
            }
        }
    }

    #[test]
    fn normals_point_out() {
        for shape in [Shape::Sphere, Shape::Cylinder, Shape::Cube, Shape::Pyramid] {
            for dir in [DVec3::X, DVec3::NEG_Y, DVec3::new(0.3, -0.2, -1.0)] {
                let o = -dir * 10.0 + DVec3::new(0.0, -0.3, 0.0);
                let (t, n) = intersect_shape(shape, o, dir).unwrap();
                assert!(n.dot(dir) < 0.0, "{shape:?} {dir}: normal {n} at t {t}");
            }
        }
    }

    #[test]
    fn reference_render_sees_the_scene() {
        let scene = Scene::builtin("default").unwrap();
        let img = render_reference(&scene, SpecularModel::CookTorrance, 64, 36);
        assert!(img.pixels.iter().all(|p| p.iter().all(|c| c.is_finite() && *c >= 0.0)));
        let seen: std::collections::HashSet<_> = img.object.iter().flatten().collect();
        assert!(seen.len() >= 6, "objects seen: {seen:?}");
        assert_eq!(img.get(0, 0), BACKGROUND);
    }
}
