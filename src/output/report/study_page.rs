//! The report's sections on the studies beyond Table 5.2: the placement
//! study over tracking noise (a plot per strategy and a table) and the
//! thesis's law given its departures back one at a time (a table).

use super::markup::{escape, plot, table};
use super::plots::{Drawn, PALETTE, chart, font, legend_box, plottable, svg, tick};
use super::{Ablation, Estimate, NoiseSummary, SweepRow, SweepStudy};
use plotters::prelude::*;
use std::fmt::Write;

/// The command that writes the sweep's JSON.
pub const SWEEP_COMMAND: &str = "coulomb-hands eval sweep --json > sweep.json";
/// The command that writes the ablation's JSON.
pub const ABLATION_COMMAND: &str = "coulomb-hands eval ablation --json > ablation.json";

/// `value [low, high]`, each with `decimals`, `—` for what is not finite.
fn ci(e: &Estimate, decimals: usize) -> String {
    let n = |v: f64| if v.is_finite() { format!("{v:.decimals$}") } else { "—".into() };
    format!("#{} [{}, {}]", n(e.value), n(e.low), n(e.high))
}

/// A proportion as a percentage with its interval.
fn percent(e: &Estimate) -> String {
    ci(&Estimate { value: e.value * 100.0, low: e.low * 100.0, high: e.high * 100.0 }, 0)
}

/// Each name once, in the order first met: the rows come method by method,
/// so one strategy's rows are not next to each other.
fn distinct<'a>(names: impl Iterator<Item = &'a str>) -> Vec<&'a str> {
    let mut seen = Vec::new();
    for name in names {
        if !seen.contains(&name) {
            seen.push(name);
        }
    }
    seen
}

/// The sweep section's body.
pub(super) fn sweep(p: &mut String, s: &SweepStudy) {
    let seeds: Vec<String> = s.seeds.iter().map(u64::to_string).collect();
    let _ = writeln!(
        p,
        "<p>Seeds {}, each {} synthetic users × {} trials, per method, strategy and noise \
         strength. Noise ×1 is that of {}: rms {:.2} mm per joint and axis, {}. Glance \
         errors ×{} those of the thesis's headset. Intervals are 95 %: Student's t for means, \
         Wilson for the share of failed trials, trials taken as independent.</p>",
        seeds.join(", "),
        s.users,
        s.trials,
        escape(&s.noise.sources.join(", ")),
        s.noise.rms_mm,
        s.noise.dropouts(),
        s.perception
    );
    let strategies = distinct(s.rows.iter().map(|r| r.strategy.as_str()));
    for strategy in &strategies {
        let rows: Vec<&SweepRow> = s.rows.iter().filter(|r| r.strategy == *strategy).collect();
        p.push_str("<div class=\"row\">\n");
        let caption = format!(
            "{strategy}: mean placement error of the completed trials against the tracking \
             noise's rms, with its 95 % interval; one line per method."
        );
        let error = Against { title: "Placement error", y: "error (mm)", value: |r| r.error_mm };
        plot(p, &noise_plot(strategy, &rows, &s.noise, error), &caption);
        let caption = format!(
            "{strategy}: times the cube fell out of the hand per trial, against the tracking \
             noise's rms, with its 95 % interval; one line per method."
        );
        let drops = Against { title: "Drops", y: "drops per trial", value: |r| r.drops };
        plot(p, &noise_plot(strategy, &rows, &s.noise, drops), &caption);
        p.push_str("</div>\n");
    }
    let rows: Vec<Vec<String>> = s
        .rows
        .iter()
        .map(|r| {
            vec![
                escape(&r.method),
                escape(&r.strategy),
                format!("#×{} ({:.2} mm)", r.noise, s.noise.rms_mm_at(r.noise)),
                format!("#{}", r.trials),
                ci(&r.error_mm, 1),
                ci(&r.time_s, 1),
                percent(&r.failed),
                ci(&r.drops, 2),
                r.held_across_mm.map_or("—".into(), |h| format!("#{h:+.1}")),
            ]
        })
        .collect();
    let head = [
        "method",
        "moves",
        "noise",
        "trials",
        "error (mm)",
        "time (s)",
        "failed (%)",
        "drops per trial",
        "held across the grip (mm)",
    ];
    table(p, &head, &rows);
}

/// What a noise plot shows of each row.
struct Against {
    /// The plot's title, before the strategy.
    title: &'static str,
    /// The y axis.
    y: &'static str,
    value: fn(&SweepRow) -> Estimate,
}

/// One of [`Against`]'s values against the noise's rms (mm; the rows'
/// scale times `noise`'s own) for one strategy's rows, one
/// line per method, with interval bars.
fn noise_plot(strategy: &str, rows: &[&SweepRow], noise: &NoiseSummary, shown: Against) -> String {
    let methods = distinct(rows.iter().map(|r| r.method.as_str()));
    let x = |r: &SweepRow| noise.rms_mm_at(r.noise);
    let points = |m: &str| -> Vec<(f64, Estimate)> {
        let of = rows.iter().filter(|r| r.method == m);
        let pts = of.map(|r| (x(r), (shown.value)(r)));
        pts.filter(|(x, e)| plottable(*x) && plottable(e.value)).collect()
    };
    let xs = rows.iter().map(|r| x(r)).filter(|x| plottable(*x));
    let x_max = xs.fold(0.0f64, f64::max).max(0.5);
    let highs = rows.iter().flat_map(|r| [(shown.value)(r).value, (shown.value)(r).high]);
    let y_max = highs.filter(|v| plottable(*v)).fold(0.1f64, f64::max) * 1.1;
    svg((460, 340), |root| -> Drawn {
        let title = format!("{}, {strategy}", shown.title);
        let mut c = chart(root, &title, -0.05 * x_max..x_max * 1.08, 0.0..y_max)?;
        c.configure_mesh()
            .x_desc("tracking noise (mm rms per joint and axis)")
            .y_desc(shown.y)
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .label_style(font(13))
            .draw()?;
        for (k, m) in methods.iter().enumerate() {
            let color = PALETTE[k % PALETTE.len()];
            // Each method a little apart, so the bars do not hide each other.
            let shift = (k as f64 - (methods.len() as f64 - 1.0) / 2.0) * 0.02 * x_max;
            let pts = points(m);
            let line = pts.iter().map(|(x, e)| (x + shift, e.value));
            let style = color.stroke_width(2);
            c.draw_series(LineSeries::new(line, style))?
                .label(*m)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
            let bars = pts.iter().filter(|(_, e)| plottable(e.low) && plottable(e.high));
            c.draw_series(bars.map(|(x, e)| {
                PathElement::new(vec![(x + shift, e.low.max(0.0)), (x + shift, e.high)], style)
            }))?;
            c.draw_series(
                pts.iter().map(|(x, e)| Circle::new((x + shift, e.value), 3, color.filled())),
            )?;
        }
        legend_box(&mut c, SeriesLabelPosition::UpperLeft)
    })
}

/// The ablation section's body.
pub(super) fn ablation(p: &mut String, a: &Ablation) {
    let _ = writeln!(
        p,
        "<p>The thesis's law as written, then with each of this crate's departures given back \
         alone, then with all of them: {} synthetic users × {} trials each, seed {}.</p>",
        a.users, a.trials, a.seed
    );
    let rows: Vec<Vec<String>> = a
        .rows
        .iter()
        .map(|r| {
            vec![
                escape(&r.config),
                escape(&r.strategy),
                format!("#{} of {}", r.completed, r.trials),
                ci(&r.drops, 2),
                ci(&r.error_mm, 1),
            ]
        })
        .collect();
    let head = ["configuration", "moves", "completed", "drops per trial", "error (mm)"];
    table(p, &head, &rows);
}
