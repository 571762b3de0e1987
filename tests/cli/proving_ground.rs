//! An independent four-wheel proving ground that is not our own model.

#[allow(unused_imports)]
use super::*;
