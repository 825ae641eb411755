//! Reading a filter chain from a plugin's parameters, one element per kernel, in order:
//!
//! ```xml
//! <filter radius="2">blur</filter>
//! <filter>sobel</filter>
//! <filter file="kernels/emboss.glsl" strength="1.5"/>
//! ```
//!
//! A built-in is named by the element's text (see [`BUILTIN_NAMES`]); `radius` (blur, erode,
//! dilate) and `amount` (sharpen) are its parameters. A `file` is GLSL source, relative to the
//! composition, read here; its other attributes are the values of its `uniform float`s. The
//! source is compiled only by the renderer, which reports a kernel that does not compile.

use std::sync::Arc;

use crate::config::{ConfigValueError, Param, PluginConfig};

use super::filter::{BUILTIN_NAMES, FilterChain, GlslKernel, Kernel, MAX_KERNEL_RADIUS};

/// The largest GLSL kernel file read: far above any kernel, far below harm.
pub const MAX_KERNEL_SOURCE_BYTES: u64 = 256 * 1024;

/// The chain the `element` parameters of `config` describe (none: an empty chain). A radius
/// is in the plugin's own unit, which `to_pixels` turns into pixels (rounded up, so that a
/// robot's configuration space is never smaller than the robot).
pub fn read_filter_chain(
    config: &PluginConfig,
    element: &str,
    to_pixels: impl Fn(f64) -> f64,
) -> Result<FilterChain, ConfigValueError> {
    let mut kernels = Vec::new();
    for param in config.params.iter().filter(|p| p.name == element) {
        kernels.push(read_kernel(config, param, &to_pixels)?);
    }
    Ok(FilterChain(kernels))
}

fn read_kernel(
    config: &PluginConfig,
    param: &Param,
    to_pixels: &impl Fn(f64) -> f64,
) -> Result<Kernel, ConfigValueError> {
    let fail = |message: String| ConfigValueError {
        origin: if param.origin.is_empty() {
            config.origin.clone()
        } else {
            param.origin.clone()
        },
        library: config.library.clone(),
        param: param.name.clone(),
        message,
    };
    let number = |name: &str| -> Result<Option<f64>, ConfigValueError> {
        param
            .attr(name)
            .map(|text| {
                text.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| fail(format!("{name}=\"{text}\" is not a number")))
            })
            .transpose()
    };
    if let Some(file) = param.attr("file") {
        let path = config.base_dir.join(file);
        let source = read_source(&path).map_err(|e| fail(format!("{}: {e}", path.display())))?;
        let mut params = Vec::new();
        for (name, _) in param.attributes.iter().filter(|(n, _)| n != "file") {
            let value = number(name)?.expect("the attribute is there");
            params.push((name.clone(), value as f32));
        }
        return Ok(Kernel::Glsl(GlslKernel {
            name: path.display().to_string(),
            source: Arc::from(source),
            params,
        }));
    }
    let name = param.text.trim();
    let mut kernel = Kernel::builtin(name).ok_or_else(|| {
        fail(format!(
            "{name:?} is not a kernel: expected one of {} or a file=\"….glsl\"",
            BUILTIN_NAMES.join(", ")
        ))
    })?;
    if let Some(radius) = number("radius")? {
        let pixels = to_pixels(radius).ceil();
        let slot = kernel
            .radius_mut()
            .ok_or_else(|| fail(format!("{name} has no radius")))?;
        if !(0.0..=f64::from(MAX_KERNEL_RADIUS)).contains(&pixels) {
            return Err(fail(format!(
                "radius {radius} is {pixels} pixels, outside 0..={MAX_KERNEL_RADIUS}"
            )));
        }
        *slot = pixels as u32;
    }
    if let Some(amount) = number("amount")? {
        match &mut kernel {
            Kernel::Sharpen { amount: a } => *a = amount as f32,
            _ => return Err(fail(format!("{name} has no amount"))),
        }
    }
    Ok(kernel)
}

/// Why a kernel's source file is not read.
#[derive(Debug, thiserror::Error)]
enum SourceError {
    #[error(transparent)]
    Io(#[from] std::io::Error),
    #[error("{0} bytes, above the {MAX_KERNEL_SOURCE_BYTES}-byte limit for a kernel")]
    TooLarge(u64),
}

fn read_source(path: &std::path::Path) -> Result<String, SourceError> {
    let size = std::fs::metadata(path)?.len();
    if size > MAX_KERNEL_SOURCE_BYTES {
        return Err(SourceError::TooLarge(size));
    }
    Ok(std::fs::read_to_string(path)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn filter(text: &str, attributes: &[(&str, &str)]) -> Param {
        Param {
            attributes: attributes
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            origin: "k.xml:7:3".into(),
            ..Param::new("filter", text)
        }
    }

    fn config(params: Vec<Param>, base_dir: &std::path::Path) -> PluginConfig {
        PluginConfig {
            library: "libpv3d_image".into(),
            params,
            base_dir: base_dir.to_path_buf(),
            ..PluginConfig::default()
        }
    }

    #[test]
    fn built_ins_take_their_parameters_in_order() {
        let c = config(
            vec![
                filter("dilate", &[("radius", "0.3")]),
                filter("sharpen", &[("amount", "2")]),
                filter(" sobel ", &[]),
            ],
            std::path::Path::new("."),
        );
        // Radius in metres, 0.05 m cells: 6 cells, rounded up never down.
        let chain = read_filter_chain(&c, "filter", |m| m / 0.05).unwrap();
        assert_eq!(
            chain.0,
            [
                Kernel::Dilate { radius: 6 },
                Kernel::Sharpen { amount: 2.0 },
                Kernel::SobelEdges
            ]
        );
        let none = read_filter_chain(&config(vec![], std::path::Path::new(".")), "filter", |r| r);
        assert!(none.unwrap().is_empty());
    }

    #[test]
    fn bad_filters_say_what_and_where() {
        let dir = std::path::Path::new(".");
        let cases = [
            (filter("emboss", &[]), "not a kernel"),
            (filter("blur", &[("radius", "wide")]), "not a number"),
            (filter("blur", &[("radius", "1000")]), "outside 0..=64"),
            (filter("sobel", &[("radius", "2")]), "sobel has no radius"),
            (filter("blur", &[("amount", "2")]), "blur has no amount"),
            (filter("", &[("file", "missing.glsl")]), "missing.glsl"),
        ];
        for (param, expected) in cases {
            let err = read_filter_chain(&config(vec![param], dir), "filter", |r| r)
                .unwrap_err()
                .to_string();
            assert!(
                err.starts_with("k.xml:7:3: <filter> of libpv3d_image"),
                "{err}"
            );
            assert!(err.contains(expected), "{err} should say {expected}");
        }
    }

    #[test]
    fn a_glsl_file_is_read_with_its_parameters() {
        let dir = std::env::temp_dir().join(format!("pv3d-filter-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let source =
            "uniform float gain;\nvec4 filter_pixel(ivec2 at) { return pixel(at) * gain; }\n";
        std::fs::write(dir.join("gain.glsl"), source).unwrap();
        let c = config(
            vec![filter("", &[("file", "gain.glsl"), ("gain", "1.5")])],
            &dir,
        );
        let chain = read_filter_chain(&c, "filter", |r| r).unwrap();
        let Kernel::Glsl(kernel) = &chain.0[0] else {
            panic!("{chain:?}");
        };
        assert_eq!(&*kernel.source, source);
        assert_eq!(kernel.params, [("gain".to_string(), 1.5)]);
        assert!(kernel.name.ends_with("gain.glsl"));
        let bad = config(
            vec![filter("", &[("file", "gain.glsl"), ("gain", "x")])],
            &dir,
        );
        assert!(read_filter_chain(&bad, "filter", |r| r).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
