//! The camera the GPU renderer and the f64 reference share, perspective or orthographic: view,
//! projection, the ray through a pixel centre and the eye as the shading sees it.

use glam::{DMat4, DVec3, DVec4, Mat4};

/// The aspect ratio the built-in scenes are composed for.
pub const COMPOSED_ASPECT: f64 = 16.0 / 9.0;

/// A perspective or orthographic camera; the GPU renderer and the f64 reference use the same one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub eye: DVec3,
    pub target: DVec3,
    pub up: DVec3,
    /// Vertical field of view, degrees (perspective).
    pub fov_y_deg: f64,
    pub near: f64,
    pub far: f64,
    /// Half the view's height in world units (glTF's `ymag`) for an orthographic camera; `None`:
    /// perspective. The width follows the image's aspect ratio.
    pub orthographic: Option<f64>,
}

impl Camera {
    pub fn view(&self) -> DMat4 {
        DMat4::look_at_rh(self.eye, self.target, self.up)
    }
    pub fn projection(&self, aspect: f64) -> DMat4 {
        match self.orthographic {
            Some(h) => DMat4::orthographic_rh(-h * aspect, h * aspect, -h, h, self.near, self.far),
            None => DMat4::perspective_rh(self.fov_y_deg.to_radians(), aspect, self.near, self.far),
        }
    }

    /// The eye as the shading sees it, homogeneous: `(eye, 1)` for a perspective camera, whose
    /// view vector at p is `eye − p`; `(−forward, 0)` for an orthographic one, whose view vector is
    /// the same everywhere. Either way `V = normalize(e.xyz − p·e.w)`.
    pub fn eye_h(&self) -> DVec4 {
        match self.orthographic {
            Some(_) => (self.eye - self.target).normalize_or(DVec3::Z).extend(0.0),
            None => self.eye.extend(1.0),
        }
    }
    /// The same camera with its vertical field of view widened, for images narrower than the
    /// 16:9 the built-in scenes are composed for, so that the whole width still shows.
    pub fn fitted(&self, aspect: f64) -> Camera {
        if aspect >= COMPOSED_ASPECT || aspect <= 0.0 {
            return *self;
        }
        let half = (self.fov_y_deg.to_radians() * 0.5).tan() * COMPOSED_ASPECT / aspect;
        Camera {
            fov_y_deg: (2.0 * half.atan()).to_degrees().min(120.0),
            orthographic: self.orthographic.map(|h| h * COMPOSED_ASPECT / aspect),
            ..*self
        }
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
        let forward = (self.target - self.eye).normalize();
        let right = forward.cross(self.up).normalize();
        let up = right.cross(forward);
        if let Some(h) = self.orthographic {
            // Parallel rays from the image plane through the eye.
            return (self.eye + right * (ndc_x * h * aspect) + up * (ndc_y * h), forward);
        }
        let t = (self.fov_y_deg.to_radians() * 0.5).tan();
        let dir = (forward + right * (ndc_x * t * aspect) + up * (ndc_y * t)).normalize();
        (self.eye, dir)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ray through a pixel lands on that pixel's centre under the GPU's projection, at every
    /// depth, for both kinds of camera; an orthographic camera's rays are parallel.
    #[test]
    fn rays_and_projection_agree_for_both_projections() {
        let perspective = Camera {
            eye: DVec3::new(0.5, 2.0, 5.0),
            target: DVec3::new(0.0, 0.3, 0.0),
            up: DVec3::Y,
            fov_y_deg: 40.0,
            near: 0.1,
            far: 50.0,
            orthographic: None,
        };
        let ortho = Camera { orthographic: Some(1.7), ..perspective };
        let (w, h) = (64, 36);
        for cam in [perspective, ortho] {
            let m = cam.projection(w as f64 / h as f64) * cam.view();
            for (x, y) in [(0, 0), (10, 30), (63, 35), (32, 18)] {
                let (o, d) = cam.ray(x, y, w, h);
                for t in [1.0, 4.0, 20.0] {
                    let c = m * (o + d * t).extend(1.0);
                    let (nx, ny) = (c.x / c.w, c.y / c.w);
                    let want = ((x as f64 + 0.5) / w as f64 * 2.0 - 1.0, 1.0 - (y as f64 + 0.5) / h as f64 * 2.0);
                    assert!((nx - want.0).abs() < 1e-9 && (ny - want.1).abs() < 1e-9, "{cam:?} ({x}, {y}) t {t}");
                }
                if cam.orthographic.is_some() {
                    assert!((d - (cam.target - cam.eye).normalize()).length() < 1e-12);
                }
            }
        }
        // The shading's eye: a point for perspective, the view direction for orthographic.
        assert_eq!(perspective.eye_h(), perspective.eye.extend(1.0));
        let e = ortho.eye_h();
        assert!(e.w == 0.0 && (e.truncate() + (ortho.target - ortho.eye).normalize()).length() < 1e-12);
    }
}
