//! The macro that expands the registry's one list of models (`registry.rs`)
//! into everything that must name each model in code: the [`super::Tyre`]
//! enum (a variant per model, plus one for models registered at run time),
//! its dispatch to the model (`as_model`, the hot-loop lateral force, the
//! generic lateral force's visitor `visit_lateral`), its
//! `Serialize` (the model's fields behind its `model` key), the built-in
//! registry entries and the `ModelName` constants. Nothing here is written
//! per model: a new model is a line of the list.
//!
//! A line is `Variant(ModelType)`, or `Variant(ModelType, boxed)` for a
//! model stored boxed (the Magic Formula: its coefficient set would make
//! every tyre as large). The expansion's names (`Tyre`, `Model`, …) resolve
//! where the list is, so this file imports nothing.

/// Expands the list of tyre models; invoked once, in `registry.rs`.
macro_rules! tyre_models {
    (@stored $model:ident) => { $model };
    (@stored $model:ident, boxed) => { Box<$model> };
    ($( $(#[$doc:meta])* $variant:ident($model:ident $(, $boxed:ident)?) ),* $(,)?) => {
        /// A tyre of any model, selected at run time by the `model` key of
        /// its TOML file: one variant per model of the registry's list, and
        /// [`Tyre::Registered`] for a model registered at run time.
        #[derive(Debug, Clone, PartialEq)]
        pub enum Tyre {
            $( $(#[$doc])* $variant(tyre_models!(@stored $model $(, $boxed)?)), )*
            /// A tyre of a model registered at run time ([`register`]).
            Registered(Erased),
        }

        impl Tyre {
            /// The model behind the tyre, for everything it knows about itself.
            pub(crate) fn as_model(&self) -> &dyn ModelParameters {
                match self {
                    $( Tyre::$variant(t) => Borrow::<$model>::borrow(t), )*
                    Tyre::Registered(t) => t.as_model(),
                }
            }

            /// The model behind the tyre, to change its parameters.
            pub(crate) fn as_model_mut(&mut self) -> &mut dyn ModelParameters {
                match self {
                    $( Tyre::$variant(t) => BorrowMut::<$model>::borrow_mut(t), )*
                    Tyre::Registered(t) => t.as_model_mut(),
                }
            }

            /// The model of this tyre.
            pub fn model(&self) -> ModelName {
                match self {
                    $( Tyre::$variant(_) => ModelName::new(<$model as Model>::NAME), )*
                    Tyre::Registered(t) => ModelName::new(t.name()),
                }
            }

            /// The lateral force by a direct call to each model's override
            /// (the vehicle's hot loop), not one through the vtable.
            pub(super) fn lateral_force_direct(&self, s: &SlipState) -> f64 {
                match self {
                    $( Tyre::$variant(t) => Borrow::<$model>::borrow(t).lateral_force(s), )*
                    Tyre::Registered(t) => t.as_model().lateral_force(s),
                }
            }

            /// [`TyreModel::lateral_forces`] of a vehicle's four wheels,
            /// front on this tyre and rear on `rear`: one call to the model's
            /// override when both are of one model, else a call per wheel.
            pub(super) fn lateral_forces_direct(&self, rear: &Tyre, s: &[SlipState; 4]) -> [f64; 4] {
                match (self, rear) {
                    $( (Tyre::$variant(f), Tyre::$variant(r)) => Borrow::<$model>::borrow(f)
                        .lateral_forces(Borrow::<$model>::borrow(r), s), )*
                    _ => [
                        self.lateral_force_direct(&s[0]),
                        self.lateral_force_direct(&s[1]),
                        rear.lateral_force_direct(&s[2]),
                        rear.lateral_force_direct(&s[3]),
                    ],
                }
            }

            /// Visitor `v`'s answer from the model's generic lateral force
            /// ([`MaybeLateralForceOf`]): `None` for a model without one and
            /// for a model registered at run time (a trait object cannot
            /// take a generic method).
            pub(super) fn visit_lateral<V: LateralVisitor>(&self, v: V) -> Option<V::Output> {
                match self {
                    $( Tyre::$variant(t) => Borrow::<$model>::borrow(t).visit_lateral(v), )*
                    Tyre::Registered(_) => None,
                }
            }

            /// [`TyreModel::lateral_force_per_load`] of the model, directly.
            pub(super) fn lateral_force_per_load_direct(&self, s: &SlipState) -> Option<f64> {
                match self {
                    $( Tyre::$variant(t) => Borrow::<$model>::borrow(t).lateral_force_per_load(s), )*
                    Tyre::Registered(t) => t.as_model().lateral_force_per_load(s),
                }
            }
        }

        /// A tyre file's table: the `model` key, then the model's fields.
        impl Serialize for Tyre {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                match self {
                    $( Tyre::$variant(t) => Tagged {
                        model: <$model as Model>::NAME,
                        fields: Borrow::<$model>::borrow(t),
                    }
                    .serialize(s), )*
                    Tyre::Registered(t) => t.serialize(s),
                }
            }
        }

        /// The models of the list, in its order.
        static BUILT_IN: &[&dyn ModelEntry] = &[
            $( &Registration::<$model>::new(|m| Tyre::$variant(m.into())), )*
        ];

        /// The built-in models' names.
        #[allow(non_upper_case_globals)]
        impl ModelName {
            $(
                #[doc = concat!("The `", stringify!($variant), "` model's name.")]
                pub const $variant: ModelName = ModelName::new(<$model as Model>::NAME);
            )*
        }
    };
}

pub(super) use tyre_models;
