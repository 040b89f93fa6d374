//! Which backends an evaluation ran on, as its reports record them.

use crate::backend::Backend;
use serde::Serialize;

/// A backend the evaluation ran on.
#[derive(Clone, Debug, Serialize)]
pub struct BackendInfo {
    pub kind: String,
    pub device: String,
    pub driver: String,
}

impl BackendInfo {
    /// What the reports say of `backend`.
    pub fn of(backend: &dyn Backend) -> Self {
        BackendInfo { kind: backend.kind().to_string(), device: backend.device_name(), driver: backend.driver() }
    }
}
