//! The Magic Formula 6.1/6.2 from .tir files through the CLI.

#[allow(unused_imports)]
use super::*;
