//! Cameras: every perspective camera of the node graph (an orthographic one is shown in
//! perspective, with a warning; none: one placed to frame the scene), looking along its node's
//! −Z; written as one perspective camera with the orbit pivot, the up vector and the exact eye
//! and projection in `extras.shadelab`.

use super::GltfError;
use super::extras::{self, Number, Vec3, agrees};
use super::scene_file::{Reader, num, quat, vec3};
use crate::scene::{COMPOSED_ASPECT, Camera};
use glam::{DMat3, DMat4, DQuat, DVec3};
use gltf::json;
use serde_json::{Value, json};

/// Field of view of a camera placed by the loader (no camera in the file, or an orthographic one):
/// the built-in scenes'.
pub(super) const FALLBACK_FOV_Y_DEG: f64 = 40.0;

/// A node's −Z or its cross product with its +Y shorter (squared) than this: no view direction.
const DEGENERATE_LENGTH_SQUARED: f64 = 1e-20;
/// The written orbit pivot is used when its direction from the eye is within this (1 − cos) of
/// the node's view direction.
const TARGET_ON_AXIS: f64 = 1e-9;
/// The written up vector must be this far (squared cross product) from the view direction.
const UP_OFF_AXIS: f64 = 1e-12;
/// …and give the node's view matrix to this.
const UP_SAME_VIEW: f64 = 1e-6;

super::extras_struct! {
    /// `extras.shadelab` of a camera: the eye exactly (the node's fields are read as f32), the orbit
    /// pivot and the up vector (the node's rotation alone does not keep them) and the projection,
    /// each used when it agrees with the file's own fields (fields in the order they are checked).
    struct CameraExtras {
        eye: Option<Vec3>,
        fov_y_deg: Option<Number>,
        near: Option<Number>,
        far: Option<Number>,
        target: Option<Vec3>,
        up: Option<Vec3>,
        /// An orthographic camera's half height (left out for a perspective camera).
        ymag: Option<Number>,
    }
}

impl Reader<'_> {
    /// The cameras of `camera_nodes` (node, camera, world matrix), each with its name (the
    /// camera's, else its node's, else "camera N"); none: the framing camera, with a warning.
    pub(super) fn cameras(
        &mut self,
        camera_nodes: Vec<(usize, usize, DMat4)>,
        center: DVec3,
        radius: f64,
    ) -> Result<Vec<(String, Camera)>, GltfError> {
        let root = self.root;
        let mut cameras = Vec::with_capacity(camera_nodes.len());
        for (ni, ci, world) in camera_nodes {
            let name = root.cameras[ci].name.clone().or_else(|| root.nodes[ni].name.clone());
            cameras.push((name.unwrap_or_else(|| format!("camera {ci}")), self.camera(ci, &world, center, radius)?));
        }
        if cameras.is_empty() {
            self.cx.warn("no camera: one is placed to frame the scene".into());
            cameras.push(("framing the scene".into(), framing_camera(center, radius)));
        }
        Ok(cameras)
    }

    fn camera(&mut self, ci: usize, world: &DMat4, center: DVec3, radius: f64) -> Result<Camera, GltfError> {
        let root = self.root;
        let c = &root.cameras[ci];
        let what = format!("camera {ci}");
        let eye = world.transform_point3(DVec3::ZERO);
        let forward = world.transform_vector3(DVec3::NEG_Z);
        let up_node = world.transform_vector3(DVec3::Y);
        if forward.length_squared() < DEGENERATE_LENGTH_SQUARED
            || forward.cross(up_node).length_squared() < DEGENERATE_LENGTH_SQUARED
        {
            return Err(self.cx.invalid(format!("{what}: its node's transform is degenerate")));
        }
        let forward = forward.normalize();
        let far_auto = ((eye - center).length() + radius) * 2.0;
        let (fov, near, far, orthographic) = self.projection(c, &what, far_auto)?;
        let depth = (center - eye).dot(forward).max(radius * 0.1).max(1e-3);
        let camera = Camera {
            eye,
            target: eye + forward * depth,
            up: up_node.normalize(),
            fov_y_deg: fov,
            near,
            far,
            orthographic,
        };
        // The exact eye, the orbit pivot and the up vector shadelab wrote, when they still agree
        // with the node.
        let ex: CameraExtras = extras::read(&self.cx, &c.extras, &what)?;
        Ok(exact_view(camera, ex, forward))
    }

    /// The camera's projection, checked: field of view (degrees), near, far and an orthographic half height.
    fn projection(
        &mut self,
        c: &json::Camera,
        what: &str,
        far_auto: f64,
    ) -> Result<(f64, f64, f64, Option<f64>), GltfError> {
        Ok(match (&c.perspective, &c.orthographic) {
            (Some(p), _) => {
                let yfov = p.yfov as f64;
                if !(yfov > 0.0 && yfov < std::f64::consts::PI) {
                    return Err(self.cx.invalid(format!("{what}: yfov {yfov} is not in (0, π)")));
                }
                let near = p.znear as f64;
                if !(near > 0.0 && near.is_finite()) {
                    return Err(self.cx.invalid(format!("{what}: znear {near} is not a positive number")));
                }
                let far = match p.zfar {
                    Some(f) if (f as f64) > near && f.is_finite() => f as f64,
                    Some(f) => return Err(self.cx.invalid(format!("{what}: zfar {f} is not beyond znear {near}"))),
                    // Infinite projection: far enough for the whole scene.
                    None => far_auto.max(near * 10.0),
                };
                (yfov.to_degrees(), near, far, None)
            }
            (None, Some(o)) => {
                // glTF 2.0 §5.13: ymag > 0 (half the height), 0 ≤ znear < zfar.
                let (ymag, near, far) = (o.ymag as f64, o.znear as f64, o.zfar as f64);
                if !(ymag > 0.0 && ymag.is_finite()) {
                    return Err(self.cx.invalid(format!("{what}: ymag {ymag} is not a positive number")));
                }
                if !(near >= 0.0 && far > near && far.is_finite()) {
                    return Err(self
                        .cx
                        .invalid(format!("{what}: znear {near}, zfar {far}: 0 ≤ znear < zfar is required")));
                }
                if (o.xmag as f64 / ymag - COMPOSED_ASPECT).abs() > 1e-3 {
                    self.cx.warn(format!("{what}: xmag/ymag is not the image's aspect: the width follows the image"));
                }
                (FALLBACK_FOV_Y_DEG, near, far, Some(ymag))
            }
            (None, None) => return Err(self.cx.invalid(format!("{what} has neither perspective nor orthographic"))),
        })
    }
}

/// The camera with the extras' exact eye, projection, orbit pivot and up vector where they agree.
fn exact_view(mut camera: Camera, ex: CameraExtras, forward: DVec3) -> Camera {
    if let Some(eye) = ex.eye.filter(|e| agrees(e.0, camera.eye)) {
        camera.eye = eye.0;
    }
    for (v, field) in [(ex.fov_y_deg, &mut camera.fov_y_deg), (ex.near, &mut camera.near), (ex.far, &mut camera.far)] {
        if let Some(Number(v)) = v
            && agrees(DVec3::splat(v), DVec3::splat(*field))
        {
            *field = v;
        }
    }
    if let (Some(Number(v)), Some(h)) = (ex.ymag, camera.orthographic.as_mut())
        && agrees(DVec3::splat(v), DVec3::splat(*h))
    {
        *h = v;
    }
    let eye = camera.eye;
    if let Some(Vec3(t)) = ex.target
        && (t - eye).length_squared() > 0.0
        && (t - eye).normalize().dot(forward) > 1.0 - TARGET_ON_AXIS
    {
        camera.target = t;
    }
    if let Some(Vec3(up)) = ex.up {
        let with = Camera { up, ..camera };
        if up.cross(forward).length_squared() > UP_OFF_AXIS && with.view().abs_diff_eq(camera.view(), UP_SAME_VIEW) {
            camera.up = up;
        }
    }
    camera
}

/// A camera that shows a sphere of `radius` about `center`, from the front and a little above.
pub(super) fn framing_camera(center: DVec3, radius: f64) -> Camera {
    let fov = FALLBACK_FOV_Y_DEG;
    let dist = radius / (fov.to_radians() * 0.5).sin() * 1.05;
    let eye = center + DVec3::new(0.0, 0.35, 1.0).normalize() * dist;
    Camera {
        eye,
        target: center,
        up: DVec3::Y,
        fov_y_deg: fov,
        near: (dist - radius).max(dist * 1e-3) * 0.5,
        far: (dist + radius) * 2.0,
        orthographic: None,
    }
}

/// The camera's node (at the eye, rotated to the view) and the glTF camera (perspective, the
/// composed image's aspect), with the exact values in `extras.shadelab`.
pub(super) fn write_camera(c: &Camera) -> (Value, Value) {
    let to_world = c.view().inverse();
    let node = json!({
        "name": "camera",
        "camera": 0,
        "translation": vec3(c.eye),
        "rotation": quat(DQuat::from_mat3(&DMat3::from_mat4(to_world))),
    });
    let ex = CameraExtras {
        eye: Some(Vec3(c.eye)),
        fov_y_deg: Some(Number(c.fov_y_deg)),
        near: Some(Number(c.near)),
        far: Some(Number(c.far)),
        target: Some(Vec3(c.target)),
        up: Some(Vec3(c.up)),
        ymag: c.orthographic.map(Number),
    };
    let camera = match c.orthographic {
        Some(h) => json!({
            "name": "camera",
            "type": "orthographic",
            "orthographic": { "xmag": num(h * COMPOSED_ASPECT), "ymag": num(h), "znear": num(c.near), "zfar": num(c.far) },
            "extras": extras::shadelab(&ex),
        }),
        None => json!({
            "name": "camera",
            "type": "perspective",
            "perspective": {
                "yfov": num(c.fov_y_deg.to_radians()),
                "znear": num(c.near),
                "zfar": num(c.far),
                "aspectRatio": num(COMPOSED_ASPECT),
            },
            "extras": extras::shadelab(&ex),
        }),
    };
    (node, camera)
}
