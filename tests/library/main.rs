//! The library's integration tests: jobs and analyses called as functions
//! of `handling`, without the binary, on the bundled files and on
//! campaigns the proving ground generates in memory. What a user sees of
//! the command line is tested in `tests/cli/`; the unit tests sit beside
//! their code in `src/`.

mod derivatives;
mod diagnose;
mod screening;
