//! The `curvekit` command-line tool (see `docs/interfaces.md`, "Command-line tool").
//!
//! Exit status: 0 success, 2 bad input or usage (one line on stderr), 1 anything else.

mod cli;

use clap::error::ErrorKind;
use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    // Never die with a multi-line panic report: one line, exit 1.
    std::panic::set_hook(Box::new(|info| {
        let msg = info.to_string().replace('\n', " ");
        eprintln!("curvekit: internal error: {msg}");
    }));
    let args = match cli::Cli::try_parse() {
        Ok(args) => args,
        Err(e) => return usage_error(&e),
    };
    let outcome = std::panic::catch_unwind(|| cli::progress::watched(|| cli::run(args)));
    match outcome {
        Ok(Ok(())) => ExitCode::SUCCESS,
        Ok(Err(failure)) => {
            eprintln!("curvekit: {}", failure.message());
            ExitCode::from(failure.exit_code())
        }
        Err(_) => ExitCode::from(1),
    }
}

/// Help and version go to stdout with status 0; every usage error is one line and status 2.
fn usage_error(e: &clap::Error) -> ExitCode {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            print!("{e}");
            ExitCode::SUCCESS
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            use clap::CommandFactory;
            let names: Vec<String> = cli::Cli::command()
                .get_subcommands()
                .map(|c| c.get_name().to_string())
                .collect();
            eprintln!(
                "curvekit: no command given (one of: {}; see --help)",
                names.join(", ")
            );
            ExitCode::from(2)
        }
        _ => {
            // clap's first paragraph, joined into one line (it may list arguments below).
            let text = e.to_string();
            let first: Vec<&str> = text
                .trim_start()
                .lines()
                .map(str::trim)
                .take_while(|l| !l.is_empty())
                .collect();
            // (And clap's suggestions for a typo: "tip: a similar subcommand exists: 'medial'".)
            let tips = text
                .lines()
                .map(str::trim)
                .filter(|l| l.starts_with("tip:"))
                .map(|l| format!("; {}", l.trim_start_matches("tip:").trim()));
            let line = first.join(" ") + &tips.collect::<String>();
            let line = line.strip_prefix("error: ").unwrap_or(&line);
            eprintln!("curvekit: {line} (see --help)");
            ExitCode::from(2)
        }
    }
}
