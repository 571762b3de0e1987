//! What a fresh-eyes check of `tyre-eval` and the tyre files found
//! (stop 72), run as a user runs the tool.

use super::*;
