//! Output writers for the contact examples ([`crate::examples`]).
//!
//! * [`svg`]: plots of contact pressure and shear against the closed forms (Hertz,
//!   Cattaneo-Mindlin, `mu p` for slip), one file per example, one panel per run, one curve per
//!   increment.
//! * [`vtu`]: VTK XML unstructured-grid files of both bodies: displacement (point data), stress at
//!   element centres (cell data `sx`, `sy`, `txy`, von Mises) and the body id; of brick models
//!   the six stresses and, as point data, the contact pressure and traction.
//! * [`json`]: machine-readable results (serde).

pub mod json;
pub mod svg;
pub mod vtu;

use std::path::{Path, PathBuf};

/// What went wrong while writing a report.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// A file could not be created or written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The plotting library failed.
    #[error("plot {path}: {message}")]
    Plot {
        /// The file.
        path: PathBuf,
        /// The cause.
        message: String,
    },
    /// Serialization failed.
    #[error("json: {0}")]
    Json(#[from] serde_json::Error),
    /// Recovering the stresses failed.
    #[error(transparent)]
    Model(#[from] hycon::Error),
}

/// Result alias of the writers.
pub type Result<T> = std::result::Result<T, ReportError>;

pub(crate) fn io_error(path: &Path) -> impl FnOnce(std::io::Error) -> ReportError + '_ {
    move |source| ReportError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Create `path` (and its parent directories) and write `contents`.
pub(crate) fn write_file(path: &Path, contents: &[u8]) -> Result<()> {
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent).map_err(io_error(parent))?;
    }
    std::fs::write(path, contents).map_err(io_error(path))
}
