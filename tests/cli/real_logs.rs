//! Real logs as loggers write them: standstills, crawling and glitches, from files through the CLI.

#[allow(unused_imports)]
use super::*;
