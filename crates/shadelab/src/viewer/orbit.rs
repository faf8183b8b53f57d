//! The viewer's orbit camera: yaw and pitch around a target at a distance, steered by the
//! pointer over the view (drag orbits, right or middle drag pans, the wheel zooms, a double click
//! goes back to the scene's camera).

use eframe::egui::{self, PointerButton};
use glam::DVec3;
use shadelab_model::Camera;

/// Radians of yaw or pitch per point dragged.
const ORBIT_RAD_PER_POINT: f64 = 0.01;
/// Pitch stays short of straight up or down (±π/2), where the view's up vector would be parallel
/// to the line of sight.
const PITCH_LIMIT: f64 = 1.5;
/// Pan per point dragged, as a share of the distance to the target (the scene moves with the
/// pointer at any zoom).
const PAN_PER_POINT: f64 = 0.0015;
/// Zoom: each point scrolled scales the distance by exp(−ZOOM_PER_POINT).
const ZOOM_PER_POINT: f64 = 0.002;
/// Nearest and farthest distance to the target, scene units (the built-in scenes span a few).
const DISTANCE_MIN: f64 = 0.3;
const DISTANCE_MAX: f64 = 60.0;

/// Orbit camera around a target: yaw and pitch in radians, distance in scene units.
#[derive(Clone, Copy, Debug)]
pub(super) struct Orbit {
    pub target: DVec3,
    yaw: f64,
    pitch: f64,
    distance: f64,
}

impl Orbit {
    pub fn from_camera(c: &Camera) -> Orbit {
        let d = c.eye - c.target;
        let distance = d.length();
        Orbit { target: c.target, yaw: d.x.atan2(d.z), pitch: (d.y / distance).asin(), distance }
    }

    /// The orbit as a link writes it: target x,y,z, then yaw, pitch and distance, each float in
    /// the shortest form that reads back to the same bits.
    pub fn link_text(&self) -> String {
        let t = self.target;
        [t.x, t.y, t.z, self.yaw, self.pitch, self.distance].map(|x| format!("{x}")).join(",")
    }

    /// The orbit a link gives (see [`parse_link`]).
    pub fn from_link(target: DVec3, [yaw, pitch, distance]: [f64; 3]) -> Orbit {
        Orbit { target, yaw, pitch, distance }
    }

    /// The camera looking from the orbit at its target, with `base`'s lens.
    pub fn camera(&self, base: &Camera) -> Camera {
        let dir = DVec3::new(self.pitch.cos() * self.yaw.sin(), self.pitch.sin(), self.pitch.cos() * self.yaw.cos());
        // An orthographic view zooms by its height: the same share of it as the distance.
        let base_distance = (base.eye - base.target).length().max(1e-9);
        Camera {
            eye: self.target + dir * self.distance,
            target: self.target,
            orthographic: base.orthographic.map(|h| h * self.distance / base_distance),
            ..*base
        }
    }

    /// Follow the pointer over the view (`response`); a double click goes back to `base`.
    pub fn steer(&mut self, ui: &egui::Ui, response: &egui::Response, base: &Camera) {
        let delta = response.drag_delta();
        if response.dragged_by(PointerButton::Primary) {
            self.yaw -= delta.x as f64 * ORBIT_RAD_PER_POINT;
            self.pitch = (self.pitch + delta.y as f64 * ORBIT_RAD_PER_POINT).clamp(-PITCH_LIMIT, PITCH_LIMIT);
        }
        if response.dragged_by(PointerButton::Secondary) || response.dragged_by(PointerButton::Middle) {
            let cam = self.camera(base);
            let forward = (cam.target - cam.eye).normalize();
            let right = forward.cross(cam.up).normalize();
            let up = right.cross(forward);
            let scale = self.distance * PAN_PER_POINT;
            self.target += (-right * delta.x as f64 + up * delta.y as f64) * scale;
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y) as f64;
            self.distance = (self.distance * (-scroll * ZOOM_PER_POINT).exp()).clamp(DISTANCE_MIN, DISTANCE_MAX);
        }
        if response.double_clicked() {
            *self = Orbit::from_camera(base);
        }
    }
}

shadelab_model::param_ranges! {
    /// A link's orbit yaw: any number of turns a drag can add, far past what one makes.
    const LINK_YAW = "orbit", "yaw", "orbit yaw in radians", [-1e6, 1e6];
    /// A link's orbit pitch: up to straight up or down (a scene's own camera may look so).
    const LINK_PITCH = "orbit", "pitch", "orbit pitch in radians", [-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2];
    /// A link's orbit distance, or a target coordinate: positive, within a million metres.
    const LINK_DISTANCE = "orbit", "d", "orbit distance in metres", [1e-9, 1e6];
    const LINK_COORDINATE = "orbit", "x", "orbit target coordinate in metres", [-1e6, 1e6];
}

/// Read a link's `orbit=x,y,z,yaw,pitch,distance`; an error names the part and its range.
pub fn parse_link(text: &str) -> Result<(DVec3, [f64; 3]), String> {
    let parts: Vec<&str> = text.split(',').collect();
    if parts.len() != 6 {
        return Err(format!("'{text}' is not six numbers x,y,z,yaw,pitch,distance"));
    }
    let ranges = [LINK_COORDINATE, LINK_COORDINATE, LINK_COORDINATE, LINK_YAW, LINK_PITCH, LINK_DISTANCE];
    let mut v = [0.0; 6];
    for ((o, p), r) in v.iter_mut().zip(parts).zip(ranges) {
        *o = r.parse(p).map_err(|e| e.to_string())?;
    }
    Ok((DVec3::new(v[0], v[1], v[2]), [v[3], v[4], v[5]]))
}
