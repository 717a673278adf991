//! The `degrau` binary: the app without arguments, `degrau step` on the command line.
//! Everything lives in the library ([`degrau::cli`]).

fn main() -> std::process::ExitCode {
    degrau::cli::main()
}
