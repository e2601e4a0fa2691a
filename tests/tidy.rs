//! The project's written rules, checked (rust-analyzer keeps a tidy test
//! too): short files and lines, one home per thesis equation, and the
//! module layering that ARCHITECTURE.md promises.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The equations of thesis §3.5.5–3.5.6 that the crate computes. Eq. 3.9,
/// `f = m·a`, is rapier's integration, not a function of ours.
const EQUATIONS: [&str; 7] = ["3.4", "3.5", "3.6", "3.7", "3.8", "3.10", "3.11"];

/// Every `.rs` file under `dirs`, sorted.
fn rust_files(dirs: &[&str]) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                // A build's output (the Python package's own workspace builds into
                // crates/coulomb-hands-py/target) is not source.
                if !path.ends_with("target") {
                    walk(&path, out);
                }
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let mut out = Vec::new();
    for dir in dirs {
        walk(&Path::new(ROOT).join(dir), &mut out);
    }
    out.sort();
    out
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn relative(path: &Path) -> String {
    path.strip_prefix(ROOT).unwrap_or(path).display().to_string()
}

#[test]
fn no_source_file_is_over_600_lines() {
    let long: Vec<String> = rust_files(&["src", "tests", "benches", "crates"])
        .iter()
        .map(|p| (relative(p), read(p).lines().count()))
        .filter(|(_, n)| *n > 600)
        .map(|(p, n)| format!("{p}: {n} lines"))
        .collect();
    assert!(long.is_empty(), "split these by job:\n{}", long.join("\n"));
}

#[test]
fn no_line_is_over_100_characters() {
    let mut long = Vec::new();
    for path in rust_files(&["src", "tests", "benches", "crates"]) {
        for (i, line) in read(&path).lines().enumerate() {
            let n = line.chars().count();
            if n > 100 {
                long.push(format!("{}:{}: {n} characters", relative(&path), i + 1));
            }
        }
    }
    assert!(long.is_empty(), "{}", long.join("\n"));
}

/// `(file, function)` for every function whose doc comment cites `Eq. 3.N`,
/// by equation.
fn equation_homes() -> BTreeMap<String, Vec<(String, String)>> {
    let mut homes: BTreeMap<String, Vec<(String, String)>> = BTreeMap::new();
    for path in rust_files(&["src"]) {
        let text = read(&path);
        let mut doc = String::new();
        for line in text.lines().map(str::trim) {
            if let Some(d) = line.strip_prefix("///") {
                doc.push_str(d);
                doc.push(' ');
                continue;
            }
            if line.starts_with("#[") || doc.is_empty() {
                continue;
            }
            if let Some(name) = function_name(line) {
                for eq in cited(&doc) {
                    homes.entry(eq).or_default().push((relative(&path), name.to_string()));
                }
            }
            doc.clear();
        }
    }
    homes
}

/// The name of the function a line declares, if it declares one.
fn function_name(line: &str) -> Option<&str> {
    let at = line.find("fn ")?;
    let before = &line[..at];
    let modifiers = ["pub", "pub(crate)", "pub(super)", "const", "unsafe", "async", "extern"];
    if !before.split_whitespace().all(|w| modifiers.contains(&w)) {
        return None;
    }
    let rest = &line[at + 3..];
    rest.split(|c: char| !(c.is_alphanumeric() || c == '_')).next()
}

/// The equation numbers `Eq. 3.N` cites in a text, ranges included
/// (`Eq. 3.4–3.8` cites 3.4 only: write ranges out of function docs).
fn cited(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = text;
    while let Some(at) = rest.find("Eq. 3.") {
        rest = &rest[at + 6..];
        let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
        if !digits.is_empty() {
            out.insert(format!("3.{digits}"));
        }
    }
    out
}

#[test]
fn each_thesis_equation_is_cited_on_exactly_one_function_in_friction() {
    let homes = equation_homes();
    let mut wrong = Vec::new();
    for eq in EQUATIONS {
        match homes.get(eq).map(Vec::as_slice) {
            Some([(file, _)]) if file.starts_with("src/friction/") => {}
            Some(found) => wrong.push(format!("Eq. {eq} is cited on {found:?}")),
            None => wrong.push(format!("Eq. {eq} has no function whose doc cites it")),
        }
    }
    for (eq, found) in &homes {
        if !EQUATIONS.contains(&eq.as_str()) {
            wrong.push(format!("Eq. {eq} is not one of the thesis's: cited on {found:?}"));
        }
    }
    assert!(wrong.is_empty(), "one home per equation, in src/friction:\n{}", wrong.join("\n"));
}

/// A source file's code that builds outside tests: without its comments,
/// and cut where a `#[cfg(test)]` module begins (the crate keeps its unit
/// tests last in each file, or in a `tests.rs` of their own).
fn code_outside_tests(path: &Path) -> String {
    let name = path.file_name().and_then(|n| n.to_str());
    let inside = path.strip_prefix(ROOT).unwrap_or(path);
    if name == Some("tests.rs") || inside.components().any(|c| c.as_os_str() == "tests") {
        return String::new();
    }
    let (text, mut code) = (read(path), String::new());
    let mut lines = text.lines().map(str::trim).peekable();
    while let Some(line) = lines.next() {
        if line == "#[cfg(test)]" && lines.peek().is_some_and(|l| l.contains("mod ")) {
            break;
        }
        if !line.starts_with("//") {
            code.push_str(line);
            code.push('\n');
        }
    }
    code
}

/// Whether `code` calls the function `name`: the name as a whole word,
/// followed by its arguments or a turbofish, and not its own `fn`.
fn calls(code: &str, name: &str) -> bool {
    code.match_indices(name).any(|(at, _)| {
        let before = code[..at].chars().next_back();
        let after = &code[at + name.len()..];
        let whole = !before.is_some_and(|c| c.is_alphanumeric() || c == '_');
        whole
            && !code[..at].ends_with("fn ")
            && (after.starts_with('(') || after.starts_with("::<"))
    })
}

#[test]
fn each_equation_s_home_is_called_by_code_that_runs() {
    // An equation written again where it runs leaves its home a reading
    // only, free to differ: the home must be what the step calls.
    let code: Vec<String> = rust_files(&["src"]).iter().map(|p| code_outside_tests(p)).collect();
    let mut unused = Vec::new();
    for (eq, homes) in equation_homes() {
        for (file, name) in homes {
            let called = code.iter().any(|text| calls(text, &name));
            if !called {
                unused.push(format!("Eq. {eq}: {name} in {file}"));
            }
        }
    }
    assert!(
        unused.is_empty(),
        "no code outside tests calls these equations' homes:\n{}",
        unused.join("\n")
    );
}

#[test]
fn the_equation_table_in_architecture_md_names_each_home() {
    let table = read(&Path::new(ROOT).join("ARCHITECTURE.md"));
    let homes = equation_homes();
    for eq in EQUATIONS {
        let Some([(file, name)]) = homes.get(eq).map(Vec::as_slice) else { continue };
        let row = table
            .lines()
            .find(|l| l.starts_with('|') && l.contains(&format!("Eq. {eq} ")))
            .unwrap_or_else(|| panic!("ARCHITECTURE.md has no table row for Eq. {eq}"));
        assert!(
            row.contains(name) && row.contains(file.as_str()),
            "Eq. {eq}: {name} in {file}: {row}"
        );
    }
}

/// The top-level module a file of the crate at `src` belongs to (`None`
/// for the crate root and the binary).
fn top_module(src: &str, path: &Path) -> Option<String> {
    let rel = path.strip_prefix(Path::new(ROOT).join(src)).ok()?;
    let first = rel.components().next()?.as_os_str().to_str()?;
    match first {
        "lib.rs" | "main.rs" => None,
        f => Some(f.trim_end_matches(".rs").to_string()),
    }
}

/// The code of a file without comments (doc links are not imports).
fn code(text: &str) -> String {
    let lines = text.lines().map(|l| l.split_once("//").map_or(l, |(code, _)| code));
    lines.collect::<Vec<_>>().join("\n")
}

/// `crate::x` paths in code, as the top-level modules `x` they name.
fn crate_paths(code: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        rest = &rest[at + 7..];
        let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        out.insert(name);
    }
    out
}

/// Which top-level modules each top-level module's code names, in the
/// crate whose sources are at `src`.
fn module_graph_of(src: &str) -> BTreeMap<String, BTreeSet<String>> {
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for path in rust_files(&[src]) {
        let Some(module) = top_module(src, &path) else { continue };
        let uses = crate_paths(&code(&read(&path)));
        graph.entry(module.clone()).or_default().extend(uses.into_iter().filter(|m| *m != module));
    }
    graph
}

/// The library's module graph.
fn module_graph() -> BTreeMap<String, BTreeSet<String>> {
    module_graph_of("src")
}

/// Every crate of the workspace, by its sources.
const CRATES: [&str; 6] = [
    "src",
    "crates/coulomb-hands-bevy/src",
    "crates/coulomb-hands-view/src",
    "crates/coulomb-hands-py/src",
    "crates/coulomb-hands-web/src",
    "crates/coulomb-hands-c/src",
];

#[test]
fn modules_name_each_other_by_module_path_not_root_re_exports() {
    for (module, uses) in module_graph() {
        let root: Vec<&String> =
            uses.iter().filter(|u| u.starts_with(char::is_uppercase)).collect();
        assert!(root.is_empty(), "{module} uses root re-exports {root:?}: name their module");
    }
}

#[test]
fn the_architecture_invariants_hold() {
    let graph = module_graph();
    let uses = |m: &str| graph.get(m).cloned().unwrap_or_default();
    // `friction` knows no rapier: the law is pure math.
    for path in rust_files(&["src/friction"]) {
        let code = code(&read(&path));
        assert!(!code.contains("rapier") && !code.contains("parry"), "{}", relative(&path));
    }
    assert!(uses("friction").is_empty(), "friction uses {:?}", uses("friction"));
    // `contact` never imports the pipeline, nor anything downstream of it.
    for downstream in ["pipeline", "output", "run"] {
        assert!(!uses("contact").contains(downstream), "contact uses {downstream}");
    }
    // The pipeline never imports run-stage or output code.
    for downstream in ["output", "run"] {
        assert!(!uses("pipeline").contains(downstream), "pipeline uses {downstream}");
    }
}

#[test]
fn each_crates_top_level_modules_import_each_other_without_cycles() {
    for src in CRATES {
        // Kahn's algorithm: remove modules that use no remaining module.
        let mut left = module_graph_of(src);
        assert!(left.len() >= 3, "{src}: {} modules found", left.len());
        while let Some(leaf) = left.iter().find(|(_, u)| u.iter().all(|m| !left.contains_key(m))) {
            let leaf = leaf.0.clone();
            left.remove(&leaf);
        }
        assert!(left.is_empty(), "{src}: these modules import each other in a cycle: {left:?}");
    }
}

/// The modules that `code` names through `super::` chains of exactly
/// `depth` links (`super::x`, or each item of `super::{x, y::z}`).
fn super_paths(code: &str, depth: usize) -> BTreeSet<String> {
    let chain = "super::".repeat(depth);
    let mut out = BTreeSet::new();
    let mut rest = code;
    while let Some(at) = rest.find(&chain) {
        let before = &rest[..at];
        rest = &rest[at + chain.len()..];
        // A longer chain is another depth's.
        if before.ends_with("super::") || rest.starts_with("super::") {
            continue;
        }
        let ident =
            |s: &str| s.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        if let Some(group) = rest.strip_prefix('{') {
            // Top-level items of the group, up to its closing brace.
            let (mut level, mut item) = (0, String::new());
            for c in group.chars() {
                match c {
                    '{' => level += 1,
                    '}' if level == 0 => break,
                    '}' => level -= 1,
                    ',' if level == 0 => {
                        out.insert(ident(&item));
                        item.clear();
                        continue;
                    }
                    _ => {}
                }
                if level == 0 {
                    item.push(c);
                }
            }
            out.insert(ident(&item));
        } else {
            out.insert(ident(rest));
        }
    }
    out
}

/// The graph of the child modules of the module whose directory is `dir`
/// (its path from the crate root `module`, e.g. `pipeline::step`): which
/// siblings each child's code names, by `super::` or by its `crate::` path.
fn submodule_graph(dir: &Path, module: &str) -> BTreeMap<String, BTreeSet<String>> {
    let Ok(entries) = std::fs::read_dir(dir) else { return BTreeMap::new() };
    let children: BTreeSet<String> = (entries.flatten())
        .filter_map(|e| e.file_name().to_str().map(|n| n.trim_end_matches(".rs").to_string()))
        .filter(|n| n != "mod")
        .collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for path in rust_files(&[dir.strip_prefix(ROOT).unwrap_or(dir).to_str().expect("UTF-8")]) {
        let rel = path.strip_prefix(dir).expect("under the directory");
        let names: Vec<&str> = rel.iter().filter_map(|c| c.to_str()).collect();
        let child = names[0].trim_end_matches(".rs").to_string();
        if child == "mod" {
            continue;
        }
        // `a.rs` and `a/mod.rs` are `a`, one level below: `a/b.rs` two.
        let depth = names.len() - usize::from(names.last() == Some(&"mod.rs"));
        let code = code(&read(&path));
        let mut uses = super_paths(&code, depth);
        let prefix = format!("crate::{module}::");
        let mut rest = code.as_str();
        while let Some(at) = rest.find(&prefix) {
            rest = &rest[at + prefix.len()..];
            uses.insert(rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect());
        }
        let siblings: Vec<String> =
            uses.into_iter().filter(|u| *u != child && children.contains(u)).collect();
        graph.entry(child).or_default().extend(siblings);
    }
    graph
}

#[test]
fn each_module_s_submodules_import_each_other_without_cycles() {
    let mut cyclic = Vec::new();
    for src in CRATES {
        let root = Path::new(ROOT).join(src);
        let mut dirs = vec![];
        let mut todo = vec![root.clone()];
        while let Some(dir) = todo.pop() {
            for entry in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
                if entry.path().is_dir() {
                    todo.push(entry.path());
                    dirs.push(entry.path());
                }
            }
        }
        for dir in dirs {
            let module = dir.strip_prefix(&root).expect("under src").to_str().expect("UTF-8");
            let mut left = submodule_graph(&dir, &module.replace('/', "::"));
            while let Some(leaf) =
                left.iter().find(|(_, u)| u.iter().all(|m| !left.contains_key(m)))
            {
                let leaf = leaf.0.clone();
                left.remove(&leaf);
            }
            if !left.is_empty() {
                cyclic.push(format!("{}: {left:?}", relative(&dir)));
            }
        }
    }
    assert!(
        cyclic.is_empty(),
        "submodules that import each other in a cycle:\n{}",
        cyclic.join("\n")
    );
}
