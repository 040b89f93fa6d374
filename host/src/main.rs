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
}

fn main() -> std::process::ExitCode {
    let cli = Cli::parse();
    // No subcommand: render the default scene with the default method.
    let command = match cli.command {
        Some(command) => command,
        None => match Cli::parse_from(["dof", "render"]).command {
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
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
