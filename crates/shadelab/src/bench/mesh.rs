//! `shadelab bench mesh`: large generated spheres, each opened by `bench load` in a fresh
//! process, with the phases and the peak memory per size.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::params::NamedValue;

/// One `bench load` run in a fresh process: its `key value` lines, and `/usr/bin/time -v`'s
/// peak and wall time when that tool is installed.
struct LoadRun {
    values: std::collections::HashMap<String, String>,
    /// The `# device:` line's adapter.
    device: String,
    time_v_peak_mib: Option<f64>,
}

const TIME_V: &str = "/usr/bin/time";

fn run_load_process(scene: &str, args: &cli::BenchMeshArgs) -> anyhow::Result<LoadRun> {
    let exe = std::env::current_exe().context("finding the shadelab binary")?;
    let with_time = std::path::Path::new(TIME_V).is_file();
    let mut cmd = if with_time {
        let mut c = std::process::Command::new(TIME_V);
        c.arg("-v").arg(&exe);
        c
    } else {
        std::process::Command::new(&exe)
    };
    let (width, height) = args.size.pixels();
    cmd.args(["bench", "load", "--scene", scene, "--shading", args.shading.name()]).args([
        "--width",
        &width.to_string(),
        "--height",
        &height.to_string(),
    ]);
    let out = cmd.output().context("running shadelab bench load")?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        let line = stderr.lines().find(|l| l.starts_with("error")).unwrap_or("no error line");
        anyhow::bail!("bench load --scene {scene} failed ({}): {line}", out.status);
    }
    let values = stdout
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let device = stdout
        .lines()
        .find_map(|l| l.strip_prefix("# device: "))
        .map_or("unknown".into(), |l| l.split(';').next().unwrap_or(l).to_string());
    let time_v_peak_mib = stderr
        .lines()
        .find_map(|l| l.trim().strip_prefix("Maximum resident set size (kbytes):"))
        .and_then(|v| v.trim().parse::<f64>().ok())
        .map(|k| k / 1024.0);
    Ok(LoadRun { values, device, time_v_peak_mib })
}

/// `shadelab bench mesh`: large generated meshes through `bench load`, one process each, beside a
/// baseline process on the built-in default scene (what the device and the program hold anyway).
pub fn run(args: &cli::BenchMeshArgs) -> Result<(), Failure> {
    let counts: Vec<usize> = args.triangles.iter().map(|&n| n as usize).collect();
    std::fs::create_dir_all(&args.out).with_context(|| format!("creating {}", args.out.display()))?;
    let has_time = std::path::Path::new(TIME_V).is_file();
    if !has_time {
        eprintln!("{TIME_V} is not installed (Debian: apt-get install time): peak memory from /proc/self/status only");
    }
    eprintln!("baseline: bench load --scene default");
    let base = run_load_process("default", args)?;
    let field = |r: &LoadRun, k: &str| r.values.get(k).cloned().unwrap_or_else(|| "?".into());
    let peak = |r: &LoadRun| {
        r.time_v_peak_mib.or_else(|| r.values.get("peak_rss_mib").and_then(|v| v.parse().ok())).unwrap_or(f64::NAN)
    };
    println!(
        "# shadelab bench mesh — generated spheres {}, {}×{}, {} shading; one process per row",
        if args.without_normals { "without normals (crease-angle rule)" } else { "with normals" },
        args.size.width,
        args.size.height,
        args.shading
    );
    println!("# device: {}", base.device);
    println!(
        "# peak memory: {}; baseline (built-in default scene): {:.0} MiB",
        if has_time { "/usr/bin/time -v, maximum resident set size" } else { "VmHWM of /proc/self/status" },
        peak(&base)
    );
    println!(
        "| triangles | file MiB | load s | build + upload s | first frame s | open → first frame s | next frame ms | peak MiB | bytes/triangle over baseline |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in counts {
        let (glb, actual) = shadelab_model::gltf_io::synthetic::sphere_glb(n, !args.without_normals);
        let kind = if args.without_normals { "-without-normals" } else { "" };
        let path = args.out.join(format!("sphere-{actual}{kind}.glb"));
        std::fs::write(&path, &glb).with_context(|| format!("writing {}", path.display()))?;
        let file_mib = glb.len() as f64 / (1024.0 * 1024.0);
        drop(glb);
        eprintln!("{actual} triangles: bench load --scene {}", path.display());
        let run = run_load_process(&path.to_string_lossy(), args)?;
        let s = |k: &str| field(&run, k).parse::<f64>().map_or("?".into(), |v| format!("{:.2}", v / 1e3));
        let over = (peak(&run) - peak(&base)) * 1024.0 * 1024.0 / actual as f64;
        println!(
            "| {actual} | {file_mib:.1} | {} | {} | {} | {} | {} | {:.0} | {over:.0} |",
            s("load_ms"),
            s("upload_ms"),
            s("first_frame_ms"),
            s("to_first_frame_ms"),
            field(&run, "next_frame_ms").split(' ').next().unwrap_or("?"),
            peak(&run)
        );
    }
    Ok(())
}
