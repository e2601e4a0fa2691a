//! A scenario's plot: the hand force on its objects and their heights
//! over time, a few objects of many, and the series thinned to an
//! envelope that keeps their peaks.

use super::plots::{
    Line, PALETTE, chart, draw_lines, finite, font, palette_lines, plottable, svg, tick, up_to_max,
};
use super::{ObjectSeries, ScenarioRun};
use plotters::prelude::*;

/// Objects shown in a scenario's plot at most.
pub(super) const MAX_OBJECTS: usize = 5;
/// Points per line at most (pairs of a bucket's least and greatest value).
const MAX_POINTS: usize = 600;

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
    palette_lines(shown.iter().map(|o| (o.name.as_str(), envelope(series(o), dt))))
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
