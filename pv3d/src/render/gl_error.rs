//! Why an OpenGL object could not be made: the driver's refusal (glow reports it as text), a
//! shader that does not compile (with its stage and the driver's log), a program that does not
//! link, or a framebuffer the driver calls incomplete. One type for every GL setup path, so
//! the renderer, the pictures and the kernels say alike which step failed. The renderer's own
//! error is here as well, so that its parts (the fill layer) return it without using the
//! renderer.

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum GlError {
    #[error("the driver made no object: {0}")]
    Driver(String),
    #[error("{stage}: {log}")]
    Compile { stage: &'static str, log: String },
    #[error("link: {0}")]
    Link(String),
    #[error("{what} {width}×{height} incomplete (status 0x{status:x})")]
    Incomplete {
        what: &'static str,
        width: u32,
        height: u32,
        status: u32,
    },
}

/// Why the renderer could not be created.
#[derive(Debug, thiserror::Error)]
#[error("OpenGL setup failed: {0}")]
pub struct RendererError(#[from] pub GlError);

/// glow's object constructors report failure as the driver's text.
impl From<String> for GlError {
    fn from(text: String) -> GlError {
        GlError::Driver(text)
    }
}
