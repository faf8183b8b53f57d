//! The pipeline cache: one shader module per effect set and one render pipeline per
//! [`PipelineKey`] (program + colour format), built on first use, or on a worker thread while the
//! uber pipeline draws (the viewer), and the shadow pass's depth-only pipeline. A program with
//! cast shadows has three bind groups (the shadow maps are @group(2)), one without has two.
//! Hot-reloaded WGSL replaces them all.

use crate::light_loop::LightLoop;
use crate::program::Program;
use crate::shaders;
use crate::vertex::{FlatVertex, SmoothVertex};
use shadelab_model::effects::{Effect, EffectKey};
use std::collections::HashMap;
use std::time::Duration;
use web_time::Instant;

pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Everything that selects a distinct pipeline. Plain `Copy + Hash`: pipelines are cached by it
/// and never rebuilt per frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PipelineKey {
    pub program: Program,
    pub color_format: wgpu::TextureFormat,
}

/// The pipeline layouts of one renderer.
#[derive(Clone)]
pub struct Layouts {
    /// Globals and object: programs without cast shadows.
    pub lit: wgpu::PipelineLayout,
    /// Globals, object and the shadow maps: programs with cast shadows.
    pub lit_shadows: wgpu::PipelineLayout,
    /// The flat and Gouraud pipelines: also the lit colours (group 3).
    pub lit_vertex: wgpu::PipelineLayout,
    pub lit_shadows_vertex: wgpu::PipelineLayout,
    /// The lighting passes, without and with the shadow maps.
    pub lighting_pass: wgpu::PipelineLayout,
    pub lighting_pass_shadows: wgpu::PipelineLayout,
    /// The shadow pass: object (group 1) and the layers' matrices (group 3).
    pub shadow_pass: wgpu::PipelineLayout,
    pub glass: wgpu::PipelineLayout,
    pub glass_shadows: wgpu::PipelineLayout,
    pub glass_back: wgpu::PipelineLayout,
}

impl Layouts {
    /// The layout a program's pipeline uses: three bind groups with cast shadows, two without.
    pub fn for_program(&self, program: Program) -> &wgpu::PipelineLayout {
        let shadows = program.effects().has(Effect::CastShadows);
        match (program.lighting_pass().is_some(), shadows) {
            (false, false) => &self.lit,
            (false, true) => &self.lit_shadows,
            (true, false) => &self.lit_vertex,
            (true, true) => &self.lit_shadows_vertex,
        }
    }
}

/// A pipeline being built on a worker thread (the viewer keeps drawing meanwhile).
struct PendingBuild {
    started: Instant,
    rx: std::sync::mpsc::Receiver<wgpu::RenderPipeline>,
}

/// The shader modules and pipelines of one device, by key.
pub struct PipelineCache {
    device: wgpu::Device,
    /// The WGSL before preprocessing (shipped, or hot-reloaded).
    raw_source: String,
    modules: HashMap<EffectKey, wgpu::ShaderModule>,
    layouts: Layouts,
    /// The shadow pass's depth-only pipeline, built on first use.
    shadow_pipeline: Option<wgpu::RenderPipeline>,
    /// The lighting passes' compute pipelines, by effect set, light loop and entry point, built
    /// on first use.
    lighting_pipelines: HashMap<(EffectKey, LightLoop, &'static str), wgpu::ComputePipeline>,
    /// The glass pass's pipelines by effects, light loop, colour format and back faces or not.
    glass_pipelines: HashMap<(EffectKey, LightLoop, wgpu::TextureFormat, bool), wgpu::RenderPipeline>,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    pending: HashMap<PipelineKey, PendingBuild>,
    /// Build missing pipelines on a worker thread and draw with the uber pipeline meanwhile
    /// (the viewer); off, a missing pipeline is built before the draw (renders, tests, benches).
    pub build_in_background: bool,
    /// How many pipelines have been built (the viewer shows it: it must not grow per frame).
    pub pipeline_builds: u32,
    /// The last pipeline built and how long it took (module + pipeline creation).
    pub last_build: Option<(PipelineKey, Duration)>,
}

impl PipelineCache {
    /// An empty cache whose pipelines use `layouts` (the renderer's bind groups).
    pub fn new(device: &wgpu::Device, layouts: Layouts) -> PipelineCache {
        PipelineCache {
            device: device.clone(),
            raw_source: shaders::raw_lighting_source(),
            modules: HashMap::new(),
            layouts,
            shadow_pipeline: None,
            lighting_pipelines: HashMap::new(),
            glass_pipelines: HashMap::new(),
            pipelines: HashMap::new(),
            pending: HashMap::new(),
            build_in_background: false,
            pipeline_builds: 0,
            last_build: None,
        }
    }

    /// Replace the shader source (hot reload). The source is preprocessed and validated by naga
    /// first: on an error nothing changes (the old modules and pipelines stay) and the message is
    /// returned; on success the cached modules and pipelines are dropped and rebuilt on next use.
    pub fn reload_shaders(&mut self, raw_source: &str) -> Result<(), String> {
        shaders::validate_raw(raw_source)?;
        self.raw_source = raw_source.to_owned();
        self.modules.clear();
        self.pipelines.clear();
        self.shadow_pipeline = None;
        self.lighting_pipelines.clear();
        self.glass_pipelines.clear();
        self.pending.clear();
        Ok(())
    }

    fn module(&mut self, effects: EffectKey) -> wgpu::ShaderModule {
        let (device, raw) = (&self.device, &self.raw_source);
        self.modules
            .entry(effects)
            .or_insert_with(|| {
                let src = shaders::lighting_source_for(raw, effects).expect("validated when loaded");
                device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(&format!("shadelab lighting [{}]", effects.label())),
                    source: wgpu::ShaderSource::Wgsl(src.into()),
                })
            })
            .clone()
    }

    /// The pipeline for a key, built on first use and cached.
    pub fn pipeline(&mut self, key: PipelineKey) -> &wgpu::RenderPipeline {
        if !self.pipelines.contains_key(&key) {
            let start = Instant::now();
            let module = self.module(key.program.effects());
            let p = build_pipeline(&self.device, self.layouts.for_program(key.program), &module, key);
            self.finish_build(key, p, start.elapsed());
        }
        &self.pipelines[&key]
    }

    fn finish_build(&mut self, key: PipelineKey, p: wgpu::RenderPipeline, took: Duration) {
        self.pipeline_builds += 1;
        self.last_build = Some((key, took));
        log::info!("pipeline {} built in {:.1} ms", key.program.label(), took.as_secs_f64() * 1e3);
        self.pipelines.insert(key, p);
    }

    /// The shadow pass's depth-only pipeline (`vs_shadow` of the shadow permutation, with the
    /// slope-scaled bias), built on first use and after a reload.
    pub fn shadow_pipeline(&mut self) -> &wgpu::RenderPipeline {
        if self.shadow_pipeline.is_none() {
            let module = self.module(EffectKey::NONE.with(Effect::CastShadows));
            let p = crate::shadow_pass::build_pipeline(&self.device, &self.layouts.shadow_pass, &module);
            self.shadow_pipeline = Some(p);
        }
        self.shadow_pipeline.as_ref().expect("built above")
    }

    /// The lighting pass `entry` (`cs_flat`, `cs_gouraud`) of a program: its effect set and light
    /// loop, built on first use.
    pub fn lighting_pipeline(&mut self, program: Program, entry: &'static str) -> &wgpu::ComputePipeline {
        let (effects, lights) = (program.effects(), program.light_loop());
        if !self.lighting_pipelines.contains_key(&(effects, lights, entry)) {
            let module = self.module(effects);
            let layout = if effects.has(Effect::CastShadows) {
                &self.layouts.lighting_pass_shadows
            } else {
                &self.layouts.lighting_pass
            };
            let label = format!("{entry} [{}] {}", effects.label(), lights.label());
            let p = crate::lighting_pass::build_pipeline(&self.device, layout, &module, entry, &label, lights);
            self.lighting_pipelines.insert((effects, lights, entry), p);
        }
        &self.lighting_pipelines[&(effects, lights, entry)]
    }

    /// Move pipelines finished on worker threads into the cache.
    /// The glass pass's pipeline of `program` (`back`: a mesh's back faces), built on first use.
    pub fn glass_pipeline(
        &mut self,
        program: Program,
        format: wgpu::TextureFormat,
        back: bool,
    ) -> &wgpu::RenderPipeline {
        let (effects, lights) = (program.effects(), program.light_loop());
        let key = (effects, lights, format, back);
        if !self.glass_pipelines.contains_key(&key) {
            let module = self.module(effects);
            let layout = match (back, effects.has(Effect::CastShadows)) {
                (true, _) => &self.layouts.glass_back,
                (false, false) => &self.layouts.glass,
                (false, true) => &self.layouts.glass_shadows,
            };
            let constants = lights.constants();
            let p = crate::glass_pass::build_pipeline(&self.device, layout, &module, effects, &constants, format, back);
            self.glass_pipelines.insert(key, p);
        }
        &self.glass_pipelines[&key]
    }

    pub fn poll_builds(&mut self) {
        let done: Vec<(PipelineKey, wgpu::RenderPipeline, Duration)> = self
            .pending
            .iter()
            .filter_map(|(k, b)| b.rx.try_recv().ok().map(|p| (*k, p, b.started.elapsed())))
            .collect();
        for (k, p, took) in done {
            self.pending.remove(&k);
            self.finish_build(k, p, took);
        }
    }

    /// Whether pipelines are being built in the background.
    pub fn building(&self) -> bool {
        !self.pending.is_empty()
    }

    /// The key to draw with now: `key` if its pipeline is ready; with `build_in_background`, the
    /// uber pipeline of the same shading while `key` is built on a worker thread. The baseline
    /// is always built before the draw.
    pub fn ready_key(&mut self, key: PipelineKey) -> PipelineKey {
        self.poll_builds();
        if !self.build_in_background || self.pipelines.contains_key(&key) || key.program == Program::NullBaseline {
            return key;
        }
        if !self.pending.contains_key(&key) {
            let (tx, rx) = std::sync::mpsc::channel();
            let (device, layout) = (self.device.clone(), self.layouts.for_program(key.program).clone());
            let module = self.module(key.program.effects());
            std::thread::spawn(move || {
                // A send fails only if the renderer is gone: nothing to do then.
                let _ = tx.send(build_pipeline(&device, &layout, &module, key));
            });
            self.pending.insert(key, PendingBuild { started: Instant::now(), rx });
        }
        PipelineKey { program: key.program.uber(), ..key }
    }
}

/// Build the pipeline of a key from its module (free, so worker threads can run it).
fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    key: PipelineKey,
) -> wgpu::RenderPipeline {
    let (vs, fs) = match key.program {
        Program::Lit { shading, interpolation, .. } => shaders::entry_points_with(shading, interpolation),
        Program::NullBaseline => shaders::BASELINE_ENTRY_POINTS,
    };
    let constants = key.program.light_loop().constants();
    let options = wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() };
    let first = if key.program.draws_flat_mesh() { FlatVertex::LAYOUT } else { SmoothVertex::LAYOUT };
    let buffers = &crate::vertex::buffers(first, key.program.effects());
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(&key.program.label()),
        layout: Some(layout),
        vertex: wgpu::VertexState { module, entry_point: Some(vs), compilation_options: options.clone(), buffers },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            // Every mesh is closed or seen from its front, but no culling keeps a wrong
            // winding from making geometry vanish.
            cull_mode: None,
            ..Default::default()
        },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fs),
            compilation_options: options,
            targets: &[Some(wgpu::ColorTargetState {
                format: key.color_format,
                blend: None,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}
