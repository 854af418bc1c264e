use std::fmt;
use std::path::PathBuf;

/// Why an image could not be written or read. Every variant names the file, because the
/// study tools handle many files at once and an error without a path is useless there.
#[derive(Debug)]
pub enum OutputError {
    /// The extension is neither `.png` nor `.exr`.
    UnsupportedFormat { path: PathBuf },
    /// The operating system refused (missing directory, permissions, full disk...).
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// The PNG encoder or decoder failed, or the file is not a PNG we understand.
    Png { path: PathBuf, message: String },
    /// The EXR encoder or decoder failed, or the file lacks the channels we need.
    Exr { path: PathBuf, message: String },
    /// The request itself is unusable (empty image, bad layer or attribute name...).
    Invalid { path: PathBuf, message: String },
}

impl OutputError {
    pub fn path(&self) -> &std::path::Path {
        match self {
            OutputError::UnsupportedFormat { path }
            | OutputError::Io { path, .. }
            | OutputError::Png { path, .. }
            | OutputError::Exr { path, .. }
            | OutputError::Invalid { path, .. } => path,
        }
    }
}

impl fmt::Display for OutputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OutputError::UnsupportedFormat { path } => write!(
                f,
                "{}: unsupported image format (use a .png or .exr extension)",
                path.display()
            ),
            OutputError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            OutputError::Png { path, message } => write!(f, "{}: PNG: {message}", path.display()),
            OutputError::Exr { path, message } => {
                write!(f, "{}: OpenEXR: {message}", path.display())
            }
            OutputError::Invalid { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

impl std::error::Error for OutputError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            OutputError::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}
