//! [`Effect`]'s accessors into its declaration ([`DECLARED`]), its printed name, and the checks
//! that hold the table to the enum's order and to unique names.

use super::declared::{DECLARED, Declaration, Effect};
use std::fmt;

// The table is indexed by the enum, and a key holds one bit per effect.
const _: () = {
    let mut i = 0;
    while i < DECLARED.len() {
        assert!(DECLARED[i].effect as usize == i, "DECLARED is in Effect's order");
        i += 1;
    }
    assert!(DECLARED.len() <= u64::BITS as usize, "an EffectKey holds one bit per effect");
};

impl Effect {
    /// The effect's entry in [`DECLARED`].
    pub const fn declaration(self) -> &'static Declaration {
        &DECLARED[self as usize]
    }

    /// Whether the shader has code for the effect (it has a define).
    pub const fn is_simulated(self) -> bool {
        self.declaration().define.is_some()
    }

    /// The WGSL preprocessor name of the effect; `None` when it is not simulated.
    pub const fn define(self) -> Option<&'static str> {
        self.declaration().define
    }

    /// The short name (`bench effects`: "without …").
    pub const fn name(self) -> &'static str {
        self.declaration().name
    }

    /// The part of a pipeline label this effect contributes.
    pub const fn label(self) -> &'static str {
        self.declaration().label
    }

    /// The WGSL functions only this effect calls.
    pub const fn functions(self) -> &'static [&'static str] {
        self.declaration().functions
    }

    /// The `(struct, member)` uniforms only this effect reads.
    pub const fn members(self) -> &'static [(&'static str, &'static str)] {
        self.declaration().members
    }

    pub(super) const fn bit(self) -> u64 {
        1 << self as u64
    }
}

/// The effect as the analysis prints it.
impl fmt::Display for Effect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.declaration().explain)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_labels_and_defines_are_unique() {
        for (i, a) in DECLARED.iter().enumerate() {
            for b in &DECLARED[i + 1..] {
                assert_ne!(a.label, b.label);
                assert_ne!(a.name, b.name);
                assert_ne!(a.explain, b.explain);
                if a.define.is_some() {
                    assert_ne!(a.define, b.define);
                }
            }
            // A label joins with '+' and must not read as a whole key's label.
            assert!(!a.label.contains('+') && a.label != "uber" && a.label != "none", "{}", a.label);
            if let Some(d) = a.define {
                assert!(d.starts_with("EFFECT_") && !d.contains(char::is_whitespace), "{d}");
            }
            if a.define.is_none() {
                assert!(a.functions.is_empty() && a.members.is_empty(), "{}: no code, so no functions", a.effect);
            }
        }
    }
}
