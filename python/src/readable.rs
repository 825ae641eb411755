//! The `read(timeout)` / `latest` pair every sensor has, written once: `read` waits for a
//! reading newer than the last it returned, `latest` is the newest (or `None`) at once.

/// `readable!(Class, DataType, convert, Output, "what" { more methods })` adds `read` and
/// `latest` (and the methods in braces) to a `#[pyclass]` whose field `core` is a
/// `DeviceCore`; `convert(DataType) -> Output`.
macro_rules! readable {
    ($class:ident, $data:ty, $convert:expr, $output:ty, $what:literal { $($more:tt)* }) => {
        #[pyo3::pymethods]
        impl $class {
            #[doc = concat!("Waits for the next new ", $what, " (never the same one twice); ")]
            #[doc = "`TimeoutError` after `timeout` seconds (0: only look)."]
            #[pyo3(signature = (timeout = 1.0))]
            fn read(&self, py: pyo3::Python<'_>, timeout: f64) -> pyo3::PyResult<$output> {
                let limit = crate::waiting::timeout_arg(timeout, concat!($what, " read"))?;
                let (data, _) = self.core.next::<$data>(py, limit)?;
                Ok($convert(data))
            }

            #[doc = concat!("The newest ", $what, ", or `None` before the first.")]
            #[getter]
            fn latest(&self) -> Option<$output> {
                self.core.newest::<$data>().map(|(data, _)| $convert(data))
            }

            fn __repr__(&self) -> String {
                format!(
                    "<{} {} on {}>",
                    stringify!($class),
                    self.core.label,
                    self.core.link.place
                )
            }

            $($more)*
        }
    };
}

pub(crate) use readable;
