//! glTF scenes through the `shadelab` binary: `--scene FILE`, `--save-scene`, the file's shading
//! and specular choice, and bad files exiting 2 with one line (on lavapipe, like `crates/shadelab/tests/app/cli.rs`).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn shadelab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(args)
        .current_dir(project_root())
        .env("SHADELAB_ADAPTER", "lavapipe")
        .output()
        .expect("run shadelab")
}

fn project_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn out(name: &str) -> String {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("gltf-cli");
    std::fs::create_dir_all(&d).unwrap();
    d.join(name).to_str().unwrap().to_string()
}

fn ok(o: &Output) {
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
}

fn error_lines(o: &Output) -> Vec<String> {
    String::from_utf8_lossy(&o.stderr).lines().filter(|l| l.starts_with("error:")).map(String::from).collect()
}

const SIZE: [&str; 4] = ["--width", "160", "--height", "90"];

#[test]
fn saved_scene_renders_pixel_identical_with_its_recorded_modes() {
    let (a, b, scene) = (out("a.png"), out("b.png"), out("saved.gltf"));
    let mut args = vec!["render", "--shading", "gouraud", "--specular", "phong", "--m", "0.1", "--light", "point"];
    args.extend(SIZE);
    args.extend(["--output", &a, "--save-scene", &scene]);
    ok(&shadelab(&args));
    // No --shading/--specular: the file's (gouraud, phong) are used.
    let mut args = vec!["render", "--scene", &scene];
    args.extend(SIZE);
    args.extend(["--output", &b]);
    ok(&shadelab(&args));
    assert!(std::fs::read(&a).unwrap() == std::fs::read(&b).unwrap(), "the reloaded scene renders differently");
    // A flag still wins over the file.
    let c = out("c.png");
    let mut args = vec!["render", "--scene", &scene, "--shading", "flat"];
    args.extend(SIZE);
    args.extend(["--output", &c]);
    ok(&shadelab(&args));
    assert!(std::fs::read(&a).unwrap() != std::fs::read(&c).unwrap(), "--shading flat was ignored");
}

#[test]
fn shipped_assets_and_glb_render() {
    for scene in [
        "assets/figure-7-3-pyramid.gltf",
        "assets/gouraud-vs-phong.gltf",
        "assets/material-board.gltf",
        "assets/textured-floor.gltf",
    ] {
        let png = out("asset.png");
        let glb = out("asset.glb");
        let mut args = vec!["render", "--scene", scene, "--output", &png, "--save-scene", &glb];
        args.extend(SIZE);
        ok(&shadelab(&args));
        let mut args = vec!["render", "--scene", &glb, "--output", &png];
        args.extend(SIZE);
        ok(&shadelab(&args));
    }
}

#[test]
fn bad_scene_files_exit_2_with_one_line() {
    let png = out("bad.png");
    let cases: &[(&str, &str)] = &[
        ("tests/gltf-corpus/index-past-vertex-count.gltf", "mesh 0 primitive 0: index 17 is past the vertex count 8"),
        ("tests/gltf-corpus/huge-count.gltf", "1000000000 elements of 12 bytes"),
        ("tests/gltf-corpus/wrong-magic.glb", "not a glTF file"),
        ("tests/gltf-corpus/missing-external-buffer.gltf", "cannot read 'missing.bin'"),
        ("no-such-scene.glb", "--scene: unknown value 'no-such-scene.glb'"),
    ];
    for (scene, needle) in cases {
        let o = shadelab(&["render", "--scene", scene, "--output", &png]);
        assert_eq!(o.status.code(), Some(2), "{scene}: {}", String::from_utf8_lossy(&o.stderr));
        let lines = error_lines(&o);
        assert_eq!(lines.len(), 1, "{scene}: {lines:?}");
        assert!(lines[0].contains(needle), "{scene}: {}", lines[0]);
    }
    let o = shadelab(&["render", "--output", &png, "--save-scene", &out("scene.obj")]);
    assert_eq!(o.status.code(), Some(2));
    assert!(error_lines(&o)[0].contains("--save-scene") && error_lines(&o)[0].contains(".gltf, .glb"));
}

/// `--explain` names the textures a per-vertex mode leaves to Phong shading, and its pipeline is
/// the mode's own.
#[test]
fn explain_says_which_textures_a_mode_leaves_out() {
    let png = out("explain-maps.png");
    let run = |shading: &str| {
        let mut args = vec!["render", "--explain", "--scene", "assets/textured-floor.gltf", "--shading", shading];
        args.extend(["--width", "32", "--height", "18", "--output", png.as_str()]);
        let o = shadelab(&args);
        ok(&o);
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let flat = run("flat");
    for e in ["metallic–roughness texture", "occlusion texture", "normal texture"] {
        assert!(flat.contains(&format!("{e}: not drawn in flat shading")), "{flat}");
    }
    assert!(!flat.contains("mrtex") && flat.contains("+emit+emittex]"), "{flat}");
    let phong = run("phong");
    assert!(phong.contains("+mrtex+aotex+emit+emittex+normtex]") && !phong.contains("not drawn"), "{phong}");
}

/// A plain glTF file opens with the glTF BRDF and `--explain` says which terms are in and why;
/// `--microfacet chapter` is the chapter's model one switch away, a term flag overrides one term,
/// and the two images differ. A bad term name is one line and exit 2.
#[test]
fn a_gltf_file_opens_with_the_gltf_brdf_and_the_chapters_is_one_switch_away() {
    let scene = "../shared/gltf-samples/BoxTextured.gltf";
    let run = |extra: &[&str], png: &str| {
        let mut args = vec!["render", "--explain", "--scene", scene, "--width", "96", "--height", "54"];
        args.extend(extra);
        args.extend(["--output", png]);
        let o = shadelab(&args);
        ok(&o);
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let (a, b) = (out("box-gltf.png"), out("box-chapter.png"));
    let gltf = run(&[], &a);
    for line in ["GGX D (Trowbridge–Reitz): on — used by", "Smith G, height-correlated", "Schlick's"] {
        assert!(gltf.contains(line), "{line} in {gltf}");
    }
    assert!(gltf.contains("Beckmann D (the chapter's): off — no material with r_s > 0 uses it"), "{gltf}");
    assert!(gltf.contains("+ggx+smith-hc+schlick+") && !gltf.contains("beckmann+"), "{gltf}");
    let chapter = run(&["--microfacet", "chapter"], &b);
    assert!(chapter.contains("+beckmann+vgroove+exact-f+") && !chapter.contains("ggx+"), "{chapter}");
    assert!(std::fs::read(&a).unwrap() != std::fs::read(&b).unwrap(), "the two BRDFs draw the same image");
    let one = run(&["--microfacet", "chapter", "--fresnel", "schlick"], &b);
    assert!(one.contains("+beckmann+vgroove+schlick+"), "{one}");
    assert!(gltf.contains("multiple scattering 1 + F0·(1 − E)/E: off"), "{gltf}");
    let ms = run(&["--multiple-scattering", "on"], &b);
    assert!(ms.contains("multiple scattering 1 + F0·(1 − E)/E: on") && ms.contains("+schlick+ms+"), "{ms}");
    // glTF's fresnel_mix comes with the preset and goes with the chapter's terms or its own flag.
    assert!(
        gltf.contains("diffuse weighted by 1 − F (glTF's fresnel_mix): on") && gltf.contains("+schlick+fmix+"),
        "{gltf}"
    );
    assert!(!chapter.contains("fmix"), "{chapter}");
    let (c, d) = (out("box-gltf-unmixed.png"), out("box-chapter-mixed.png"));
    let unmixed = run(&["--fresnel-mix", "off"], &c);
    assert!(
        unmixed.contains("diffuse weighted by 1 − F (glTF's fresnel_mix): off") && !unmixed.contains("fmix"),
        "{unmixed}"
    );
    assert!(std::fs::read(&a).unwrap() != std::fs::read(&c).unwrap(), "the weight changes nothing");
    let mixed = run(&["--microfacet", "chapter", "--fresnel-mix", "on"], &d);
    assert!(mixed.contains("+exact-f+fmix+"), "{mixed}");
    let o = shadelab(&["render", "--scene", scene, "--masking", "smiths", "--output", &b]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("smiths") && e.contains("v-groove, smith, smith-correlated"), "{e}");
}

/// `--phong-normalized on` puts the normalization in the pipeline with Phong specular (and says
/// why), brightens the highlights, and a saved scene keeps it.
#[test]
fn phong_normalized_is_a_flag_an_effect_and_saved() {
    let (a, b, saved) = (out("phong-plain.png"), out("phong-normalized.png"), out("phong-normalized.gltf"));
    let run = |scene: &str, extra: &[&str], png: &str| {
        let mut args =
            vec!["render", "--explain", "--scene", scene, "--specular", "phong", "--width", "96", "--height", "54"];
        args.extend(extra);
        args.extend(["--output", png]);
        let o = shadelab(&args);
        ok(&o);
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let plain = run("sphere", &[], &a);
    assert!(plain.contains("Phong lobe normalized (h + 1)/2: off — no material with r_s > 0 asks for it"), "{plain}");
    let normalized = run("sphere", &["--phong-normalized", "on", "--save-scene", &saved], &b);
    assert!(
        normalized.contains("Phong lobe normalized (h + 1)/2: on") && normalized.contains("+phong-norm+"),
        "{normalized}"
    );
    assert!(std::fs::read(&a).unwrap() != std::fs::read(&b).unwrap(), "the normalization changed nothing");
    let again = run(&saved, &[], &a);
    assert!(again.contains("Phong lobe normalized (h + 1)/2: on"), "{again}");
}
