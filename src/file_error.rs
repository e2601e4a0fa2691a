//! Errors located in a file: which file, and what is wrong in it. Shared by
//! mesh, scene and scenario files.

use std::path::Path;

/// A problem reading or checking a file; the reason says where in it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}: {reason}")]
pub struct FileError {
    /// The file's path as given, for messages.
    pub file: String,
    /// What is wrong, and where in the file.
    pub reason: String,
}

impl FileError {
    /// An error in `file` for `reason`.
    pub fn new(file: &str, reason: impl Into<String>) -> FileError {
        FileError { file: file.to_string(), reason: reason.into() }
    }

    /// Reads a text file, naming it in the error.
    pub fn read(path: &Path) -> Result<String, FileError> {
        std::fs::read_to_string(path)
            .map_err(|e| FileError::new(&path.display().to_string(), e.to_string()))
    }

    /// Parses JSON text of `file`; a syntax or schema error gives its line
    /// and column.
    pub fn json<T: serde::de::DeserializeOwned>(file: &str, text: &str) -> Result<T, FileError> {
        serde_json::from_str(text).map_err(|e| FileError::new(file, json_reason(&e)))
    }
}

/// A JSON error as `line L column C: what`, its place said once (serde's
/// own message ends with the place too).
pub fn json_reason(e: &serde_json::Error) -> String {
    let message = e.to_string();
    let place = format!(" at line {} column {}", e.line(), e.column());
    let what = message.strip_suffix(&place).unwrap_or(&message);
    format!("line {} column {}: {what}", e.line(), e.column())
}
