//! Rig files in the layouts real rigs and papers produce: grouping and thinning lose nothing silently.

#[allow(unused_imports)]
use super::*;
