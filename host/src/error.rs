//! Errors of the crate `dof`: the core's ([`CoreError`]: backends, contexts, bad arguments), and
//! those only what sits above the core raises (scene files, plots). A core error keeps its message,
//! so the `dof` command prints the same words whichever layer failed. The one-shot path
//! ([`crate::methods`]) only runs the core's contexts and returns the core's errors.

pub use dof_core::Error as CoreError;

#[derive(Debug)]
pub enum Error {
    /// An error of the core (or a bad argument, which both layers refuse with the core's words).
    Core(CoreError),
    /// A plot that cannot be drawn or written.
    Plot(String),
    /// A scene file that cannot be read or used (malformed, missing parts, out-of-range data).
    Scene(String),
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// The core's [`CoreError::InvalidArgument`].
    pub fn invalid(message: String) -> Self {
        Error::Core(CoreError::InvalidArgument(message))
    }
}

impl From<CoreError> for Error {
    fn from(e: CoreError) -> Self {
        Error::Core(e)
    }
}

/// Back into the core's type where the core's traits want it (a context above the core, closures
/// the core runs): a scene or plot error becomes an invalid argument with the same message.
impl From<Error> for CoreError {
    fn from(e: Error) -> Self {
        match e {
            Error::Core(e) => e,
            other => CoreError::InvalidArgument(other.to_string()),
        }
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::Core(e) => e.fmt(f),
            Error::Plot(m) => write!(f, "cannot draw a plot: {m}"),
            Error::Scene(m) => write!(f, "scene: {m}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Core(e) => e.source(),
            _ => None,
        }
    }
}
