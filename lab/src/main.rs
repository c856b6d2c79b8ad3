//! The `hycon` command-line program: runs the reference analyses and prints their tables.
//! `hycon` with no arguments runs the main job (see `hycon --help`).

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
