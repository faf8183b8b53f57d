//! GPU time of a render pass from timestamp queries at the pass boundaries, or CPU time around
//! submit + wait where the device has no timestamps (the result says which).

use crate::program::{Program, RenderSettings};
use crate::renderer::Renderer;
use crate::target::Target;
use crate::upload::SceneGpu;
use web_time::Instant;

/// Where a frame time came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeSource {
    /// Timestamp queries at the beginning and end of the scene pass.
    GpuTimestamps,
    /// Wall-clock time around submit and wait (includes submission overhead).
    CpuSubmitWait,
}

impl TimeSource {
    pub fn label(self) -> &'static str {
        match self {
            TimeSource::GpuTimestamps => "GPU timestamps",
            TimeSource::CpuSubmitWait => "CPU submit+wait",
        }
    }
}

/// Measures frames of one renderer.
pub struct FrameTimer {
    queries: Option<(wgpu::QuerySet, wgpu::Buffer, wgpu::Buffer)>,
    period_ns: f64,
}

impl FrameTimer {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> FrameTimer {
        let queries = device.features().contains(wgpu::Features::TIMESTAMP_QUERY).then(|| {
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("frame timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            });
            let resolve = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamp resolve"),
                size: 16,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let read = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamp read"),
                size: 16,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            });
            (set, resolve, read)
        });
        FrameTimer { queries, period_ns: queue.get_timestamp_period() as f64 }
    }

    pub fn source(&self) -> TimeSource {
        if self.queries.is_some() { TimeSource::GpuTimestamps } else { TimeSource::CpuSubmitWait }
    }

    /// Draw one frame of `program` with the uniforms last written, wait for it, and return its
    /// time in milliseconds.
    pub fn frame(&self, r: &mut Renderer, gpu_scene: &mut SceneGpu, target: &Target, program: Program) -> f64 {
        let mut enc = r.device.create_command_encoder(&Default::default());
        let start = Instant::now();
        match &self.queries {
            Some((set, resolve, read)) => {
                r.encode(&mut enc, gpu_scene, target, program, Some((set, 0)));
                enc.resolve_query_set(set, 0..2, resolve, 0);
                enc.copy_buffer_to_buffer(resolve, 0, read, 0, 16);
                r.queue.submit([enc.finish()]);
                let slice = read.slice(..);
                slice.map_async(wgpu::MapMode::Read, |res| res.expect("map timestamps"));
                r.device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
                let t: [u64; 2] = bytemuck::pod_read_unaligned(&slice.get_mapped_range().expect("mapped"));
                read.unmap();
                t[1].saturating_sub(t[0]) as f64 * self.period_ns * 1e-6
            }
            None => {
                r.encode(&mut enc, gpu_scene, target, program, None);
                r.queue.submit([enc.finish()]);
                r.device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
                start.elapsed().as_secs_f64() * 1e3
            }
        }
    }
}

/// One draw of an interleaved measurement: which of the uploaded scenes it draws (an index into
/// the slice given to [`FrameTimer::interleaved_draws`]), the parameters its uniforms are written
/// from, and the program that draws it.
#[derive(Clone, Copy)]
pub struct TimedDraw<'a> {
    pub upload: usize,
    pub scene: &'a shadelab_model::Scene,
    pub program: Program,
    pub settings: RenderSettings,
}

impl FrameTimer {
    /// Time several programs side by side, each with the settings its uniforms are written with:
    /// each is warmed up (at least one frame, which builds its pipeline), then `frames` rounds
    /// draw every program once, so the machine's noise spreads evenly over them. Returns each
    /// program's frame times in milliseconds.
    #[allow(clippy::too_many_arguments)]
    pub fn interleaved(
        &self,
        r: &mut Renderer,
        gpu_scene: &mut SceneGpu,
        scene: &shadelab_model::Scene,
        target: &Target,
        programs: &[(Program, RenderSettings)],
        frames: usize,
        warmup: usize,
    ) -> Vec<Vec<f64>> {
        let draws: Vec<TimedDraw> =
            programs.iter().map(|&(program, settings)| TimedDraw { upload: 0, scene, program, settings }).collect();
        self.interleaved_draws(r, std::slice::from_mut(gpu_scene), target, &draws, frames, warmup)
    }

    /// [`FrameTimer::interleaved`] over draws that may each have their own scene (e.g. other
    /// shadow settings) and upload in `uploads`, in the same order: warm-up per draw, then
    /// `frames` rounds of every draw. Every frame draws its shadow maps, as one after a change.
    pub fn interleaved_draws(
        &self,
        r: &mut Renderer,
        uploads: &mut [SceneGpu],
        target: &Target,
        draws: &[TimedDraw],
        frames: usize,
        warmup: usize,
    ) -> Vec<Vec<f64>> {
        for d in draws {
            for _ in 0..warmup.max(1) {
                let gs = &mut uploads[d.upload];
                gs.redraw_shadows();
                r.write_uniforms(gs, d.scene, target, &d.settings);
                self.frame(r, gs, target, d.program);
            }
        }
        let mut samples = vec![Vec::with_capacity(frames); draws.len()];
        for _ in 0..frames {
            for (i, d) in draws.iter().enumerate() {
                let gs = &mut uploads[d.upload];
                gs.redraw_shadows();
                r.write_uniforms(gs, d.scene, target, &d.settings);
                samples[i].push(self.frame(r, gs, target, d.program));
            }
        }
        samples
    }
}

/// Median of a sample (sorts it).
pub fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 { v[n / 2] } else { 0.5 * (v[n / 2 - 1] + v[n / 2]) }
}

/// The `q` quantile (0..=1) of a sorted sample, nearest rank.
pub fn quantile_sorted(v: &[f64], q: f64) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v[((v.len() - 1) as f64 * q).round() as usize]
}
