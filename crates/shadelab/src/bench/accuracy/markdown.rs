//! The accuracy study's Markdown report and terminal summary.

use super::report::{MAPPED_FLOOR, Report, Row, Study, TEXTURED_FLOOR, crossovers};
use shadelab_model::scene_variants;
use std::fmt::Write as _;

/// The Markdown report: device, command, the findings, then every table.
pub fn markdown(report: &Report) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# What accuracy costs — `{}`\n", report.command);
    let _ = writeln!(
        s,
        "Device: {}. Time: {}, median of {} frames after {} warm-up, every program of a group interleaved frame by frame. Error: against the f64 ray-cast reference of the exact surface, same size. Run took {:.0} s.\n",
        report.device,
        report.time_source.label(),
        report.plan.frames,
        report.plan.warmup,
        report.seconds
    );
    let _ = writeln!(s, "## Gouraud against Phong shading\n");
    let _ = writeln!(
        s,
        "The error Phong shading has at the coarsest level, and where Gouraud shading first gets as close to the exact surface:\n"
    );
    let _ = writeln!(
        s,
        "| scene | size | specular | Phong shading: level, RMSE, ms | Gouraud reaches it at: level, RMSE, ms |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    for c in crossovers(report) {
        let g = match c.gouraud {
            Some((l, e, ms)) => format!("{l}, {e:.2e}, {ms:.2}"),
            None => format!("not by level {}", report.plan.levels.last().copied().unwrap_or(0)),
        };
        let _ = writeln!(
            s,
            "| {} | {}×{} | {} | {}, {:.2e}, {:.2} | {} |",
            c.scene, c.size.0, c.size.1, c.specular, c.phong_level, c.phong_rmse, c.phong_ms, g
        );
    }
    let _ = writeln!(s, "\n## Every configuration\n");
    let _ = writeln!(
        s,
        "RMSE and max: linear RGB. FLIP: nv-flip mean of the display-encoded images. Off: share of pixels more than one 8-bit sRGB step away. ×base: median time over the null-shader baseline's (same geometry, constant colour). ★: on the Pareto front of time and RMSE for its scene, size and specular model (nothing else with that specular model is both faster and closer).\n"
    );
    table(&mut s, report.rows.iter().filter(|r| r.study == Study::Modes));
    let _ = writeln!(
        s,
        "\n## Cost per light ({} level {}, {}×{})\n",
        report.plan.light_study.0, report.plan.light_study.1, report.plan.light_study.2.0, report.plan.light_study.2.1
    );
    table(&mut s, report.rows.iter().filter(|r| r.study == Study::Lights));
    let _ = writeln!(
        s,
        "\n## Cost per resolution ({} level {})\n",
        report.plan.resolution_study.0, report.plan.resolution_study.1
    );
    table(&mut s, report.rows.iter().filter(|r| r.study == Study::Resolution));
    let _ = writeln!(
        s,
        "\n## The four illumination models ({} level {}, {}×{}, no cast shadows)\n\nEach model against the f64 reference of the same model: what each costs and how close each shading mode draws it.\n",
        report.plan.model_study.0, report.plan.model_study.1, report.plan.model_study.2.0, report.plan.model_study.2.1
    );
    table(&mut s, report.rows.iter().filter(|r| r.study == Study::Models));
    let (_, level, (w, h)) = report.plan.texture_study;
    let _ = writeln!(
        s,
        "\n## Material textures (level {level}, {w}×{h})\n\n*{TEXTURED_FLOOR}*: the floor a mesh with a {n}² bilinear checker repeated {r} times as its base colour texture, against the reference that samples it the same way: every mode samples it per pixel; flat and Gouraud shading light per face or vertex and tint per pixel. *{MAPPED_FLOOR}*: the same floor a glTF metal with metallic–roughness, occlusion and emissive textures too; flat and Gouraud shading draw its emission per pixel and leave the metallic–roughness and occlusion textures, which vary the lighting, to Phong shading (docs/textures.md).\n",
        n = scene_variants::CHECKER_TEXELS,
        r = scene_variants::CHECKER_REPEATS,
    );
    table(&mut s, report.rows.iter().filter(|r| r.study == Study::Textures));
    if let Some((name, level, (w, h))) = report.plan.glass_study {
        let _ = writeln!(
            s,
            "\n## Transparent objects ({name} level {level}, {w}×{h})\n\nThe glass scene against the reference's Whitted tracer (docs/transparency.md): every mode draws the glass per pixel; Phong shading also straight through (no refraction) and with the back-face exit instead of the analytic one.\n"
        );
        table(&mut s, report.rows.iter().filter(|r| r.study == Study::Glass));
    }
    s
}

fn table<'a>(s: &mut String, rows: impl Iterator<Item = &'a Row>) {
    let _ = writeln!(
        s,
        "| scene | level | triangles | size | lights | program | median ms | p10–p90 | ×base | RMSE | max | FLIP | off | ★ |"
    );
    let _ = writeln!(s, "|---|---:|---:|---|---:|---|---:|---|---:|---:|---:|---:|---:|---|");
    for r in rows {
        let (e1, e2, e3, e4) = match r.error {
            Some(e) => (
                format!("{:.2e}", e.rmse),
                format!("{:.3}", e.max_abs),
                format!("{:.4}", e.flip_mean),
                format!("{:.1} %", e.share_off * 100.0),
            ),
            None => Default::default(),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {}×{} | {} | {} | {:.2} | {:.2}–{:.2} | {:.2} | {} | {} | {} | {} | {} |",
            r.scene,
            r.level,
            r.triangles,
            r.width,
            r.height,
            r.lights,
            r.program(),
            r.median_ms,
            r.p10_ms,
            r.p90_ms,
            r.ratio_to_baseline,
            e1,
            e2,
            e3,
            e4,
            if r.pareto { "★" } else { "" }
        );
    }
}

/// What the terminal shows at the end: the findings and the Pareto front.
pub fn summary(report: &Report) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# device: {}; time: {}; {:.0} s", report.device, report.time_source.label(), report.seconds);
    for c in crossovers(report) {
        let g = match c.gouraud {
            Some((l, e, ms)) => format!("Gouraud reaches it at level {l} ({e:.2e}, {ms:.2} ms)"),
            None => "Gouraud does not reach it in the measured levels".into(),
        };
        let _ = writeln!(
            s,
            "{} {}×{} {}: Phong shading at level {} has RMSE {:.2e} in {:.2} ms; {}",
            c.scene, c.size.0, c.size.1, c.specular, c.phong_level, c.phong_rmse, c.phong_ms, g
        );
    }
    s
}
