//! Why a query's argument cannot be read: the answer names the element and the attribute, so
//! that whoever wrote the composition or script finds what to fix.

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ArgumentError {
    #[error("<{element}> has no {attribute} attribute")]
    Missing { element: String, attribute: String },
    #[error("{attribute}={text:?} of <{element}> is not a number")]
    NotANumber {
        element: String,
        attribute: String,
        text: String,
    },
}
