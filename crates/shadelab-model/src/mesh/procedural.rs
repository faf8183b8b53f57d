//! The analytic shapes tessellated (sphere, cylinder, cube, plane, pyramid; see [`Shape`] for
//! each one's object-space extent), oriented outwards, and their meshes by the crease-angle rule.

use super::{CREASE_ANGLE_DEG, MeshData, build_mesh, face_normal};
use crate::scene::Shape;
use glam::DVec3;

/// Tessellate a shape (see [`Shape`] for its object-space extent) and build its meshes. A
/// `Shape::Mesh` has no analytic form: build it from `Scene::meshes` ([`super::TriangleMesh::build`]
/// or `Scene::mesh_data`); here it gives an empty mesh.
pub fn tessellate(shape: Shape, tessellation: u32) -> MeshData {
    build_mesh(&triangles(shape, tessellation), CREASE_ANGLE_DEG).expect("procedural shapes are finite")
}

/// Segments around a sphere or cylinder for a tessellation parameter (at least 3).
pub fn segments(tessellation: u32) -> u32 {
    tessellation.max(3)
}

/// Rings of a sphere with `segments` segments.
pub fn sphere_rings(segments: u32) -> u32 {
    (segments / 2).max(2)
}

/// Triangles a shape has at a tessellation, without building it.
pub fn triangle_count(shape: Shape, tessellation: u32) -> usize {
    let n = tessellation.max(1) as usize;
    let s = segments(tessellation) as usize;
    match shape {
        Shape::Sphere => s * 2 * (sphere_rings(s as u32) as usize - 1),
        Shape::Cylinder => 4 * s,
        Shape::Cube => 12 * n * n,
        Shape::Plane => 2 * n * n,
        Shape::Pyramid => 6 * n * n,
        // Counted from `Scene::meshes` by `Scene::triangle_count`.
        Shape::Mesh(_) => 0,
    }
}

/// The triangles of an analytic shape (empty for `Shape::Mesh`), oriented so that each face's normal points out of the shape.
pub fn triangles(shape: Shape, tessellation: u32) -> Vec<[DVec3; 3]> {
    let n = tessellation.max(1);
    let (tris, inside) = match shape {
        Shape::Sphere => (sphere(segments(n)), DVec3::ZERO),
        Shape::Cylinder => (cylinder(segments(n)), DVec3::ZERO),
        Shape::Cube => (cube(n), DVec3::ZERO),
        Shape::Plane => (plane(n), DVec3::NEG_Y),
        Shape::Pyramid => (pyramid(n), DVec3::new(0.0, -0.5, 0.0)),
        // A file's mesh has no analytic form: its triangles are `Scene::meshes[i]`.
        Shape::Mesh(_) => return Vec::new(),
    };
    // Every shape is convex (the plane is one face of one), so a face is oriented outwards when
    // its normal points away from a point inside.
    tris.into_iter()
        .map(|t| match face_normal(&t) {
            Some(nrm) if nrm.dot((t[0] + t[1] + t[2]) / 3.0 - inside) < 0.0 => [t[0], t[2], t[1]],
            _ => t,
        })
        .collect()
}

fn quad(out: &mut Vec<[DVec3; 3]>, a: DVec3, b: DVec3, c: DVec3, d: DVec3) {
    // a b
    // c d
    out.push([a, c, d]);
    out.push([a, d, b]);
}

fn sphere(seg: u32) -> Vec<[DVec3; 3]> {
    let rings = sphere_rings(seg);
    let v = |i: u32, j: u32| -> DVec3 {
        if i == 0 {
            return DVec3::Y;
        }
        if i == rings {
            return DVec3::NEG_Y;
        }
        let theta = std::f64::consts::PI * i as f64 / rings as f64;
        let phi = std::f64::consts::TAU * (j % seg) as f64 / seg as f64;
        DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
    };
    let mut out = Vec::new();
    for i in 0..rings {
        for j in 0..seg {
            let (a, b, c, d) = (v(i, j), v(i, j + 1), v(i + 1, j), v(i + 1, j + 1));
            if i == 0 {
                out.push([a, c, d]);
            } else if i == rings - 1 {
                out.push([a, c, b]);
            } else {
                quad(&mut out, a, b, c, d);
            }
        }
    }
    out
}

fn cylinder(seg: u32) -> Vec<[DVec3; 3]> {
    let rim = |j: u32, y: f64| {
        let phi = std::f64::consts::TAU * (j % seg) as f64 / seg as f64;
        DVec3::new(phi.cos(), y, phi.sin())
    };
    let mut out = Vec::new();
    for j in 0..seg {
        quad(&mut out, rim(j, 1.0), rim(j + 1, 1.0), rim(j, -1.0), rim(j + 1, -1.0));
        out.push([DVec3::Y, rim(j, 1.0), rim(j + 1, 1.0)]);
        out.push([DVec3::NEG_Y, rim(j, -1.0), rim(j + 1, -1.0)]);
    }
    out
}

fn grid(out: &mut Vec<[DVec3; 3]>, n: u32, point: impl Fn(f64, f64) -> DVec3) {
    let t = |i: u32| -1.0 + 2.0 * i as f64 / n as f64;
    for i in 0..n {
        for j in 0..n {
            quad(out, point(t(i), t(j)), point(t(i + 1), t(j)), point(t(i), t(j + 1)), point(t(i + 1), t(j + 1)));
        }
    }
}

fn cube(n: u32) -> Vec<[DVec3; 3]> {
    let mut out = Vec::new();
    for axis in 0..3 {
        for s in [-1.0, 1.0] {
            grid(&mut out, n, |u, v| {
                let mut p = [0.0; 3];
                p[axis] = s;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                DVec3::from_array(p)
            });
        }
    }
    out
}

fn plane(n: u32) -> Vec<[DVec3; 3]> {
    let mut out = Vec::new();
    grid(&mut out, n, |u, v| DVec3::new(u, 0.0, v));
    out
}

fn pyramid(n: u32) -> Vec<[DVec3; 3]> {
    let mut out = Vec::new();
    grid(&mut out, n, |u, v| DVec3::new(u, -1.0, v));
    let apex = DVec3::Y;
    let base = [
        DVec3::new(-1.0, -1.0, -1.0),
        DVec3::new(1.0, -1.0, -1.0),
        DVec3::new(1.0, -1.0, 1.0),
        DVec3::new(-1.0, -1.0, 1.0),
    ];
    let nf = n as f64;
    for k in 0..4 {
        let (b0, b1) = (base[k], base[(k + 1) % 4]);
        let p = |i: u32, j: u32| b0 + (b1 - b0) * (i as f64 / nf) + (apex - b0) * (j as f64 / nf);
        for j in 0..n {
            for i in 0..n - j {
                out.push([p(i, j), p(i + 1, j), p(i, j + 1)]);
                if i + 1 < n - j {
                    out.push([p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::crease::tests::unit_normals;

    #[test]
    fn counts_match_and_normals_are_unit() {
        for shape in Shape::ALL {
            for t in [1, 3, 8, 17] {
                let m = tessellate(shape, t);
                assert_eq!(m.triangle_count(), triangle_count(shape, t), "{shape:?} {t}");
                assert_eq!(m.flat_vertices.len(), 3 * m.triangle_count());
                assert!(unit_normals(&m), "{shape:?} {t}");
            }
        }
    }

    #[test]
    fn faces_point_outwards() {
        for shape in [Shape::Sphere, Shape::Cylinder, Shape::Cube, Shape::Pyramid] {
            for t in triangles(shape, 8) {
                let n = face_normal(&t).unwrap();
                let c = (t[0] + t[1] + t[2]) / 3.0;
                let inside = if shape == Shape::Pyramid { DVec3::new(0.0, -0.5, 0.0) } else { DVec3::ZERO };
                assert!(n.dot(c - inside) > 0.0, "{shape:?}");
            }
        }
    }
}
