//! `shadelab figures --out DIR`: the chapter's figures as PNGs, each made by one `shadelab
//! render` command that `DIR/commands.txt` lists, so a teacher can re-run or change any of them.
//! The scene files the figures use are written into `DIR` first, so the commands run from there
//! on any machine.

use crate::{Failure, cli, render};
use anyhow::Context;
use clap::Parser;
use std::path::Path;

/// The scene files written beside the figures: (file name, the scene).
fn scene_files() -> [(&'static str, shadelab_model::Scene); 3] {
    [
        ("figure-7-3-pyramid.gltf", shadelab_model::assets::figure_7_3_pyramid()),
        ("gouraud-vs-phong.gltf", shadelab_model::assets::gouraud_vs_phong()),
        ("material-board.gltf", shadelab_model::assets::material_board()),
    ]
}

/// One figure: its image's file name, its caption and the `render` flags that make it.
pub struct Figure {
    pub file: &'static str,
    pub caption: &'static str,
    pub flags: &'static [&'static str],
}

/// The figures, in the chapter's order.
pub const FIGURES: &[Figure] = &[
    Figure {
        file: "figure-7-3-pyramid.png",
        caption: "7.3: the pyramid in parallel light, its cast shadow and its self-shadow boundary ABCDEV (cyan)",
        flags: &["--scene", "figure-7-3-pyramid.gltf", "--shading", "phong", "--overlay", "terminator"],
    },
    Figure {
        file: "figure-7-9-sphere-normals.png",
        caption: "7.9-7.10: the sphere's vertex normals, each the mean of all the faces around its vertex",
        flags: &["--scene", "sphere", "--shading", "gouraud", "--overlay", "normals,creases"],
    },
    Figure {
        file: "figure-7-11-cylinder-normals.png",
        caption: "7.11-7.12: the cylinder's vertex normals; the rim keeps the cap's and the side's apart (creases orange)",
        flags: &["--scene", "cylinder", "--shading", "gouraud", "--overlay", "normals,creases"],
    },
    Figure {
        file: "gouraud.png",
        caption: "7.6: Gouraud shading of the coarse sphere: the highlight is lost between the vertices",
        flags: &["--scene", "gouraud-vs-phong.gltf", "--shading", "gouraud"],
    },
    Figure {
        file: "phong.png",
        caption: "7.6: Phong shading of the same sphere: the normal interpolated, the highlight kept",
        flags: &["--scene", "gouraud-vs-phong.gltf", "--shading", "phong"],
    },
    Figure {
        file: "model-lambert.png",
        caption: "7.1: the Lambert rule R·I·cos α + R·(1 − I); the fill R·(1 − I) keeps the shadowed side from black",
        flags: &["--model", "lambert"],
    },
    Figure {
        file: "model-sum.png",
        caption: "7.1, equation (1): the four-term sum; its reflected term K_r·I·cos φ follows the eye, not the light",
        flags: &["--model", "sum"],
    },
    Figure { file: "model-phong.png", caption: "7.2: the Phong model with (V·R)^h", flags: &["--model", "phong"] },
    Figure {
        file: "model-cook-torrance.png",
        caption: "7.3: Cook–Torrance, Beckmann D, the min() G and the exact Fresnel F",
        flags: &["--model", "cook-torrance"],
    },
    Figure {
        file: "brdf-chapter.png",
        caption: "7.3: the material board with the chapter's terms: Beckmann D, V-groove G, exact F",
        flags: &["--scene", "material-board.gltf", "--microfacet", "chapter"],
    },
    Figure {
        file: "brdf-gltf.png",
        caption: "the same board with glTF 2.0's terms: GGX D (long tails), height-correlated Smith G, Schlick's F",
        flags: &["--scene", "material-board.gltf", "--microfacet", "gltf"],
    },
    Figure {
        file: "interpolation-screen.png",
        caption: "7.6: Gouraud with the chapter's screen-space interpolation: the field's large triangles show",
        flags: &["--scene", "field", "--shading", "gouraud", "--interpolation", "screen"],
    },
    Figure {
        file: "interpolation-perspective.png",
        caption: "7.6: the same with the GPU's perspective-correct interpolation",
        flags: &["--scene", "field", "--shading", "gouraud"],
    },
    Figure {
        file: "interpolation-difference.png",
        caption: "7.6: the FLIP map of the screen-space image against the perspective-correct one",
        flags: &["--scene", "field", "--shading", "gouraud", "--interpolation-difference"],
    },
    Figure {
        file: "term-ambient.png",
        caption: "equation (1): the ambient term I_a alone",
        flags: &["--term", "ambient"],
    },
    Figure {
        file: "term-diffuse.png",
        caption: "equation (1): the diffuse term I_d alone (Lambert, with cast shadows)",
        flags: &["--term", "diffuse"],
    },
    Figure {
        file: "term-shadow.png",
        caption: "the cast-shadow factor V alone: black where both lights are hidden, grey where one is",
        flags: &["--term", "shadow"],
    },
    Figure {
        file: "term-specular.png",
        caption: "equation (1): the specular term I_s alone, the spheres going from sharp to rough",
        flags: &["--term", "specular"],
    },
    Figure {
        file: "term-transmitted.png",
        caption: "equation (1): the four-term sum's transmitted term I_t alone, with 1 − t = 0.5",
        flags: &["--model", "sum", "--transmission", "0.5", "--term", "transmitted"],
    },
    Figure {
        file: "area-point.png",
        caption: "7.4: the plate lit by a point light: a hard shadow, what the chapter calls unnatural",
        flags: &["--scene", "penumbra", "--light", "point"],
    },
    Figure {
        file: "area-rect.png",
        caption: "7.4: the same plate under a 0.5 m square light: the penumbra, PCSS",
        flags: &["--scene", "penumbra", "--light", "rect"],
    },
    Figure {
        file: "area-disk.png",
        caption: "7.4: under a disk light 0.5 m across: the penumbra, PCSS",
        flags: &["--scene", "penumbra", "--light", "disk"],
    },
    Figure {
        file: "area-sphere.png",
        caption: "7.4: under a sphere light 0.5 m across: the penumbra, PCSS",
        flags: &["--scene", "penumbra", "--light", "sphere"],
    },
    Figure {
        file: "area-points-4.png",
        caption: "7.4: the square light as the chapter's 4 point sources: four hard shadows, unnatural",
        flags: &["--scene", "penumbra", "--light", "rect", "--area-points", "4"],
    },
    Figure {
        file: "area-points-16.png",
        caption: "7.4: as 16 point sources, each with its own hard shadow: the penumbra in 16 steps",
        flags: &["--scene", "penumbra", "--light", "rect", "--area-points", "16"],
    },
    Figure {
        file: "penumbra-error-pcf.png",
        caption: "7.4: the shadow factor's FLIP error against the reference's soft shadow, PCF: the whole penumbra is off",
        flags: &["--scene", "penumbra", "--shadow-filter", "pcf", "--term", "shadow", "--difference"],
    },
    Figure {
        file: "penumbra-error-pcss.png",
        caption: "7.4: the same with PCSS: a thin line where its umbra ends early, the penumbra close",
        flags: &["--scene", "penumbra", "--shadow-filter", "pcss", "--term", "shadow", "--difference"],
    },
    Figure {
        file: "penumbra-error-points16.png",
        caption: "7.4: the same with the light as 16 point sources: steps inside the penumbra, its edges in place",
        flags: &["--scene", "penumbra", "--area-points", "16", "--term", "shadow", "--difference"],
    },
];

/// The command that makes `figure` at `width`×`height`, run from the figures' folder.
pub fn command(figure: &Figure, width: u32, height: u32) -> Vec<String> {
    let mut args = vec!["render".to_string()];
    args.extend(figure.flags.iter().map(|f| f.to_string()));
    args.extend(["--width".into(), width.to_string(), "--height".into(), height.to_string()]);
    args.extend(["--output".into(), figure.file.into()]);
    args
}

pub fn run(args: &cli::FiguresArgs) -> Result<(), Failure> {
    let out = &args.out;
    std::fs::create_dir_all(out)
        .map_err(|e| Failure::Usage(format!("--out: cannot make the folder '{}': {e}", out.display())))?;
    for (name, scene) in scene_files() {
        let settings = shadelab_model::gltf_io::SceneSettings::default();
        shadelab_model::gltf_io::save_scene(&scene, &settings, &out.join(name))
            .with_context(|| format!("writing {}", out.join(name).display()))?;
    }
    let mut listing = String::from(
        "# The chapter's figures, made by `shadelab figures`. Run these from this folder to remake\n\
         # or change one.\n",
    );
    for f in FIGURES {
        let words = command(f, args.width, args.height);
        listing += &format!("\n# {}\nshadelab {}\n", f.caption, words.join(" "));
        render::run(&render_args(&words, out)?)?;
        println!("wrote {}", out.join(f.file).display());
    }
    std::fs::write(out.join("commands.txt"), listing).context("writing commands.txt")?;
    println!("wrote {}", out.join("commands.txt").display());
    Ok(())
}

/// The `render` arguments of `words` with the files it names (the scene files written here and
/// the output) inside `dir`, parsed as the command line would be.
fn render_args(words: &[String], dir: &Path) -> Result<cli::RenderArgs, Failure> {
    let mut argv = vec!["shadelab".to_string()];
    for w in words {
        let file = w.ends_with(".gltf") || w.ends_with(".png");
        argv.push(if file { dir.join(w).to_string_lossy().into_owned() } else { w.to_string() });
    }
    match cli::Cli::try_parse_from(&argv) {
        Ok(cli::Cli { command: Some(cli::Command::Render(a)), .. }) => Ok(a),
        Ok(_) => Err(Failure::Usage(format!("figure command '{}' is not a render command", words.join(" ")))),
        Err(e) => Err(Failure::Usage(cli::one_line(&e))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every figure's command parses, and each names a distinct image.
    #[test]
    fn every_figure_command_parses() {
        let dir = Path::new("figures");
        let mut files: Vec<_> = FIGURES.iter().map(|f| f.file).collect();
        for f in FIGURES {
            render_args(&command(f, 640, 360), dir).unwrap_or_else(|_| panic!("{}", f.file));
        }
        files.sort();
        files.dedup();
        assert_eq!(files.len(), FIGURES.len());
    }
}
