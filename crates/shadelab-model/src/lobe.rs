//! The lobe of one shaded point (docs/model.md §4, §5), from the f64 model: the point a pixel
//! sees ([`pick`], by the reference's ray caster), its N, V and each light's L with their angles,
//! the specular terms along the plane of incidence ([`plane_lobe`]), and the Cook–Torrance BRDF
//! over (θ_h, θ_d) at φ_d = 90°, the slice BRDF Explorer draws ([`theta_h_theta_d_slice`]).

use crate::guards::N_DOT_V_MIN;
use crate::lighting::brdf::{fresnel_v_from_mu, specular_phong};
use crate::lighting::common::safe_normalize;
use crate::lighting::lights::light_sample;
use crate::lighting::microfacet::{microfacet_d, microfacet_f, microfacet_g};
use crate::scene::{MAX_LIGHTS, Material, Scene};
use glam::DVec3;

/// The point a pixel sees: the object, the material, the position, the shading normal N, the
/// unit view vector V, and per light its unit L and the radiance that reaches the point.
#[derive(Clone, Debug, PartialEq)]
pub struct Pick {
    pub pixel: (u32, u32),
    pub object: usize,
    pub material: Material,
    pub point: DVec3,
    pub n: DVec3,
    pub v: DVec3,
    pub lights: Vec<(DVec3, [f64; 3])>,
}

/// The angles of one light at a picked point, in degrees: θ_i (N, L), θ_v (N, V), θ_h (N, H) and
/// θ_d (L, H), H the half vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Angles {
    pub theta_i: f64,
    pub theta_v: f64,
    pub theta_h: f64,
    pub theta_d: f64,
}

/// The angle between two unit vectors, in degrees (the cosine clamped to [−1, 1]).
fn degrees_between(a: DVec3, b: DVec3) -> f64 {
    a.dot(b).clamp(-1.0, 1.0).acos().to_degrees()
}

impl Angles {
    pub fn of(n: DVec3, v: DVec3, l: DVec3) -> Angles {
        let h = safe_normalize(l + v, n);
        Angles {
            theta_i: degrees_between(n, l),
            theta_v: degrees_between(n, v),
            theta_h: degrees_between(n, h),
            theta_d: degrees_between(l, h),
        }
    }
}

/// The point pixel `(x, y)` of a `width` × `height` image of `scene` sees, through the same pixel
/// centre as the renderer and the reference; `None` on the background.
pub fn pick(scene: &Scene, (x, y): (u32, u32), (width, height): (u32, u32)) -> Option<Pick> {
    if x >= width || y >= height {
        return None;
    }
    let geo = crate::reference::Geometry::new(scene);
    let (o, dir) = scene.camera.ray(x, y, width, height);
    let hit = crate::reference::trace_ray(scene, &geo, o, dir)?;
    let material = scene.materials.get(scene.objects[hit.object].material)?.clone();
    let e = scene.camera.eye_h();
    let v = safe_normalize(e.truncate() - hit.point * e.w, DVec3::Y);
    let n = safe_normalize(hit.normal, v);
    let lights = scene
        .lights
        .iter()
        .take(MAX_LIGHTS)
        .map(|l| light_sample(l, hit.point, n, v, material.m))
        .map(|s| (s.l, s.radiance))
        .collect();
    Some(Pick { pixel: (x, y), object: hit.object, material, point: hit.point, n, v, lights })
}

/// Samples of [`plane_lobe`]: every degree from −90° to 90°.
pub const LOBE_SAMPLES: usize = 181;

/// The specular terms along the plane of incidence of one light, for outgoing directions at
/// θ = −90°…90° from N (positive on the mirror side of L), as the sum multiplies them by the
/// light: Phong's `(V·R)^h`, Cook–Torrance's `F·D·G/(N·V)` (mean of the channels), and the
/// material's D (over its peak `1/(4 m²)`), G and F (mean of the channels) on their own.
#[derive(Clone, Debug, PartialEq)]
pub struct Lobe {
    pub theta: Vec<f64>,
    pub phong: Vec<f64>,
    pub cook_torrance: Vec<f64>,
    pub d: Vec<f64>,
    pub g: Vec<f64>,
    pub f: Vec<f64>,
}

/// The outgoing direction at `theta_deg` in the plane of N and L: `cos θ·N + sin θ·T`, T the
/// unit tangent pointing away from L (the mirror side); a light along N takes any tangent.
pub fn plane_direction(n: DVec3, l: DVec3, theta_deg: f64) -> DVec3 {
    let t = safe_normalize(-(l - l.dot(n) * n), n.any_orthonormal_vector());
    let th = theta_deg.to_radians();
    th.cos() * n + th.sin() * t
}

/// The specular terms of `mat` for light direction `l` along its plane of incidence (see
/// [`Lobe`]).
pub fn plane_lobe(n: DVec3, l: DVec3, mat: &Material) -> Lobe {
    let v_index = mat.mu.map(fresnel_v_from_mu);
    let mean = |c: [f64; 3]| (c[0] + c[1] + c[2]) / 3.0;
    let m = mat.m;
    let terms = mat.microfacet;
    let peak = microfacet_d(terms, 1.0, 0.0, m);
    let mut lobe = Lobe {
        theta: Vec::new(),
        phong: Vec::new(),
        cook_torrance: Vec::new(),
        d: Vec::new(),
        g: Vec::new(),
        f: Vec::new(),
    };
    for k in 0..LOBE_SAMPLES {
        let theta = -90.0 + k as f64;
        let w = plane_direction(n, l, theta);
        let r = 2.0 * n.dot(l) * n - l;
        let h = safe_normalize(l + w, n);
        let (nl, nw, nh, wh) = (n.dot(l), n.dot(w), n.dot(h), w.dot(h).clamp(0.0, 1.0));
        let lit = nl > 0.0 && nw > 0.0;
        let d = microfacet_d(terms, nh, n.cross(h).length_squared(), m);
        let g = microfacet_g(terms, nh, nw, nl, wh, m);
        let f = mean(microfacet_f(terms, wh, v_index));
        lobe.theta.push(theta);
        lobe.phong.push(if lit { specular_phong(w.dot(r), mat.h.value(), mat.h.is_mirror()) } else { 0.0 });
        lobe.cook_torrance.push(if lit { f * d * g / nw.max(N_DOT_V_MIN) } else { 0.0 });
        lobe.d.push(d / peak);
        lobe.g.push(g);
        lobe.f.push(f);
    }
    lobe
}

/// The Cook–Torrance specular BRDF `ρ_s = (F/π)·D·G/((N·V)(N·L))` with the material's terms
/// (docs/model.md §5, mean of the channels) at Rusinkiewicz angles θ_h, θ_d (degrees) and φ_d = 90°; 0 where L or V
/// is below the surface.
pub fn rho_s_at(theta_h: f64, theta_d: f64, mat: &Material) -> f64 {
    let (th, td) = (theta_h.to_radians(), theta_d.to_radians());
    // H in the xz plane at θ_h from N = z; L is the difference vector at (θ_d, φ_d = 90°) about
    // H, rotated with it; V its mirror about H.
    let h = DVec3::new(th.sin(), 0.0, th.cos());
    let d = DVec3::new(0.0, td.sin(), td.cos());
    let l = DVec3::new(d.x * th.cos() + d.z * th.sin(), d.y, -d.x * th.sin() + d.z * th.cos());
    let v = 2.0 * l.dot(h) * h - l;
    let n = DVec3::Z;
    let (nl, nv) = (n.dot(l), n.dot(v));
    if nl <= 0.0 || nv <= 0.0 {
        return 0.0;
    }
    let v_index = mat.mu.map(fresnel_v_from_mu);
    let t = mat.microfacet;
    let f = microfacet_f(t, l.dot(h), v_index).iter().sum::<f64>() / 3.0;
    let dd = microfacet_d(t, n.dot(h), n.cross(h).length_squared(), mat.m);
    let g = microfacet_g(t, n.dot(h), nv, nl, v.dot(h), mat.m);
    f / std::f64::consts::PI * dd * g / (nv * nl)
}

/// [`rho_s_at`] over a `size` × `size` grid, θ_h along x and θ_d down y, each from 0 to 90°
/// (cell centres), row by row.
pub fn theta_h_theta_d_slice(mat: &Material, size: usize) -> Vec<f64> {
    let at = |i: usize| (i as f64 + 0.5) / size as f64 * 90.0;
    (0..size).flat_map(|y| (0..size).map(move |x| (x, y))).map(|(x, y)| rho_s_at(at(x), at(y), mat)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_picked_pixel_sees_the_reference_object_and_its_angles() {
        let scene = Scene::builtin("sphere").unwrap();
        let (w, h) = (96, 54);
        let reference = crate::reference::render_reference(&scene, crate::SpecularModel::CookTorrance, w, h);
        let centre = (w / 2, h / 2);
        let p = pick(&scene, centre, (w, h)).expect("the sphere is at the centre");
        assert_eq!(Some(p.object), reference.object_at(centre.0, centre.1));
        assert!((p.n.length() - 1.0).abs() < 1e-12 && (p.v.length() - 1.0).abs() < 1e-12);
        assert!(p.n.dot(p.v) > 0.0, "a visible point faces the eye");
        // The model at the picked point, N and V is the reference's pixel.
        let lit = crate::lighting::shading::shade(
            p.point,
            p.n,
            scene.camera.eye_h(),
            &p.material,
            &scene.lights,
            scene.ambient,
            crate::SpecularModel::CookTorrance,
            scene.illumination,
        );
        let expected = reference.unshadowed[(centre.1 * w + centre.0) as usize];
        assert!(lit.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-12), "{lit:?} vs {expected:?}");
        assert!(pick(&scene, (0, 0), (w, h)).is_none_or(|q| q.object != p.object));
        assert!(pick(&scene, (w, 0), (w, h)).is_none());
    }

    #[test]
    fn the_lobe_peaks_at_the_mirror_direction() {
        let n = DVec3::Z;
        let l = DVec3::new(30f64.to_radians().sin(), 0.0, 30f64.to_radians().cos());
        let mat = Material { m: 0.2, h: crate::PhongExponent::Finite(50.0), ..Material::default() };
        let lobe = plane_lobe(n, l, &mat);
        let argmax = |v: &[f64]| v.iter().enumerate().fold(0, |b, (i, x)| if *x > v[b] { i } else { b });
        // L is 30° off N; its mirror is at +30°.
        assert_eq!(lobe.theta[argmax(&lobe.phong)], 30.0);
        assert_eq!(lobe.theta[argmax(&lobe.d)], 30.0);
        assert!((lobe.d[120] - 1.0).abs() < 1e-9, "{}", lobe.d[120]);
        assert!(lobe.g.iter().all(|g| (0.0..=1.0).contains(g)));
        assert!(lobe.f.iter().all(|f| (0.0..=1.0).contains(f)));
    }

    #[test]
    fn the_slice_is_the_chapters_brdf_and_peaks_at_theta_h_zero() {
        let mat = Material { m: 0.2, ..Material::default() };
        let s = theta_h_theta_d_slice(&mat, 30);
        assert!(s.iter().all(|x| x.is_finite() && *x >= 0.0));
        // Along θ_d = small, the BRDF falls as θ_h grows (D's peak at θ_h = 0).
        assert!(s[0] > s[10] && s[10] > s[20]);
        // At θ_h = 0 the half vector is N: rho_s agrees with the two-form identity of brdf.rs.
        let (seed, _) = crate::lighting::brdf::rho_s_forms(
            DVec3::Z,
            DVec3::new(0.0, -0.3f64.sin(), 0.3f64.cos()),
            DVec3::new(0.0, 0.3f64.sin(), 0.3f64.cos()),
            0.2,
            fresnel_v_from_mu(0.04),
        );
        assert!((rho_s_at(0.0, 0.3f64.to_degrees(), &mat) - seed).abs() < 1e-9 * seed);
    }
}
