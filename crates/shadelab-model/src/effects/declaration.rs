//! The macro that turns the table of `declared.rs` into `Declaration` (what is declared about
//! one effect), the `Effect` enum, `Effect::ALL` and `DECLARED`, so that a variant and its
//! declaration cannot fall out of step.

/// Declares `Declaration`, the `Effect` enum, `Effect::ALL` and `DECLARED` from one entry per effect, so that
/// a variant and its declaration cannot fall out of step.
macro_rules! declare_effects {
    ($($(#[$doc:meta])* $effect:ident {
        explain: $explain:expr,
        name: $name:expr,
        label: $label:expr,
        define: $define:expr,
        functions: $functions:expr,
        members: $members:expr $(,)?
    },)*) => {
        /// What is declared about one effect.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub struct Declaration {
            pub effect: Effect,
            /// The effect as the analysis prints it (`render --explain`, the viewer's list).
            pub explain: &'static str,
            /// The short name `bench effects` prints in its "without …" rows.
            pub name: &'static str,
            /// The part of a pipeline label this effect contributes (see [`crate::effects::EffectKey::label`]).
            pub label: &'static str,
            /// The WGSL preprocessor name that holds the effect's code; `None` for an effect that is
            /// analysed but not simulated yet (no shader code, never in an [`crate::effects::EffectKey`]).
            pub define: Option<&'static str>,
            /// The WGSL functions only this effect calls (a permutation without it reaches none).
            pub functions: &'static [&'static str],
            /// The `(struct, member)` uniforms only this effect reads (a permutation without it reads
            /// none).
            pub members: &'static [(&'static str, &'static str)],
        }

        /// One effect of the lighting model, simulated or only analysed.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Effect {
            $($(#[$doc])* $effect,)*
        }

        /// Every declared effect, in [`Effect`]'s order (the order of pipeline labels).
        pub const DECLARED: &[Declaration] = &[
            $(Declaration {
                effect: Effect::$effect,
                explain: $explain,
                name: $name,
                label: $label,
                define: $define,
                functions: $functions,
                members: $members,
            },)*
        ];

        impl Effect {
            /// Every simulated effect (those with a define), in declaration order.
            pub const ALL: [Effect; simulated_count()] = {
                let mut out = [Effect::Diffuse; simulated_count()];
                let (mut i, mut n) = (0, 0);
                while i < DECLARED.len() {
                    if DECLARED[i].define.is_some() {
                        out[n] = DECLARED[i].effect;
                        n += 1;
                    }
                    i += 1;
                }
                out
            };
        }
    };
}

pub(super) use declare_effects;
