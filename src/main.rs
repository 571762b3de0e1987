//! The `handling` command-line tool: a thin layer over the library.

fn main() -> std::process::ExitCode {
    handling_cli::run()
}

#[path = "cli/mod.rs"]
mod handling_cli;
