//! `shadelab render --overlay`: the self-shadow boundary is accepted and drawn; a bad value is
//! one line naming the flag and what it allows (exit 2).

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
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("overlay-cli");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// stderr lines that are shadelab's own (the Vulkan driver may print its own warnings).
fn error_lines(o: &Output) -> Vec<String> {
    String::from_utf8_lossy(&o.stderr).lines().filter(|l| l.starts_with("error:")).map(String::from).collect()
}

#[test]
fn overlay_terminator_renders_and_a_bad_value_is_one_line() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let figure = root.join("assets/figure-7-3-pyramid.gltf");
    let png = out_dir().join("terminator.png");
    for scene in [figure.to_str().unwrap(), "pyramid"] {
        let o = shadelab(&[
            "render",
            "--scene",
            scene,
            "--overlay",
            "terminator",
            "--width",
            "160",
            "--height",
            "90",
            "--output",
            png.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{scene}: {}", String::from_utf8_lossy(&o.stderr));
        let img = image::open(&png).unwrap().to_rgb8();
        assert!(img.pixels().any(|p| p.0 == [0, 255, 255]), "{scene}: no boundary pixel");
    }
    for bad in ["outline", "terminator,outline", ""] {
        let o = shadelab(&["render", "--overlay", bad, "--output", png.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{bad:?}: {}", String::from_utf8_lossy(&o.stderr));
        let lines = error_lines(&o);
        assert_eq!(lines.len(), 1, "{bad:?}: {lines:?}");
        assert!(lines[0].contains("--overlay") && lines[0].contains("terminator"), "{bad:?}: {}", lines[0]);
    }
}
