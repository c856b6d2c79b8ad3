//! SVG plots (plotters, SVG backend only) of the contact tractions against the closed forms.
//!
//! One file per example; one column of panels per run (e.g. per modulus ratio); the top row is
//! the pressure `p / p0` against Hertz, the bottom row (frictional runs only) the shear `q / p0`
//! against Cattaneo-Mindlin (which is `mu p` in full slip). `x` is in target half-widths `a`,
//! `p0` is the Hertz peak of the run's last increment. Lines are the closed forms at each
//! increment's measured load and centre, dots the nodal multipliers; colours go from blue (first
//! increment) to red (last).
//! The axisymmetric and 3D examples put the distance `r` from the axis on `x`.

use super::{ReportError, Result, write_file};
use crate::examples::{ClosedForm, Example, Increment, NodeRow, Phase, Run};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use std::path::Path;

type Plot<T> = std::result::Result<T, Box<dyn std::error::Error>>;

/// Pixels per panel.
const PANEL: (u32, u32) = (560, 400);
const FONT: &str = "sans-serif";

/// Write the plot of `example` to `path`.
pub fn write(path: &Path, example: &Example) -> Result<()> {
    let text = to_string(example).map_err(|e| ReportError::Plot {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    write_file(path, text.as_bytes())
}

/// The SVG text of the plot of `example`.
pub fn to_string(example: &Example) -> Plot<String> {
    let shear = example.runs.iter().any(|r| r.setup.friction > 0.0);
    let rows = if shear { 2 } else { 1 };
    let cols = example.runs.len().max(1);
    let size = (PANEL.0 * cols as u32, PANEL.1 * rows as u32 + 30);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        // the naive font metrics (no font files) take a character as about 0.55 em
        let fit = f64::from(size.0) / (0.55 * example.title.len().max(1) as f64);
        let root = root.titled(&example.title, (FONT, fit.clamp(8.0, 16.0)))?;
        let panels = root.split_evenly((rows, cols));
        for (c, run) in example.runs.iter().enumerate() {
            pressure_panel(&panels[c], run)?;
            if shear {
                shear_panel(&panels[cols + c], run)?;
            }
        }
        root.present()?;
    }
    Ok(svg)
}

fn colour(k: usize, n: usize) -> HSLColor {
    let t = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        1.0
    };
    HSLColor(0.66 * (1.0 - t), 0.85, 0.42)
}

fn label(inc: &Increment, a: f64) -> String {
    match inc.phase {
        Phase::Press => format!("{}: press {:.3e}", inc.number, inc.approach),
        Phase::Slide => format!("{}: slide {:.4} a", inc.number, inc.slide / a),
    }
}

/// Scales of a run: target half-width, reference peak, and the plotted x range (in `a`).
fn scales(run: &Run) -> (f64, f64, (f64, f64)) {
    let a = run.setup.target_half_width;
    let p0 = run
        .increments
        .last()
        .map_or(1.0, |i| i.hertz.peak)
        .max(f64::MIN_POSITIVE);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut all_lo, mut all_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for inc in &run.increments {
        let cf = &inc.closed_form;
        lo = lo.min(cf.centre - cf.half_width);
        hi = hi.max(cf.centre + cf.half_width);
        for n in &inc.nodes {
            all_lo = all_lo.min(n.x);
            all_hi = all_hi.max(n.x);
            if n.p > 0.0 {
                lo = lo.min(n.x);
                hi = hi.max(n.x);
            }
        }
    }
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        (lo, hi) = (-a, a);
    }
    let margin = 0.5 * a;
    let x0 = (lo - margin).max(all_lo);
    let x1 = (hi + margin).min(all_hi);
    (a, p0, (x0 / a, x1 / a))
}

fn samples((x0, x1): (f64, f64), a: f64) -> impl Iterator<Item = f64> + Clone {
    (0..=400).map(move |i| a * (x0 + (x1 - x0) * i as f64 / 400.0))
}

fn pressure_panel(area: &DrawingArea<SVGBackend<'_>, Shift>, run: &Run) -> Plot<()> {
    let (a, p0, range) = scales(run);
    let mut y1: f64 = 0.0;
    for inc in &run.increments {
        for n in &inc.nodes {
            y1 = y1.max(n.p / p0).max(n.p_exact / p0);
        }
    }
    let y1 = 1.15 * y1.max(1e-12);
    let mut chart = panel(
        area,
        format!("{}: pressure (lines Hertz, dots FE)", run.label),
        range,
        0.0..y1,
        "p / p0",
    )?;
    draw_increments(
        &mut chart,
        run,
        |cf, x| cf.pressure(x),
        |p| p.p,
        |inc| label(inc, a),
    )?;
    draw_legend(&mut chart)?;
    Ok(())
}

fn shear_panel(area: &DrawingArea<SVGBackend<'_>, Shift>, run: &Run) -> Plot<()> {
    let (a, p0, range) = scales(run);
    let mu = run.setup.friction;
    let (mut y0, mut y1): (f64, f64) = (0.0, 0.0);
    for (k, inc) in run.increments.iter().enumerate() {
        // the slip bound is drawn for the last increment only
        let bound = if k + 1 == run.increments.len() {
            mu * inc.closed_form.sign
        } else {
            0.0
        };
        for n in &inc.nodes {
            for v in [n.q, n.q_exact, bound * n.p_exact] {
                y0 = y0.min(v / p0);
                y1 = y1.max(v / p0);
            }
        }
    }
    let span = (y1 - y0).max(1e-12);
    let mut chart = panel(
        area,
        format!(
            "{}: shear (lines Cattaneo-Mindlin / mu p, dots FE)",
            run.label
        ),
        range,
        (y0 - 0.05 * span)..(y1 + 0.2 * span),
        "q / p0",
    )?;
    if let Some(last) = run.increments.last().filter(|_| mu > 0.0) {
        let cf = last.closed_form;
        chart
            .draw_series(DashedLineSeries::new(
                samples(range, a).map(|x| (x / a, cf.sign * mu * cf.pressure(x) / p0)),
                4,
                3,
                BLACK.mix(0.5).stroke_width(1),
            ))?
            .label(format!("mu p (slip bound), increment {}", last.number))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLACK.mix(0.5)));
    }
    draw_increments(
        &mut chart,
        run,
        |cf, x| cf.shear(x),
        |p| p.q,
        |inc| match inc.q_over_mu_p {
            Some(r) => format!("{}, Q/muP {r:.2}", label(inc, a)),
            None => label(inc, a),
        },
    )?;
    draw_legend(&mut chart)?;
    Ok(())
}

/// An empty panel: caption, axes over `range` (in `a`) and `y`, mesh and labels.
fn panel<'a, 'b>(
    area: &'a DrawingArea<SVGBackend<'b>, Shift>,
    caption: String,
    range: (f64, f64),
    y: std::ops::Range<f64>,
    y_desc: &str,
) -> Plot<Chart<'a, 'b>> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 14))
        .margin(8)
        .x_label_area_size(36)
        .y_label_area_size(52)
        .build_cartesian_2d(range.0..range.1, y)?;
    chart
        .configure_mesh()
        .x_desc("x / a")
        .y_desc(y_desc)
        .label_style((FONT, 12))
        .draw()?;
    Ok(chart)
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Per increment of `run`, in its colour: the closed form `closed(cf, x)` as a line (labelled
/// `name(increment)`) and the nodal values `value(node)` as dots, both divided by `p0`.
fn draw_increments(
    chart: &mut Chart<'_, '_>,
    run: &Run,
    closed: impl Fn(&ClosedForm, f64) -> f64,
    value: impl Fn(&NodeRow) -> f64,
    name: impl Fn(&Increment) -> String,
) -> Plot<()> {
    let (a, p0, range) = scales(run);
    let n = run.increments.len();
    for (k, inc) in run.increments.iter().enumerate() {
        let c = colour(k, n);
        let cf = inc.closed_form;
        chart
            .draw_series(LineSeries::new(
                samples(range, a).map(|x| (x / a, closed(&cf, x) / p0)),
                c.stroke_width(1),
            ))?
            .label(name(inc))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2)));
        chart.draw_series(
            inc.nodes
                .iter()
                .filter(|p| (range.0..=range.1).contains(&(p.x / a)))
                .map(|p| Circle::new((p.x / a, value(p) / p0), 2, c.filled())),
        )?;
    }
    Ok(())
}

/// The legend box in the upper right corner.
fn draw_legend<'a, 'b: 'a>(chart: &mut Chart<'a, 'b>) -> Plot<()> {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .label_font((FONT, 10))
        .draw()?;
    Ok(())
}
