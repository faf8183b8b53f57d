// An environment's diffuse light from nine spherical-harmonic coefficients (globals.env_sh,
// written by environment.rs's sh_project; Ramamoorthi and Hanrahan): E(n)/π, in the unit of the
// chapter's I_a. Only with the environment effect (the whole file is one #if). The f64 twin is
// crates/shadelab-model/src/lighting/environment.rs.

#if EFFECT_ENVIRONMENT_SH
// The real SH basis's factors: 1/(2√π), √(3/(4π)), √(15/(4π)), √(5/(16π)), √(15/(16π)).
const SH_Y0: f32 = 0.2820947918;
const SH_Y1: f32 = 0.4886025119;
const SH_Y2: f32 = 1.0925484306;
const SH_Y20: f32 = 0.3153915653;
const SH_Y22: f32 = 0.5462742153;

// E(n)/π at unit n: the basis at n weighed by the coefficients (already scaled by the clamped
// cosine's band weights); a negative sum (ringing behind a bright source) is 0.
fn env_sh_radiance(n: vec3<f32>) -> vec3<f32> {
    let x = n.x;
    let y = n.y;
    let z = n.z;
    var e = globals.env_sh[0].rgb * SH_Y0;
    e += globals.env_sh[1].rgb * (SH_Y1 * y) + globals.env_sh[2].rgb * (SH_Y1 * z) + globals.env_sh[3].rgb * (SH_Y1 * x);
    e += globals.env_sh[4].rgb * (SH_Y2 * x * z) + globals.env_sh[5].rgb * (SH_Y2 * y * z);
    e += globals.env_sh[6].rgb * (SH_Y20 * (3.0 * y * y - 1.0));
    e += globals.env_sh[7].rgb * (SH_Y2 * x * y) + globals.env_sh[8].rgb * (SH_Y22 * (x * x - z * z));
    return max(e, vec3(0.0));
}
#endif
