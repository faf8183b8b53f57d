use super::*;
use shadelab_model::lighting::microfacet::{Distribution, Fresnel, Masking};
use shadelab_model::lighting::sky::TURBIDITY;
use shadelab_model::scene::BUILTIN_SCENES;
use shadelab_model::shadow_settings::ShadowFilter;
use shadelab_model::{AreaSpecular, FalloffForm, LightKind};

/// A repeatable xorshift stream: the test's random states are the same on every run. With
/// `short`, a value is rounded to three significant digits, as the panel's sliders pick them (egui
/// aims at the simplest number under the pointer).
struct Rng(u64, bool);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    fn within(&mut self, r: ParamRange) -> f64 {
        let x = r.min + (r.max - r.min) * self.unit();
        if self.1 { format!("{x:.2e}").parse::<f64>().unwrap().clamp(r.min, r.max) } else { x }
    }
    fn count(&mut self, r: ParamRange) -> u32 {
        r.min as u32 + (self.next() % (r.max as u64 - r.min as u64 + 1)) as u32
    }
    fn rgb(&mut self, r: ParamRange) -> [f64; 3] {
        [self.within(r), self.within(r), self.within(r)]
    }
    fn vector(&mut self) -> DVec3 {
        DVec3::new(self.unit() * 8.0 - 4.0, self.unit() * 8.0 - 4.0, self.unit() * 8.0 - 4.0)
    }
    fn pick<T: Copy>(&mut self, from: &[T]) -> T {
        from[(self.next() % from.len() as u64) as usize]
    }
    fn of<T: NamedValue>(&mut self) -> T {
        self.pick(T::ALL).1
    }
}

/// What the panel may change in a material, each with chance `p`: the test's own list, apart
/// from the link's table, so a field the table misses fails the round trip.
fn edit_material(m: &mut Material, r: &mut Rng, p: f64) {
    if r.chance(p) {
        m.color = r.rgb(params::UNIT);
    }
    if r.chance(p) {
        (m.r_s, m.r_d, m.r_a) = (r.within(params::UNIT), r.within(params::UNIT), r.within(params::UNIT));
    }
    if r.chance(p) {
        m.m = r.within(params::M);
    }
    if r.chance(p) {
        m.h = if r.chance(0.2) { PhongExponent::Mirror } else { PhongExponent::Finite(r.within(params::H)) };
    }
    if r.chance(p) {
        m.mu = r.rgb(params::MU);
    }
    if r.chance(p) {
        (m.transmission, m.thickness) = (r.within(params::TRANSMISSION), r.within(params::THICKNESS));
    }
    if r.chance(p) {
        m.ior = r.chance(0.7).then(|| r.rgb(params::IOR));
    }
    if r.chance(p) {
        (m.absorption, m.emission) = (r.rgb(params::ABSORPTION), r.rgb(params::UNIT));
    }
    if r.chance(p) {
        (m.microfacet.d, m.microfacet.g, m.microfacet.f) =
            (r.of::<Distribution>(), r.of::<Masking>(), r.of::<Fresnel>());
    }
    if r.chance(p) {
        m.microfacet.multiple_scattering = r.chance(0.5);
        m.microfacet.fresnel_mix = r.chance(0.5);
        m.phong_normalized = r.chance(0.5);
    }
    if r.chance(p) {
        m.fresnel_mix.f0 = r.within(params::UNIT);
        m.fresnel_mix.weight = r.within(params::UNIT);
    }
}

/// What the panel may change in a light, each with chance `p`.
fn edit_light(l: &mut Light, r: &mut Rng, p: f64) {
    if r.chance(p) {
        l.kind = r.of::<LightKind>();
    }
    if r.chance(p) {
        (l.position, l.direction) = (r.vector(), r.vector());
    }
    if r.chance(p) {
        (l.color, l.intensity) = (r.rgb(params::UNIT), r.within(lights::INTENSITY));
    }
    if r.chance(p) {
        l.falloff_form = r.of::<FalloffForm>();
        (l.falloff_alpha, l.d0) = (r.within(lights::FALLOFF), r.within(lights::D0));
    }
    if r.chance(p) {
        (l.inner_cone, l.outer_cone) = (r.within(lights::CONE_ANGLE), r.within(lights::CONE_ANGLE));
        l.range = r.chance(0.5).then(|| r.within(lights::RANGE));
    }
    if r.chance(p) {
        l.size = [r.within(lights::LIGHT_SIZE), r.within(lights::LIGHT_SIZE)];
        (l.tangent, l.area_points) = (r.vector(), r.count(lights::AREA_POINTS));
        l.area_specular = r.of::<AreaSpecular>();
    }
    if r.chance(p) {
        l.shadow.casts = r.chance(0.5);
        l.shadow.resolution = r.count(SHADOW_RESOLUTION);
        l.shadow.filter = r.of::<ShadowFilter>();
        l.shadow.cascades = r.chance(0.5);
        l.shadow.pcss_taps = r.count(PCSS_TAPS);
    }
}

fn edit_environment(s: &mut Scene, r: &mut Rng, p: f64) {
    if r.chance(p) {
        s.ambient = r.rgb(params::UNIT);
    }
    if r.chance(p) {
        s.environment = match r.next() % 3 {
            0 => None,
            1 => Some(Environment::new(EnvSource::Uniform(r.rgb(ENV_RADIANCE)))),
            _ => {
                let sun = r.chance(0.5).then(|| r.vector());
                Some(Environment::new(EnvSource::Sky { turbidity: r.within(TURBIDITY), sun }))
            }
        };
    }
    if let Some(env) = s.environment.as_mut().filter(|_| r.chance(p)) {
        (env.intensity, env.rotation_deg) = (r.within(ENV_INTENSITY), r.within(ENV_ROTATION));
        (env.specular, env.occlusion, env.background) = (r.chance(0.5), r.chance(0.5), r.chance(0.5));
    }
}

/// A random state of `base`: each field edited with chance `p`, lights added or taken away.
fn random_state(base: &Scene, r: &mut Rng, p: f64) -> Scene {
    let mut s = base.clone();
    if r.chance(p) {
        s.lights.resize(r.count(LIGHT_COUNT) as usize, added_light());
    }
    s.materials.iter_mut().for_each(|m| edit_material(m, r, p));
    s.lights.iter_mut().for_each(|l| edit_light(l, r, p));
    edit_environment(&mut s, r, p);
    s
}

/// The query a viewer writes for `keys`, read back as the page does.
fn through_a_link(keys: &[(String, String)]) -> super::super::link::Link {
    let query: Vec<String> = keys.iter().map(|(k, v)| format!("{k}={}", super::super::link::encode(v))).collect();
    super::super::link::parse_query(&format!("?{}", query.join("&")))
}

/// The query's length for `keys`, as a link writes it.
fn query_length(keys: &[(String, String)]) -> usize {
    keys.iter().map(|(k, v)| k.len() + super::super::link::encode(v).len() + 2).sum()
}

/// Hundreds of random states of every built-in scene, from one field here and there to half of
/// every field of every material and light, each with full-precision floats, through a link and
/// back onto the scene as opened, come back equal field by field, every float to the bit (the
/// Debug form prints the shortest text that reads back to the same bits, so equal text is equal
/// bits).
#[test]
fn random_states_come_back_from_a_link_to_the_bit() {
    let mut r = Rng(0x2545_F491_4F6C_DD1D, false);
    let mut longest = (0, "");
    for round in 0..300 {
        let name = BUILTIN_SCENES[round % BUILTIN_SCENES.len()];
        let base = Scene::builtin(name).unwrap();
        let state = random_state(&base, &mut r, [0.05, 0.2, 0.5][round % 3]);
        let (keys, note) = scene_keys(&state, &base);
        assert!(note.is_none(), "{note:?}");
        let link = through_a_link(&keys);
        assert!(link.errors.is_empty(), "{name}: {:?}", link.errors);
        let mut opened = base.clone();
        for (k, v) in link.scene_keys_in_order() {
            apply_scene_key(&mut opened, k, v).unwrap_or_else(|e| panic!("{name}: {k}={v}: {e}"));
        }
        assert_eq!(format!("{opened:?}"), format!("{state:?}"), "{name}, round {round}");
        longest = longest.max((query_length(&keys), name));
    }
    eprintln!("longest query of a full-precision state: {} characters ({})", longest.0, longest.1);
}

/// Views as the panel makes them (a fifth of the fields or fewer edited, each to a value the
/// sliders pick) and an orbit (six full-precision floats) make links under 2 000 characters.
#[test]
fn links_of_panel_edits_stay_under_2000_characters() {
    let mut r = Rng(0x9E37_79B9_7F4A_7C15, true);
    let orbit = "-0.12345678901234567,1.2345678901234567,0.12345678901234567,2.3456789012345678,0.3456789012345678,7.123456789012345";
    let mut longest = (0, "");
    for round in 0..300 {
        let name = BUILTIN_SCENES[round % BUILTIN_SCENES.len()];
        let base = Scene::builtin(name).unwrap();
        let state = random_state(&base, &mut r, [0.05, 0.2][round % 2]);
        let (keys, _) = scene_keys(&state, &base);
        longest = longest.max((query_length(&keys) + "orbit=&".len() + orbit.len(), name));
    }
    eprintln!("longest query of a panel-made state: {} characters ({})", longest.0, longest.1);
    assert!(longest.0 < 2000, "{longest:?}");
}

#[test]
fn an_untouched_scene_has_no_keys() {
    for name in BUILTIN_SCENES {
        let base = Scene::builtin(name).unwrap();
        assert_eq!(scene_keys(&base, &base).0, Vec::<(String, String)>::new(), "{name}");
    }
}

#[test]
fn a_bad_key_or_value_says_what_and_where() {
    let mut s = Scene::builtin("default").unwrap();
    let cases = [
        ("mat0.m", "2", "[0, 1]"),
        ("mat99.m", "0.3", "index 99 is past them"),
        ("mat0.zz", "1", "is not one of C, r_s"),
        ("light0.kind", "laser", "directional"),
        ("light0.dir", "0,0,0", "has no direction"),
        ("light0.pos", "1,2", "is not 3 numbers"),
        ("lights", "9", "[0, 8]"),
        ("env.T", "3", "no environment"),
        ("env", "image", "cannot carry"),
        ("mat0.h", "nan", "Phong exponent"),
    ];
    for (k, v, says) in cases {
        let e = apply_scene_key(&mut s, k, v).expect_err(k);
        assert!(e.contains(says) && !e.contains('\n'), "{k}={v}: {e}");
    }
    // None of the refused values changed the scene.
    assert_eq!(format!("{s:?}"), format!("{:?}", Scene::builtin("default").unwrap()));
}
