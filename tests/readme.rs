//! The docs are true: README.md and every page of the book (`docs/book/src/`).
//! Every `console` block is run and its output compared with the page's
//! (trycmd; `TRYCMD=overwrite` writes the new outputs); every link between
//! the pages, image and `{{#include}}` resolves; and the config page shows
//! the library's defaults (`TRYCMD=overwrite` rewrites them too).

use coulomb_hands::InteractionConfig;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");
const BOOK: &str = "docs/book/src";

#[test]
fn console_blocks_match_the_binary() {
    trycmd::TestCases::new().case("README.md").case(format!("{BOOK}/**/*.md"));
}

/// README.md, the crates' READMEs and the book's pages.
fn pages() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let root = Path::new(ROOT);
    let mut out = vec![root.join("README.md")];
    for krate in
        ["coulomb-hands-bevy", "coulomb-hands-view", "coulomb-hands-web", "coulomb-hands-c"]
    {
        out.push(root.join("crates").join(krate).join("README.md"));
    }
    out.push(root.join("bindings/unity/README.md"));
    out.push(root.join("bindings/unity/Samples~/HandCubeTable/README.md"));
    walk(&root.join(BOOK), &mut out);
    out.sort();
    out
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A page's text outside fenced code blocks.
fn prose(text: &str) -> String {
    let mut fenced = false;
    let mut out = String::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// The targets of a page's links and images, `[text](target)`, and of its
/// `<img src="target">`s.
fn link_targets(text: &str) -> Vec<String> {
    let text = prose(text);
    let mut out = Vec::new();
    for (open, close) in [("](", ')'), ("src=\"", '"')] {
        let mut rest = text.as_str();
        while let Some(at) = rest.find(open) {
            rest = &rest[at + open.len()..];
            let end = rest.find(close).unwrap_or(rest.len());
            out.push(rest[..end].trim().to_string());
        }
    }
    out
}

/// The `{{#include path}}` and `{{#include path:anchor}}` of a page.
fn includes(text: &str) -> Vec<(String, Option<String>)> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("{{#include ") {
        rest = &rest[at + 11..];
        let end = rest.find("}}").expect("an unclosed {{#include");
        let arg = rest[..end].trim();
        match arg.split_once(':') {
            Some((file, anchor)) => out.push((file.to_string(), Some(anchor.to_string()))),
            None => out.push((arg.to_string(), None)),
        }
    }
    out
}

/// The ids mdBook gives a page's headings (its own and those it includes
/// whole): lower case, spaces as `-`, other punctuation dropped.
fn heading_ids(page: &Path) -> BTreeSet<String> {
    let text = read(page);
    let mut ids = BTreeSet::new();
    for line in prose(&text).lines() {
        if let Some(heading) = line.strip_prefix('#') {
            let id = heading.trim_start_matches('#').trim().chars().filter_map(|c| {
                if c.is_alphanumeric() || c == '_' || c == '-' {
                    Some(c.to_lowercase().next().unwrap())
                } else {
                    c.is_whitespace().then_some('-')
                }
            });
            ids.insert(id.collect());
        }
    }
    for (file, anchor) in includes(&text) {
        if anchor.is_none() {
            ids.extend(heading_ids(&page.parent().unwrap().join(file)));
        }
    }
    ids
}

#[test]
fn links_images_and_includes_resolve() {
    let mut broken = Vec::new();
    for page in pages() {
        let text = read(&page);
        let dir = page.parent().unwrap();
        let name = page.strip_prefix(ROOT).unwrap().display().to_string();
        for target in link_targets(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (file, anchor) = target.split_once('#').unwrap_or((&target, ""));
            let path = if file.is_empty() { page.clone() } else { dir.join(file) };
            if !path.exists() {
                broken.push(format!("{name}: {target}: no such file"));
            } else if !anchor.is_empty() && !heading_ids(&path).contains(anchor) {
                broken.push(format!("{name}: {target}: no such heading"));
            }
        }
        for (file, anchor) in includes(&text) {
            let path = dir.join(&file);
            let Ok(included) = std::fs::read_to_string(&path) else {
                broken.push(format!("{name}: includes {file}: no such file"));
                continue;
            };
            if let Some(anchor) = anchor
                && !included.contains(&format!("ANCHOR: {anchor} "))
            {
                broken.push(format!("{name}: includes {file}: no ANCHOR: {anchor}"));
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn every_book_page_is_in_the_summary() {
    let book = Path::new(ROOT).join(BOOK);
    let summary = read(&book.join("SUMMARY.md"));
    let listed: BTreeSet<PathBuf> = link_targets(&summary).iter().map(|t| book.join(t)).collect();
    let pages = pages().into_iter().filter(|p| p.starts_with(&book));
    let unlisted: Vec<PathBuf> =
        pages.filter(|p| !p.ends_with("SUMMARY.md") && !listed.contains(p)).collect();
    assert!(unlisted.is_empty(), "pages SUMMARY.md does not list: {unlisted:?}");
}

#[test]
fn the_config_page_shows_the_defaults_and_every_field() {
    let path = Path::new(ROOT).join(BOOK).join("reference/config.md");
    let page = read(&path);
    let defaults = serde_json::to_value(InteractionConfig::default()).unwrap();
    for field in defaults.as_object().unwrap().keys() {
        assert!(page.contains(&format!("\n| `{field}` |")), "config.md's table has no {field}");
    }
    let (begin, end) = ("<!-- config:begin -->\n", "<!-- config:end -->");
    let start = page.find(begin).expect("config.md has no config:begin") + begin.len();
    let stop = page.find(end).expect("config.md has no config:end");
    // Serialised from the struct itself, in its fields' order and with f32s as f32s.
    let json = serde_json::to_string_pretty(&InteractionConfig::default()).unwrap();
    let block = format!("```json\n{json}\n```\n");
    if page[start..stop] != block {
        if std::env::var("TRYCMD").is_ok_and(|v| v == "overwrite") {
            let page = format!("{}{block}{}", &page[..start], &page[stop..]);
            std::fs::write(&path, page).unwrap();
        } else {
            panic!("config.md's defaults are not the library's; TRYCMD=overwrite writes:\n{block}");
        }
    }
}

/// The words of README.md's set-up line, between its `setup` anchors.
fn set_up_line() -> String {
    let readme = read(&Path::new(ROOT).join("README.md"));
    let (_, after) = readme.split_once("<!-- ANCHOR: setup -->").expect("a setup anchor");
    let (block, _) = after.split_once("<!-- ANCHOR_END: setup -->").expect("its end");
    let lines: Vec<&str> =
        block.lines().filter(|l| !l.trim().is_empty() && !l.starts_with("```")).collect();
    assert_eq!(lines.len(), 1, "one set-up line: {lines:?}");
    lines[0].to_string()
}

#[test]
fn the_set_up_line_installs_what_ci_installs_with_or_without_sudo() {
    let line = set_up_line();
    // As root in a plain container there is no `sudo`: the line takes it
    // only where `command -v` finds it, and reads the package lists first.
    assert!(
        line.starts_with("sudo=$(command -v sudo); $sudo apt-get update && $sudo apt-get install"),
        "{line}"
    );
    let (_, packages) = line.split_once("install -y ").expect("apt-get install -y");
    let readme: BTreeSet<&str> = packages.split_whitespace().collect();
    let ci = read(&Path::new(ROOT).join(".ci/run"));
    let (_, list) = ci.split_once("packages=(").expect(".ci/run's packages");
    let (list, _) = list.split_once(')').expect("the list's end");
    let ci: BTreeSet<&str> = list.split_whitespace().collect();
    assert_eq!(readme, ci, "README.md's set-up line and .ci/run's packages");
}
