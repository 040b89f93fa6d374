//! The `dof` command.

mod cli;

#[global_allocator]
static HEAP: cli::heap::CountingHeap = cli::heap::CountingHeap;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "dof", version, about = "Multi-layer depth of field with tiled splatting, on Vulkan and the CPU")]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Renders a scene with one method to EXR + PNG (the default command: the `simple` scene's reference).
    Render(cli::render::RenderArgs),
    /// Backends, Vulkan devices and their limits, and a sort and scan self-check on every backend.
    Info(cli::info::InfoArgs),
    /// Error against run time for every method, setting, scene and backend (report.json, report.md).
    Eval(cli::eval::EvalArgs),
    /// The stiff and extreme cases on every method and backend; fails on any failure.
    Stress(cli::stress::StressArgs),
    /// The built-in scenes: lens, multi-layer statistics, reference sample counts.
    Scenes(cli::scenes::ScenesArgs),
    /// PSNR, SSIM and FLIP of one RGB EXR against another, full frame and inside a mask.
    Compare(cli::compare::CompareArgs),
    /// Benchmarks of the kernels on each backend.
    #[command(subcommand)]
    Bench(cli::bench::BenchCommand),
    /// Many frames through the frame API with the method, size, aperture and lens changing at
    /// random: memory must stay flat and the validation layer silent.
    Soak(cli::soak::SoakArgs),
    /// An interactive viewer: a window with the depth of field recorded every frame through the
    /// frame API, an orbit camera, click to focus, the lens and method on a panel, GPU times.
    #[cfg(feature = "view")]
    View(cli::view::ViewArgs),
    /// Lists every numeric option of every subcommand, one a line: the subcommand, the flag and
    /// its type, tab-separated (what the flag-table test walks).
    #[command(hide = true)]
    FlagTable,
}

/// The type of a numeric option's value (`None` for any other argument).
fn numeric_type(arg: &clap::Arg) -> Option<&'static str> {
    use std::any::TypeId;
    let types: [(TypeId, &'static str); 8] = [
        (TypeId::of::<u8>(), "u8"),
        (TypeId::of::<u16>(), "u16"),
        (TypeId::of::<u32>(), "u32"),
        (TypeId::of::<u64>(), "u64"),
        (TypeId::of::<usize>(), "usize"),
        (TypeId::of::<i32>(), "i32"),
        (TypeId::of::<f32>(), "f32"),
        (TypeId::of::<f64>(), "f64"),
    ];
    if !arg.get_action().takes_values() {
        return None;
    }
    let id = arg.get_value_parser().type_id();
    types.iter().find(|(t, _)| id == *t).map(|(_, name)| *name)
}

/// The numeric options of `command` and its subcommands, as `(subcommand path, --flag, type)`.
fn numeric_flags(command: &clap::Command, path: &str, out: &mut Vec<(String, String, &'static str)>) {
    for arg in command.get_arguments() {
        if let (Some(long), Some(name)) = (arg.get_long(), numeric_type(arg)) {
            out.push((path.to_string(), format!("--{long}"), name));
        }
    }
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set()) {
        let path = if path.is_empty() { sub.get_name().to_string() } else { format!("{path} {}", sub.get_name()) };
        numeric_flags(sub, &path, out);
    }
}

/// The command line's grammar: every subcommand takes a value that starts with `-` and reads as a
/// number (`--frames -1`, `--lum-threshold -inf`) as that option's value, so that the option's own
/// range check answers, rather than taking it for an unknown flag.
fn grammar() -> clap::Command {
    fn negatives(c: clap::Command) -> clap::Command {
        // clap reads `-1` as a number, not `-inf` or `-1e-45`: a numeric option takes any value.
        c.allow_negative_numbers(true)
            .mut_args(|a| if a.get_long().is_some() && numeric_type(&a).is_some() { a.allow_hyphen_values(true) } else { a })
            .mut_subcommands(negatives)
    }
    negatives(<Cli as clap::CommandFactory>::command())
}

fn parse<I: IntoIterator<Item = T>, T: Into<std::ffi::OsString> + Clone>(args: I) -> Cli {
    let matches = grammar().get_matches_from(args);
    <Cli as clap::FromArgMatches>::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

fn main() -> std::process::ExitCode {
    let cli = parse(std::env::args_os());
    // No subcommand: render the default scene with the default method.
    let command = match cli.command {
        Some(command) => command,
        None => match parse(["dof", "render"]).command {
            Some(command) => command,
            None => unreachable!("`dof render` parses to the render command"),
        },
    };
    let result = match command {
        Command::Render(args) => cli::render::run(&args),
        Command::Stress(args) => cli::stress::run(&args),
        Command::Info(args) => cli::info::run(&args),
        Command::Scenes(args) => cli::scenes::run(&args),
        Command::Compare(args) => cli::compare::run(&args),
        Command::Eval(args) => cli::eval::run(&args),
        Command::Bench(cmd) => cli::bench::run(&cmd),
        Command::Soak(args) => cli::soak::run(&args),
        #[cfg(feature = "view")]
        Command::View(args) => cli::view::run(&args),
        Command::FlagTable => {
            let mut flags = Vec::new();
            numeric_flags(&<Cli as clap::CommandFactory>::command(), "", &mut flags);
            for (sub, flag, ty) in flags {
                println!("{sub}\t{flag}\t{ty}");
            }
            Ok(())
        }
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
