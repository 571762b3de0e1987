//! The macro that expands the library's one list of effects (`library.rs`)
//! into everything that must name each effect in code: a unit struct per
//! effect (which implements [`super::Effect`] in the library), the
//! [`super::EffectKind`] enum (a variant per effect, in the list's order),
//! `EffectKind::ALL`, the dispatch of every item of the trait to the
//! effect's impl, and `Serialize`/`Deserialize` by the effect's name. It
//! checks at compile time that every effect has one to three parameters and
//! one truth value per parameter. Nothing here is written per effect: a new
//! effect is a line of the list and its impl.
//!
//! A line is a variant name with its doc comment; the unit struct of the
//! same name is the effect. The expansion's names (`Effect`, `Effects`,
//! `Scalar`, …) resolve where the list is, so this file imports nothing.

/// Expands the list of effects; invoked once, in `library.rs`.
macro_rules! effect_library {
    ($( $(#[$doc:meta])* $variant:ident ),* $(,)?) => {
        $(
            $(#[$doc])*
            #[derive(Debug, Clone, Copy, PartialEq, Eq)]
            pub struct $variant;

            const _: () = {
                let p = <$variant as Effect>::PARAMETERS;
                assert!(
                    !p.is_empty() && p.len() <= 3,
                    concat!(stringify!($variant), ": one to three parameters")
                );
                assert!(
                    <$variant as Effect>::TRUTH.len() == p.len(),
                    concat!(stringify!($variant), ": one truth value per parameter")
                );
            };
        )*

        /// One candidate effect: a variant per effect of the library's
        /// list, in its order; its name, parameters, signature, needs,
        /// truth and physics are its [`Effect`] impl's.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum EffectKind {
            $( $(#[$doc])* $variant, )*
        }

        /// The effects' names in the list's order.
        const NAMES: &[&str] = &[$(<$variant as Effect>::NAME),*];

        impl EffectKind {
            /// Every effect, in the list's order: the candidates of a
            /// campaign that names none, and the order error messages list
            /// them in.
            pub const ALL: [EffectKind; NAMES.len()] = [$(EffectKind::$variant),*];

            /// The name in a campaign's `[diagnose] effects` and in
            /// `diagnosis.json` ([`Effect::NAME`]).
            pub fn name(self) -> &'static str {
                match self { $( EffectKind::$variant => <$variant as Effect>::NAME, )* }
            }

            /// Its parameters ([`Effect::PARAMETERS`]).
            pub fn parameters(self) -> &'static [Parameter] {
                match self { $( EffectKind::$variant => <$variant as Effect>::PARAMETERS, )* }
            }

            /// What it does to the measurements that no other effect does
            /// ([`Effect::SIGNATURE`]).
            pub fn signature(self) -> &'static str {
                match self { $( EffectKind::$variant => <$variant as Effect>::SIGNATURE, )* }
            }

            /// What a run must carry for it to show ([`Effect::NEEDS`]).
            pub fn needs(self) -> Needs {
                match self { $( EffectKind::$variant => <$variant as Effect>::NEEDS, )* }
            }

            /// Whether it acts through the roll degree of freedom
            /// ([`Effect::USES_ROLL`]).
            pub fn uses_roll(self) -> bool {
                match self { $( EffectKind::$variant => <$variant as Effect>::USES_ROLL, )* }
            }

            /// Its values on the augmented proving ground ([`Effect::TRUTH`]).
            pub fn truth(self) -> &'static [f64] {
                match self { $( EffectKind::$variant => <$variant as Effect>::TRUTH, )* }
            }

            /// Sets its numbers for parameters `p` on `effects`
            /// ([`Effect::apply`]).
            pub fn apply<T: Scalar>(self, p: &[T], effects: &mut Effects<T>) {
                match self { $( EffectKind::$variant => <$variant as Effect>::apply(p, effects), )* }
            }
        }

        impl Serialize for EffectKind {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }

        impl<'de> Deserialize<'de> for EffectKind {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let name = String::deserialize(d)?;
                EffectKind::from_name(&name)
                    .ok_or_else(|| serde::de::Error::unknown_variant(&name, NAMES))
            }
        }
    };
}

pub(super) use effect_library;
