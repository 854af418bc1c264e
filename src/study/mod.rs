//! Tools that measure penumbra against POV-Ray: bias and noise statistics against a
//! converged reference (see docs on testing statistics), and the reference renderer that
//! drives the installed `povray`.

pub mod bench;
pub mod charts;
pub mod compare;
pub mod converge;
pub mod corpus;
pub mod distribution;
pub mod media_quadrature;
pub mod metrics;
pub mod parse_bench;
pub mod pipeline_bench;
pub mod reference;
mod tempdir;

pub use self::metrics::{
    Bias, ImageDifference, NonFinite, SQRT_B_THRESHOLD, TileFailure, TileReport, Verdict,
    bias_estimate, compare, evaluate, max_abs_error, mean_abs_error, noise_variance, rmse,
    tile_test,
};
pub use self::reference::{
    Reference, ReferenceRequest, read_reference, render_povray, render_reference, write_reference,
};
pub use self::tempdir::TempDir;

use crate::output::OutputError;
use std::fmt;
use std::path::PathBuf;

/// Why a study computation or a reference render could not be done.
#[derive(Debug)]
pub enum StudyError {
    /// The statistics need at least two replicates to separate noise from bias.
    TooFewReplicates { found: usize },
    /// Images that must be compared pixel by pixel differ in size.
    SizeMismatch {
        what: String,
        expected: (usize, usize),
        found: (usize, usize),
    },
    /// An image has no pixels, or its pixel count does not match its size.
    InvalidImage { what: String },
    /// A reference request that cannot be rendered as asked.
    InvalidRequest(String),
    /// `povray` is not on PATH.
    PovrayNotFound,
    /// POV-Ray ran and failed; `output` holds the last lines it printed.
    PovrayFailed {
        scene: PathBuf,
        status: String,
        output: String,
    },
    /// A file could not be read or written.
    Output(OutputError),
    /// A file-system operation outside image I/O failed.
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// A reference file lacks what a reference must hold.
    BadReferenceFile { path: PathBuf, message: String },
    /// The scene could not be loaded; the diagnostic, formatted.
    Scene(String),
    /// penumbra could not render the scene.
    Render(String),
    /// A chart or difference image could not be drawn or written.
    Chart(String),
}

impl fmt::Display for StudyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StudyError::TooFewReplicates { found } => write!(
                f,
                "need at least 2 replicate images to separate noise from bias, got {found}"
            ),
            StudyError::SizeMismatch {
                what,
                expected,
                found,
            } => write!(
                f,
                "{what} is {}x{}, expected {}x{}",
                found.0, found.1, expected.0, expected.1
            ),
            StudyError::InvalidImage { what } => {
                write!(
                    f,
                    "{what} is empty or its pixel count does not match its size"
                )
            }
            StudyError::InvalidRequest(message) => {
                write!(f, "invalid reference request: {message}")
            }
            StudyError::PovrayNotFound => write!(
                f,
                "`povray` was not found on PATH; install POV-Ray 3.7 to render references"
            ),
            StudyError::PovrayFailed {
                scene,
                status,
                output,
            } => write!(
                f,
                "povray failed on {} ({status}); its last output:\n{output}",
                scene.display()
            ),
            StudyError::Output(error) => write!(f, "{error}"),
            StudyError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            StudyError::BadReferenceFile { path, message } => {
                write!(f, "{}: not a penumbra reference: {message}", path.display())
            }
            StudyError::Scene(diagnostic) => write!(f, "{diagnostic}"),
            StudyError::Render(message) => write!(f, "render failed: {message}"),
            StudyError::Chart(message) => write!(f, "cannot draw chart: {message}"),
        }
    }
}

impl std::error::Error for StudyError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            StudyError::Output(error) => Some(error),
            StudyError::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<OutputError> for StudyError {
    fn from(error: OutputError) -> Self {
        StudyError::Output(error)
    }
}
