//! Step-steer metrics of measured (noisy) runs from files.

#[allow(unused_imports)]
use super::*;
