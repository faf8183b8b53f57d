//! The `shadelab` binary from the outside: every flag combination renders, every bad value exits
//! 2 with one line naming the flag and its allowed range.

use std::path::PathBuf;
use std::process::{Command, Output};

fn shadelab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(args)
        .env("SHADELAB_ADAPTER", "lavapipe")
        .output()
        .expect("run shadelab")
}

fn out_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// stderr lines that are shadelab's own (the Vulkan driver may print its own warnings).
fn error_lines(o: &Output) -> Vec<String> {
    String::from_utf8_lossy(&o.stderr).lines().filter(|l| l.starts_with("error:")).map(String::from).collect()
}

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
        (&["--falloff-form", "cubic"], &["--falloff-form", "quadratic, linear"]),
        (&["--d0", "0"], &["--d0", "[0.001, 1000]"]),
        (&["--scene", "nowhere.gltf"], &["--scene", "default"]),
        (&["--output", "x.bmp"], &["--output", ".png, .exr"]),
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
            let o = shadelab(&[
                "render",
                "--shading",
                shading,
                "--specular",
                specular,
                "--width",
                "97",
                "--height",
                "41",
                "--output",
                path.to_str().unwrap(),
            ]);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            let img = image::open(&path).unwrap();
            assert_eq!((img.width(), img.height()), (97, 41));
        }
    }
}

#[test]
fn every_scene_flag_is_accepted() {
    let path = out_dir().join("flags.png");
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
        "--width",
        "64",
        "--height",
        "64",
        "--output",
        path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
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
    for specular in ["phong", "cook-torrance"] {
        let o = shadelab(&[
            "render",
            "--specular",
            specular,
            "--m",
            "0",
            "--h",
            "1e9",
            "--mu",
            "1",
            "--falloff",
            "1e6",
            "--light",
            "point",
            "--width",
            "160",
            "--height",
            "90",
            "--output",
            path.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let img = image::open(&path).unwrap().to_rgba32f();
        assert_eq!((img.width(), img.height()), (160, 90));
        assert!(img.pixels().all(|p| p.0.iter().all(|c| c.is_finite() && *c >= 0.0)), "{specular}");
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
        let o = shadelab(&["bench", "render", flag, value]);
        assert_eq!(o.status.code(), Some(2), "{flag} {value}: {}", String::from_utf8_lossy(&o.stderr));
        let lines = error_lines(&o);
        assert!(lines.len() == 1 && lines[0].contains(needle), "{flag} {value}: {lines:?}");
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
    ] {
        assert!(text.contains(flag), "{flag}");
    }
}
