//! Frame times without stalling the GPU (the viewer): a ring of query slots, each with its own
//! resolve and readback buffers. A frame takes a free slot, its timestamps are resolved and
//! copied, and the readback is mapped asynchronously; a later frame collects every slot whose map
//! has finished. When every slot is still in flight the frame is drawn untimed. Without
//! timestamp queries the frame is submitted untimed (the viewer then shows no GPU time).

use crate::program::Program;
use crate::renderer::Renderer;
use crate::target::Target;
use crate::upload::SceneGpu;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Slots in the ring: frames that may be in flight at once before one goes untimed.
pub const RING_SLOTS: usize = 4;

struct Slot {
    resolve: wgpu::Buffer,
    read: wgpu::Buffer,
    /// Set by the map callback once the readback can be read.
    ready: Arc<AtomicBool>,
    in_flight: bool,
}

/// The ring of one device.
pub struct TimestampRing {
    queries: Option<(wgpu::QuerySet, Vec<Slot>)>,
    period_ns: f64,
    latest_ms: Option<f64>,
}

impl TimestampRing {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> TimestampRing {
        let queries = device.features().contains(wgpu::Features::TIMESTAMP_QUERY).then(|| {
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("frame timestamp ring"),
                ty: wgpu::QueryType::Timestamp,
                count: 2 * RING_SLOTS as u32,
            });
            let buffer = |label, usage| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size: 16,
                    usage,
                    mapped_at_creation: false,
                })
            };
            let slots = (0..RING_SLOTS)
                .map(|_| Slot {
                    resolve: buffer(
                        "timestamp ring resolve",
                        wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                    ),
                    read: buffer("timestamp ring read", wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ),
                    ready: Arc::new(AtomicBool::new(false)),
                    in_flight: false,
                })
                .collect();
            (set, slots)
        });
        TimestampRing { queries, period_ns: queue.get_timestamp_period() as f64, latest_ms: None }
    }

    /// Whether the device has timestamps (else no time is ever reported).
    pub fn timed(&self) -> bool {
        self.queries.is_some()
    }

    /// Collect finished slots (without waiting) and return the newest time read, in ms.
    pub fn collect(&mut self, device: &wgpu::Device) -> Option<f64> {
        let _ = device.poll(wgpu::PollType::Poll);
        if let Some((_, slots)) = &mut self.queries {
            for s in slots.iter_mut().filter(|s| s.in_flight && s.ready.load(Ordering::Acquire)) {
                let t: [u64; 2] = {
                    let view = s.read.slice(..).get_mapped_range().expect("mapped by its callback");
                    bytemuck::pod_read_unaligned(&view)
                };
                s.read.unmap();
                s.in_flight = false;
                s.ready.store(false, Ordering::Release);
                self.latest_ms = Some(t[1].saturating_sub(t[0]) as f64 * self.period_ns * 1e-6);
            }
        }
        self.latest_ms
    }

    /// Draw one frame of `program` (uniforms last written) and submit it, timed in a free slot
    /// when there is one; never waits for the GPU. Returns the newest time collected so far.
    pub fn frame(
        &mut self,
        r: &mut Renderer,
        gpu_scene: &mut SceneGpu,
        target: &Target,
        program: Program,
    ) -> Option<f64> {
        let latest = self.collect(&r.device);
        let mut enc = r.device.create_command_encoder(&Default::default());
        let free = self.queries.as_mut().and_then(|(set, slots)| {
            slots.iter_mut().enumerate().find(|(_, s)| !s.in_flight).map(|(i, s)| (&*set, i, s))
        });
        match free {
            Some((set, i, slot)) => {
                let first = 2 * i as u32;
                r.encode(&mut enc, gpu_scene, target, program, Some((set, first)));
                enc.resolve_query_set(set, first..first + 2, &slot.resolve, 0);
                enc.copy_buffer_to_buffer(&slot.resolve, 0, &slot.read, 0, 16);
                r.queue.submit([enc.finish()]);
                let ready = slot.ready.clone();
                slot.read.slice(..).map_async(wgpu::MapMode::Read, move |res| {
                    // A failed map (the device lost) leaves the slot in flight: it is not reused.
                    if res.is_ok() {
                        ready.store(true, Ordering::Release);
                    }
                });
                slot.in_flight = true;
            }
            None => {
                r.encode(&mut enc, gpu_scene, target, program, None);
                r.queue.submit([enc.finish()]);
            }
        }
        latest
    }
}
