//! The report's plots, drawn by plotters as SVG text. Each function gives
//! one `<svg>` element; a plot that cannot be drawn gives a paragraph
//! saying so instead. Non-finite values are left out; empty data gives
//! empty axes.

use super::{BenchReport, MethodResult, ObjectsPoint, SweepPoint};
use plotters::coord::Shift;
use plotters::coord::combinators::LogCoord;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
pub(super) type Drawn = Result<(), Box<dyn std::error::Error>>;
type Chart<'a, X, Y> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<X, Y>>;

const FONT: &str = "sans-serif";
const BLUE: RGBColor = RGBColor(31, 119, 180);
const ORANGE: RGBColor = RGBColor(255, 127, 14);
const GREEN: RGBColor = RGBColor(44, 160, 44);
const RED: RGBColor = RGBColor(214, 39, 40);
const PURPLE: RGBColor = RGBColor(148, 103, 189);
const GREY: RGBColor = RGBColor(127, 127, 127);
const BROWN: RGBColor = RGBColor(140, 86, 75);
/// Line colours, in order.
pub(super) const PALETTE: [RGBColor; 6] = [BLUE, ORANGE, GREEN, RED, PURPLE, BROWN];
/// The three parts of a step: interaction layer, rapier, full step.
const PARTS: [(&str, RGBColor); 3] =
    [("interaction layer", BLUE), ("rapier step", ORANGE), ("full step", GREEN)];

/// Draws with `draw` on a `size` SVG canvas; the SVG text, or a paragraph
/// with the error.
pub(super) fn svg(size: (u32, u32), draw: impl FnOnce(&Area) -> Drawn) -> String {
    let mut text = String::new();
    let drawn = {
        let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
        root.fill(&WHITE).map_err(Into::into).and_then(|()| draw(&root)).and_then(|()| {
            root.present()?;
            Ok(())
        })
    };
    match drawn {
        Ok(()) => text,
        Err(e) => format!(
            "<p class=\"error\">The plot could not be drawn: {}</p>",
            super::markup::escape(&e.to_string())
        ),
    }
}

/// Values beyond this size are left out of plots (their axes would
/// overflow).
const LARGEST: f64 = 1e12;

/// Whether `v` is finite and at most [`LARGEST`] in size.
pub(super) fn plottable(v: f64) -> bool {
    v.abs() <= LARGEST
}

/// The [`plottable`] values among `values`.
pub(super) fn finite(values: impl IntoIterator<Item = f64>) -> Vec<f64> {
    values.into_iter().filter(|v| plottable(*v)).collect()
}

/// `0` to a little above the largest of `values` (at least `floor`).
pub(super) fn up_to_max(values: &[f64], floor: f64) -> std::ops::Range<f64> {
    let max = values.iter().copied().fold(floor, f64::max);
    0.0..max * 1.08
}

/// A log axis over the positive `values`, from a power of ten below them
/// to a little above, about five decades at most.
fn log_span(values: &[f64]) -> std::ops::Range<f64> {
    let positive = values.iter().copied().filter(|v| *v > 0.0 && *v <= LARGEST);
    let (lo, hi) = positive.fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    // plotters labels a log axis from its first power of ten up: start at one.
    let decade = |v: f64| 10f64.powf(v.log10().floor());
    if hi > 0.0 { decade((lo / 1.2).max(hi * 1e-5))..hi * 1.6 } else { 1.0..1000.0 }
}

/// The `p`-quantile (0..=1) of sorted `s`, linearly interpolated; NaN
/// if `s` is empty.
pub(crate) fn quantile(s: &[f64], p: f64) -> f64 {
    let rank = p * (s.len().saturating_sub(1)) as f64;
    let (i, frac) = (rank.floor() as usize, rank.fract());
    let lo = s.get(i).copied().unwrap_or(f64::NAN);
    lo + (s.get(i + 1).copied().unwrap_or(lo) - lo) * frac
}

/// A tick label: up to three decimals, without trailing zeros.
pub(super) fn tick(v: &f64) -> String {
    let text = format!("{v:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" { "0".into() } else { text.into() }
}

/// The label of a category axis at `x`: the name of category `x` where
/// `x` is its index, else nothing.
fn category(names: &[&str], x: f64) -> String {
    let i = x.round();
    let name = names.get(i as usize).filter(|_| (x - i).abs() < 1e-6 && i >= 0.0);
    name.map_or(String::new(), |n| n.to_string())
}

/// Text in the plots' font.
pub(super) fn font(size: u32) -> TextStyle<'static> {
    (FONT, size).into_font().into()
}

/// A chart on `area` with a caption and room for axis labels.
pub(super) fn chart<'a, X: AsRangedCoord, Y: AsRangedCoord>(
    area: &Area<'a>,
    caption: &str,
    x: X,
    y: Y,
) -> Result<Chart<'a, X::CoordDescType, Y::CoordDescType>, Box<dyn std::error::Error>> {
    let chart = ChartBuilder::on(area)
        .caption(caption, font(17))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(x, y)?;
    Ok(chart)
}

/// A polyline, with round markers or dashed if asked, labelled for the
/// legend.
pub(super) struct Line<'l> {
    pub(super) label: &'l str,
    pub(super) color: RGBColor,
    pub(super) points: Vec<(f64, f64)>,
    pub(super) markers: bool,
    pub(super) dashed: bool,
}

/// One plain line per `(label, points)`, in palette order.
pub(super) fn palette_lines<'l>(
    series: impl Iterator<Item = (&'l str, Vec<(f64, f64)>)>,
) -> Vec<Line<'l>> {
    let line = |(k, (label, points))| {
        let color = PALETTE[k % PALETTE.len()];
        Line { label, color, points, markers: false, dashed: false }
    };
    series.enumerate().map(line).collect()
}

/// Draws `lines`, labelled for the legend, on `chart`.
pub(super) fn draw_lines<'a, X, Y>(chart: &mut Chart<'a, X, Y>, lines: &[Line]) -> Drawn
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    for l in lines {
        let style = l.color.stroke_width(2);
        let points = l.points.iter().copied();
        if l.dashed {
            chart.draw_series(DashedLineSeries::new(points, 7, 4, style))?.label(l.label).legend(
                move |(x, y)| {
                    plotters::element::DashedPathElement::new(
                        vec![(x, y), (x + 18, y)],
                        5,
                        3,
                        style,
                    )
                },
            );
        } else {
            chart
                .draw_series(LineSeries::new(points, style))?
                .label(l.label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
        }
        if l.markers {
            chart.draw_series(l.points.iter().map(|&p| Circle::new(p, 3, l.color.filled())))?;
        }
    }
    Ok(())
}

/// The legend of `chart`'s labelled series.
pub(super) fn legend_box<'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, SVGBackend<'a>, CT>,
    position: SeriesLabelPosition,
) -> Drawn {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .draw()?;
    Ok(())
}

/// Placement error per method: each method's trials as dots beside a box
/// (quartiles, median, whiskers to the farthest trial within 1.5 IQR),
/// and the thesis's mean ± sd and median beside it where it has them.
/// `thesis` is `(method, mean, sd, median)` in mm.
pub(super) fn placement(methods: &[MethodResult], thesis: &[(String, f64, f64, f64)]) -> String {
    let labels: Vec<String> = methods.iter().map(MethodResult::label).collect();
    let mut names: Vec<&str> = labels.iter().map(String::as_str).collect();
    names.extend(
        thesis.iter().map(|t| t.0.as_str()).filter(|t| !methods.iter().any(|m| m.method == *t)),
    );
    let errors: Vec<Vec<f64>> =
        methods.iter().map(|m| sorted(finite(m.errors_mm.iter().copied()))).collect();
    let thesis_ys = thesis.iter().flat_map(|t| [t.1 - t.2, t.1 + t.2, t.3]);
    let span = log_span(&finite(errors.iter().flatten().copied().chain(thesis_ys)));
    let floor = span.start;
    let n = names.len().max(1) as f64;
    svg((760, 420), |root| {
        let title = "Placement error per method (log scale)";
        let mut chart = chart(root, title, -0.6..n - 0.4, span.log_scale())?;
        let label = |x: &f64| category(&names, *x);
        chart
            .configure_mesh()
            .max_light_lines(2)
            .disable_x_mesh()
            .x_labels(names.len() + 1)
            .x_label_formatter(&label)
            .y_desc("placement error (mm)")
            .y_label_formatter(&tick)
            .label_style(font(14))
            .draw()?;
        for (i, e) in errors.iter().enumerate() {
            draw_box(&mut chart, i as f64 - 0.17, e, floor)?;
        }
        for (method, mean, sd, median) in thesis {
            // Beside the method's first row, or its own column.
            let row = methods.iter().position(|m| m.method == *method);
            let Some(i) = row.or_else(|| names.iter().position(|n| n == method)) else { continue };
            if ![mean, sd, median].iter().all(|v| plottable(**v)) {
                continue;
            }
            let x = i as f64 + 0.17;
            let style = RED.stroke_width(2);
            let (lo, hi) = ((mean - sd).max(floor), (mean + sd).max(floor));
            let (mean, median) = (&mean.max(floor), &median.max(floor));
            let mut paths = vec![vec![(x, lo), (x, hi)], vec![(x - 0.05, lo), (x + 0.05, lo)]];
            paths.extend([
                vec![(x - 0.05, hi), (x + 0.05, hi)],
                vec![(x - 0.09, *median), (x + 0.09, *median)],
            ]);
            chart.draw_series(paths.into_iter().map(|p| PathElement::new(p, style)))?;
            chart.draw_series([Circle::new((x, *mean), 5, RED.filled())])?;
        }
        Ok(())
    })
}

fn sorted(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v
}

/// One box of a box plot at `x` over sorted finite `s`, with its points,
/// on a log axis whose bottom is `floor` (smaller values are drawn there).
fn draw_box<'a>(
    chart: &mut Chart<'a, RangedCoordf64, LogCoord<f64>>,
    x: f64,
    s: &[f64],
    floor: f64,
) -> Drawn {
    if s.is_empty() {
        return Ok(());
    }
    let (q1, median, q3) = (quantile(s, 0.25), quantile(s, 0.5), quantile(s, 0.75));
    let iqr = q3 - q1;
    let low = s.iter().copied().find(|v| *v >= q1 - 1.5 * iqr).unwrap_or(q1);
    let high = s.iter().rev().copied().find(|v| *v <= q3 + 1.5 * iqr).unwrap_or(q3);
    let [q1, median, q3, low, high] = [q1, median, q3, low, high].map(|v| v.max(floor));
    let w = 0.13;
    chart.draw_series([Rectangle::new([(x - w, q1), (x + w, q3)], BLUE.mix(0.15).filled())])?;
    let style = BLUE.stroke_width(2);
    let paths = [
        vec![(x - w, q1), (x + w, q1), (x + w, q3), (x - w, q3), (x - w, q1)],
        vec![(x - w, median), (x + w, median)],
        vec![(x, q3), (x, high)],
        vec![(x, q1), (x, low)],
        vec![(x - w / 2.0, high), (x + w / 2.0, high)],
        vec![(x - w / 2.0, low), (x + w / 2.0, low)],
    ];
    chart.draw_series(paths.into_iter().map(|p| PathElement::new(p, style)))?;
    // A fixed spread across the box, so the dots do not sit on one line.
    let spread = |k: usize| ((k * 37) % 23) as f64 / 22.0 - 0.5;
    let dots = s.iter().enumerate().map(|(k, &v)| (x + 1.6 * w * spread(k), v.max(floor)));
    chart.draw_series(dots.map(|p| Circle::new(p, 2, BLACK.mix(0.45).filled())))?;
    Ok(())
}

/// The sweep's three parts as lines against bones in contact.
fn sweep_lines(sweep: &[SweepPoint]) -> Vec<Line<'static>> {
    let mut points: Vec<&SweepPoint> = sweep.iter().collect();
    points.sort_by_key(|p| (p.bones, p.hands));
    part_lines(points.iter().map(|p| (p.bones as f64, &p.times)))
}

/// A step's three parts as lines through `(x, times)`, in that order.
fn part_lines<'t>(
    points: impl Iterator<Item = (f64, &'t super::StepTimes)> + Clone,
) -> Vec<Line<'static>> {
    PARTS
        .iter()
        .enumerate()
        .map(|(i, &(label, color))| {
            let xy = points.clone().map(|(x, t)| (x, parts(t)[i].0));
            let points = xy.filter(|(_, y)| plottable(*y)).collect();
            Line { label, color, points, markers: true, dashed: false }
        })
        .collect()
}

/// Step time against objects in the scene (`bench --objects`), the same 32
/// bones pressing throughout.
pub(super) fn step_time_objects(objects: &[ObjectsPoint]) -> String {
    let mut points: Vec<&ObjectsPoint> = objects.iter().collect();
    points.sort_by_key(|p| p.objects);
    let lines = part_lines(points.iter().map(|p| (p.objects as f64, &p.times)));
    let ys = finite(lines.iter().flat_map(|l| l.points.iter().map(|p| p.1)));
    let xs = finite(objects.iter().map(|p| p.objects as f64));
    svg((560, 400), |root| {
        let title = "Step time against objects in the scene";
        let mut chart = chart(root, title, up_to_max(&xs, 100.0), up_to_max(&ys, 1.0))?;
        chart
            .configure_mesh()
            .max_light_lines(2)
            .x_desc("objects in the scene (32 bones pressing)")
            .x_label_formatter(&tick)
            .y_desc("time per step (µs)")
            .y_label_formatter(&tick)
            .label_style(font(14))
            .draw()?;
        draw_lines(&mut chart, &lines)?;
        legend_box(&mut chart, SeriesLabelPosition::UpperLeft)
    })
}

/// The axes of step time (µs) against bones in contact.
fn bones_axes<'a, Y>(chart: &mut Chart<'a, RangedCoordf64, Y>) -> Drawn
where
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    chart
        .configure_mesh()
        .max_light_lines(2)
        .x_desc("bones in contact")
        .x_label_formatter(&tick)
        .y_desc("time per step (µs)")
        .y_label_formatter(&tick)
        .label_style(font(14))
        .draw()?;
    Ok(())
}

/// Step time against bones in contact, linear axes (ours only).
pub(super) fn step_time_linear(sweep: &[SweepPoint]) -> String {
    let lines = sweep_lines(sweep);
    let ys = finite(lines.iter().flat_map(|l| l.points.iter().map(|p| p.1)));
    let xs = finite(sweep.iter().map(|p| p.bones as f64));
    svg((560, 400), |root| {
        let title = "Step time against bones in contact";
        let mut chart = chart(root, title, up_to_max(&xs, 8.0), up_to_max(&ys, 1.0))?;
        bones_axes(&mut chart)?;
        draw_lines(&mut chart, &lines)?;
        legend_box(&mut chart, SeriesLabelPosition::UpperLeft)
    })
}

/// Step time against bones in contact on a log axis, with the thesis's
/// Fig. 5.6 points and MuJoCo's step on the reference scene.
pub(super) fn step_time_log(bench: &BenchReport) -> String {
    let lines = sweep_lines(&bench.sweep);
    let thesis: Vec<(f64, f64)> =
        super::THESIS_FIG_5_6.iter().map(|&(b, us)| (b as f64, us)).collect();
    let mujoco = bench
        .mujoco
        .as_ref()
        .map(|m| (bench.reference.bones_pressing as f64, m.step_us))
        .filter(|p| p.1 > 0.0 && plottable(p.1));
    let all = lines.iter().flat_map(|l| l.points.iter()).chain(&thesis).chain(&mujoco);
    let ys = finite(all.clone().map(|p| p.1));
    let xs = finite(all.map(|p| p.0));
    svg((560, 400), |root| {
        let title = "… beside the thesis and MuJoCo (log scale)";
        let mut chart = chart(root, title, up_to_max(&xs, 8.0), log_span(&ys).log_scale())?;
        bones_axes(&mut chart)?;
        let positive = |l: &Line| l.points.iter().copied().filter(|p| p.1 > 0.0).collect();
        let lines: Vec<Line> = lines.iter().map(|l| Line { points: positive(l), ..*l }).collect();
        draw_lines(&mut chart, &lines)?;
        let square = |&(x, y): &(f64, f64)| {
            EmptyElement::at((x, y)) + Rectangle::new([(-5, -5), (5, 5)], RED.filled())
        };
        chart
            .draw_series(thesis.iter().map(square))?
            .label("thesis Fig. 5.6 (total physics)")
            .legend(|(x, y)| Rectangle::new([(x + 4, y - 5), (x + 14, y + 5)], RED.filled()));
        if let Some(m) = mujoco {
            let triangle = |(x, y): (f64, f64)| TriangleMarker::new((x, y), 7, GREY.filled());
            chart
                .draw_series([triangle(m)])?
                .label("MuJoCo, reference scene")
                .legend(move |(x, y)| TriangleMarker::new((x + 9, y), 7, GREY.filled()));
        }
        legend_box(&mut chart, SeriesLabelPosition::UpperRight)
    })
}

/// The reference scene's step, asleep, awake and in its first second,
/// beside MuJoCo's, as bars on a log axis.
pub(super) fn reference_bars(bench: &BenchReport) -> String {
    let r = &bench.reference;
    let mut groups: Vec<(&str, Vec<(f64, RGBColor)>)> = vec![
        ("tower asleep", parts(&r.asleep)),
        ("tower awake", parts(&r.awake)),
        ("first second", vec![(r.settling_us, GREEN)]),
    ];
    if let Some(m) = &bench.mujoco {
        groups.push(("MuJoCo", vec![(m.step_us, GREY)]));
    }
    let ys = finite(groups.iter().flat_map(|g| g.1.iter().map(|b| b.0)));
    let span = log_span(&ys);
    let base = span.start;
    let n = groups.len() as f64;
    svg((560, 400), |root| {
        let title = "Reference scene: time per step";
        let mut chart = chart(root, title, -0.6..n - 0.4, span.log_scale())?;
        let names: Vec<&str> = groups.iter().map(|g| g.0).collect();
        let label = |x: &f64| category(&names, *x);
        chart
            .configure_mesh()
            .max_light_lines(2)
            .disable_x_mesh()
            .x_labels(groups.len() + 1)
            .x_label_formatter(&label)
            .y_desc("time per step (µs)")
            // Powers of ten only: plotters crowds the labels between them.
            .y_labels(3)
            .y_label_formatter(&tick)
            .label_style(font(14))
            .draw()?;
        let w = 0.8 / 3.0;
        for (i, (_, bars)) in groups.iter().enumerate() {
            let left = i as f64 - 0.5 * w * bars.len() as f64;
            for (k, &(v, color)) in bars.iter().enumerate() {
                if !(plottable(v) && v > 0.0) {
                    continue;
                }
                let x0 = left + k as f64 * w;
                let bar = Rectangle::new([(x0 + 0.02, base), (x0 + w - 0.02, v)], color.filled());
                chart.draw_series([bar])?;
            }
        }
        let mujoco = bench.mujoco.as_ref().map(|_| ("MuJoCo mj_step", GREY));
        for (label, color) in PARTS.iter().copied().chain(mujoco) {
            let legend = move |(x, y): (i32, i32)| {
                Rectangle::new([(x + 4, y - 5), (x + 14, y + 5)], color.filled())
            };
            chart
                .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
                .label(label)
                .legend(legend);
        }
        legend_box(&mut chart, SeriesLabelPosition::UpperLeft)
    })
}

/// A step's three parts with their colours, in [`PARTS`]' order.
fn parts(t: &super::StepTimes) -> Vec<(f64, RGBColor)> {
    vec![(t.interaction_us, BLUE), (t.rapier_us, ORANGE), (t.full_us, GREEN)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_interpolate_and_survive_empty_input() {
        let s = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(quantile(&s, 0.5), 2.5);
        assert_eq!(quantile(&s, 0.0), 1.0);
        assert_eq!(quantile(&s, 1.0), 4.0);
        assert!(quantile(&[], 0.5).is_nan());
    }
}
