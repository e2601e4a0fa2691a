//! The page's HTML pieces that every section uses: escaped text, numbers,
//! tables and captioned plots.

use std::fmt::Write;

/// `text` with `<`, `>`, `&` and quotes escaped.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// `v` with `decimals`, or `—` if it is not finite.
pub(crate) fn num(v: f64, decimals: usize) -> String {
    if v.is_finite() { format!("{v:.decimals$}") } else { "—".to_string() }
}

/// A right-aligned number cell for [`table`].
pub(crate) fn cell(v: f64, decimals: usize) -> String {
    format!("#{}", num(v, decimals))
}

/// A table: `head` cells (none: no head row), then rows of cells already in HTML (`num`
/// cells are right-aligned when they start with `#`).
pub(crate) fn table(p: &mut String, head: &[&str], rows: &[Vec<String>]) {
    p.push_str("<table>\n");
    if !head.is_empty() {
        p.push_str("<tr>");
        for h in head {
            let _ = write!(p, "<th>{}</th>", escape(h));
        }
        p.push_str("</tr>\n");
    }
    for row in rows {
        p.push_str("<tr>");
        for cell in row {
            match cell.strip_prefix('#') {
                Some(n) => {
                    let _ = write!(p, "<td class=\"num\">{n}</td>");
                }
                None => {
                    let _ = write!(p, "<td>{cell}</td>");
                }
            }
        }
        p.push_str("</tr>\n");
    }
    p.push_str("</table>\n");
}

pub(crate) fn plot(p: &mut String, svg: &str, caption: &str) {
    plot_with_legend(p, svg, "", caption);
}

/// A plot with a caption that starts with `legend` (HTML).
pub(crate) fn plot_with_legend(p: &mut String, svg: &str, legend: &str, caption: &str) {
    let _ = writeln!(
        p,
        "<figure class=\"plot\">\n{svg}\n<figcaption class=\"caption\">{legend}{}</figcaption>\n\
         </figure>",
        escape(caption)
    );
}
