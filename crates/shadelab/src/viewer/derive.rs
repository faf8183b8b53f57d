//! The frame as drawn, derived from the scene and the settings only when either changes: the
//! extract step. The scene is never changed to draw a view of it; its copy as drawn (one term
//! alone, small area lights drawn as points) shares its meshes and textures, so the copy is cheap.
//! Everything the frame needs is derived from that copy once: the effect analysis, the program.
//! The camera is no input: orbiting changes it alone, and the copy takes it without deriving.

use shadelab_model::Scene;
use shadelab_model::effects::{Analysis, analyze};
use shadelab_model::terms::Term;
use shadelab_render::{Program, RenderSettings};
use std::collections::VecDeque;
use web_time::{Duration, Instant};

/// What a frame draws: the scene as drawn, its analysis and program, and why area lights are drawn
/// as points (the panel's lines).
pub struct Drawn {
    /// Which derivation this is (1 for the first).
    pub derivation: u64,
    pub scene: Scene,
    pub analysis: Analysis,
    pub program: Program,
    pub small_area_lights: Vec<String>,
}

/// What the derivation depends on: the scene but its camera (of which only whether it is
/// orthographic counts, for a directional light's cascade layers).
struct Inputs {
    scene: Scene,
    settings: RenderSettings,
    term: Term,
    /// The view's size: the small area lights' test and the uniforms depend on it.
    size: (u32, u32),
}

/// The last derivation, and how many were made (the live numbers show them: derivations happen
/// on changes, never on a frame that changes nothing).
#[derive(Default)]
pub struct Derived {
    last: Option<(Inputs, Drawn)>,
    count: u64,
    recent: VecDeque<Instant>,
}

impl Derived {
    /// The frame as drawn for these inputs, derived again only if they changed; the camera alone
    /// changing (an orbit) is given to the drawn copy as it is.
    pub fn get(&mut self, scene: &Scene, settings: &RenderSettings, term: Term, size: (u32, u32)) -> &Drawn {
        let same = self.last.as_mut().is_some_and(|(i, _)| {
            let projection = i.scene.camera.orthographic.is_some() == scene.camera.orthographic.is_some();
            // The kept copy takes the current camera, so comparing the scenes leaves it out.
            i.scene.camera = scene.camera;
            projection && i.settings == *settings && i.term == term && i.size == size && i.scene == *scene
        });
        if !same {
            let inputs = Inputs { scene: scene.clone(), settings: *settings, term, size };
            self.count += 1;
            self.last = Some((inputs, derive(scene, settings, term, size.1, self.count)));
            self.recent.push_back(Instant::now());
        }
        let drawn = &mut self.last.as_mut().expect("derived above").1;
        drawn.scene.camera = scene.camera;
        drawn
    }

    /// Derivations so far.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// Derivations in the last second.
    pub fn per_second(&mut self) -> usize {
        while self.recent.front().is_some_and(|t| t.elapsed() > Duration::from_secs(1)) {
            self.recent.pop_front();
        }
        self.recent.len()
    }
}

/// The scene as drawn and what is derived from it.
fn derive(scene: &Scene, settings: &RenderSettings, term: Term, height: u32, derivation: u64) -> Drawn {
    let mut drawn = scene.clone();
    // One term alone: the other terms' coefficients at 0 (the reference sees the same scene).
    term.apply(&mut drawn);
    // An area light too small on screen to show its area: a point light, and why.
    let small_area_lights = shadelab_model::effects::draw_small_area_lights_as_points(&mut drawn, height);
    let analysis = analyze(&drawn, settings.specular);
    let program = Program::for_analysis(&drawn, settings, analysis.key);
    Drawn { derivation, scene: drawn, analysis, program, small_area_lights }
}
