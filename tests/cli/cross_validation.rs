//! Held-out scoring that agrees with the fit.

#[allow(unused_imports)]
use super::*;
