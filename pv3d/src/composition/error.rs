//! Configuration errors: every one names file:line:column and what was expected there.

use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;

/// A place in a configuration file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SourcePos {
    pub file: Arc<PathBuf>,
    /// 1-based.
    pub line: usize,
    /// 1-based, in bytes.
    pub col: usize,
}

impl SourcePos {
    /// A position for elements made by the program rather than read from a file.
    pub fn generated() -> SourcePos {
        SourcePos {
            file: Arc::new(PathBuf::from("<generated>")),
            line: 1,
            col: 1,
        }
    }
}

impl fmt::Display for SourcePos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file.display(), self.line, self.col)
    }
}

/// Why a composition could not be loaded.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConfigError {
    #[error("{}: cannot read: {message}", path.display())]
    Io { path: PathBuf, message: String },
    #[error("{pos}: {message}")]
    At { pos: SourcePos, message: String },
}

impl ConfigError {
    pub fn at(pos: SourcePos, message: impl Into<String>) -> ConfigError {
        ConfigError::At {
            pos,
            message: message.into(),
        }
    }

    /// Where the error is, when it is inside a file.
    pub fn pos(&self) -> Option<&SourcePos> {
        match self {
            ConfigError::At { pos, .. } => Some(pos),
            ConfigError::Io { .. } => None,
        }
    }
}
