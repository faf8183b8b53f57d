//! The pipeline cache: one shader module per effect set and one render pipeline per
//! [`PipelineKey`] (program + colour format), built on first use, or on a worker thread while the
//! uber pipeline draws (the viewer), and the other passes' pipelines, which each pass builds
//! itself through [`PipelineCache::pass_pipeline`] (the cache knows no pass). A program with
//! cast shadows has three bind groups (the shadow maps are @group(2)), one without has two.
//! Hot-reloaded WGSL replaces them all.

use crate::light_loop::LightLoop;
use crate::program::Program;
use crate::shaders;
use crate::target::DEPTH_FORMAT;
use crate::vertex::{FlatVertex, SmoothVertex};
use shadelab_model::effects::{Effect, EffectKey};
use std::collections::HashMap;
use std::time::Duration;
use web_time::Instant;

/// A pass drawn over the scene's depth without writing it: its fragments where they are not behind
/// what is drawn (the overlay's lines, the environment's background at the far plane).
pub fn depth_tested_over() -> wgpu::DepthStencilState {
    depth_state(false, wgpu::CompareFunction::LessEqual, Default::default())
}

/// A depth test on the targets' `DEPTH_FORMAT` with `compare`, writing depth or not, and `bias`:
/// what every pass that meets the scene's depth shares.
pub fn depth_state(write: bool, compare: wgpu::CompareFunction, bias: wgpu::DepthBiasState) -> wgpu::DepthStencilState {
    wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(write),
        depth_compare: Some(compare),
        stencil: Default::default(),
        bias,
    }
}

/// A 2D texture of `sample_type` at `binding`, read by the fragment stage.
pub fn fragment_texture(binding: u32, sample_type: wgpu::TextureSampleType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

/// Triangle lists, culling `cull` (`None`: both faces drawn).
pub fn triangles(cull: Option<wgpu::Face>) -> wgpu::PrimitiveState {
    wgpu::PrimitiveState { topology: wgpu::PrimitiveTopology::TriangleList, cull_mode: cull, ..Default::default() }
}

/// A colour target of `format`, written whole and unblended.
pub fn opaque_target(format: wgpu::TextureFormat) -> Option<wgpu::ColorTargetState> {
    Some(wgpu::ColorTargetState { format, blend: None, write_mask: wgpu::ColorWrites::ALL })
}

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
    /// The environment's background: the globals alone.
    pub background: wgpu::PipelineLayout,
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

/// What selects one of a pass's own pipelines: the pass (and its variant, say "glass back"),
/// the effect set whose module it is built from, its light loop and its colour format (`None`:
/// depth only or compute). The cache stores them; each pass builds its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PassKey {
    pub pass: &'static str,
    pub effects: EffectKey,
    pub lights: LightLoop,
    pub format: Option<wgpu::TextureFormat>,
}

/// What a pass's build function gets from the cache: the device, the renderer's layouts and the
/// effect set's shader module.
pub struct BuildContext<'a> {
    pub device: &'a wgpu::Device,
    pub layouts: &'a Layouts,
    pub module: &'a wgpu::ShaderModule,
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
    /// The other passes' pipelines (shadow, glass, the lighting passes), each built by its pass
    /// on first use through [`PipelineCache::pass_pipeline`] or [`PipelineCache::pass_compute`].
    pass_pipelines: HashMap<PassKey, wgpu::RenderPipeline>,
    pass_computes: HashMap<PassKey, wgpu::ComputePipeline>,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    pending: HashMap<PipelineKey, PendingBuild>,
    /// Build missing pipelines on a worker thread and draw with the uber pipeline meanwhile
    /// (the viewer); off, a missing pipeline is built before the draw (renders, tests, benches).
    pub build_in_background: bool,
    /// How many pipelines have been built, the programs' and the other passes' (the viewer shows
    /// it: it must not grow per frame).
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
            pass_pipelines: HashMap::new(),
            pass_computes: HashMap::new(),
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
        self.pass_pipelines.clear();
        self.pass_computes.clear();
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

    /// A pass's render pipeline for `key`, built by the pass's own `build` on first use (from the
    /// module of `key.effects`) and cached until a reload.
    pub fn pass_pipeline(
        &mut self,
        key: PassKey,
        build: impl FnOnce(&BuildContext) -> wgpu::RenderPipeline,
    ) -> &wgpu::RenderPipeline {
        if !self.pass_pipelines.contains_key(&key) {
            let module = self.module(key.effects);
            let p = build(&BuildContext { device: &self.device, layouts: &self.layouts, module: &module });
            self.pipeline_builds += 1;
            self.pass_pipelines.insert(key, p);
        }
        &self.pass_pipelines[&key]
    }

    /// A pass's compute pipeline for `key`, built by the pass on first use, as [`Self::pass_pipeline`].
    pub fn pass_compute(
        &mut self,
        key: PassKey,
        build: impl FnOnce(&BuildContext) -> wgpu::ComputePipeline,
    ) -> &wgpu::ComputePipeline {
        if !self.pass_computes.contains_key(&key) {
            let module = self.module(key.effects);
            let p = build(&BuildContext { device: &self.device, layouts: &self.layouts, module: &module });
            self.pipeline_builds += 1;
            self.pass_computes.insert(key, p);
        }
        &self.pass_computes[&key]
    }

    /// Move pipelines finished on worker threads into the cache.
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
        // Every mesh is closed or seen from its front, but no culling keeps a wrong winding from
        // making geometry vanish.
        primitive: triangles(None),
        depth_stencil: Some(depth_state(true, wgpu::CompareFunction::Less, Default::default())),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fs),
            compilation_options: options,
            targets: &[opaque_target(key.color_format)],
        }),
        multiview_mask: None,
        cache: None,
    })
}
