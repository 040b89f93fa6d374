//! `dof eval`'s engine: every registered method appears for every setting and backend, and the
//! report carries the documented fields.

use dof::backend::{Backend, CpuBackend};
use dof::eval::methods::registry;
use dof::eval::{EvalOptions, evaluate};

#[test]
fn quick_evaluation_covers_every_method_and_setting() {
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    let options = EvalOptions { scenes: vec!["simple".into()], methods: vec![], quick: true, runs: 1, progress: false };
    let report = evaluate(&options, &mut backends).unwrap();
    for method in registry() {
        for setting in method.settings(true) {
            let found = report.records.iter().filter(|r| r.method == method.name() && r.setting == setting.label).count();
            assert_eq!(found, 1, "{} {}", method.name(), setting.label);
        }
    }
    let pinhole = report.records.iter().find(|r| r.method == "pinhole").unwrap();
    let best_gather = report.records.iter().filter(|r| r.method == "gather").map(|r| r.psnr_db).fold(f64::MIN, f64::max);
    assert!(best_gather > pinhole.psnr_db, "the gather beats the unblurred image");

    let json: serde_json::Value = serde_json::from_str(&report.to_json()).unwrap();
    for field in ["scene", "method", "setting", "backend", "device", "time_ms", "stages_ms", "psnr_db", "ssim", "psnr_masked_db", "ssim_masked"] {
        assert!(json["records"][0].get(field).is_some(), "report.json records lack `{field}`");
    }
    assert!(report.to_markdown().contains("| method | setting | backend |"));
}

#[test]
fn unknown_methods_are_named() {
    let mut backends: Vec<Box<dyn Backend>> = vec![Box::new(CpuBackend::new())];
    let options = EvalOptions { scenes: vec!["simple".into()], methods: vec!["nope".into()], quick: true, runs: 1, progress: false };
    let err = evaluate(&options, &mut backends).err().unwrap();
    assert!(err.to_string().contains("gather"), "{err}");
}
