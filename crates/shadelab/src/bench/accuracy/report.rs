//! The accuracy study's data: what a run measures (`Plan`), its rows and report, and what is
//! read from them (the programs drawn, the Gouraud–Phong crossovers). The driver fills them; the
//! Markdown report, the CSV and the plots read them.

use shadelab_model::scene_variants::ANALYTIC_SCENES;
use shadelab_model::{ModelChoice, ShadingMode, SpecularModel};
use shadelab_render::RenderSettings;
use shadelab_render::image_error::ErrorStats;
use shadelab_render::timing::TimeSource;

/// What one run measures.
#[derive(Clone, Debug)]
pub struct Plan {
    pub scenes: Vec<&'static str>,
    /// Levels of detail: segments around spheres and cylinders (see `scene_variants::at_level`).
    pub levels: Vec<u32>,
    pub resolutions: Vec<(u32, u32)>,
    /// Cost per light: this scene, level and resolution with 1, 2, 4, 8 point lights.
    pub light_study: (&'static str, u32, (u32, u32)),
    pub light_counts: Vec<usize>,
    /// Cost per resolution step: this scene and level at these sizes.
    pub resolution_study: (&'static str, u32),
    pub study_resolutions: Vec<(u32, u32)>,
    /// The four illumination models: this scene, level and resolution, each shading mode, no
    /// cast shadows.
    pub model_study: (&'static str, u32, (u32, u32)),
    /// A base colour texture: this scene with its floor a textured mesh
    /// (`scene_variants::with_textured_floor`) at this level and resolution, each shading mode.
    pub texture_study: (&'static str, u32, (u32, u32)),
    /// Transparent objects: this scene at this level and resolution, each shading mode, and Phong
    /// shading straight through and with the back-face exit (`None`: not measured).
    pub glass_study: Option<(&'static str, u32, (u32, u32))>,
    pub frames: usize,
    pub warmup: usize,
}

impl Plan {
    /// The full study (a few minutes on lavapipe).
    pub fn full() -> Plan {
        Plan {
            scenes: ANALYTIC_SCENES.to_vec(),
            levels: vec![8, 16, 32, 64, 128, 256, 512],
            resolutions: vec![(320, 180), (640, 360)],
            light_study: ("sphere", 64, (640, 360)),
            light_counts: vec![1, 2, 4, 8],
            resolution_study: ("default", 64),
            study_resolutions: vec![(160, 90), (320, 180), (640, 360), (1280, 720), (1920, 1080)],
            model_study: ("default", 64, (640, 360)),
            texture_study: ("default", 64, (640, 360)),
            glass_study: Some(("glass", 32, (640, 360))),
            frames: 50,
            warmup: 5,
        }
    }

    /// A small subset for CI and a first look (well under a minute on lavapipe).
    pub fn quick() -> Plan {
        Plan {
            scenes: vec!["sphere", "default"],
            levels: vec![8, 32, 128],
            resolutions: vec![(160, 90), (320, 180)],
            light_study: ("sphere", 32, (160, 90)),
            light_counts: vec![1, 2, 4, 8],
            resolution_study: ("default", 32),
            study_resolutions: vec![(160, 90), (320, 180), (640, 360)],
            model_study: ("default", 32, (160, 90)),
            texture_study: ("default", 32, (160, 90)),
            glass_study: Some(("glass", 32, (160, 90))),
            frames: 10,
            warmup: 2,
        }
    }
}

/// Which part of the study a row belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Study {
    /// Mode × specular × level × resolution, scene lights.
    Modes,
    /// Cost per added light.
    Lights,
    /// Cost per resolution step.
    Resolution,
    /// The chapter's four illumination models, each shading mode.
    Models,
    /// A textured floor, each shading mode.
    Textures,
    /// Transparent objects: each shading mode, and the glass pass's cheaper ways.
    Glass,
}

impl Study {
    pub fn name(self) -> &'static str {
        match self {
            Study::Modes => "modes",
            Study::Lights => "lights",
            Study::Resolution => "resolution",
            Study::Models => "models",
            Study::Textures => "textures",
            Study::Glass => "glass",
        }
    }
}

/// One measured configuration. `shading`/`specular` are `None` for the null-shader baseline,
/// which has no error.
#[derive(Clone, Debug)]
pub struct Row {
    pub study: Study,
    pub scene: String,
    pub level: u32,
    pub triangles: usize,
    pub width: u32,
    pub height: u32,
    pub lights: usize,
    pub shading: Option<ShadingMode>,
    pub specular: Option<SpecularModel>,
    /// The illumination model (`None` for the baseline).
    pub model: Option<ModelChoice>,
    pub frames: usize,
    pub median_ms: f64,
    pub p10_ms: f64,
    pub p90_ms: f64,
    /// Median time over the baseline's median in the same group.
    pub ratio_to_baseline: f64,
    pub error: Option<ErrorStats>,
    /// On the Pareto front of (time, RMSE) among the shaded rows of its scene and resolution.
    pub pareto: bool,
    /// How the glass study's row draws its glass, beside its program ("" elsewhere).
    pub variant: &'static str,
}

impl Row {
    pub fn program(&self) -> String {
        match (self.shading, self.specular, self.model) {
            (Some(s), _, Some(m @ (ModelChoice::Lambert | ModelChoice::Sum))) => format!("{s}/{m}"),
            (Some(s), Some(p), _) if !self.variant.is_empty() => format!("{s}/{p}, {}", self.variant),
            (Some(s), Some(p), _) => format!("{s}/{p}"),
            _ => "baseline".into(),
        }
    }
}

/// Everything a run produced.
pub struct Report {
    pub rows: Vec<Row>,
    pub device: String,
    pub time_source: TimeSource,
    pub plan: Plan,
    pub command: String,
    pub seconds: f64,
}

/// The baseline (`None`: `Program::NullBaseline`), then every shading mode × specular model.
pub fn programs() -> Vec<Option<RenderSettings>> {
    let mut v = vec![None];
    for shading in ShadingMode::ALL_MODES {
        for specular in SpecularModel::ALL_MODELS {
            v.push(Some(RenderSettings::new(shading, specular)));
        }
    }
    v
}

/// The names of the texture study's scenes in the rows (each its own reference: not the plain
/// scene's).
pub(crate) const TEXTURED_FLOOR: &str = "default with a textured floor";
pub(crate) const MAPPED_FLOOR: &str = "default with a material-mapped floor";

pub(crate) fn rmse(r: &Row) -> f64 {
    r.error.map_or(f64::NAN, |e| e.rmse)
}

/// For each scene, resolution and specular model: the error Phong shading reaches at the
/// coarsest level, and the level (and time) at which Gouraud shading first reaches it.
pub struct Crossover {
    pub scene: String,
    pub size: (u32, u32),
    pub specular: SpecularModel,
    pub phong_level: u32,
    pub phong_rmse: f64,
    pub phong_ms: f64,
    /// (level, rmse, ms) of the first Gouraud row at or below `phong_rmse`, if any.
    pub gouraud: Option<(u32, f64, f64)>,
}

pub fn crossovers(report: &Report) -> Vec<Crossover> {
    let modes: Vec<&Row> = report.rows.iter().filter(|r| r.study == Study::Modes && r.error.is_some()).collect();
    let mut out = Vec::new();
    for &scene in &report.plan.scenes {
        for &size in &report.plan.resolutions {
            for specular in SpecularModel::ALL_MODELS {
                let pick = |mode: ShadingMode| {
                    let mut v: Vec<&&Row> = modes
                        .iter()
                        .filter(|r| {
                            r.scene == scene
                                && (r.width, r.height) == size
                                && r.shading == Some(mode)
                                && r.specular == Some(specular)
                        })
                        .collect();
                    v.sort_by_key(|r| r.level);
                    v
                };
                let (phong, gouraud) = (pick(ShadingMode::Phong), pick(ShadingMode::Gouraud));
                let Some(p) = phong.first() else { continue };
                let target = rmse(p);
                out.push(Crossover {
                    scene: scene.to_string(),
                    size,
                    specular,
                    phong_level: p.level,
                    phong_rmse: target,
                    phong_ms: p.median_ms,
                    gouraud: gouraud.iter().find(|g| rmse(g) <= target).map(|g| (g.level, rmse(g), g.median_ms)),
                });
            }
        }
    }
    out
}
