//! The views of the model from the outside: `render --overlay` (boundary, normals, creases),
//! `render --term` (one term alone, the shadow factor), `render --link` and `shadelab figures`.

use crate::common;
use crate::common::{error_lines, out_dir, render, shadelab};
use std::process::Command;

/// `render --overlay`: the self-shadow boundary is accepted and drawn.
#[test]
fn overlay_terminator_renders_and_a_bad_value_is_one_line() {
    let figure = common::root().join("assets/figure-7-3-pyramid.gltf");
    let png = out_dir().join("terminator.png");
    for scene in [figure.to_str().unwrap(), "pyramid"] {
        let img = render(&["--scene", scene, "--overlay", "terminator"], (160, 90), &png).to_rgb8();
        assert!(img.pixels().any(|p| p.0 == [0, 255, 255]), "{scene}: no boundary pixel");
    }
    // Normals (yellow) and creases (orange, sRGB-encoded) over the cylinder, in one image.
    let img = render(&["--scene", "cylinder", "--overlay", "normals,creases,normals"], (320, 180), &png).to_rgb8();
    assert!(img.pixels().any(|p| p.0 == [255, 255, 0]), "no normal pixel");
    assert!(img.pixels().any(|p| p.0[0] == 255 && p.0[2] == 0 && p.0[1] > 100 && p.0[1] < 200), "no crease pixel");
    for bad in ["outline", "terminator,outline", ""] {
        let o = shadelab(&["render", "--overlay", bad, "--output", png.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{bad:?}: {}", String::from_utf8_lossy(&o.stderr));
        let lines = error_lines(&o);
        assert_eq!(lines.len(), 1, "{bad:?}: {lines:?}");
        assert!(
            lines[0].contains("--overlay") && lines[0].contains("terminator, normals, creases"),
            "{bad:?}: {}",
            lines[0]
        );
    }
}

/// `render --term` draws one term alone: each differs from the whole image, and the three add up
/// to it on every pixel with the background composited under them.
#[test]
fn render_term_draws_one_term() {
    let dir = out_dir();
    let read = |term: &str| {
        let path = dir.join(format!("term-{term}.exr"));
        let o = shadelab(&[
            "render",
            "--term",
            term,
            "--width",
            "64",
            "--height",
            "36",
            "--output",
            path.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{term}: {}", String::from_utf8_lossy(&o.stderr));
        image::open(&path).unwrap().to_rgba32f()
    };
    let all = read("all");
    for term in ["ambient", "diffuse", "specular"] {
        let img = read(term);
        let differ = img.pixels().zip(all.pixels()).filter(|(a, b)| (a.0[0] - b.0[0]).abs() > 1e-3).count();
        assert!(differ > 100, "{term}: only {differ} pixels differ from the whole image");
    }
    // The shadow factor is grey on the objects, in [0, 1], with cast shadows in it; the
    // background stays; it takes no overlay.
    let v = read("shadow");
    let bg = shadelab_model::scene::BACKGROUND.map(|c| c as f32);
    let grey = |p: &image::Rgba<f32>| p.0[0] == p.0[1] && p.0[1] == p.0[2] && (0.0..=1.0).contains(&p.0[0]);
    assert!(v.pixels().all(|p| p.0[..3] == bg || grey(p)));
    assert!(v.pixels().any(|p| p.0[0] < 0.5), "no cast shadow in the factor");
    let o = shadelab(&["render", "--term", "shadow", "--overlay", "terminator", "--output", "x.png"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(error_lines(&o).len() == 1 && error_lines(&o)[0].contains("--overlay"), "{:?}", error_lines(&o));
    // The terms add up to the whole on every pixel: each is black with alpha 0 where nothing is
    // hit, and the background composited under their sum, (1 − α)·background, gives the rest.
    let parts: Vec<_> = ["ambient", "diffuse", "specular"].map(read).into_iter().collect();
    let bg = shadelab_model::scene::BACKGROUND.map(|c| c as f32);
    let mut background_pixels = 0;
    for (i, p) in all.pixels().enumerate() {
        let alpha = parts[0].as_raw()[i * 4 + 3];
        assert!(parts.iter().all(|q| q.as_raw()[i * 4 + 3] == alpha), "pixel {i}: the terms' alphas differ");
        background_pixels += (alpha == 0.0) as usize;
        for c in 0..3 {
            let sum: f32 = parts.iter().map(|q| q.as_raw()[i * 4 + c]).sum::<f32>() + (1.0 - alpha) * bg[c];
            assert!((sum - p.0[c]).abs() < 1e-5, "pixel {i} channel {c}: {sum} vs {}", p.0[c]);
        }
    }
    // About 900 of the 64×36 pixels show no object: the composited sum is checked there too.
    assert!(background_pixels > 500, "{background_pixels} background pixels: the check can fail");
}

/// `shadelab figures` writes every figure, the scene files they use and commands.txt; each
/// listed command, run from that folder, remakes its figure byte for byte. At 160×90 (a
/// sixteenth of the default 640×360's pixels, the same commands and checks) to keep it quick.
#[test]
fn figures_writes_each_figure_and_the_commands_that_remake_it() {
    let dir = out_dir().join("figures");
    let _ = std::fs::remove_dir_all(&dir);
    let o = shadelab(&["figures", "--out", dir.to_str().unwrap(), "--width", "160", "--height", "90"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let listing = std::fs::read_to_string(dir.join("commands.txt")).unwrap();
    let commands: Vec<&str> = listing.lines().filter(|l| l.starts_with("shadelab ")).collect();
    assert_eq!(commands.len(), shadelab::figures::FIGURES.len(), "{listing}");
    for f in shadelab::figures::FIGURES {
        let img = image::open(dir.join(f.file)).unwrap_or_else(|e| panic!("{}: {e}", f.file)).to_rgb8();
        assert_eq!((img.width(), img.height()), (160, 90), "{}", f.file);
        let colours: std::collections::HashSet<_> = img.pixels().map(|p| p.0).collect();
        // Not blank: the ambient term alone is flat, one colour per material and the background.
        assert!(colours.len() >= 4, "{}: {} colours", f.file, colours.len());
    }
    // The cylinder's figure, remade from its listed command in the folder.
    let line = commands.iter().find(|l| l.contains("cylinder")).unwrap();
    let again = Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(line.split_whitespace().skip(1).map(|w| if w.ends_with(".png") { "again.png" } else { w }))
        .current_dir(&dir)
        .env("SHADELAB_ADAPTER", "lavapipe")
        .output()
        .unwrap();
    assert!(again.status.success(), "{}", String::from_utf8_lossy(&again.stderr));
    assert!(
        std::fs::read(dir.join("again.png")).unwrap()
            == std::fs::read(dir.join("figure-7-11-cylinder-normals.png")).unwrap()
    );
    // A folder that cannot be made is one line.
    let blocker = out_dir().join("figures-blocker");
    std::fs::write(&blocker, b"a file").unwrap();
    let o = shadelab(&["figures", "--out", blocker.join("sub").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let lines = error_lines(&o);
    assert!(lines.len() == 1 && lines[0].contains("--out"), "{lines:?}");
}

/// `render --model` draws each of the chapter's four models, each image its own; a saved scene
/// keeps its model; contradicting flags and a term the model lacks are one line and exit 2.
#[test]
fn render_model_draws_each_of_the_four_models() {
    let dir = out_dir();
    let render = |name: &str, extra: &[&str]| render_exr(&dir.join(format!("model-{name}.exr")), (64, 36), extra);
    let models = ["lambert", "sum", "phong", "cook-torrance"];
    let images: Vec<_> = models.iter().map(|m| render(m, &["--model", m])).collect();
    for i in 0..4 {
        for j in i + 1..4 {
            let differ = images[i].pixels().zip(images[j].pixels()).filter(|(a, b)| (a.0[0] - b.0[0]).abs() > 1e-3);
            assert!(differ.count() > 100, "{} and {} draw alike", models[i], models[j]);
        }
    }
    // --model cook-torrance is --specular cook-torrance.
    assert_eq!(render("ct", &["--specular", "cook-torrance"]).as_raw(), images[3].as_raw());
    // The four-term sum's transmitted term alone is dark without transmission and lit with it.
    let opaque = render("it0", &["--model", "sum", "--term", "transmitted"]);
    let lit = render("it", &["--model", "sum", "--term", "transmitted", "--transmission", "0.5"]);
    let bg = shadelab_model::scene::BACKGROUND.map(|c| c as f32);
    assert!(opaque.pixels().all(|p| p.0[..3] == bg || p.0[..3] == [0.0; 3]));
    assert!(lit.pixels().filter(|p| p.0[..3] != bg && p.0[0] > 0.05).count() > 500);
    // A saved scene keeps its model (and the sum's falloff).
    let saved = dir.join("model-sum.gltf");
    render("sum-saved", &["--model", "sum", "--save-scene", saved.to_str().unwrap()]);
    assert_eq!(render("sum-loaded", &["--scene", saved.to_str().unwrap()]).as_raw(), images[1].as_raw());
    for bad in [
        &["--model", "phong", "--specular", "cook-torrance"][..],
        &["--model", "sum", "--falloff-form", "quadratic"],
        &["--term", "transmitted"],
        &["--model", "lambert", "--term", "specular"],
        &["--model", "blinn"],
        &["--transmission", "1.5"],
    ] {
        let mut args = vec!["render", "--output", "x.png"];
        args.extend_from_slice(bad);
        let o = shadelab(&args);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
        assert_eq!(error_lines(&o).len(), 1, "{bad:?}: {:?}", error_lines(&o));
    }
}

/// `render --interpolation screen` draws the chapter's screen-space interpolation, finite, and
/// `--interpolation-difference` writes its FLIP map against the perspective-correct image.
#[test]
fn render_interpolation_screen_and_its_difference_map() {
    let dir = out_dir();
    let exr = |name: &str, extra: &[&str]| render_exr(&dir.join(format!("interp-{name}.exr")), (160, 90), extra);
    for shading in ["gouraud", "phong"] {
        let screen = exr(&format!("{shading}-screen"), &["--shading", shading, "--interpolation", "screen"]);
        let perspective = exr(&format!("{shading}-perspective"), &["--shading", shading]);
        assert!(screen.pixels().all(|p| p.0.iter().all(|c| c.is_finite())), "{shading}: a non-finite pixel");
        let differ = screen.pixels().zip(perspective.pixels()).filter(|(a, b)| (a.0[1] - b.0[1]).abs() > 1e-3).count();
        assert!(differ > 50, "{shading}: only {differ} pixels differ");
    }
    // Flat shading interpolates nothing: the same image.
    let flat = exr("flat-screen", &["--shading", "flat", "--interpolation", "screen"]);
    assert_eq!(flat.as_raw(), exr("flat", &["--shading", "flat"]).as_raw());
    let map = dir.join("interp-difference.png");
    let o =
        shadelab(&["render", "--shading", "gouraud", "--interpolation-difference", "--output", map.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let said = String::from_utf8_lossy(&o.stdout);
    let mean: f64 = said.split("mean FLIP ").nth(1).and_then(|r| r.split(',').next()).unwrap().parse().unwrap();
    assert!(mean > 0.0 && mean < 0.1, "{said}");
    assert_eq!(image::open(&map).unwrap().width(), 1280);
    for bad in
        [&["--shading", "flat", "--interpolation-difference"][..], &["--interpolation-difference", "--output", "x.exr"]]
    {
        let mut args = vec!["render", "--output", "x.png"];
        args.extend_from_slice(bad);
        let o = shadelab(&args);
        assert_eq!((o.status.code(), error_lines(&o).len()), (Some(2), 1), "{bad:?}");
    }
}

/// `shadelab lobe --pixel X,Y` prints the f64 model's N, V and angles of the point that pixel of
/// a render sees and writes the plots; a pixel off the image, on the background or a light the
/// scene lacks is one line and exit 2.
#[test]
fn lobe_prints_the_pixels_angles_and_writes_its_plots() {
    let png = out_dir().join("lobe.png");
    let o = shadelab(&["lobe", "--pixel", "640,410", "--output", png.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let scene = shadelab_model::Scene::builtin("default").unwrap();
    let p = shadelab_model::lobe::pick(&scene, (640, 410), (1280, 720)).expect("an object there");
    assert_eq!(String::from_utf8_lossy(&o.stdout), shadelab::lobe::describe(&p));
    let a = shadelab_model::lobe::Angles::of(p.n, p.v, p.lights[0].0);
    assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("θ_i = {:.1}°", a.theta_i)));
    assert_eq!(image::open(&png).unwrap().width(), 1100);
    for bad in [
        &["--pixel", "1280,0"][..],
        &["--pixel", "10,10"],
        &["--pixel", "640,410", "--plane-of", "3"],
        &["--pixel", "x"],
    ] {
        let mut args = vec!["lobe"];
        args.extend_from_slice(bad);
        let o = shadelab(&args);
        assert_eq!((o.status.code(), error_lines(&o).len()), (Some(2), 1), "{bad:?}: {:?}", error_lines(&o));
    }
}

/// `render --reference` writes the f64 reference of the same term, close to the GPU's;
/// `--difference` writes the FLIP map of the two and prints its numbers; a file of 20 000
/// triangles has its reference; bad combinations of the flags are one line and exit 2.
#[test]
fn render_reference_and_difference_give_each_term_its_reference() {
    let dir = out_dir();
    for term in ["diffuse", "specular", "shadow"] {
        let path = |what: &str| dir.join(format!("ref-{term}-{what}.exr"));
        let run = |extra: &[&str], out: &std::path::Path| {
            let mut args =
                vec!["render", "--term", term, "--width", "160", "--height", "90", "--output", out.to_str().unwrap()];
            args.extend_from_slice(extra);
            let o = shadelab(&args);
            assert!(o.status.success(), "{term}: {}", String::from_utf8_lossy(&o.stderr));
            o
        };
        run(&["--reference"], &path("reference"));
        run(&[], &path("gpu"));
        let (r, g) =
            (image::open(path("reference")).unwrap().to_rgba32f(), image::open(path("gpu")).unwrap().to_rgba32f());
        let mean =
            r.pixels().zip(g.pixels()).map(|(a, b)| (a.0[1] - b.0[1]).abs() as f64).sum::<f64>() / (160.0 * 90.0);
        // Silhouettes and shadow edges differ; the rest agrees (measured 2e-3 to 1.4e-2).
        assert!(mean < 0.03, "{term}: mean |GPU − reference| {mean}");
        assert!(r.as_raw() != g.as_raw(), "{term}: the reference is not the GPU's image");
        let map = dir.join(format!("ref-{term}-difference.png"));
        let o = run(&["--difference"], &map);
        assert!(String::from_utf8_lossy(&o.stdout).contains("mean FLIP"), "{term}");
        assert_eq!(image::open(&map).unwrap().width(), 160);
    }
    // A small file mesh (one triangle) is its own exact surface: the reference renders it.
    let mesh_path = dir.join("ref-triangle.gltf");
    std::fs::write(&mesh_path, TRIANGLE_GLTF).unwrap();
    let out = dir.join("ref-triangle.png");
    let o = shadelab(&[
        "render",
        "--scene",
        mesh_path.to_str().unwrap(),
        "--reference",
        "--width",
        "64",
        "--height",
        "36",
        "--output",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    // One of more triangles than testing each per ray allowed (10⁴) renders through its
    // hierarchy (docs/reference.md).
    let big_path = dir.join("ref-big.glb");
    std::fs::write(&big_path, shadelab_model::gltf_io::synthetic::sphere_glb(20_000, true).0).unwrap();
    let big_out = dir.join("ref-big.png");
    let args = ["render", "--scene", big_path.to_str().unwrap(), "--reference", "--width", "64", "--height", "36"];
    let o = shadelab(&[&args[..], &["--output", big_out.to_str().unwrap()]].concat());
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    for bad in [
        &["--reference", "--difference", "--output", "x.png"][..],
        &["--difference", "--output", "x.exr"],
        &["--reference", "--overlay", "normals", "--output", "x.png"],
    ] {
        let mut args = vec!["render"];
        args.extend_from_slice(bad);
        let o = shadelab(&args);
        assert_eq!((o.status.code(), error_lines(&o).len()), (Some(2), 1), "{bad:?}: {:?}", error_lines(&o));
    }
    // The reference alone is the CPU's: it opens no adapter, so it renders where no Vulkan driver
    // is found, where the GPU's image and the difference cannot.
    let no_driver = |extra: &[&str]| {
        let out = dir.join("ref-no-driver.png");
        let args = [&["render", "--width", "32", "--height", "18", "--output", out.to_str().unwrap()][..], extra];
        Command::new(env!("CARGO_BIN_EXE_shadelab"))
            .args(args.concat())
            .env("SHADELAB_ADAPTER", "lavapipe")
            // Both of the Vulkan loader's driver lists (the newer name wins where both are set).
            .env("VK_DRIVER_FILES", dir.join("no-such-driver.json"))
            .env("VK_ICD_FILENAMES", dir.join("no-such-driver.json"))
            .output()
            .expect("run shadelab")
    };
    let o = no_driver(&["--reference"]);
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    for gpu_side in [&[][..], &["--difference"]] {
        let o = no_driver(gpu_side);
        assert_eq!(o.status.code(), Some(1), "{gpu_side:?}: {:?}", error_lines(&o));
        assert!(error_lines(&o)[0].contains("no lavapipe adapter found"), "{gpu_side:?}: {:?}", error_lines(&o));
    }
}

/// `shadelab render` at `size` with `extra` flags into the EXR `path`, which it must write; read
/// back as linear float.
fn render_exr(path: &std::path::Path, size: (u32, u32), extra: &[&str]) -> image::Rgba32FImage {
    let (w, h) = (size.0.to_string(), size.1.to_string());
    let mut args = vec!["render", "--width", &w, "--height", &h, "--output", path.to_str().unwrap()];
    args.extend_from_slice(extra);
    let o = shadelab(&args);
    assert!(o.status.success(), "{}: {}", path.display(), String::from_utf8_lossy(&o.stderr));
    image::open(path).unwrap().to_rgba32f()
}

/// A glTF file of one triangle, its positions in a data URI.
const TRIANGLE_GLTF: &str = r#"{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}"#;

/// `render --link` draws the view a link describes: a material edited by its key draws as the
/// flag that edits every material does; an orbit moves the camera; a bad key is one line naming it.
#[test]
fn render_link_draws_the_links_view_and_names_a_bad_key() {
    let dir = out_dir();
    let (a, b, c) = (dir.join("link-keys.png"), dir.join("link-flag.png"), dir.join("link-orbit.png"));
    let by_keys = render(&["--link", "?scene=sphere&mat0.m=0.6&mat1.m=0.6&light0.I=0.7"], (160, 90), &a).to_rgb8();
    let by_flags = render(&["--scene", "sphere", "--m", "0.6", "--link", "?scene=sphere&light0.I=0.7"], (160, 90), &b);
    let plain = render(&["--scene", "sphere"], (160, 90), &b).to_rgb8();
    assert_ne!(by_keys, plain, "the keys change the picture");
    // --m is a flag of the link's own scene: the link replaces the render's scene flags.
    assert_ne!(by_flags.to_rgb8(), by_keys, "the render's --m gives way to the link");
    let flagged = render(&["--link", "?scene=sphere&m=0.6&light0.I=0.7"], (160, 90), &b).to_rgb8();
    assert_eq!(flagged, by_keys, "mat<i>.m on every material draws as the flag m");
    let orbited = render(&["--link", "?scene=sphere&orbit=0,1,0,0.5,0.3,6"], (160, 90), &c).to_rgb8();
    assert_ne!(orbited, plain, "the orbit moves the camera");
    for (query, says) in [("?scene=sphere&mat0.m=2", "mat0.m=2"), ("?scene=sphere&orbit=1,2", "six numbers")] {
        let o = shadelab(&["render", "--link", query, "--output", a.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{query}: {}", String::from_utf8_lossy(&o.stderr));
        let lines = error_lines(&o);
        assert!(lines.len() == 1 && lines[0].contains(says), "{query}: {lines:?}");
    }
}

/// `render --link '?file=…'`: a model relative to the working folder opens as `--scene` does,
/// with the link's edits over it; a path out of the folder or to another origin is one line.
#[test]
fn render_link_opens_a_relative_file_and_refuses_others() {
    let dir = out_dir();
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_shadelab"))
            .args(args)
            .current_dir(common::root())
            .env("SHADELAB_ADAPTER", "lavapipe")
            .output()
            .expect("run shadelab")
    };
    let draw = |link: &str, name: &str| {
        let out = dir.join(name);
        let o = run(&["render", "--link", link, "--width", "160", "--height", "90", "--output", out.to_str().unwrap()]);
        assert!(o.status.success(), "{link}: {}", String::from_utf8_lossy(&o.stderr));
        image::open(&out).unwrap().to_rgb8()
    };
    let file = common::root().join("assets/textured-floor.gltf");
    let by_scene = render(&["--scene", file.to_str().unwrap()], (160, 90), &dir.join("file-scene.png")).to_rgb8();
    assert_eq!(draw("?file=assets/textured-floor.gltf", "file-link.png"), by_scene, "file= opens as --scene");
    assert_ne!(draw("?file=assets/textured-floor.gltf&mat0.m=0.9&light0.I=0.2", "file-edited.png"), by_scene);
    for bad in ["?file=../x.glb", "?file=https://example.org/x.glb", "?file=/etc/x.gltf", "?file=x.png"] {
        let o = run(&["render", "--link", bad, "--output", dir.join("x.png").to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        let lines = error_lines(&o);
        assert!(lines.len() == 1 && lines[0].contains("file="), "{bad}: {lines:?}");
    }
}

/// `camera=1` in a link looks through a file's second camera (another field of view), as
/// `--camera 1` does; a camera the file does not have is one line with the range.
#[test]
fn render_link_looks_through_a_files_chosen_camera() {
    let dir = out_dir().join("two-cameras");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = shadelab_model::Scene::builtin("default").unwrap();
    let text = shadelab_model::gltf_io::scene_to_gltf_json(&scene, &Default::default());
    let mut gltf: serde_json::Value = serde_json::from_str(&text).unwrap();
    gltf["cameras"].as_array_mut().unwrap().push(serde_json::json!({
        "type": "perspective", "perspective": { "yfov": 0.35, "znear": 0.1, "zfar": 100.0 }
    }));
    let node = gltf["nodes"].as_array().unwrap().len();
    gltf["nodes"].as_array_mut().unwrap().push(serde_json::json!({ "camera": 1, "translation": [0.5, 1.5, 7.0] }));
    gltf["scenes"][0]["nodes"].as_array_mut().unwrap().push(node.into());
    std::fs::write(dir.join("two.gltf"), gltf.to_string()).unwrap();
    let run = |args: &[&str]| {
        let mut all = vec!["render", "--width", "160", "--height", "90"];
        all.extend(args);
        Command::new(env!("CARGO_BIN_EXE_shadelab"))
            .args(all)
            .current_dir(&dir)
            .env("SHADELAB_ADAPTER", "lavapipe")
            .output()
            .expect("run shadelab")
    };
    let draw = |args: &[&str], name: &str| {
        let o = run(&[args, &["--output", name]].concat());
        assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
        image::open(dir.join(name)).unwrap().to_rgb8()
    };
    let second = draw(&["--scene", "two.gltf", "--camera", "1"], "second.png");
    assert_eq!(draw(&["--link", "?file=two.gltf&camera=1"], "second-link.png"), second);
    assert_ne!(draw(&["--link", "?file=two.gltf"], "first-link.png"), second, "the second camera is another view");
    let o = run(&["--link", "?file=two.gltf&camera=2", "--output", "x.png"]);
    assert_eq!(o.status.code(), Some(2));
    let lines = error_lines(&o);
    assert!(lines.len() == 1 && lines[0].contains("--camera") && lines[0].contains("[0, 1]"), "{lines:?}");
}
