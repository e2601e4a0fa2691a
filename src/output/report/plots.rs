//! The report's plots, drawn by plotters as SVG text. Each function gives
//! one `<svg>` element; a plot that cannot be drawn gives a paragraph
//! saying so instead. Non-finite values are left out; empty data gives
//! empty axes.

use super::{BenchReport, MethodResult, ObjectSeries, ObjectsPoint, ScenarioRun, SweepPoint};
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

/// Objects shown in a scenario's plot at most.
pub(super) const MAX_OBJECTS: usize = 5;
/// Points per line at most (pairs of a bucket's least and greatest value).
const MAX_POINTS: usize = 600;

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
fn finite(values: impl IntoIterator<Item = f64>) -> Vec<f64> {
    values.into_iter().filter(|v| plottable(*v)).collect()
}

/// `0` to a little above the largest of `values` (at least `floor`).
fn up_to_max(values: &[f64], floor: f64) -> std::ops::Range<f64> {
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

/// A polyline with round markers, labelled for the legend.
struct Line<'l> {
    label: &'l str,
    color: RGBColor,
    points: Vec<(f64, f64)>,
    markers: bool,
}

/// Draws `lines`, labelled for the legend, on `chart`.
fn draw_lines<'a, X, Y>(chart: &mut Chart<'a, X, Y>, lines: &[Line]) -> Drawn
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    for l in lines {
        let style = l.color.stroke_width(2);
        chart
            .draw_series(LineSeries::new(l.points.iter().copied(), style))?
            .label(l.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
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
            Line { label, color, points, markers: true }
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

/// The objects a scenario's plot shows, at most [`MAX_OBJECTS`], in scene
/// order: those the hands pushed on hardest, then those whose height
/// changed most (by more than 1 mm); the first ones if none qualifies.
pub(super) fn shown_objects(run: &ScenarioRun) -> Vec<&ObjectSeries> {
    let largest = |v: &[f32]| finite(v.iter().map(|&f| f as f64)).into_iter().fold(0.0, f64::max);
    let range = |v: &[f32]| {
        let h = finite(v.iter().map(|&f| f as f64));
        let lo = h.iter().copied().fold(f64::INFINITY, f64::min);
        h.iter().map(|v| v - lo).fold(0.0, f64::max)
    };
    let ranked = |score: &dyn Fn(&ObjectSeries) -> f64, least: f64| {
        let mut r: Vec<(usize, f64)> =
            run.objects.iter().map(score).enumerate().filter(|(_, s)| *s > least).collect();
        r.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
        r.into_iter().map(|r| r.0).collect::<Vec<_>>()
    };
    let pushed = ranked(&|o| largest(&o.hand_force_n), 0.0);
    let moved = ranked(&|o| range(&o.height_m), 0.001);
    let mut chosen: Vec<usize> = Vec::new();
    for i in pushed.into_iter().chain(moved) {
        if chosen.len() < MAX_OBJECTS && !chosen.contains(&i) {
            chosen.push(i);
        }
    }
    if chosen.is_empty() {
        chosen = (0..run.objects.len().min(MAX_OBJECTS)).collect();
    }
    chosen.sort_unstable();
    chosen.into_iter().map(|i| &run.objects[i]).collect()
}

/// The colour of the `k`-th line of a plot, as CSS hex.
pub(super) fn line_color(k: usize) -> String {
    let RGBColor(r, g, b) = PALETTE[k % PALETTE.len()];
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// At most [`MAX_POINTS`] `(t, value)` points of a per-step series: for
/// each bucket of steps, its least and greatest finite value, in time
/// order, so peaks survive.
fn envelope(values: &[f32], dt: f64) -> Vec<(f64, f64)> {
    let t = |i: usize| (i + 1) as f64 * dt;
    let per = values.len().div_ceil(MAX_POINTS / 2).max(1);
    let mut out = Vec::new();
    for (b, chunk) in values.chunks(per).enumerate() {
        let finite = chunk.iter().copied().enumerate().filter(|(_, v)| plottable(f64::from(*v)));
        let lo = finite.clone().min_by(|a, b| a.1.total_cmp(&b.1));
        let hi = finite.max_by(|a, b| a.1.total_cmp(&b.1));
        let mut pair: Vec<(usize, f32)> = lo.into_iter().chain(hi).collect();
        pair.sort_by_key(|p| p.0);
        pair.dedup_by_key(|p| p.0);
        out.extend(pair.into_iter().map(|(i, v)| (t(b * per + i), v as f64)));
    }
    out
}

/// One line per object of `series(object)`, in palette order.
fn object_lines<'r>(
    shown: &[&'r ObjectSeries],
    dt: f64,
    series: fn(&ObjectSeries) -> &[f32],
) -> Vec<Line<'r>> {
    let line = |(k, o): (usize, &&'r ObjectSeries)| Line {
        label: o.name.as_str(),
        color: PALETTE[k % PALETTE.len()],
        points: envelope(series(o), dt),
        markers: false,
    };
    shown.iter().enumerate().map(line).collect()
}

/// A scenario's hand force on its objects (top) and their heights
/// (bottom) over time; the legend is the page's ([`line_color`]).
pub(super) fn scenario(run: &ScenarioRun) -> String {
    let shown = shown_objects(run);
    let steps = run.objects.iter().map(|o| o.height_m.len()).max().unwrap_or(0);
    let dt = if run.dt > 0.0 && plottable(run.dt * steps as f64) { run.dt } else { 1e-3 };
    let duration = (steps as f64 * dt).max(dt);
    let forces = object_lines(&shown, dt, |o| &o.hand_force_n);
    let heights = object_lines(&shown, dt, |o| &o.height_m);
    let ys = |ls: &[Line]| finite(ls.iter().flat_map(|l| l.points.iter().map(|p| p.1)));
    let (fy, hy) = (ys(&forces), ys(&heights));
    let (lo, hi) =
        hy.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let pad = ((hi - lo) * 0.08).max(0.01);
    let height = if lo <= hi { (lo - pad).min(0.0)..hi + pad } else { 0.0..0.1 };
    svg((560, 440), |root| {
        let (top, bottom) = root.split_vertically(210);
        let force = up_to_max(&fy, 0.1);
        let mut upper = chart(&top, "hand force on the objects", 0.0..duration, force)?;
        upper
            .configure_mesh()
            .max_light_lines(2)
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .y_desc("force (N)")
            .label_style(font(13))
            .draw()?;
        draw_lines(&mut upper, &forces)?;
        let mut lower = chart(&bottom, "object height", 0.0..duration, height)?;
        lower
            .configure_mesh()
            .max_light_lines(2)
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .x_desc("time (s)")
            .y_desc("height (m)")
            .label_style(font(13))
            .draw()?;
        for l in &heights {
            lower
                .draw_series(LineSeries::new(l.points.iter().copied(), l.color.stroke_width(2)))?;
        }
        Ok(())
    })
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

    #[test]
    fn the_envelope_keeps_peaks_and_drops_non_finite_values() {
        let mut v = vec![0.0_f32; 10_000];
        v[4321] = 7.0;
        v[17] = f32::NAN;
        let e = envelope(&v, 0.001);
        assert!(e.len() <= MAX_POINTS, "{}", e.len());
        assert!(e.iter().any(|p| p.1 == 7.0 && (p.0 - 4.322).abs() < 1e-9));
        assert!(e.iter().all(|p| p.1.is_finite()));
        assert!(e.windows(2).all(|w| w[0].0 < w[1].0));
    }
}
