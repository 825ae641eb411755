//! Reading Stage 4 world files and Player 3 config files, which share one syntax.

pub mod lexer;
pub mod parser;

pub use parser::{Block, Item, Pos, Property, Value};

/// A syntax error or an unreadable file, with file:line:col.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{file}:{line}:{col}: {message}")]
pub struct WorldFileError {
    pub file: String,
    pub line: usize,
    pub col: usize,
    pub message: String,
}

impl WorldFileError {
    pub fn at(file: &str, line: usize, col: usize, message: impl Into<String>) -> WorldFileError {
        WorldFileError {
            file: file.to_string(),
            line,
            col,
            message: message.into(),
        }
    }
}

/// Tokenizes and parses a file's text.
pub fn parse_text(text: &str, file: &str) -> Result<Vec<Item>, WorldFileError> {
    parser::parse(&lexer::tokenize(text, file)?, file)
}
