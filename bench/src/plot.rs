//! p99 latency and client CPU against N for both designs, as a PNG (plotters' bitmap backend;
//! the font comes from a crate, so no system fonts are needed).

use std::path::Path;
use std::sync::Once;

use plotters::prelude::*;

use crate::BenchError;
use crate::run::{Design, Measurement};

const FONT: &str = "sans-serif";
const DESIGNS: [(Design, RGBColor); 2] = [
    (Design::ThreadPerRobot, RGBColor(0, 114, 178)),
    (Design::SinglePoller, RGBColor(213, 94, 0)),
];

fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        if plotters::style::register_font(
            FONT,
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        )
        .is_err()
        {
            tracing::warn!("the plot font did not load; labels will be missing");
        }
    });
}

/// Draws two panels, p99 latency (log scale) and client CPU, with the targets.
pub fn draw(path: &Path, title: &str, results: &[Measurement]) -> Result<(), BenchError> {
    register_font();
    let fail = |why: String| BenchError::Plot {
        path: path.display().to_string(),
        why,
    };
    let (width, height) = (1200u32, 520u32);
    let mut pixels = vec![0u8; width as usize * height as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (width, height)).into_drawing_area();
        draw_on(root, title, results).map_err(fail)?;
    }
    image::save_buffer(path, &pixels, width, height, image::ExtendedColorType::Rgb8)
        .map_err(|e| fail(e.to_string()))
}

fn draw_on(
    root: DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    title: &str,
    results: &[Measurement],
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let root = root.titled(title, (FONT, 24)).map_err(|e| e.to_string())?;
    let (left, right) = root.split_horizontally(600);
    let p99_ms = |m: &Measurement| m.latency.map(|l| l.p99 * 1e3);
    panel(
        &left,
        "p99 latency, send to store (ms)",
        true,
        20.0,
        results,
        p99_ms,
    )?;
    panel(
        &right,
        "client-side CPU (cores)",
        false,
        1.0,
        results,
        |m| Some(m.client_cpu),
    )?;
    root.present().map_err(|e| e.to_string())
}

fn panel(
    area: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    what: &str,
    log_y: bool,
    target: f64,
    results: &[Measurement],
    value: impl Fn(&Measurement) -> Option<f64>,
) -> Result<(), String> {
    let max_n = results.iter().map(|m| m.robots).max().unwrap_or(256) as f64;
    let values: Vec<f64> = results.iter().filter_map(&value).collect();
    let top = values.iter().copied().fold(target, f64::max) * 1.5;
    let x_range = (2.0..max_n * 1.5).log_scale();
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(what, (FONT, 20))
        .margin(14)
        .x_label_area_size(44)
        .y_label_area_size(64);
    if log_y {
        let bottom = values.iter().copied().fold(target, f64::min).max(1e-3) / 2.0;
        let mut chart = builder
            .build_cartesian_2d(x_range, (bottom..top).log_scale())
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("robots (N)")
            .x_label_formatter(&|x| format!("{x:.0}"))
            .y_labels(14)
            .y_label_formatter(&|y| format!("{y:.1}"))
            .light_line_style(WHITE)
            .label_style((FONT, 15))
            .draw()
            .map_err(|e| e.to_string())?;
        series(&mut chart, results, &value, target, max_n)
    } else {
        let mut chart = builder
            .build_cartesian_2d(x_range, 0.0..top)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("robots (N)")
            .x_label_formatter(&|x| format!("{x:.0}"))
            .light_line_style(WHITE)
            .label_style((FONT, 15))
            .draw()
            .map_err(|e| e.to_string())?;
        series(&mut chart, results, &value, target, max_n)
    }
}

fn series<'a, Y>(
    chart: &mut ChartContext<
        'a,
        BitMapBackend<'a>,
        Cartesian2d<plotters::coord::combinators::LogCoord<f64>, Y>,
    >,
    results: &[Measurement],
    value: &impl Fn(&Measurement) -> Option<f64>,
    target: f64,
    max_n: f64,
) -> Result<(), String>
where
    Y: Ranged<ValueType = f64>,
{
    for (design, color) in DESIGNS {
        let points: Vec<(f64, f64)> = results
            .iter()
            .filter(|m| m.design == design)
            .filter_map(|m| value(m).map(|v| (m.robots as f64, v)))
            .collect();
        chart
            .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label(design.label())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        chart
            .draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled())))
            .map_err(|e| e.to_string())?;
    }
    let red = RGBColor(204, 0, 0);
    chart
        .draw_series(LineSeries::new(
            vec![(2.0, target), (max_n * 1.5, target)],
            red.stroke_width(2),
        ))
        .map_err(|e| e.to_string())?
        .label("target at 256 robots")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], red.stroke_width(2)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font((FONT, 15))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| e.to_string())
}
