//! `render --environment` (docs/environment.md): the environment takes I_amb's place, its effect
//! is explained, a map file is read, and bad flags and files are one line each.

use crate::common::{error_lines, out_dir, render, shadelab};

/// The sky turns the environment's effect on and says why; a map file lights the scene, and a
/// 1×1 map of I_amb's colour draws the image I_amb draws.
#[test]
fn the_environment_replaces_the_ambient() {
    let dir = out_dir();
    let o =
        shadelab(&["render", "--environment", "sky", "--explain", "--output", dir.join("sky.png").to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    assert!(out.contains("env-sh") && out.contains("environment light (sky)"), "{out}");
    assert!(out.contains("environment's occlusion is off"), "{out}");
    // Asked for, the occlusion and the background are drawn, and say so.
    let o = shadelab(&[
        "render",
        "--environment",
        "sky",
        "--env-occlusion",
        "on",
        "--env-background",
        "on",
        "--explain",
        "--output",
        dir.join("occluded.png").to_str().unwrap(),
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    assert!(out.contains("env-occ") && out.contains("asks for occlusion"), "{out}");
    assert!(out.contains("env-bg") && out.contains("drawn as the background"), "{out}");
    // The default scene's I_amb is 0.12 grey: the same light as a 1×1 map.
    let one = shadelab_model::lighting::env_map::EnvImage {
        name: "one".into(),
        width: 1,
        height: 1,
        texels: vec![[0.12; 3]],
    };
    let map = dir.join("one.exr");
    std::fs::write(&map, shadelab_model::lighting::env_file::write_env_exr(&one).unwrap()).unwrap();
    let draw = |extra: &[&str], name: &str| {
        let path = dir.join(name);
        render(extra, (96, 54), &path).to_rgb8().into_raw()
    };
    let constant = draw(&[], "constant.png");
    let mapped = draw(&["--environment", map.to_str().unwrap(), "--env-specular", "off"], "mapped.png");
    let worst = constant.iter().zip(&mapped).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
    assert!(worst <= 1, "a 1×1 map of I_amb differs by {worst} levels");
}

#[test]
fn bad_environment_flags_are_one_line() {
    let not_a_map = out_dir().join("not-a-map.hdr");
    std::fs::write(&not_a_map, b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n\x80").unwrap();
    for (args, says) in [
        (vec!["--env-rotation", "10"], "--env-rotation: the scene has no environment"),
        (vec!["--env-occlusion", "on"], "--env-occlusion: the scene has no environment"),
        (vec!["--env-background", "on"], "--env-background: the scene has no environment"),
        (vec!["--term", "environment-specular"], "--term environment-specular: the scene has no environment light"),
        (vec!["--environment", "sky", "--env-occlusion", "maybe"], "--env-occlusion"),
        (vec!["--environment", "sky", "--turbidity", "40"], "--turbidity"),
        (vec!["--environment", "uniform", "--turbidity", "3"], "--turbidity: only for --environment sky"),
        (vec!["--environment", "sky", "--env-intensity", "-1"], "--env-intensity"),
        (vec!["--environment", "/no/such/map.hdr"], "--environment: environment map /no/such/map.hdr"),
        (vec!["--environment", not_a_map.to_str().unwrap()], "not-a-map.hdr"),
    ] {
        let o = shadelab(&[&["render", "--output", "/dev/null"][..], &args].concat());
        let lines = error_lines(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {lines:?}");
        assert!(lines.len() == 1 && lines[0].contains(says), "{args:?}: {lines:?}");
    }
}

/// `bench environment` prints each rung with its error against the truth, and the SH terms come
/// closer to it than the constant on the default scene under the sky.
#[test]
fn the_study_prints_its_rungs() {
    let o =
        shadelab(&["bench", "environment", "--width", "48", "--height", "27", "--truth-spp", "16", "--bounces", "2"]);
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    let rmse = |row: &str| -> f64 {
        let line = out.lines().find(|l| l.starts_with(row)).unwrap_or_else(|| panic!("no row {row}: {out}"));
        line.trim_end_matches('|').rsplit('|').next().unwrap().trim().parse().unwrap()
    };
    let (constant, sh) = (rmse("| constant I_a"), rmse("| nine SH terms |"));
    assert!(sh < constant, "SH {sh} against constant {constant}: {out}");
    let (split, bare) = (rmse("| nine SH terms + split-sum specular |"), rmse("| no environment light at all |"));
    assert!(split.is_finite() && sh < bare, "split sum {split}, no environment {bare}: {out}");
    assert!(out.contains("+ per-pixel ambient occlusion of the diffuse") && out.contains("sky environment"), "{out}");
    let grid = rmse("| + the diffuse occluded by the precomputed grid");
    assert!(grid.is_finite() && grid > 0.0, "grid {grid}: {out}");
}

/// Under an environment, `--reference` says which reference it is: the GPU's twin, or with
/// `--bounces` the path-traced truth, once with `--explain` too; `--help` says it, and a scene
/// without an environment gets no such line.
#[test]
fn the_reference_under_an_environment_says_whether_it_is_the_twin_or_the_truth() {
    let dir = out_dir();
    let out = |extra: &[&str]| {
        let path = dir.join("which-reference.png");
        let mut args = vec!["render", "--reference", "--width", "32", "--height", "18"];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--output", path.to_str().unwrap()]);
        let o = shadelab(&args);
        assert_eq!(o.status.code(), Some(0), "{extra:?}: {:?}", error_lines(&o));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let twin = out(&["--environment", "sky"]);
    assert!(twin.contains("the GPU's f64 twin") && twin.contains("not the truth"), "{twin}");
    let truth = out(&["--environment", "sky", "--bounces", "2", "--spp", "1"]);
    assert!(truth.contains("the path-traced truth") && truth.contains("(2 vertices, 1 paths a pixel)"), "{truth}");
    assert!(!truth.contains("twin"), "{truth}");
    let explained = out(&["--environment", "sky", "--explain"]);
    assert_eq!(explained.matches("reference: under the environment light").count(), 1, "{explained}");
    assert!(!out(&[]).contains("reference: "), "a scene without an environment");
    // clap wraps the help to the terminal's width: compared with its line breaks as spaces.
    let help = String::from_utf8_lossy(&shadelab(&["render", "--help"]).stdout)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(help.contains("Under an environment light it is the GPU's f64 twin"), "{help}");
}
