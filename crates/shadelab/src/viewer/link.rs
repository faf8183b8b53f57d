//! A link that opens a view: the page's query (`?scene=glass&shading=gouraud`) holds the viewer's
//! command-line options, each checked by the same parsers as the flag, so a bad one is named in
//! the panel with the flag's own one line and the others still apply. The panel's switches that
//! have no flag (the term, the error map, the overlays, the glass views) have keys of their own,
//! the camera's orbit its own, and the scene's edits theirs (`link_scene`). The desktop viewer
//! reads the same query with `shadelab --link`.

use super::Viewer;
use super::difference::{Against, DifferenceKind};
use super::link_scene::{self, on_off};
use super::site_path::site_path;
use crate::cli;
use glam::DVec3;
use shadelab_model::lighting::transmission::{GlassExit, GlassView};
use shadelab_model::params::NamedValue;
use shadelab_model::terms::Term;
use shadelab_model::{ModelChoice, Scene, SpecularModel};

/// Options a link may not carry: they name files or end the program, which a page cannot.
const REFUSED: &[&str] = &["screenshot", "exit-after-frames", "shaders", "link"];

/// The panel's switches that have no flag: key, and what it turns on.
const SWITCHES: &[(&str, &str)] = &[
    ("nonfinite", "paint non-finite pixels magenta"),
    ("boundary", "the self-shadow boundary"),
    ("normals", "the vertex normals"),
    ("creases", "the creases"),
    ("continuous", "render continuously (for live timing)"),
];

/// A link's query, checked.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Link {
    /// The command-line options it gives, as arguments (`--shading`, `gouraud`, …).
    pub args: Vec<String>,
    pub term: Option<Term>,
    pub error_map: Option<DifferenceKind>,
    /// What the FLIP map compares with (`reference=twin|truth`).
    pub against: Option<Against>,
    /// The truth's path tracer: surface vertices (`bounces=N`) and paths a pixel (`spp=N`).
    pub bounces: Option<u32>,
    pub spp: Option<u32>,
    /// The switches given, by key, on or off.
    pub switches: Vec<(&'static str, bool)>,
    pub glass_view: Option<GlassView>,
    pub glass_exit: Option<GlassExit>,
    /// The camera's orbit: its target, then yaw, pitch (radians) and distance.
    pub orbit: Option<(DVec3, [f64; 3])>,
    /// The scene's edits, key and value as given, read once the scene is open.
    pub scene: Vec<(String, String)>,
    /// A model on the page's own site (`file=models/duck.glb`), checked by [`site_path`].
    pub file: Option<String>,
    /// The lights whose "show shadow map" box is ticked (`shadow-maps=0,2`).
    pub shadow_maps: Option<Vec<usize>>,
    /// One line per bad parameter.
    pub errors: Vec<String>,
}

/// `%41` → `A`, `+` → space (the form a browser writes a query in); a bad escape stays as it is.
fn decode(text: &str) -> String {
    // `+` first: an encoded plus (`%2B`) stays a plus.
    shadelab_model::gltf_io::percent_decode(&text.replace('+', " "))
}

/// `A` stays, a space → `%20`, and so on: the characters a query value may hold as they are
/// (`/` among them, so a file's path reads as written).
pub(super) fn encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || matches!(b, b'-' | b'_' | b'.' | b'~' | b',' | b'/') {
            out.push(b as char);
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// Check one key and value; a flag's value goes through the command line's own parser.
fn take(link: &mut Link, key: &str, value: &str) -> Result<(), String> {
    let named = |e: shadelab_model::params::ParamError| e.to_string();
    match key {
        "term" => link.term = Some(Term::parse_named(value).map_err(named)?),
        "error-map" => {
            link.error_map = Some(match value {
                "flip" => DifferenceKind::Flip,
                "shadow" => DifferenceKind::Shadow,
                "ambient" => DifferenceKind::Ambient,
                _ => return Err(format!("error-map: '{value}' is not one of flip, shadow, ambient")),
            })
        }
        "reference" => {
            link.against = Some(match value {
                "twin" => Against::Twin,
                "truth" => Against::Truth,
                _ => return Err(format!("reference: '{value}' is not one of twin, truth")),
            })
        }
        "bounces" => link.bounces = Some(shadelab_model::params::BOUNCES.parse_u32(value).map_err(named)?),
        "spp" => link.spp = Some(shadelab_model::params::SPP.parse_u32(value).map_err(named)?),
        "glass-view" => link.glass_view = Some(GlassView::parse_named(value).map_err(named)?),
        "glass-exit" => link.glass_exit = Some(GlassExit::parse_named(value).map_err(named)?),
        "orbit" => link.orbit = Some(super::orbit::parse_link(value)?),
        "file" => link.file = Some(site_path(value)?),
        "shadow-maps" => link.shadow_maps = Some(light_list(value)?),
        k if link_scene::is_scene_key(k) => link.scene.push((k.to_string(), value.to_string())),
        "difference" => match on_off(value) {
            Some(true) => link.args.push("--difference".into()),
            Some(false) => {}
            None => return Err(format!("difference: '{value}' is not on or off")),
        },
        k if REFUSED.contains(&k) => {
            return Err(format!("{k}: a link cannot carry --{k} (it names a file or ends the viewer)"));
        }
        k if SWITCHES.iter().any(|(s, _)| *s == k) => {
            let on = on_off(value).ok_or_else(|| format!("{k}: '{value}' is not on or off"))?;
            let key = SWITCHES.iter().find(|(s, _)| *s == k).map(|(s, _)| *s).unwrap_or_default();
            link.switches.push((key, on));
        }
        k => {
            let flag = format!("--{k}");
            cli::parse_args(["shadelab", flag.as_str(), value]).map_err(|e| cli::one_line(&e))?;
            link.args.extend([flag, value.to_string()]);
        }
    }
    Ok(())
}

/// `0,2`: light indices, each below `MAX_LIGHTS` (the scene's own count is checked on opening).
fn light_list(value: &str) -> Result<Vec<usize>, String> {
    let max = shadelab_model::lighting::lights::MAX_LIGHTS;
    value
        .split(',')
        .filter(|v| !v.is_empty())
        .map(|v| v.parse::<usize>().ok().filter(|&i| i < max))
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| format!("'{value}' is not a list of light indices 0 to {} (i,j,…)", max - 1))
}

/// A line with its control characters escaped (`%0A` decodes to a newline): an error names what
/// the link holds, on one line.
fn printable(line: &str) -> String {
    line.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

/// Read a page's query (with or without its `?`). Each bad parameter is one line in `errors`,
/// prefixed with the parameter as written; the others are kept.
pub fn parse_query(query: &str) -> Link {
    let mut link = Link::default();
    for pair in query.trim_start_matches('?').split('&').filter(|p| !p.is_empty()) {
        let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
        let (key, value) = (decode(k), decode(v));
        if let Err(e) = take(&mut link, key.trim(), value.trim()) {
            let e = e.strip_prefix("error: ").unwrap_or(&e).to_string();
            link.errors.push(printable(&format!("link parameter {key}={value}: {e}")));
        }
    }
    link
}

impl Link {
    /// The command line the link's flags make; a file is its `--scene` on the desktop (the page
    /// fetches it from its site instead).
    pub(super) fn flag_args(&self) -> Vec<String> {
        let mut args = vec!["shadelab".to_string()];
        args.extend(self.args.iter().cloned());
        if let Some(file) = self.file.as_ref().filter(|_| !cfg!(target_arch = "wasm32")) {
            args.extend(["--scene".to_string(), file.clone()]);
        }
        args
    }

    /// The scene's edits in the order they are read: those that change what the others apply to
    /// (the ambient term, the light count, the environment's source) first, each group as given.
    pub fn scene_keys_in_order(&self) -> impl Iterator<Item = (&str, &str)> {
        let first = self.scene.iter().filter(|(k, _)| link_scene::is_structural(k));
        let rest = self.scene.iter().filter(|(k, _)| !link_scene::is_structural(k));
        first.chain(rest).map(|(k, v)| (k.as_str(), v.as_str()))
    }
}

/// A link's scene edits applied to `scene`, each bad one a line in `errors`.
fn apply_edits(link: &Link, scene: &mut shadelab_model::Scene, errors: &mut Vec<String>) {
    for (k, v) in link.scene_keys_in_order() {
        if let Err(e) = link_scene::apply_scene_key(scene, k, v) {
            errors.push(printable(&format!("link parameter {k}={v}: {e}")));
        }
    }
}

/// What a link opens, without a window (`render --link`): the scene as its flags load it with
/// its edits, the orbit's camera and the settings with its glass views; and its term. Every bad
/// parameter is a line of the error.
pub fn open_headless(
    link: &Link,
) -> Result<(shadelab_model::gltf_io::LoadedScene, shadelab_render::RenderSettings, Option<Term>), String> {
    let c = cli::parse_args(link.flag_args()).map_err(|e| format!("link: {}", cli::one_line(&e)))?;
    let usage = |f: crate::Failure| format!("link: {}", f.message());
    let mut loaded = cli::load(&c.scene).map_err(usage)?;
    let mut settings = c.mode.settle(&mut loaded, &c.scene).map_err(usage)?;
    settings.glass_view = link.glass_view.unwrap_or(settings.glass_view);
    settings.glass_exit = link.glass_exit.unwrap_or(settings.glass_exit);
    let mut errors = link.errors.clone();
    apply_edits(link, &mut loaded.scene, &mut errors);
    if let Some((target, angles)) = link.orbit {
        loaded.scene.camera = super::orbit::Orbit::from_link(target, angles).camera(&loaded.scene.camera);
    }
    if errors.is_empty() { Ok((loaded, settings, link.term)) } else { Err(errors.join("; ")) }
}

impl Viewer {
    /// Open the view a link describes: its scene and modes as the command line would, then the
    /// switches. Every bad parameter is named in the panel; the rest apply.
    pub fn open_link(&mut self, link: &Link) {
        let mut errors = link.errors.clone();
        match cli::parse_args(link.flag_args()) {
            Ok(c) => {
                if let Some(file) = link.file.as_ref().filter(|_| cfg!(target_arch = "wasm32")) {
                    // The page fetches the file; the rest of the view waits for it.
                    self.fetch_link_file(file, link.clone());
                    if !errors.is_empty() {
                        self.message = Some((errors.join("\n"), true));
                    }
                    return;
                }
                match self.open_scene_args(&c.scene, &c.mode) {
                    Ok(raw) => self.link_file = link.file.clone().map(|f| (f, raw)),
                    Err(e) => errors.push(format!("link: {e}")),
                }
                self.set_difference_view(c.difference);
            }
            Err(e) => errors.push(format!("link: {}", cli::one_line(&e))),
        }
        self.apply_view(link, errors);
    }

    /// The part of a link that applies to the scene on show: the term, the error map, the glass
    /// views, the scene's edits, the orbit and the switches; then every error in the panel.
    pub(super) fn apply_view(&mut self, link: &Link, mut errors: Vec<String>) {
        if let Some(term) = link.term {
            if term.in_scene(&self.scene) {
                self.term = term;
            } else if term.in_model(self.scene.illumination) {
                errors.push(format!("link parameter term={}: the scene has no environment light", term.name()));
            } else {
                errors.push(format!("link parameter term={}: not a term of this model", term.name()));
            }
        }
        if let Some(kind) = link.error_map {
            self.difference.kind = kind;
        }
        self.difference.against = link.against.unwrap_or(self.difference.against);
        let paths = &mut self.difference.paths.0;
        (paths.bounces, paths.spp) = (link.bounces.unwrap_or(paths.bounces), link.spp.unwrap_or(paths.spp));
        self.settings.glass_view = link.glass_view.unwrap_or(self.settings.glass_view);
        self.settings.glass_exit = link.glass_exit.unwrap_or(self.settings.glass_exit);
        apply_edits(link, &mut self.scene, &mut errors);
        if let Some((target, angles)) = link.orbit {
            self.orbit = super::orbit::Orbit::from_link(target, angles);
        }
        for &i in link.shadow_maps.iter().flatten() {
            if i < self.scene.lights.len() {
                self.shadow_maps.set(i, true);
            } else {
                errors.push(format!("link parameter shadow-maps: the scene has no light {i}"));
            }
        }
        for &(key, on) in &link.switches {
            match key {
                "nonfinite" => self.settings.debug_nonfinite = on,
                "boundary" => self.boundary.enabled = on,
                "normals" => self.normals.enabled = on,
                "creases" => self.creases.enabled = on,
                "continuous" => self.continuous = on,
                _ => {}
            }
        }
        if !errors.is_empty() {
            self.message = Some((errors.join("\n"), true));
        }
    }

    /// Load a scene and settle its modes as the command line does; on failure the scene on show
    /// stays.
    /// Returns the scene as loaded, before the mode's model: the base of a file's link.
    fn open_scene_args(&mut self, scene: &cli::SceneArgs, mode: &cli::ModeArgs) -> Result<Scene, String> {
        let usage = |f: crate::Failure| f.message();
        let mut loaded = cli::load_unchanged(scene).map_err(usage)?;
        let raw = loaded.scene.clone();
        cli::apply_flags(scene, &mut loaded.scene).map_err(usage)?;
        let settings = mode.settle(&mut loaded, scene).map_err(usage)?;
        self.show_loaded(loaded, &scene.scene)?;
        self.settings = settings;
        Ok(raw)
    }

    /// The link to the view on show: `base` (the page's address) with the scene, the modes, the
    /// term, the switches, the file's camera, the orbit and the scene's edits. A scene opened from a file other than
    /// a link's own `file=` cannot travel in a link: it is left out (the link opens the default
    /// scene) and `note` says so.
    pub fn link(&self, base: &str) -> (String, Option<String>) {
        let mut q: Vec<(String, String)> = Vec::new();
        let builtin = shadelab_model::scene::BUILTIN_SCENES.contains(&self.scene_name.as_str());
        let file = self.link_file.as_ref().filter(|_| !builtin);
        if builtin {
            q.push(("scene".into(), self.scene_name.clone()));
        } else if let Some((path, _)) = file {
            q.push(("file".into(), path.clone()));
        }
        q.push(("shading".into(), self.settings.shading.name().into()));
        let model = ModelChoice::of(self.scene.illumination, self.settings.specular);
        q.push(("model".into(), model.name().into()));
        if model.split().1.is_none() && self.settings.specular != SpecularModel::CookTorrance {
            q.push(("specular".into(), self.settings.specular.name().into()));
        }
        if self.settings.interpolation != shadelab_model::Interpolation::Perspective {
            q.push(("interpolation".into(), self.settings.interpolation.name().into()));
        }
        if self.term != Term::All {
            q.push(("term".into(), self.term.name().into()));
        }
        if self.difference.enabled {
            q.push(("difference".into(), "on".into()));
            match self.difference.kind {
                DifferenceKind::Flip => {}
                DifferenceKind::Shadow => q.push(("error-map".into(), "shadow".into())),
                DifferenceKind::Ambient => q.push(("error-map".into(), "ambient".into())),
            }
            if self.difference.kind == DifferenceKind::Flip && self.difference.against == Against::Truth {
                q.push(("reference".into(), "truth".into()));
            }
            let (now, default) = (self.difference.paths.0, super::difference::VIEWER_PATHS);
            if self.difference.truth().is_some() && now.bounces != default.bounces {
                q.push(("bounces".into(), now.bounces.to_string()));
            }
            if self.difference.truth().is_some() && now.spp != default.spp {
                q.push(("spp".into(), now.spp.to_string()));
            }
        }
        let defaults = shadelab_render::RenderSettings::default();
        if self.settings.glass_view != defaults.glass_view {
            q.push(("glass-view".into(), self.settings.glass_view.name().into()));
        }
        if self.settings.glass_exit != defaults.glass_exit {
            q.push(("glass-exit".into(), self.settings.glass_exit.name().into()));
        }
        let mut note = None;
        let from = if builtin { self.link_base(model) } else { file.map(|(_, raw)| link_scene::base(raw, model)) };
        if self.camera_choice != 0 {
            q.push(("camera".into(), self.camera_choice.to_string()));
        }
        if let Some(from) = from {
            // The orbit moves the chosen camera, whose lens the link's `camera` picks.
            let orbit = self.orbit.link_text();
            if orbit != super::orbit::Orbit::from_camera(&self.base_camera).link_text() {
                q.push(("orbit".into(), orbit));
            }
            let (keys, why) = link_scene::scene_keys(&self.scene, &from);
            q.extend(keys);
            note = why;
        }
        let maps: Vec<String> =
            (0..self.scene.lights.len()).filter(|&i| self.shadow_maps.is_on(i)).map(|i| i.to_string()).collect();
        if !maps.is_empty() {
            q.push(("shadow-maps".into(), maps.join(",")));
        }
        let on = [
            ("nonfinite", self.settings.debug_nonfinite),
            ("boundary", self.boundary.enabled),
            ("normals", self.normals.enabled),
            ("creases", self.creases.enabled),
            ("continuous", self.continuous),
        ];
        q.extend(on.iter().filter(|(_, v)| *v).map(|(k, _)| (k.to_string(), "on".to_string())));
        let query: Vec<String> = q.iter().map(|(k, v)| format!("{k}={}", encode(v))).collect();
        if !builtin && file.is_none() {
            note = Some(format!(
                "{} is a file, which a link cannot carry: save the scene and share the file",
                self.scene_name
            ));
        }
        (format!("{base}?{}", query.join("&")), note)
    }

    /// The scene a link's scene and model keys open, which its edits are written against.
    fn link_base(&self, model: ModelChoice) -> Option<shadelab_model::Scene> {
        let args = ["shadelab", "--scene", self.scene_name.as_str(), "--model", model.name()];
        let c = cli::parse_args(args).ok()?;
        let mut loaded = cli::load(&c.scene).ok()?;
        c.mode.settle(&mut loaded, &c.scene).ok()?;
        Some(loaded.scene)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_and_switches_are_read() {
        let l = parse_query("?scene=glass&shading=gouraud&term=diffuse&boundary=on&difference=1&error-map=shadow");
        assert_eq!(l.errors, Vec::<String>::new());
        assert_eq!(l.args, ["--scene", "glass", "--shading", "gouraud", "--difference"]);
        assert_eq!(l.term, Some(Term::Diffuse));
        assert_eq!(l.error_map, Some(DifferenceKind::Shadow));
        assert_eq!(l.switches, [("boundary", true)]);
        assert_eq!(parse_query("difference=on&error-map=ambient").error_map, Some(DifferenceKind::Ambient));
        assert_eq!(parse_query("error-map=sky").errors.len(), 1);
        assert_eq!(parse_query("shadow-maps=0,2").shadow_maps, Some(vec![0, 2]));
        for bad in ["shadow-maps=8", "shadow-maps=a", "shadow-maps=-1"] {
            let e = parse_query(bad).errors;
            assert!(e.len() == 1 && e[0].contains("0 to 7"), "{bad}: {e:?}");
        }
    }

    #[test]
    fn a_bad_parameter_is_named_and_the_rest_apply() {
        let l = parse_query("shading=wobbly&m=-1&specular=phong&term=nope&screenshot=x.png&creases=maybe&zzz=1");
        assert_eq!(l.args, ["--specular", "phong"]);
        assert_eq!(l.errors.len(), 6, "{:#?}", l.errors);
        assert!(
            l.errors[0].starts_with("link parameter shading=wobbly: ") && l.errors[0].contains("flat"),
            "{}",
            l.errors[0]
        );
        assert!(l.errors[1].contains("[0, 1]"), "the range is named: {}", l.errors[1]);
        assert!(l.errors[2].contains("term=nope"), "{}", l.errors[2]);
        assert!(l.errors[3].contains("cannot carry --screenshot"), "{}", l.errors[3]);
        assert!(l.errors[4].contains("creases=maybe"), "{}", l.errors[4]);
        assert!(l.errors[5].contains("zzz"), "{}", l.errors[5]);
        for e in &l.errors {
            assert!(!e.contains('\n'), "one line each: {e}");
        }
    }

    #[test]
    fn values_are_percent_decoded_and_encoded() {
        assert_eq!(decode("a%20b+c%2C%zz%4"), "a b c,%zz%4");
        assert_eq!(encode("a b/c,d&e=f"), "a%20b/c,d%26e%3Df");
        let l = parse_query("mu=0.9%2C0.6%2C0.2");
        assert_eq!(l.args, ["--mu", "0.9,0.6,0.2"]);
        assert!(l.errors.is_empty(), "{:?}", l.errors);
    }

    #[test]
    fn hostile_queries_do_not_panic() {
        for q in
            ["?", "&&&", "=", "%", "%%", "?=x", "?scene", "?scene=", "?m=%FF%FE", "?term=%E2%88%9E", "?shading=\u{0}"]
        {
            let _ = parse_query(q);
        }
    }

    /// The link parser's stand-in for a fuzz target (instrumenting the viewer crate for libFuzzer
    /// would cost more CI time than the rest of the fuzzing): 20000 mutations of real links, each
    /// with bytes replaced, inserted or removed from an alphabet of the query's own syntax, parse
    /// without a panic and with every error on one line; the scene's edits among them are also
    /// applied to a built-in scene, which must not panic either. A fixed seed keeps the run
    /// repeatable.
    #[test]
    fn mutated_links_parse_without_a_panic() {
        let seeds = [
            "?scene=glass&shading=gouraud&term=diffuse&boundary=on&difference=1&error-map=shadow&reference=truth&spp=8",
            "?mu=0.9%2C0.6%2C0.2&m=0.3&h=mirror&light=rect&light-size=0.5&shadow-filter=pcss",
            "?model=sum&transmission=0.5&falloff-form=linear&d0=0.2&camera=0&normals=1",
            "?orbit=0,0.35,-0.4,-0.36,0.3,5.8&Ia=0,0,0&mat0.m=0.1&mat1.mu=0.9,0.5,0.25&lights=3&light2.pos=-2,3,1",
            "?file=models/box.gltf&light1.filter=pcss&light0.range=none&env=sky&env.T=4&env.sun=0,1,0&shadow-maps=0,1",
        ];
        let base = shadelab_model::Scene::builtin("default").unwrap();
        let alphabet: Vec<char> = "?&=%,.-+0123456789aAfFzZ \u{0}\u{7f}é∞".chars().collect();
        let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = move |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        for i in 0..20_000 {
            let mut q: Vec<char> = seeds[i % seeds.len()].chars().collect();
            for _ in 0..1 + next(6) {
                let at = next(q.len() + 1);
                match next(3) {
                    0 if at < q.len() => q[at] = alphabet[next(alphabet.len())],
                    1 => q.insert(at, alphabet[next(alphabet.len())]),
                    _ if at < q.len() => {
                        q.remove(at);
                    }
                    _ => {}
                }
            }
            let query: String = q.into_iter().collect();
            let link = parse_query(&query);
            assert!(link.errors.iter().all(|e| !e.contains('\n')), "{query}: {:?}", link.errors);
            let mut scene = base.clone();
            for (k, v) in link.scene_keys_in_order() {
                if let Err(e) = link_scene::apply_scene_key(&mut scene, k, v) {
                    assert!(!e.contains('\n'), "{query}: {k}={v}: {e}");
                }
            }
        }
    }
}
