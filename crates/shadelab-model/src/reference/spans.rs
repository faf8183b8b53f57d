//! The reference image traced on every core: its rows cut into spans of pixels, each traced into
//! its own buffer (the exact light, and with paths the light between surfaces), appended in
//! order, so the image is the same on any number of threads.

use super::intersect::{self, Geometry, trace};
use super::path::{self, PathSettings};
use super::shadow_rays::ShadowRays;
use super::{Context, EnvUse, ReferenceImage};
use crate::Light;
use crate::lighting::env_map::EnvLight;
use crate::params::SpecularModel;
use crate::scene::{Material, Scene, UvFootprint};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// Trace the rows `rows` of `img`'s size, appending their pixels (rows come in order); `exact`:
/// area lights integrated exactly ([`super::render_reference`]), else as drawn ([`super::render_drawn`]);
/// `paths`: the indirect light path traced and added, and the constant ambient per unit of `I_a`
/// from the exact image of the scene given with `I_a = 1`.
pub(super) fn trace_rows(
    scene: &Scene,
    geo: &Geometry,
    specular: SpecularModel,
    img: &mut ReferenceImage,
    rows: std::ops::Range<u32>,
    exact: bool,
    paths: Option<(&PathSettings, &[Scene; 2])>,
    env: Option<&EnvLight>,
) {
    let rays = ShadowRays::new(scene, geo);
    let env_use = if paths.is_some() { EnvUse::Traced } else { EnvUse::Sh };
    let areas = |scene: &Scene| scene.lights.iter().map(Light::area_light).collect();
    let area_error = AtomicU64::default();
    let ctx = Context { scene, geo, rays: &rays, specular, exact, env, env_use, area_error, areas: areas(scene) };
    let unit_rays = paths.map(|(_, [unit, _])| ShadowRays::new(unit, geo));
    let unit_ctx = paths.zip(unit_rays.as_ref()).map(|((p, [one, zero]), rays)| {
        let ctx = |scene| {
            let area_error = AtomicU64::default();
            Context { scene, geo, rays, specular, exact, env, env_use, area_error, areas: areas(scene) }
        };
        (p, [ctx(one), ctx(zero)])
    });
    // Spans of rows on every core, each into its own buffer, appended in order: the same image
    // as one thread would trace.
    let (width, height) = (img.width, img.height);
    let spans: Vec<Span> = rows
        .flat_map(|y| {
            (0..width.div_ceil(SPAN_PIXELS)).map(move |s| Span {
                y,
                xs: s * SPAN_PIXELS..((s + 1) * SPAN_PIXELS).min(width),
                width,
                height,
            })
        })
        .collect();
    let traced: Vec<SpanPixels> = spans
        .into_par_iter()
        .map(|span| {
            let mut row = trace_span(&ctx, &span);
            if let Some((paths, unit)) = &unit_ctx {
                path::add_paths(&ctx, unit, paths, &span, &mut row);
            }
            row
        })
        .collect();
    for row in traced {
        img.indirect.extend(row.indirect);
        img.per_ambient.extend(row.per_ambient);
        img.std_error.extend(row.std_error);
        img.fireflies += row.fireflies;
        img.pixels.extend(row.pixels);
        img.unshadowed.extend(row.unshadowed);
        img.object.extend(row.object);
        img.hidden.extend(row.hidden);
    }
    img.area_error = img.area_error.max(f64::from_bits(ctx.area_error.load(Ordering::Relaxed)));
}

/// Pixels a unit of the reference's parallel work spans: rows are cut into pieces this wide, so
/// that a step of a few rows (the progress bar's fiftieth of an image) still keeps every core
/// busy; whole rows left one of two threads idle a third of the time on 3 rows a step.
const SPAN_PIXELS: u32 = 32;

/// Pixels `xs` of row `y` of a `width × height` image: one unit of the parallel work.
pub(super) struct Span {
    pub(super) y: u32,
    pub(super) xs: std::ops::Range<u32>,
    pub(super) width: u32,
    pub(super) height: u32,
}

/// One span's pixels, as [`ReferenceImage`] holds them.
#[derive(Default)]
pub(super) struct SpanPixels {
    pub(super) pixels: Vec<[f64; 3]>,
    pub(super) unshadowed: Vec<[f64; 3]>,
    pub(super) object: Vec<Option<usize>>,
    pub(super) hidden: Vec<u8>,
    pub(super) indirect: Vec<[f64; 3]>,
    pub(super) per_ambient: Vec<[f64; 3]>,
    pub(super) std_error: Vec<[f64; 3]>,
    pub(super) fireflies: usize,
}

/// The pixels of `span`, traced in `ctx`.
pub(super) fn trace_span(ctx: &Context, span: &Span) -> SpanPixels {
    let (scene, geo) = (ctx.scene, ctx.geo);
    let Span { y, width, height, .. } = *span;
    let mut img = SpanPixels::default();
    let mut tinted: Vec<Material> = scene.materials.clone();
    for x in span.xs.clone() {
        let (o, dir) = scene.camera.ray(x, y, width, height);
        let Some(hit) = trace(scene, geo, o, dir) else {
            let background = ctx.env_background(dir).unwrap_or_else(|| scene.background.unwrap_or([0.0; 3]));
            img.pixels.push(background);
            img.unshadowed.push(background);
            img.object.push(None);
            img.hidden.push(0);
            continue;
        };
        let eye = scene.camera.eye_h();
        if scene.drawn_as_glass(hit.object) {
            // A transparent object: its surface and what the traced paths bring through it.
            let shaded = ctx.glass(&hit, dir, eye);
            img.pixels.push(shaded.lit);
            img.unshadowed.push(shaded.unshadowed);
            img.object.push(Some(hit.object));
            img.hidden.push(shaded.hidden);
            continue;
        }
        let mi = scene.objects[hit.object].material;
        let material = &scene.materials[mi];
        // The pixel's footprint in texture coordinates, as the GPU's derivatives take it: the
        // differences across the 2×2 quad's pair of pixels in x and in y, on the same plane.
        let footprint = hit.triangle.filter(|_| material.varies([1.0; 3])).and_then(|k| {
            let uv_at = |px: u32, py: u32| {
                let (o, d) = scene.camera.ray(px, py, width, height);
                intersect::uv_on_triangle_plane(scene, &geo.inverses, hit.object, k, o, d)
            };
            let (x0, y0) = (x & !1, y & !1);
            let (a, b, c, d) = (uv_at(x0, y)?, uv_at(x0 + 1, y)?, uv_at(x, y0)?, uv_at(x, y0 + 1)?);
            Some(UvFootprint { dx: [b[0] - a[0], b[1] - a[1]], dy: [d[0] - c[0], d[1] - c[1]] })
        });
        let shaded = ctx.shade_hit(&hit, eye, &mut tinted, footprint.as_ref(), None, None);
        img.pixels.push(shaded.lit);
        img.unshadowed.push(shaded.unshadowed);
        img.object.push(Some(hit.object));
        img.hidden.push(shaded.hidden);
    }
    img
}
