use super::OutputError;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// Runs `write` on a fresh temporary path in the destination's directory, then renames the
/// result onto `path`. The temporary lives in the same directory so the rename stays on one
/// file system and is atomic; on any failure the temporary is removed, so readers only ever
/// see the old file or the complete new one.
pub(super) fn write_atomically(
    path: &Path,
    write: impl FnOnce(&Path) -> Result<(), OutputError>,
) -> Result<(), OutputError> {
    let file_name = path.file_name().ok_or_else(|| OutputError::Invalid {
        path: path.to_path_buf(),
        message: "not a file path".to_string(),
    })?;
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let unique = COUNTER.fetch_add(1, Ordering::Relaxed);
    let mut temp_name = std::ffi::OsString::from(".");
    temp_name.push(file_name);
    temp_name.push(format!(".{}-{unique}.tmp", std::process::id()));
    let temp = dir.join(temp_name);

    let result = write(&temp).and_then(|()| {
        std::fs::rename(&temp, path).map_err(|source| OutputError::Io {
            path: path.to_path_buf(),
            source,
        })
    });
    if result.is_err() {
        // Best effort: the temporary may never have been created.
        let _ = std::fs::remove_file(&temp);
    }
    result
}
