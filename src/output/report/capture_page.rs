//! The report's section on a real hand–object capture replayed with each
//! method: the object's height and each method's distance from the
//! captured object over time, and a row of errors per method. The two
//! plots are public, so the book's figures are drawn by the same code.

use super::markup::{cell, escape, plot, table};
use super::plots::{
    Drawn, Line, chart, draw_lines, finite, font, legend_box, palette_lines, plottable, svg, tick,
};
use super::{CaptureMethodRun, CaptureRuns};
use plotters::prelude::*;
use std::fmt::Write;

/// The bundled capture, as the command line names it.
pub const CAPTURE_FILE: &str = "data/taco/taco_20231104_017.json";

/// The section's body.
pub(super) fn captures(p: &mut String, c: &CaptureRuns) {
    let mass = if c.mass_kg.is_finite() { c.mass_kg.to_string() } else { "—".into() };
    let _ = writeln!(
        p,
        "<p>The hand of a real hand–object capture, <code>{}</code>, replayed open loop with \
         each method at the 1 kHz physics rate. The object, of {mass} kg and the skin–object \
         material {} (the capture gives neither), starts at its first captured pose on a table \
         at its lowest point; from then on only the hand's contacts move it, and it is compared \
         with the captured object at every captured frame, never put back where the capture \
         has it.</p>",
        escape(&c.capture),
        escape(&c.material)
    );
    p.push_str("<div class=\"row\">\n");
    let caption = "The object's height above where it started (mm) at every captured frame: \
                   the captured object's (black) and each method's simulated one.";
    plot(p, &capture_heights(c), caption);
    let caption = "How far each method's simulated object is from the captured one (mm, \
                   between their origins) at every captured frame.";
    plot(p, &capture_errors(c), caption);
    p.push_str("</div>\n");
    let rows: Vec<Vec<String>> = c.methods.iter().map(method_row).collect();
    let head = [
        "method",
        "translation error, mean (mm)",
        "largest (mm)",
        "rotation error, mean (°)",
        "largest (°)",
        "lift reached (mm)",
        "captured lift (mm)",
        "on target",
    ];
    table(p, &head, &rows);
    p.push_str(
        "<p class=\"note\">On target, as <code>coulomb-hands replay</code> judges it: lifted at \
         least half as high as the captured object, set down within 1 cm of the height the \
         captured one ends at, translation error at most 10 mm on average and 30 mm at worst, \
         rotation error at most 5° and 15°.</p>\n",
    );
    for m in &c.methods {
        if let Some(e) = &m.error {
            let (method, e) = (escape(&m.method), escape(e));
            let _ = writeln!(p, "<p class=\"fail\">{method}: the replay stopped: {e}</p>");
        }
    }
    let _ = writeln!(p, "<p class=\"note\">Capture data: {}.</p>", escape(&c.credit));
}

/// A method's row: its errors, its lift against the captured one, and
/// whether it is on target.
fn method_row(m: &CaptureMethodRun) -> Vec<String> {
    let verdict = match (&m.error, m.on_target) {
        (Some(_), _) => "<span class=\"fail\">stopped</span>",
        (None, true) => "<span class=\"pass\">yes</span>",
        (None, false) => "<span class=\"fail\">no</span>",
    };
    let numbers = [
        m.translation_mean_mm,
        m.translation_max_mm,
        m.rotation_mean_deg,
        m.rotation_max_deg,
        m.simulated_lift_mm,
        m.captured_lift_mm,
    ];
    let mut row = vec![escape(&m.method)];
    row.extend(numbers.map(|v| cell(v, 1)));
    row.push(verdict.to_string());
    row
}

/// The captured object's height and each method's simulated one over the
/// capture (mm), the capture's credit below.
pub fn capture_heights(c: &CaptureRuns) -> String {
    let captured = Line {
        label: "captured",
        color: BLACK,
        points: series(&c.time_s, &c.captured_height_mm),
        markers: false,
        dashed: false,
    };
    let mut lines = vec![captured];
    lines.extend(method_lines(c, |m| &m.simulated_height_mm));
    over_time(c, "Object height: captured and simulated", "height (mm)", &lines)
}

/// Each method's distance from the captured object over the capture (mm),
/// the capture's credit below.
pub fn capture_errors(c: &CaptureRuns) -> String {
    let lines = method_lines(c, |m| &m.translation_error_mm);
    over_time(c, "Distance from the captured object", "translation error (mm)", &lines)
}

/// `(t, value)` for each frame whose value is [`plottable`].
fn series(time_s: &[f64], values: &[f32]) -> Vec<(f64, f64)> {
    let points = time_s.iter().zip(values).map(|(&t, &v)| (t, f64::from(v)));
    points.filter(|(t, v)| plottable(*t) && plottable(*v)).collect()
}

/// One line per method of `values(method)`, in palette order, every
/// other one dashed: methods that move the object alike draw one line, and
/// the dashes show the one under it.
fn method_lines<'c>(c: &'c CaptureRuns, values: fn(&CaptureMethodRun) -> &[f32]) -> Vec<Line<'c>> {
    let lines = c.methods.iter().map(|m| (m.method.as_str(), series(&c.time_s, values(m))));
    let mut lines = palette_lines(lines);
    lines.iter_mut().skip(1).step_by(2).for_each(|l| l.dashed = true);
    lines
}

/// `lines` against the capture's time, from 0 (or below, if a value is)
/// to a little above the largest value, the credit in a line below.
fn over_time(c: &CaptureRuns, title: &str, y: &str, lines: &[Line]) -> String {
    let ys = finite(lines.iter().flat_map(|l| l.points.iter().map(|p| p.1)));
    let (lo, hi) = ys.iter().fold((0.0_f64, 10.0_f64), |(a, b), &v| (a.min(v), b.max(v)));
    let pad = 0.06 * (hi - lo);
    let low = if lo < 0.0 { lo - pad } else { 0.0 };
    let duration = finite(c.time_s.iter().copied()).into_iter().fold(1.0, f64::max);
    let credit = format!("Data: {}", c.credit);
    svg((560, 420), |root| -> Drawn {
        let (area, foot) = root.split_vertically(400);
        let mut chart = chart(&area, title, 0.0..duration, low..hi + pad)?;
        chart
            .configure_mesh()
            .max_light_lines(2)
            .x_desc("time (s)")
            .x_label_formatter(&tick)
            .y_desc(y)
            .y_label_formatter(&tick)
            .label_style(font(14))
            .draw()?;
        draw_lines(&mut chart, lines)?;
        legend_box(&mut chart, SeriesLabelPosition::UpperLeft)?;
        foot.draw_text(&credit, &font(11).color(&BLACK.mix(0.6)), (12, 2))?;
        Ok(())
    })
}
