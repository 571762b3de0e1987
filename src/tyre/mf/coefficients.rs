//! The coefficients of a Magic Formula 5.2/6.1/6.2 tyre, named as in the
//! TNO/ADAMS property file (`.tir`), all in SI (the reader converts the
//! file's `[UNITS]`). A coefficient absent from a file takes its version
//! default: 1 for the scaling factors λ, 2 for `PKY4` (the 5.2 form
//! `sin(2·atan(..))`), 16.7 m/s for `LONGVL`, 1 m/s for `VXLOW`, 1 for
//! `Q_RE0` (the free radius is `UNLOADED_RADIUS` at rest) and 0 for every
//! other coefficient (the term it belongs to is then off; without
//! `VERTICAL_STIFFNESS` there is no loaded radius).

use serde::{Deserialize, Serialize};

macro_rules! coefficients {
    ($($name:ident = $default:expr),* $(,)?) => {
        /// Magic Formula coefficients, keyed by their `.tir` names (SI).
        #[allow(non_snake_case, missing_docs)]
        #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct MfCoefficients {
            $(pub $name: f64,)*
        }

        impl Default for MfCoefficients {
            fn default() -> Self {
                Self { $($name: $default,)* }
            }
        }

        impl MfCoefficients {
            /// Every coefficient name the model reads, in file order.
            pub const NAMES: &'static [&'static str] = &[$(stringify!($name),)*];

            /// The value of coefficient `name` (`None` when the model does not
            /// read that key).
            pub fn get(&self, name: &str) -> Option<f64> {
                match name {
                    $(stringify!($name) => Some(self.$name),)*
                    _ => None,
                }
            }

            /// Sets coefficient `name`; false when the model does not read it.
            pub fn set(&mut self, name: &str, value: f64) -> bool {
                match name {
                    $(stringify!($name) => { self.$name = value; true })*
                    _ => false,
                }
            }

            /// The coefficients as scalars `T` (plain numbers, or dual
            /// numbers without derivatives until [`MfCoefficientsOf::set`]
            /// makes some of them variables).
            pub fn lift<T: From<f64>>(&self) -> MfCoefficientsOf<T> {
                MfCoefficientsOf { $($name: T::from(self.$name),)* }
            }
        }

        /// The coefficients in a scalar of the `num-dual` crate (a plain
        /// `f64`, or a dual number carrying the derivatives with respect
        /// to the coefficients being fitted): what
        /// [`super::MagicFormula::channel_of`] evaluates.
        #[allow(non_snake_case, missing_docs)]
        #[derive(Debug, Clone, PartialEq)]
        pub struct MfCoefficientsOf<T> {
            $(pub $name: T,)*
        }

        impl<T: Copy> MfCoefficientsOf<T> {
            /// The value of coefficient `name` (`None` when the model does
            /// not read that key).
            pub fn get(&self, name: &str) -> Option<T> {
                match name {
                    $(stringify!($name) => Some(self.$name),)*
                    _ => None,
                }
            }

            /// Sets coefficient `name`; false when the model does not read it.
            pub fn set(&mut self, name: &str, value: T) -> bool {
                match name {
                    $(stringify!($name) => { self.$name = value; true })*
                    _ => false,
                }
            }
        }
    };
}

coefficients! {
    FNOMIN = 4000.0, UNLOADED_RADIUS = 0.3, LONGVL = 16.7, VXLOW = 1.0, NOMPRES = 0.0, INFLPRES = 0.0,
    LFZO = 1.0, LCX = 1.0, LMUX = 1.0, LEX = 1.0, LKX = 1.0, LHX = 1.0, LVX = 1.0,
    LCY = 1.0, LMUY = 1.0, LEY = 1.0, LKY = 1.0, LKYC = 1.0, LKZC = 1.0, LHY = 1.0, LVY = 1.0,
    LTR = 1.0, LRES = 1.0, LXAL = 1.0, LYKA = 1.0, LVYKA = 1.0, LS = 1.0,
    LMX = 1.0, LVMX = 1.0, LMY = 1.0, LMUV = 0.0,
    PCX1 = 0.0, PDX1 = 0.0, PDX2 = 0.0, PDX3 = 0.0, PEX1 = 0.0, PEX2 = 0.0, PEX3 = 0.0, PEX4 = 0.0,
    PKX1 = 0.0, PKX2 = 0.0, PKX3 = 0.0, PHX1 = 0.0, PHX2 = 0.0, PVX1 = 0.0, PVX2 = 0.0,
    PPX1 = 0.0, PPX2 = 0.0, PPX3 = 0.0, PPX4 = 0.0,
    RBX1 = 0.0, RBX2 = 0.0, RBX3 = 0.0, RCX1 = 0.0, REX1 = 0.0, REX2 = 0.0, RHX1 = 0.0,
    QSX1 = 0.0, QSX2 = 0.0, QSX3 = 0.0, QSX4 = 0.0, QSX5 = 0.0, QSX6 = 0.0, QSX7 = 0.0,
    QSX8 = 0.0, QSX9 = 0.0, QSX10 = 0.0, QSX11 = 0.0, QSX12 = 0.0, QSX13 = 0.0, QSX14 = 0.0,
    PPMX1 = 0.0,
    PCY1 = 0.0, PDY1 = 0.0, PDY2 = 0.0, PDY3 = 0.0, PEY1 = 0.0, PEY2 = 0.0, PEY3 = 0.0,
    PEY4 = 0.0, PEY5 = 0.0, PKY1 = 0.0, PKY2 = 0.0, PKY3 = 0.0, PKY4 = 2.0, PKY5 = 0.0,
    PKY6 = 0.0, PKY7 = 0.0, PHY1 = 0.0, PHY2 = 0.0, PHY3 = 0.0, PVY1 = 0.0, PVY2 = 0.0,
    PVY3 = 0.0, PVY4 = 0.0, PPY1 = 0.0, PPY2 = 0.0, PPY3 = 0.0, PPY4 = 0.0, PPY5 = 0.0,
    RBY1 = 0.0, RBY2 = 0.0, RBY3 = 0.0, RBY4 = 0.0, RCY1 = 0.0, REY1 = 0.0, REY2 = 0.0,
    RHY1 = 0.0, RHY2 = 0.0, RVY1 = 0.0, RVY2 = 0.0, RVY3 = 0.0, RVY4 = 0.0, RVY5 = 0.0, RVY6 = 0.0,
    QSY1 = 0.0, QSY2 = 0.0, QSY3 = 0.0, QSY4 = 0.0, QSY5 = 0.0, QSY6 = 0.0, QSY7 = 0.0, QSY8 = 0.0,
    QBZ1 = 0.0, QBZ2 = 0.0, QBZ3 = 0.0, QBZ4 = 0.0, QBZ5 = 0.0, QBZ6 = 0.0, QBZ9 = 0.0, QBZ10 = 0.0,
    QCZ1 = 0.0, QDZ1 = 0.0, QDZ2 = 0.0, QDZ3 = 0.0, QDZ4 = 0.0, QDZ6 = 0.0, QDZ7 = 0.0,
    QDZ8 = 0.0, QDZ9 = 0.0, QDZ10 = 0.0, QDZ11 = 0.0,
    QEZ1 = 0.0, QEZ2 = 0.0, QEZ3 = 0.0, QEZ4 = 0.0, QEZ5 = 0.0,
    QHZ1 = 0.0, QHZ2 = 0.0, QHZ3 = 0.0, QHZ4 = 0.0, PPZ1 = 0.0, PPZ2 = 0.0,
    SSZ1 = 0.0, SSZ2 = 0.0, SSZ3 = 0.0, SSZ4 = 0.0,
    WIDTH = 0.0, ASPECT_RATIO = 0.0, VERTICAL_STIFFNESS = 0.0, Q_RE0 = 1.0, Q_V1 = 0.0, Q_V2 = 0.0,
    Q_FZ2 = 0.0, Q_FCX = 0.0, Q_FCY = 0.0, Q_FCY2 = 0.0, Q_CAM1 = 0.0, Q_CAM2 = 0.0, Q_CAM3 = 0.0,
    Q_FYS1 = 0.0, Q_FYS2 = 0.0, Q_FYS3 = 0.0, PFZ1 = 0.0, BREFF = 0.0, DREFF = 0.0, FREFF = 0.0,
}
