//! `render --reference --bounces` and `render --ambient-error` (docs/reference.md): the
//! path-traced reference and the chapter's constant ambient against it, from the command line.

use crate::common::{error_lines, out_dir, shadelab};

fn exr(path: &std::path::Path) -> Vec<f32> {
    image::open(path).unwrap().to_rgba32f().pixels().flat_map(|p| [p.0[0], p.0[1], p.0[2]]).collect()
}

fn run(args: &[&str]) -> String {
    let o = shadelab(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {:?}", error_lines(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// More bounces add light to every pixel (the indirect light is never negative); the report
/// gives the noise and the fireflies; the same seed writes the same file.
#[test]
fn bounces_add_light_and_the_seed_repeats_the_image() {
    let dir = out_dir();
    let size = ["--width", "64", "--height", "36"];
    let file = |name: &str| dir.join(name);
    let one = file("paths-1.exr");
    let three = file("paths-3.exr");
    let again = file("paths-3-again.exr");
    run(&[&["render", "--reference", "--bounces", "1", "--output", one.to_str().unwrap()][..], &size].concat());
    let line = run(&[
        &["render", "--reference", "--bounces", "3", "--spp", "8", "--output", three.to_str().unwrap()][..],
        &size,
    ]
    .concat());
    assert!(line.contains("3 bounces, 8 paths a pixel, seed 1: noise") && line.contains("firefly"), "{line}");
    run(&[
        &["render", "--reference", "--bounces", "3", "--spp", "8", "--seed", "1", "--output", again.to_str().unwrap()]
            [..],
        &size,
    ]
    .concat());
    let (a, b) = (exr(&one), exr(&three));
    assert!(a.iter().zip(&b).all(|(x, y)| y >= x), "a bounce took light away");
    assert!(b.iter().sum::<f32>() > a.iter().sum::<f32>() * 1.02, "no light between surfaces");
    assert_eq!(exr(&three), exr(&again), "the same seed gave another image");
}

/// `--ambient-error` writes the signed error (EXR) and the map (PNG) and prints the ladder; the
/// error of the fitted I_a is at most the constant one's.
#[test]
fn ambient_error_writes_the_map_and_prints_the_ladder() {
    let dir = out_dir();
    let (e, p) = (dir.join("ambient-error.exr"), dir.join("ambient-error.png"));
    let size = ["--width", "64", "--height", "36", "--spp", "8"];
    let report = run(&[&["render", "--ambient-error", "--output", e.to_str().unwrap()][..], &size].concat());
    run(&[&["render", "--ambient-error", "--output", p.to_str().unwrap()][..], &size].concat());
    assert_eq!(image::open(&p).unwrap().to_rgb8().dimensions(), (64, 36));
    let error = exr(&e);
    assert!(error.iter().all(|x| x.is_finite()) && error.iter().any(|x| *x > 0.0) && error.iter().any(|x| *x < 0.0));
    assert!(report.contains("fitted I_a: [") && report.contains("| object |"), "{report}");
    let rmse = |row: &str| -> f64 {
        let line = report.lines().find(|l| l.starts_with(row)).unwrap_or_else(|| panic!("no {row} in {report}"));
        line.rsplit('|').nth(1).unwrap().trim().parse().unwrap()
    };
    assert!(rmse("| fitted I_a") <= rmse("| constant I_a"), "{report}");
    assert!(rmse("| ambient occlusion") > 0.0, "{report}");
}

/// Bad path-tracing flags are one line and exit 2.
#[test]
fn bad_path_flags_are_one_line() {
    for bad in [
        &["--reference", "--bounces", "0"][..],
        &["--reference", "--bounces", "65"],
        &["--reference", "--bounces", "2", "--spp", "0"],
        &["--bounces", "2"],
        &["--spp", "4"],
        &["--ambient-error", "--model", "lambert"],
        &["--reference", "--bounces", "2", "--term", "diffuse"],
        &["--ambient-error", "--reference"],
    ] {
        let mut args = vec!["render", "--width", "32", "--height", "18", "--output", "/dev/null/x.png"];
        args.extend_from_slice(bad);
        let o = shadelab(&args);
        assert_eq!((o.status.code(), error_lines(&o).len()), (Some(2), 1), "{bad:?}: {:?}", error_lines(&o));
    }
}
