//! The `shadelab` binary from the outside: every flag combination renders, every bad value exits
//! 2 with one line naming the flag and its allowed range, and the benchmarks are well formed.
//! The views of the model (`--overlay`, `--term`, `figures`) are in `cli_views.rs`, `compare` in
//! `cli_compare.rs`.

use crate::common;
use crate::common::{error_lines, out_dir, render, shadelab};
use shadelab_model::shadows::{ShadowFilter, ShadowSettings};

#[test]
fn bad_values_exit_2_with_one_line_naming_flag_and_range() {
    let png = out_dir().join("bad.png");
    let png = png.to_str().unwrap();
    let cases: &[(&[&str], &[&str])] = &[
        (&["--m", "-1"], &["--m", "[0, 1]"]),
        (&["--m", "abc"], &["--m", "not a number"]),
        (&["--mu", "1.5"], &["--mu", "[0, 1]"]),
        (&["--mu", "0.5,2,0.1"], &["--mu", "[0, 1]"]),
        (&["--mu", "0.5,0.1"], &["--mu", "R,G,B"]),
        (&["--h", "0.5"], &["--h", "[1, 1000000000]"]),
        (&["--h", "sharp"], &["--h", "mirror"]),
        (&["--width", "0"], &["--width", "[1, 8192]"]),
        (&["--height", "8193"], &["--height", "[1, 8192]"]),
        (&["--shading", "toon"], &["--shading", "flat, gouraud, phong"]),
        (&["--specular", "blinn"], &["--specular", "phong, cook-torrance"]),
        (&["--light", "sun"], &["--light", "directional, point"]),
        (&["--falloff", "-2"], &["--falloff", "[0, 1000000]"]),
        (&["--light-size", "-1"], &["--light-size", "[0, 1000000]"]),
        (&["--light", "tube"], &["--light", "rect, disk, sphere"]),
        (&["--area-points", "17"], &["--area-points", "[0, 16]"]),
        (&["--area-points", "2.5"], &["--area-points", "[0, 16]"]),
        (&["--pcss-taps", "3"], &["--pcss-taps", "[4, 64]"]),
        (&["--small-area-lights", "ignore"], &["--small-area-lights", "point", "area"]),
        (&["--falloff-form", "cubic"], &["--falloff-form", "quadratic, linear"]),
        (&["--d0", "0"], &["--d0", "[0.001, 1000]"]),
        (&["--shadows", "maybe"], &["--shadows", "on, off"]),
        (&["--shadow-resolution", "100"], &["--shadow-resolution", "[256, 4096]"]),
        (&["--shadow-resolution", "big"], &["--shadow-resolution", "[256, 4096]"]),
        (&["--shadow-filter", "vsm"], &["--shadow-filter", "hard, pcf, poisson"]),
        (&["--shadow-cascades", "auto"], &["--shadow-cascades", "on, off"]),
        (&["--term", "emission"], &["--term", "all, ambient, diffuse, specular"]),
        (&["--scene", "nowhere.gltf"], &["--scene", "default"]),
        (&["--output", "x.bmp"], &["--output", ".png, .exr"]),
        (&["--ior", "0.5"], &["--ior", "[1, 3]"]),
        (&["--ior", "1.5,1.6"], &["--ior", "R,G,B"]),
        (&["--absorption-coef", "-1"], &["--absorption-coef", "[0, 1000000]"]),
        (&["--absorption", "approximate"], &["--absorption", "exact, rule"]),
        (&["--glass-exit", "rays"], &["--glass-exit", "analytic, back-faces"]),
        (&["--glass-view", "depth"], &["--glass-view", "color, tir, path, regime"]),
        (&["--bogus"], &["--bogus"]),
    ];
    for (args, needles) in cases {
        let mut all = vec!["render"];
        if !args.contains(&"--output") {
            all.extend(["--output", png]);
        }
        all.extend_from_slice(args);
        let o = shadelab(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
        let lines = error_lines(&o);
        assert_eq!(lines.len(), 1, "{args:?}: {lines:?}");
        for n in *needles {
            assert!(lines[0].contains(n), "{args:?}: '{}' lacks '{n}'", lines[0]);
        }
    }
}

#[test]
fn every_shading_and_specular_combination_renders_a_png() {
    for shading in ["flat", "gouraud", "phong"] {
        for specular in ["phong", "cook-torrance"] {
            let path = out_dir().join(format!("{shading}-{specular}.png"));
            let img = render(&["--shading", shading, "--specular", specular], (97, 41), &path);
            assert_eq!((img.width(), img.height()), (97, 41));
        }
    }
}

#[test]
fn every_scene_flag_is_accepted() {
    let path = out_dir().join("flags.png");
    let saved = out_dir().join("flags.gltf");
    let o = shadelab(&[
        "render",
        "--scene",
        "cylinder",
        "--m",
        "0.5",
        "--h",
        "mirror",
        "--mu",
        "0.9,0.6,0.3",
        "--falloff",
        "0.5",
        "--falloff-form",
        "linear",
        "--d0",
        "0.5",
        "--light",
        "point",
        "--shadows",
        "off",
        "--shadow-resolution",
        "512",
        "--shadow-filter",
        "poisson",
        "--shadow-cascades",
        "off",
        "--save-scene",
        saved.to_str().unwrap(),
        "--width",
        "64",
        "--height",
        "64",
        "--output",
        path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The shadow flags reach every light (the saved scene holds them).
    let lights = shadelab_model::gltf_io::load_scene(&saved).unwrap().scene.lights;
    let want = ShadowSettings {
        casts: false,
        resolution: 512,
        filter: ShadowFilter::Poisson,
        cascades: false,
        ..Default::default()
    };
    assert!(!lights.is_empty() && lights.iter().all(|l| l.shadow == want), "{lights:?}");
    for scene in ["default", "sphere", "cylinder", "pyramid", "cube"] {
        let o = shadelab(&[
            "render",
            "--scene",
            scene,
            "--width",
            "32",
            "--height",
            "32",
            "--output",
            path.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{scene}: {}", String::from_utf8_lossy(&o.stderr));
    }
}

#[test]
fn extreme_legal_values_write_an_exr_without_nonfinite_pixels() {
    let path = out_dir().join("extreme.exr");
    // Both specular models on the default scene with point lights; the large `field` with its
    // sun in cascades at the coarsest map and the widest filter, and with a spot light.
    let cases = [
        ("phong", "default", "2048", "pcf", "point"),
        ("cook-torrance", "default", "2048", "pcf", "point"),
        ("cook-torrance", "field", "256", "poisson", "directional"),
        ("phong", "field", "256", "hard", "spot"),
    ];
    for (specular, scene, side, filter, light) in cases {
        let extremes = ["--m", "0", "--h", "1e9", "--mu", "1", "--falloff", "1e6"];
        let shadows = ["--scene", scene, "--shadow-resolution", side, "--shadow-filter", filter];
        let args = [&shadows[..], &["--specular", specular, "--light", light], &extremes].concat();
        let img = render(&args, (160, 90), &path).to_rgba32f();
        assert_eq!((img.width(), img.height()), (160, 90));
        assert!(img.pixels().all(|p| p.0.iter().all(|c| c.is_finite() && *c >= 0.0)), "{specular} {scene}");
        // Linear float: the background is stored as-is, not sRGB-encoded.
        let p = img.get_pixel(0, 0).0;
        assert!((p[0] - 0.03).abs() < 1e-6, "{p:?}");
    }
}

#[test]
fn bench_rejects_a_bad_frame_count() {
    for (flag, value, needle) in
        [("--warmup", "abc", "--warmup"), ("--warmup", "-1", "[0, 1000000]"), ("--frames", "0", "--frames")]
    {
        for bench in ["render", "accuracy"] {
            let o = shadelab(&["bench", bench, flag, value]);
            assert_eq!(o.status.code(), Some(2), "{bench} {flag} {value}: {}", String::from_utf8_lossy(&o.stderr));
            let lines = error_lines(&o);
            assert!(lines.len() == 1 && lines[0].contains(needle), "{bench} {flag} {value}: {lines:?}");
        }
    }
    // An output folder that cannot be made is refused before anything is measured.
    let blocker = out_dir().join("not-a-folder");
    std::fs::write(&blocker, b"a file").unwrap();
    let o = shadelab(&["bench", "accuracy", "--quick", "--out", blocker.join("sub").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    let lines = error_lines(&o);
    assert!(lines.len() == 1 && lines[0].contains("--out"), "{lines:?}");
}

/// The viewer and the benchmarks that take the scene flags take the shadow flags too: a bad
/// value is refused by each before anything opens.
#[test]
fn viewer_and_bench_take_the_shadow_flags() {
    for command in [&[][..], &["bench", "render"][..], &["bench", "load"][..]] {
        for (flag, value, needle) in [
            ("--shadows", "yes", "on, off"),
            ("--shadow-resolution", "8192", "[256, 4096]"),
            ("--shadow-filter", "soft", "hard, pcf, poisson"),
        ] {
            let mut args = command.to_vec();
            args.extend([flag, value]);
            let o = shadelab(&args);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
            let lines = error_lines(&o);
            assert!(lines.len() == 1 && lines[0].contains(flag) && lines[0].contains(needle), "{args:?}: {lines:?}");
        }
    }
}

#[test]
fn help_exits_0() {
    let o = shadelab(&["render", "--help"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    for flag in [
        "--shading",
        "--specular",
        "--m",
        "--h",
        "--mu",
        "--falloff",
        "--light",
        "--width",
        "--height",
        "--scene",
        "--output",
        "--shadows",
        "--shadow-resolution",
        "--shadow-filter",
    ] {
        assert!(text.contains(flag), "{flag}");
    }
    // The shadow flags show their range and values.
    for shown in ["[256, 4096]", "on, off", "hard, pcf, poisson"] {
        assert!(text.contains(shown), "--help lacks '{shown}'");
    }
}

/// `bench accuracy --quick` writes a well-formed CSV, report and plots, and on the coarsest
/// sphere the error against the exact surface orders the shading modes as the chapter says:
/// Phong shading < Gouraud < flat, for both specular models. Correctness only; times are
/// reported, never asserted.
#[test]
fn bench_accuracy_quick_is_well_formed_and_orders_the_modes() {
    let dir = out_dir().join("accuracy");
    let _ = std::fs::remove_dir_all(&dir);
    // Three timed frames a row, not --quick's ten: what is checked is the rows, their order and
    // their errors, which the frames' count does not change (ten took 88 s of the suite, three 30).
    let o =
        shadelab(&["bench", "accuracy", "--quick", "--frames", "3", "--warmup", "1", "--out", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("llvmpipe") && stdout.contains("GPU timestamps"), "{stdout}");

    let csv = std::fs::read_to_string(dir.join("accuracy.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header.join(","), shadelab::bench::accuracy::CSV_HEADER);
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // 2 scenes × 3 levels × 2 sizes + 4 light counts + 3 sizes, 7 programs each; then the four
    // models and the two textured floors with a baseline and three shading modes each; then the
    // glass scene's baseline, three shading modes and two cheaper ways.
    assert_eq!(rows.len(), (2 * 3 * 2 + 4 + 3) * 7 + 4 * 4 + 2 * 4 + 6);
    for r in &rows {
        assert_eq!(r.len(), header.len(), "{r:?}");
        let num = |c: &str| r[col(c)].parse::<f64>().unwrap_or_else(|_| panic!("{c} of {r:?}"));
        assert!(num("median_ms") > 0.0 && num("p10_ms") <= num("median_ms") && num("median_ms") <= num("p90_ms"));
        assert_eq!(num("frames"), 3.0);
        if r[col("shading")] == "baseline" {
            assert_eq!(num("ratio_to_baseline"), 1.0);
            assert!(r[col("rmse")].is_empty() && r[col("pareto")] == "false");
        } else {
            for c in ["rmse", "max_abs", "flip_mean", "share_off_1_255"] {
                assert!(num(c).is_finite() && num(c) >= 0.0, "{c} of {r:?}");
            }
            assert!(num("share_off_1_255") <= 1.0 && num("rmse") <= num("max_abs"));
        }
    }
    // Every (scene, size, specular) of the modes study has a Pareto front.
    assert!(rows.iter().filter(|r| r[col("pareto")] == "true").count() >= 2 * 2 * 2);

    let rmse = |shading: &str, specular: &str, width: &str| -> f64 {
        let r = rows
            .iter()
            .find(|r| {
                r[col("study")] == "modes"
                    && r[col("scene")] == "sphere"
                    && r[col("level")] == "8"
                    && r[col("width")] == width
                    && r[col("shading")] == shading
                    && r[col("specular")] == specular
            })
            .unwrap_or_else(|| panic!("sphere level 8 {shading}/{specular} at width {width}"));
        r[col("rmse")].parse().unwrap()
    };
    for width in ["160", "320"] {
        for specular in ["phong", "cook-torrance"] {
            let (f, g, p) =
                (rmse("flat", specular, width), rmse("gouraud", specular, width), rmse("phong", specular, width));
            assert!(
                p < g && g < f,
                "coarse sphere, {specular} specular, width {width}: phong {p} gouraud {g} flat {f}"
            );
        }
    }

    let md = std::fs::read_to_string(dir.join("accuracy.md")).unwrap();
    assert!(md.contains("llvmpipe") && md.contains("## Cost per light") && md.contains("★"), "{md}");
    for (png, size) in [("error-vs-time.png", (1400, 1000)), ("scaling.png", (1400, 560))] {
        let img = image::open(dir.join(png)).unwrap_or_else(|e| panic!("{png}: {e}"));
        assert_eq!((img.width(), img.height()), size, "{png}");
        // A plot, not a blank page: many distinct colours.
        let colours: std::collections::HashSet<_> = img.to_rgb8().pixels().map(|p| p.0).collect();
        assert!(colours.len() > 50, "{png}: {} colours", colours.len());
    }
}

/// The output of `render --explain` of the sphere (directional light, Phong specular) with `extra`.
fn explain_sphere(png: &std::path::Path, extra: &[&str]) -> String {
    let mut args = vec!["render", "--explain", "--scene", "sphere", "--light", "directional", "--specular", "phong"];
    args.extend_from_slice(extra);
    args.extend(["--width", "32", "--height", "18", "--output", png.to_str().unwrap()]);
    let o = shadelab(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// `render --explain` lists every decision with its reason: shadows, filters and the effects left out.
#[test]
fn explain_lists_shadow_decisions_with_reasons() {
    let png = out_dir().join("explain.png");
    // The sphere on its ground casts a shadow onto it; `--shadows off` takes the effect out.
    let text = explain_sphere(&png, &[]);
    assert!(
        text.contains("pipeline [diffuse+phong+ambient+dir+shadows+pcf+cascades]")
            && text.contains("cast shadows: on")
            && text.contains("shadow filter poisson: off — no casting light filters with poisson"),
        "{text}"
    );
    // A filter's code is in the pipeline only when a light uses it.
    let text = explain_sphere(&png, &["--shadow-filter", "poisson"]);
    assert!(text.contains("pipeline [diffuse+phong+ambient+dir+shadows+poisson+cascades]"), "{text}");
    // Cascades follow the light's setting, not the view: off, the pipeline has none.
    let text = explain_sphere(&png, &["--shadow-cascades", "off"]);
    assert!(
        text.contains("pipeline [diffuse+phong+ambient+dir+shadows+pcf]")
            && text.contains("shadow cascades: off — every directional light's cascades setting is off"),
        "{text}"
    );
    let text = explain_sphere(&png, &["--shadows", "off"]);
    for needle in [
        "pipeline [diffuse+phong+ambient+dir]",
        "cast shadows: off",
        "point lights: off — 0 in the scene",
        "Cook–Torrance specular: off — the specular model is phong",
        "absorption: off — nothing transmits",
        "the pipeline is built for the scene's lights: the loop unrolled",
    ] {
        assert!(text.contains(needle), "missing '{needle}' in:\n{text}");
    }
}

/// `render --explain` names an area light's code and PCSS, and the glass scene's glass effects.
#[test]
fn explain_names_area_light_and_glass_effects() {
    let png = out_dir().join("explain-area-glass.png");
    // An area light brings its code and PCSS; the explain line names the light.
    let args =
        ["render", "--explain", "--scene", "penumbra", "--light", "disk", "--light-size", "0.3", "--width", "32"];
    let o = shadelab(&[&args[..], &["--height", "18", "--output", png.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    for needle in [
        "+area+",
        "+pcss]",
        "area lights: on — disk light L1",
        "shadow filter pcss: on — 1 casting light(s) filter with pcss",
        "light loop: 1 light (disk)",
    ] {
        assert!(text.contains(needle), "missing '{needle}' in:\n{text}");
    }
    // The glass scene calls for the glass effects, each with its reason.
    let o = shadelab(&[
        "render",
        "--explain",
        "--scene",
        "glass",
        "--width",
        "32",
        "--height",
        "18",
        "--output",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    for needle in [
        "+glass+refract+absorb]",
        "transmission: on — 3 object(s) let light through (glass sphere, slab, absorbing cylinder)",
        "refraction: on — 3 transparent object(s) with index v ≠ 1 bend rays by Snell's law (7.5)",
        "absorption: on — glass sphere neglected",
        "absorbing cylinder exact e^(−a·d) (a·d up to 2.441 ≥ 0.5)",
    ] {
        assert!(text.contains(needle), "missing '{needle}' in:\n{text}");
    }
}

/// `bench effects` measures the specialized, uber and floor pipelines side by side.
#[test]
fn bench_effects_measures_specialized_uber_and_floors() {
    let o = shadelab(&["bench", "effects", "--frames", "2", "--warmup", "1", "--width", "64", "--height", "36"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    for shading in ["flat", "gouraud", "phong"] {
        for pipeline in [
            "specialized",
            "uber",
            "without Cook–Torrance specular",
            "without point lights",
            "without PCF shadow filter",
        ] {
            assert!(
                text.lines().any(|l| l.contains(&format!("| default | {shading} | {pipeline} |"))),
                "no row {shading}/{pipeline} in:\n{text}"
            );
        }
    }
}

/// `bench mesh` generates the spheres, runs `bench load` on each in its own process and reports a
/// row per size with the phases and the peak memory; `bench load` alone prints its phases.
#[test]
fn bench_mesh_and_bench_load_report_phases_and_peak_memory() {
    let dir = out_dir().join("bench-mesh");
    let _ = std::fs::remove_dir_all(&dir);
    let args = ["bench", "mesh", "--triangles", "2000,30000", "--width", "64", "--height", "36"];
    let o = shadelab(&[&args[..], &["--out", dir.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    // A row per size: triangles, file MiB, 4 phases in s, next frame ms, peak MiB, bytes/triangle.
    let rows: Vec<Vec<&str>> = text
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| triangles"))
        .map(|l| l.trim_matches('|').split('|').map(str::trim).collect())
        .collect();
    assert_eq!(rows.len(), 2, "{text}");
    for (row, asked) in rows.iter().zip([2000usize, 30000]) {
        let n: usize = row[0].parse().unwrap();
        // The sphere closest above the asked count: s·(s − 2) triangles for an even s.
        assert!(n >= asked && n < asked + 4 * (asked as f64).sqrt() as usize + 16, "{n} for {asked}: {text}");
        let peak: f64 = row[7].parse().unwrap_or(f64::NAN);
        assert!(peak > 10.0, "peak MiB {peak}: {text}");
        for phase in &row[2..7] {
            assert!(phase.parse::<f64>().is_ok_and(|v| v >= 0.0), "{phase}: {text}");
        }
        assert!(dir.join(format!("sphere-{n}.glb")).is_file());
    }
    let board = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/material-board.gltf");
    let o = shadelab(&["bench", "load", "--scene", board.to_str().unwrap(), "--width", "64", "--height", "36"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    for key in ["triangles ", "load_ms ", "upload_ms ", "first_frame_ms ", "next_frame_ms ", "peak_rss_mib "] {
        assert!(text.lines().any(|l| l.starts_with(key)), "no {key}in:\n{text}");
    }
    for (bad, says) in [
        ("0", "--triangles: 0 is out of range"),
        ("20000000", "--triangles: 20000000 is out of range"),
        ("1e6", "--triangles: '1e6' is not a number"),
    ] {
        let o = shadelab(&["bench", "mesh", "--triangles", bad, "--out", dir.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        let lines = error_lines(&o);
        assert!(lines.len() == 1 && lines[0].contains(says), "{bad}: {lines:?}");
    }
}

#[test]
fn camera_picks_one_of_the_files_cameras() {
    let file = common::two_camera_scene(&out_dir(), "two-cameras.gltf");
    let view = |camera: &str| {
        let png = out_dir().join(format!("camera-{camera}.png"));
        render(&["--scene", file.to_str().unwrap(), "--camera", camera], (96, 54), &png).to_rgb8()
    };
    let (a, b) = (view("0"), view("1"));
    let differ = a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count();
    assert!(differ > (96 * 54) / 4, "a camera from above sees another picture: {differ} pixels differ");
    for (args, says) in [
        (vec!["render", "--scene", file.to_str().unwrap(), "--camera", "2"], "--camera: 2 is out of range"),
        (vec!["render", "--scene", "default", "--camera", "1"], "--camera: 1 is out of range"),
        (vec!["render", "--camera", "x"], "--camera: 'x' is not a number"),
        // The viewer checks its scene and camera before opening a window (no display needed).
        (vec!["--scene", "no-such-scene.glb"], "--scene: unknown value 'no-such-scene.glb'"),
        (vec!["--camera", "3"], "--camera: 3 is out of range"),
        (vec!["--m", "5"], "--m: 5 is out of range"),
        (vec!["--light", "laser"], "--light: unknown value 'laser'"),
    ] {
        let o = shadelab(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let lines = error_lines(&o);
        assert!(lines.len() == 1 && lines[0].contains(says), "{args:?}: {lines:?}");
    }
    let o = shadelab(&["--scene", common::root().join("tests/gltf-corpus/truncated.glb").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        error_lines(&o).len() == 1 && error_lines(&o)[0].contains("truncated.glb: truncated GLB"),
        "{:?}",
        error_lines(&o)
    );
}

/// A successful run says no "error:", even where `XDG_RUNTIME_DIR` is not set (the binary gives
/// Mesa a private one).
#[test]
fn a_successful_render_is_quiet_without_xdg_runtime_dir() {
    let png = out_dir().join("quiet.png");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(["render", "--width", "64", "--height", "36", "--output", png.to_str().unwrap()])
        .env("SHADELAB_ADAPTER", "lavapipe")
        .env_remove("XDG_RUNTIME_DIR")
        .output()
        .unwrap();
    assert!(o.status.success());
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!stderr.to_ascii_lowercase().contains("error"), "{stderr}");
}
