//! The LTC specular against the integral it stands for, its identities, and its hard cases.

use super::*;
use crate::lighting::area::{AreaLight, AreaShape, sphere_irradiance};
use crate::lighting::area_exact::{specular_area_quadrature, specular_representative_point};
use crate::lighting::microfacet::Microfacet;
use crate::lighting::ms_table::ms_albedo;

fn clear(_: DVec3, _: DVec3) -> bool {
    true
}

/// The specular of the whole light by LTC, `Σ S(l)·cos θ_l·ΔA/r²` as the quadrature sums it:
/// `area_specular_ltc`'s value times `A_emit/d²`, times F at the representative point.
fn ltc_light(light: &AreaLight, p: DVec3, n: DVec3, v: DVec3, m: f64, v_index: [f64; 3]) -> f64 {
    let terms = Microfacet::CHAPTER;
    let minv = ltc_matrix(terms.d.code(), n.dot(v), m);
    let e = ms_albedo(terms, n.dot(v), m);
    let ltc = area_specular_ltc(light, p, n, v, minv, e).expect("an area light, not its point limit");
    let (l, _) = super::super::area::area_specular_point(light, p, n, v, m);
    let d2 = (light.center - p).length_squared();
    specular_ltc(n, v, l, v_index, terms, 1.0, ltc)[0] * light.emitting_area() / d2
}

/// docs/area-lights.md's table: the LTC and the representative point against the integral over
/// the light (256² cells), lights 2 m away on the mirror direction and 8° and 20° off it, the
/// view 30° off the normal, the chapter's terms with v = 1.5. The LTC stays within 7 % where the
/// light is on the mirror direction at m ≥ 0.2 and within 30 % everywhere (it falls short in the
/// Beckmann lobe's tail), where the representative point is off by up to 3.2×.
#[test]
fn ltc_specular_against_the_integral() {
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    let v = DVec3::new(-0.5, 0.0, 0.85).normalize();
    let v_index = [1.5; 3];
    for off in [0.0f64, 8.0, 20.0] {
        let mirror = f64::atan2(0.5, 0.85) + off.to_radians();
        let c = DVec3::new(mirror.sin(), 0.0, mirror.cos()) * 2.0;
        for (name, shape) in [
            ("sphere r 0.4", AreaShape::Sphere { radius: 0.4 }),
            ("rect 0.8", AreaShape::Rect { half_x: 0.4, half_y: 0.4 }),
            ("disk r 0.4", AreaShape::Disk { radius: 0.4 }),
        ] {
            let light = AreaLight { shape, center: c, normal: (-c).normalize(), tangent: DVec3::Y };
            for m in [0.1, 0.2, 0.4, 0.7] {
                let reference = specular_area_quadrature(&light, p, n, v, m, v_index, 256, &clear)[0];
                let ltc = ltc_light(&light, p, n, v, m, v_index);
                let rp = specular_representative_point(&light, p, n, v, m, v_index)[0];
                let (e_ltc, e_rp) = ((ltc - reference) / reference, (rp - reference) / reference);
                eprintln!("AREA-LTC | {name} | {off}° | {m} | {e_ltc:+.3} | {e_rp:+.3} |");
                assert!(ltc.is_finite() && ltc >= 0.0, "{name} {off}° m {m}: {ltc}");
                assert!(e_ltc.abs() <= 0.30, "{name} {off}° m {m}: LTC {e_ltc:+.3}, representative {e_rp:+.3}");
                if off == 0.0 && m >= 0.2 {
                    assert!(e_ltc.abs() <= 0.07, "{name} on the mirror direction, m {m}: LTC {e_ltc:+.3}");
                }
            }
        }
    }
}

/// With `M⁻¹` the identity the LTC is the clamped cosine itself, so the integral over a sphere
/// light drawn as the disk covering its cone is the sphere's exact cap E/L over π (within the
/// disk polygon's 0.3 %), above the horizon and across it. A light filling the hemisphere
/// integrates to the LTC's mass above the horizon: 1 less the little the fitted distribution puts
/// below it, where the lobe has none (0.65 % here).
#[test]
fn the_cosine_over_the_covering_disk_is_the_spheres_cap() {
    let n = DVec3::Z;
    for (d, theta) in [(2.0, 0.0f64), (1.0, 0.6), (3.0, 1.2), (1.5, 1.5), (1.2, 1.75)] {
        let c = DVec3::new(theta.sin(), 0.0, theta.cos()) * d;
        let light =
            AreaLight { shape: AreaShape::Sphere { radius: 0.5 }, center: c, normal: DVec3::Z, tangent: DVec3::X };
        let ltc = ltc_polygon(&sphere_as_disk(&light, DVec3::ZERO), DVec3::ZERO, n, DVec3::X, DMat3::IDENTITY);
        let exact = sphere_irradiance(0.5, d, theta.cos()) / PI;
        assert!((ltc - exact).abs() <= 3e-3 * exact + 1e-7, "d {d}, θ {theta}: {ltc} against {exact}");
    }
    let huge = AreaLight {
        shape: AreaShape::Rect { half_x: 1e4, half_y: 1e4 },
        center: DVec3::new(0.0, 0.0, 1.0),
        normal: DVec3::NEG_Z,
        tangent: DVec3::X,
    };
    let v = DVec3::new(0.3, 0.0, 1.0).normalize();
    let minv = ltc_matrix(0, n.dot(v), 0.3);
    let t = DVec3::X;
    let all = ltc_polygon(&huge, DVec3::ZERO, n, t, minv);
    assert!((0.98..=1.0).contains(&all), "a light over the whole hemisphere: {all}");
}

/// The hard cases stay finite and in range: a point on the light, inside a sphere light, a light
/// behind the surface or edge-on, a view below or along the surface, m at 0 and 1, a light too
/// small to show (the point limit: `None`).
#[test]
fn ltc_hard_cases_stay_finite() {
    let n = DVec3::Z;
    let shapes = [
        AreaShape::Rect { half_x: 0.5, half_y: 0.3 },
        AreaShape::Disk { radius: 0.4 },
        AreaShape::Sphere { radius: 0.4 },
        AreaShape::Sphere { radius: 1e-6 },
    ];
    let centres = [
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::ZERO,
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.3, 0.0, 0.2),
    ];
    let views = [DVec3::Z, DVec3::X, DVec3::new(1.0, 0.0, 1e-7).normalize(), DVec3::new(0.5, 0.0, -0.5).normalize()];
    let normals = [DVec3::NEG_Z, DVec3::X, DVec3::Z];
    for shape in shapes {
        for &center in &centres {
            for &normal in &normals {
                let light = AreaLight { shape, center, normal, tangent: normal.any_orthonormal_vector() };
                for &v in &views {
                    for m in [0.0, 0.05, 1.0] {
                        for (i, _) in Distribution::ALL.iter().enumerate() {
                            let minv = ltc_matrix(i as u32, n.dot(v), m);
                            let s = area_specular_ltc(&light, DVec3::ZERO, n, v, minv, 1.0);
                            if let Some(x) = s {
                                let bound = (center.length_squared() / light.emitting_area()) * PI;
                                assert!(
                                    x.is_finite() && x >= 0.0 && x <= bound * (1.0 + 1e-9),
                                    "{shape:?} at {center} v {v} m {m}: {x}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }
}
