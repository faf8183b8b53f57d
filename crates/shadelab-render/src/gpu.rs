//! Adapter and device: lavapipe forced for tests, or the best adapter for real use.

use std::fmt;

/// Which adapter to open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AdapterChoice {
    /// Mesa's lavapipe (device type Cpu, name "llvmpipe"): deterministic images for tests.
    Lavapipe,
    /// The highest-performance adapter available.
    Auto,
}

impl AdapterChoice {
    /// `SHADELAB_ADAPTER=lavapipe` forces lavapipe (what `cargo xtask test` sets); otherwise Auto.
    pub fn from_env() -> Self {
        match std::env::var("SHADELAB_ADAPTER").as_deref() {
            Ok("lavapipe") => AdapterChoice::Lavapipe,
            _ => AdapterChoice::Auto,
        }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error(
        "no lavapipe adapter found (adapters seen: {seen}); install Mesa's Vulkan drivers: apt-get install mesa-vulkan-drivers"
    )]
    NoLavapipe { seen: String },
    #[error("no graphics adapter found: {0}")]
    NoAdapter(String),
    #[error("could not open the device: {0}")]
    Device(#[from] wgpu::RequestDeviceError),
}

/// True for Mesa's lavapipe.
pub fn is_lavapipe(info: &wgpu::AdapterInfo) -> bool {
    info.device_type == wgpu::DeviceType::Cpu || info.name.contains("llvmpipe")
}

/// An open device with what the renderer needs to know about it.
#[derive(Clone)]
pub struct Gpu {
    pub instance: wgpu::Instance,
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
}

impl fmt::Debug for Gpu {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Gpu({})", self.describe())
    }
}

/// Optional features the renderer uses when the adapter has them (GPU timing).
pub fn wanted_features(adapter: &wgpu::Adapter) -> wgpu::Features {
    adapter.features() & (wgpu::Features::TIMESTAMP_QUERY | wgpu::Features::TIMESTAMP_QUERY_INSIDE_PASSES)
}

impl Gpu {
    /// Open a device without a window on the adapter `SHADELAB_ADAPTER` chooses
    /// ([`AdapterChoice::from_env`]): what the command line's renders and studies draw with.
    pub fn from_env() -> Result<Gpu, GpuError> {
        Gpu::headless(AdapterChoice::from_env())
    }

    /// Open a device without a window.
    pub fn headless(choice: AdapterChoice) -> Result<Gpu, GpuError> {
        let backends = match choice {
            AdapterChoice::Lavapipe => wgpu::Backends::VULKAN,
            AdapterChoice::Auto => wgpu::Backends::all(),
        };
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter = match choice {
            AdapterChoice::Lavapipe => {
                let adapters = pollster::block_on(instance.enumerate_adapters(backends));
                let seen = adapters.iter().map(|a| a.get_info().name).collect::<Vec<_>>().join(", ");
                adapters
                    .into_iter()
                    .find(|a| is_lavapipe(&a.get_info()))
                    .ok_or(GpuError::NoLavapipe { seen: if seen.is_empty() { "none".into() } else { seen } })?
            }
            AdapterChoice::Auto => pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: None,
                apply_limit_buckets: false,
            }))
            .map_err(|e| GpuError::NoAdapter(e.to_string()))?,
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("shadelab"),
            required_features: wanted_features(&adapter),
            // The adapter's own limits: 8192² float targets and their readback need more than
            // the portable defaults.
            required_limits: adapter.limits(),
            ..Default::default()
        }))?;
        Ok(Gpu { instance, adapter, device, queue })
    }

    /// Lavapipe, as every test opens it.
    pub fn lavapipe() -> Result<Gpu, GpuError> {
        Gpu::headless(AdapterChoice::Lavapipe)
    }

    /// "name (backend, device type)".
    pub fn describe(&self) -> String {
        let i = self.adapter.get_info();
        format!("{} ({:?}, {:?})", i.name, i.backend, i.device_type)
    }
}
