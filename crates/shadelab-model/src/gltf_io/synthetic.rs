//! Generated large meshes for `shadelab bench mesh`: a latitude–longitude sphere of about the
//! asked number of triangles, written straight to `.glb` as a scanner or modelling tool would
//! write it (one indexed primitive, `u32` indices, positions and normals, a camera and a light),
//! without going through the model's f64 triangle soup, so generating a file costs only the file.

use super::accessors::{FLOAT, UNSIGNED_INT};
use super::container::{ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER};
use super::glb_container;
use super::meshes::TRIANGLES;
use glam::{DQuat, DVec3};
use serde_json::json;

/// Segments around the sphere for about `triangles` triangles: a sphere of `s` segments and
/// `s/2` rings has `s·(s − 2)` triangles (`mesh::triangle_count`), so `s ≈ 1 + √(1 + N)`, even:
/// the smallest sphere with at least `triangles`, unless that one is past `MAX_TRIANGLES` (then
/// the largest the loader takes).
pub fn sphere_segments(triangles: usize) -> u32 {
    let s = (1.0 + (1.0 + triangles as f64).sqrt()).ceil() as u32;
    let mut s = (s + s % 2).max(4);
    while s > 4 && sphere_triangles(s) > super::MAX_TRIANGLES {
        s -= 2;
    }
    s
}

/// Triangles of the generated sphere with `segments` segments (the two pole rings are fans).
pub fn sphere_triangles(segments: u32) -> usize {
    let s = segments as usize;
    s * (s - 2)
}

/// A unit sphere of about `triangles` triangles as `.glb`, seen by a camera 3.2 units away and lit
/// by one directional light from the upper left front; `with_normals: false` leaves `NORMAL` out
/// (the loader then makes normals by the crease-angle rule). Returns the file and its triangle
/// count.
pub fn sphere_glb(triangles: usize, with_normals: bool) -> (Vec<u8>, usize) {
    let s = sphere_segments(triangles);
    let rings = s / 2;
    let (cols, rows) = (s as usize + 1, rings as usize + 1);
    let mut bin: Vec<u8> = Vec::with_capacity(cols * rows * 24 + sphere_triangles(s) * 12);
    push_vertices(&mut bin, s, with_normals);
    let vertex_bytes = cols * rows * 12;
    let index_offset = bin.len();
    let count = push_indices(&mut bin, s);
    debug_assert_eq!(count, sphere_triangles(s));
    let vertices = cols * rows;
    let light_dir = DVec3::new(0.5, -0.8, -0.6).normalize();
    // A glTF light and camera look down their node's −Z.
    let light_rotation = DQuat::from_rotation_arc(DVec3::NEG_Z, light_dir);
    let attributes = if with_normals { json!({ "POSITION": 0, "NORMAL": 1 }) } else { json!({ "POSITION": 0 }) };
    let root = json!({
        "asset": { "version": "2.0", "generator": "shadelab bench mesh" },
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [
            { "type": "directional", "intensity": std::f64::consts::PI, "color": [1.0, 0.97, 0.92] }
        ] } },
        "scene": 0,
        "scenes": [{ "nodes": [0, 1, 2] }],
        "nodes": [
            { "mesh": 0, "name": "sphere" },
            { "camera": 0, "translation": [0.0, 0.0, 3.2] },
            { "extensions": { "KHR_lights_punctual": { "light": 0 } },
              "rotation": [light_rotation.x, light_rotation.y, light_rotation.z, light_rotation.w] }
        ],
        "cameras": [{ "type": "perspective", "perspective": { "yfov": 40f64.to_radians(), "znear": 0.1, "zfar": 50.0 } }],
        "materials": [{ "name": "plastic", "pbrMetallicRoughness": {
            "baseColorFactor": [0.75, 0.12, 0.08, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.4 } }],
        "meshes": [{ "name": format!("sphere {count} triangles"), "primitives": [{
            "attributes": attributes, "indices": 2, "material": 0, "mode": TRIANGLES }] }],
        "bufferViews": [
            { "buffer": 0, "byteOffset": 0, "byteLength": vertex_bytes, "target": ARRAY_BUFFER },
            { "buffer": 0, "byteOffset": vertex_bytes, "byteLength": vertex_bytes, "target": ARRAY_BUFFER },
            { "buffer": 0, "byteOffset": index_offset, "byteLength": count * 12, "target": ELEMENT_ARRAY_BUFFER }
        ],
        "accessors": [
            { "bufferView": 0, "componentType": FLOAT, "count": vertices, "type": "VEC3",
              "min": [-1.0, -1.0, -1.0], "max": [1.0, 1.0, 1.0] },
            { "bufferView": 1, "componentType": FLOAT, "count": vertices, "type": "VEC3" },
            { "bufferView": 2, "componentType": UNSIGNED_INT, "count": count * 3, "type": "SCALAR" }
        ]
    });
    (glb_container(root, bin), count)
}

/// The sphere's positions, then (`with_normals`) its normals, appended to `bin` as f32 triples.
fn push_vertices(bin: &mut Vec<u8>, s: u32, with_normals: bool) {
    let rings = s / 2;
    let (cols, rows) = (s as usize + 1, rings as usize + 1);
    // Positions, then normals (the same unit vectors), vertex (i, j) at index j·cols + i; the
    // seam column is duplicated, as texture-mapped spheres are.
    let vertex = |i: usize, j: usize| {
        let theta = std::f64::consts::PI * j as f64 / rings as f64;
        let phi = std::f64::consts::TAU * i as f64 / s as f64;
        DVec3::new(theta.sin() * phi.cos(), theta.cos(), -theta.sin() * phi.sin()).as_vec3()
    };
    for _attribute in 0..(1 + usize::from(with_normals)) {
        for j in 0..rows {
            for i in 0..cols {
                for c in vertex(i, j).to_array() {
                    bin.extend_from_slice(&c.to_le_bytes());
                }
            }
        }
    }
}

/// The sphere's triangles appended to `bin` as u32 indices; how many there are.
fn push_indices(bin: &mut Vec<u8>, s: u32) -> usize {
    let rings = s / 2;
    let cols = s as usize + 1;
    let at = |i: usize, j: usize| (j * cols + i) as u32;
    let mut count = 0usize;
    for j in 0..rings as usize {
        for i in 0..s as usize {
            // Counter-clockwise seen from outside; the pole bands keep one triangle of two.
            let quad = [[at(i, j), at(i, j + 1), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i + 1, j)]];
            let keep: &[[u32; 3]] = if j == 0 {
                &quad[..1]
            } else if j + 1 == rings as usize {
                &quad[1..]
            } else {
                &quad
            };
            for t in keep {
                for v in t {
                    bin.extend_from_slice(&v.to_le_bytes());
                }
                count += 1;
            }
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gltf_io::{MAX_TRIANGLES, load_scene_from_slice};

    #[test]
    fn generated_spheres_load_as_described_and_stay_within_the_limit() {
        for (asked, with_normals) in [(5000, true), (5000, false), (1, true)] {
            let (glb, count) = sphere_glb(asked, with_normals);
            assert!(count >= asked && count == sphere_triangles(sphere_segments(asked)));
            let loaded = load_scene_from_slice(&glb).unwrap();
            assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
            assert_eq!(loaded.scene.triangle_count(), count);
            assert_eq!(loaded.scene.meshes[0].normals.is_some(), with_normals);
            assert_eq!(loaded.cameras.len(), 1);
        }
        // At the limit: the largest sphere the loader takes, not the next one up.
        let s = sphere_segments(MAX_TRIANGLES);
        assert!(sphere_triangles(s) <= MAX_TRIANGLES && sphere_triangles(s + 2) > MAX_TRIANGLES);
    }
}
