//! The twin of `shaders/models.wgsl`: the chapter's illumination models other than the Phong
//! model's sum (docs/model.md §1, §2, §3a): the Lambert rule and the four-term sum of equation
//! (1). [`IlluminationModel`] picks one of them or the Phong model (§3, with Phong or
//! Cook–Torrance specular, [`super::brdf::SpecularModel`]).

/// Which of the chapter's illumination models a scene is lit with (docs/model.md §3a).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum IlluminationModel {
    /// §3 and §5: `I_amb·r_a·C + Σ I_L (r_d·C·(N·L) + r_s·S)`, with `S` the specular model.
    #[default]
    Phong,
    /// §1: the Lambert rule `R·I·cos α + R·(1 − I)` per channel.
    Lambert,
    /// §2: the four-term sum `K_a·I_a + K_d·I_d + K_r·I_r + K_t·I_t` of equation (1).
    Sum,
}

impl IlluminationModel {
    pub const ALL_MODELS: [IlluminationModel; 3] =
        [IlluminationModel::Phong, IlluminationModel::Lambert, IlluminationModel::Sum];

    /// The value of `globals.illumination` in WGSL: `ILLUMINATION_<NAME>` of `shaders/models.wgsl`.
    pub fn code(self) -> u32 {
        match self {
            IlluminationModel::Phong => 0,
            IlluminationModel::Lambert => 1,
            IlluminationModel::Sum => 2,
        }
    }
}

// Given in scene files only (`extras.shadelab.illumination`); the command line's `--model` takes
// a `ModelChoice`.
crate::named_values!(IlluminationModel, "illumination", "phong" => Phong, "lambert" => Lambert, "sum" => Sum);

/// The four models a user picks from (`--model`, the viewer's model menu): the chapter's 7.1
/// (Lambert rule, four-term sum), 7.2 (Phong) and 7.3 (Cook–Torrance). The last two are the
/// Phong model's sum with one specular term or the other, which `--specular` also picks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ModelChoice {
    Lambert,
    Sum,
    Phong,
    CookTorrance,
}

impl ModelChoice {
    pub const ALL_CHOICES: [ModelChoice; 4] =
        [ModelChoice::Lambert, ModelChoice::Sum, ModelChoice::Phong, ModelChoice::CookTorrance];

    /// The illumination model, and the specular model it fixes (`None`: the specular model is
    /// not used).
    pub fn split(self) -> (IlluminationModel, Option<super::brdf::SpecularModel>) {
        use super::brdf::SpecularModel as S;
        match self {
            ModelChoice::Lambert => (IlluminationModel::Lambert, None),
            ModelChoice::Sum => (IlluminationModel::Sum, None),
            ModelChoice::Phong => (IlluminationModel::Phong, Some(S::Phong)),
            ModelChoice::CookTorrance => (IlluminationModel::Phong, Some(S::CookTorrance)),
        }
    }

    /// The choice an illumination model and a specular model make together.
    pub fn of(model: IlluminationModel, specular: super::brdf::SpecularModel) -> ModelChoice {
        match (model, specular) {
            (IlluminationModel::Lambert, _) => ModelChoice::Lambert,
            (IlluminationModel::Sum, _) => ModelChoice::Sum,
            (IlluminationModel::Phong, super::brdf::SpecularModel::Phong) => ModelChoice::Phong,
            (IlluminationModel::Phong, super::brdf::SpecularModel::CookTorrance) => ModelChoice::CookTorrance,
        }
    }

    /// The name on the viewer's model buttons.
    pub fn label(self) -> &'static str {
        match self {
            ModelChoice::Lambert => "Lambert rule",
            ModelChoice::Sum => "four-term sum",
            ModelChoice::Phong => "Phong model",
            ModelChoice::CookTorrance => "Cook–Torrance model",
        }
    }

    /// The chapter's name and formula, for a menu or a caption.
    pub fn title(self) -> &'static str {
        match self {
            ModelChoice::Lambert => "Lambert rule (7.1): R·I·cos α + R·(1 − I)",
            ModelChoice::Sum => "four-term sum (7.1, eq. 1): K_a·I_a + K_d·I_d + K_r·I_r + K_t·I_t",
            ModelChoice::Phong => "Phong model (7.2): I_a + I_d + I_L·r_s·(V·R)^h",
            ModelChoice::CookTorrance => "Cook–Torrance (7.3): I_a + I_d + I_L·r_s·F·D·G/(N·V)",
        }
    }
}

crate::named_values!(ModelChoice, "--model",
    "lambert" => Lambert, "sum" => Sum, "phong" => Phong, "cook-torrance" => CookTorrance
);

/// docs/model.md §1: the lit part of the Lambert rule for one light, `R·I·max(cos α, 0)`, per
/// channel with `R` and `I` clamped to [0, 1] (the rule's domain).
pub fn lambert_rule_lit(r: [f64; 3], i: [f64; 3], cos_alpha: f64) -> [f64; 3] {
    let c = cos_alpha.max(0.0);
    std::array::from_fn(|k| r[k].clamp(0.0, 1.0) * i[k].clamp(0.0, 1.0) * c)
}

/// docs/model.md §1: the Lambert rule's fill `R·(1 − I)`, per channel, clamped as above.
pub fn lambert_rule_fill(r: [f64; 3], i: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|k| r[k].clamp(0.0, 1.0) * (1.0 - i[k].clamp(0.0, 1.0)))
}

/// docs/model.md §2: the reflected term's `cos φ = N·V`, clamped at 0 (seen from behind), and 0
/// in the point's own shadow (`N·L ≤ 0`), where no light arrives to be reflected.
pub fn reflected_cos_phi(n_dot_l: f64, n_dot_v: f64) -> f64 {
    if n_dot_l > 0.0 { n_dot_v.max(0.0) } else { 0.0 }
}

/// docs/model.md §2: what one light adds to the four-term sum through the surface,
/// `I·(K_d·max(N·L, 0) + K_r·cos φ)` with `K_d = r_d·C`, `K_r = r_s`; 0 in own shadow.
/// `radiance` carries the light's `1/(d + d0)`.
pub fn sum_contribution(
    radiance: [f64; 3],
    n_dot_l: f64,
    n_dot_v: f64,
    color: [f64; 3],
    r_d: f64,
    r_s: f64,
) -> [f64; 3] {
    if n_dot_l <= 0.0 {
        return [0.0; 3];
    }
    let cos_phi = reflected_cos_phi(n_dot_l, n_dot_v);
    std::array::from_fn(|k| radiance[k] * (r_d * color[k] * n_dot_l + r_s * cos_phi))
}

/// docs/model.md §2: the transmitted term `K_t·(1 − t)·I` with `K_t = C` and `1 − t` the
/// material's transmission share (clamped to [0, 1]); it does not depend on the angles.
pub fn transmitted_term(radiance: [f64; 3], color: [f64; 3], share: f64) -> [f64; 3] {
    let s = share.clamp(0.0, 1.0);
    std::array::from_fn(|k| radiance[k] * color[k] * s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lit part and the fill make the chapter's rule (brdf::lambert_rule).
    #[test]
    fn lit_and_fill_make_the_rule() {
        for (r, i, c) in [(0.6, 1.0, 1.0), (0.6, 0.7, 0.0), (0.3, 0.4, 0.5), (1.2, -0.1, -0.5), (0.8, 2.0, 0.9)] {
            let sum = lambert_rule_lit([r; 3], [i; 3], c)[0] + lambert_rule_fill([r; 3], [i; 3])[0];
            assert!((sum - super::super::brdf::lambert_rule(r, i, c)).abs() < 1e-15, "{r} {i} {c}");
        }
    }

    #[test]
    fn the_sum_has_no_light_in_own_shadow_but_transmits() {
        let c = [0.8, 0.5, 0.2];
        assert_eq!(sum_contribution([1.0; 3], -0.2, 0.9, c, 0.8, 1.0), [0.0; 3]);
        let s = sum_contribution([0.5; 3], 0.5, 0.25, c, 0.8, 1.0);
        assert!((s[0] - 0.5 * (0.8 * 0.8 * 0.5 + 0.25)).abs() < 1e-15);
        assert_eq!(transmitted_term([0.5; 3], c, 0.5), [0.2, 0.125, 0.05]);
        assert_eq!(reflected_cos_phi(0.3, -0.4), 0.0);
    }

    #[test]
    fn choices_split_and_join() {
        use super::super::brdf::SpecularModel;
        for c in ModelChoice::ALL_CHOICES {
            let (m, s) = c.split();
            assert_eq!(ModelChoice::of(m, s.unwrap_or(SpecularModel::Phong)), c);
        }
    }
}
