//! `dof stress`: every stiff and extreme case on every method and backend, pass or fail.

use super::{BackendChoice, backends};
use dof::eval::methods::evaluated_methods;
use dof::stress::{Outcome, cases};

#[derive(clap::Args)]
pub struct StressArgs {
    #[arg(long, value_enum, default_value_t)]
    backend: BackendChoice,
    /// Methods (comma-separated); default all.
    #[arg(long, value_delimiter = ',')]
    methods: Vec<String>,
}

pub fn run(args: &StressArgs) -> anyhow::Result<()> {
    let mut backends = backends(args.backend, false)?;
    let methods: Vec<_> =
        evaluated_methods().into_iter().filter(|m| args.methods.is_empty() || args.methods.iter().any(|n| n == m.name())).collect();
    if methods.is_empty() {
        anyhow::bail!("no method matches {:?}", args.methods);
    }
    let mut failures = 0;
    for case in cases() {
        println!("{}: {}", case.name, case.expectation);
        for method in &methods {
            let targets = if method.uses_backend() { backends.len() } else { 1 };
            for backend in backends.iter_mut().take(targets) {
                let where_ = if method.uses_backend() { backend.kind().to_string() } else { "host".into() };
                let line = match case.run(method.as_ref(), backend.as_mut()) {
                    Outcome::Pass(detail) => format!("pass  {detail}"),
                    Outcome::NotApplicable(why) => format!("n/a   {why}"),
                    Outcome::Fail(why) => {
                        failures += 1;
                        format!("FAIL  {why}")
                    }
                };
                println!("  {:<11} {:<7} {line}", method.name(), where_);
            }
        }
    }
    if failures > 0 {
        anyhow::bail!("{failures} stress case(s) failed");
    }
    println!("every case passed");
    Ok(())
}
