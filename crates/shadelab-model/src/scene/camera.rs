//! The perspective camera the GPU renderer and the f64 reference share: view, projection and
//! the ray through a pixel centre.

use glam::{DMat4, DVec3, Mat4};

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
