//! What a fresh-eyes check of `identify`, `simulate` and `diagnose` found
//! (stop 72), run as a user runs the tool.

use super::*;
