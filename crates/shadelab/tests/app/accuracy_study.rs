//! The accuracy study's driver (`shadelab bench accuracy`) on lavapipe: every group is measured
//! against the reference of its own scene, so its error rows mean what they say.

use shadelab::bench::accuracy::{Plan, Study, run_plan};
use shadelab_model::ShadingMode;

#[test]
fn each_light_count_is_measured_against_its_own_reference() {
    let gpu = shadelab_render::Gpu::lavapipe().unwrap_or_else(|e| panic!("{e}"));
    // The built-in sphere has two lights of its own: its "modes" group and the two-light group of
    // the light study have the same light count but different lights.
    let plan = Plan {
        scenes: vec!["sphere"],
        levels: vec![64],
        resolutions: vec![(160, 90)],
        light_study: ("sphere", 64, (160, 90)),
        light_counts: (1..=8).collect(),
        resolution_study: ("sphere", 64),
        study_resolutions: vec![],
        model_study: ("sphere", 16, (96, 54)),
        texture_study: ("sphere", 8, (48, 27)),
        glass_study: None,
        frames: 1,
        warmup: 0,
    };
    let report = run_plan(&gpu, &plan, "test", |_| {});
    let rows: Vec<_> =
        report.rows.iter().filter(|r| r.study == Study::Lights && r.shading == Some(ShadingMode::Phong)).collect();
    assert_eq!(rows.len(), 2 * 8, "Phong shading × two specular models × eight light counts");
    for r in rows {
        let rmse = r.error.as_ref().expect("shaded rows are compared").rmse;
        eprintln!("{} lights, {}: RMSE {rmse:.2e}", r.lights, r.program());
        // Phong shading at level 64 is within about 3e-3 of the reference whatever the lights
        // (the full study: 2.5e-3 at 640×360); measured against another scene's reference the
        // two-light rows were at 9.7e-2.
        assert!(rmse < 1e-2, "{} lights, {}: RMSE {rmse} against the reference", r.lights, r.program());
    }
}

/// The study has a row per illumination model and shading mode, each with its error against the
/// reference of its own model, beside a baseline.
#[test]
fn the_models_study_measures_each_model_in_each_shading_mode() {
    let gpu = shadelab_render::Gpu::lavapipe().unwrap_or_else(|e| panic!("{e}"));
    let plan = Plan { model_study: ("default", 32, (160, 90)), ..studies_only() };
    let report = run_plan(&gpu, &plan, "test", |_| {});
    let rows: Vec<_> = report.rows.iter().filter(|r| r.study == Study::Models).collect();
    assert_eq!(rows.len(), 4 * (1 + 3), "four models × (baseline + three shading modes)");
    for m in shadelab_model::ModelChoice::ALL_CHOICES {
        let shaded: Vec<_> = rows.iter().filter(|r| r.model == Some(m)).collect();
        assert_eq!(shaded.len(), 3, "{m}");
        assert!(shaded.iter().all(|r| r.error.is_some_and(|e| e.rmse.is_finite() && e.rmse < 0.1)), "{m}");
        // Phong shading draws each model closest to its exact image.
        let rmse = |s: ShadingMode| shaded.iter().find(|r| r.shading == Some(s)).unwrap().error.unwrap().rmse;
        assert!(rmse(ShadingMode::Phong) < rmse(ShadingMode::Flat), "{m}");
    }
}

/// The texture study draws the textured floor in each shading mode against the reference that
/// samples the texture: every mode draws it (flat and Gouraud tint per pixel), so every mode is
/// far closer than the factor alone (1.2e-1), and Phong shading, which also lights per pixel, is
/// the closest. On the material-mapped floor Phong shading is the closest too: the per-vertex
/// modes leave its metallic–roughness and occlusion textures out.
#[test]
fn the_texture_study_measures_each_mode_with_its_texture() {
    let gpu = shadelab_render::Gpu::lavapipe().unwrap_or_else(|e| panic!("{e}"));
    let plan = Plan { texture_study: ("default", 32, (160, 90)), ..studies_only() };
    let report = run_plan(&gpu, &plan, "test", |_| {});
    let rows: Vec<_> = report.rows.iter().filter(|r| r.study == shadelab::bench::accuracy::Study::Textures).collect();
    assert_eq!(rows.len(), 2 * (1 + 3), "two floors: baseline + three shading modes each");
    let rmse = |scene: &str, s: ShadingMode| {
        rows.iter().find(|r| r.scene == scene && r.shading == Some(s)).unwrap().error.unwrap().rmse
    };
    let floor = "default with a textured floor";
    let (phong, gouraud, flat) =
        (rmse(floor, ShadingMode::Phong), rmse(floor, ShadingMode::Gouraud), rmse(floor, ShadingMode::Flat));
    eprintln!("textured floor RMSE: Phong {phong:.2e}, Gouraud {gouraud:.2e}, flat {flat:.2e}");
    assert!(phong <= gouraud && phong <= flat, "{phong} vs {gouraud}, {flat}");
    assert!(gouraud < 0.05 && flat < 0.05, "the per-vertex modes draw the texture: {gouraud}, {flat}");
    let mapped = "default with a material-mapped floor";
    let (phong, gouraud, flat) =
        (rmse(mapped, ShadingMode::Phong), rmse(mapped, ShadingMode::Gouraud), rmse(mapped, ShadingMode::Flat));
    eprintln!("material-mapped floor RMSE: Phong {phong:.2e}, Gouraud {gouraud:.2e}, flat {flat:.2e}");
    assert!(phong < gouraud && phong < flat, "{phong} vs {gouraud}, {flat}");
}

/// A plan of one frame per program whose modes, light and resolution parts are empty and whose
/// models and texture parts are tiny: a test sets the part it measures.
fn studies_only() -> Plan {
    Plan {
        scenes: vec![],
        levels: vec![],
        resolutions: vec![],
        light_study: ("sphere", 16, (96, 54)),
        light_counts: vec![],
        resolution_study: ("sphere", 16),
        study_resolutions: vec![],
        model_study: ("sphere", 8, (48, 27)),
        texture_study: ("sphere", 8, (48, 27)),
        glass_study: None,
        frames: 1,
        warmup: 0,
    }
}

/// The glass study measures each mode and the glass pass's cheaper ways against the Whitted
/// reference: straight through is further from it than refracting, the back-face exit further
/// than the analytic one, and refraction costs more than going straight.
#[test]
fn the_glass_study_measures_the_glass_pass_against_the_tracer() {
    let gpu = shadelab_render::Gpu::lavapipe().unwrap_or_else(|e| panic!("{e}"));
    let plan = Plan { glass_study: Some(("glass", 16, (160, 90))), frames: 2, ..studies_only() };
    let report = run_plan(&gpu, &plan, "test", |_| {});
    let rows: Vec<_> = report.rows.iter().filter(|r| r.study == shadelab::bench::accuracy::Study::Glass).collect();
    assert_eq!(rows.len(), 1 + 3 + 2, "baseline, three shading modes, straight through and back faces");
    let row = |program: &str| rows.iter().find(|r| r.program() == program).unwrap_or_else(|| panic!("{program}"));
    let rmse = |program: &str| row(program).error.unwrap().rmse;
    let (exact, straight, back) = (
        rmse("phong/cook-torrance"),
        rmse("phong/cook-torrance, straight through"),
        rmse("phong/cook-torrance, back-face exit"),
    );
    eprintln!("glass RMSE: analytic {exact:.2e}, back faces {back:.2e}, straight {straight:.2e}");
    assert!(exact < back && back < straight, "{exact} {back} {straight}");
    let md = shadelab::bench::accuracy::markdown(&report);
    assert!(md.contains("## Transparent objects (glass level 16, 160×90)"), "{md}");
}
