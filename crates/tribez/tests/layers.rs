//! The library's layers point down (docs/code-map.md, "Layers"): every top-level module of
//! `crates/tribez/src` names only modules of its own layer or of lower ones, and no two
//! top-level modules name each other through any chain (no import cycles).
//!
//! The layer order is read from the map itself, so the map cannot drift from the code: a module
//! the map does not place, or a placed module that does not exist, fails too.
//!
//! What counts as naming a module: a path `crate::x` in code (a `use` line, a `use crate::{x,
//! ..}` group, a path in an expression or type), after comments are removed. Doc links in
//! comments are not dependencies. Test code (files `tests.rs` and `*_tests.rs`, and a file's
//! trailing `#[cfg(test)] mod tests { .. }`) is left out: tests may reach anywhere.
//!
//! And no function of the library or of the command line (`crates/tribez/src`,
//! `crates/tribez-cli/src`) outside test code is longer than [`MAX_FN_LINES`] lines, but for the
//! numeric kernels of [`LONG_FN_ALLOWED`] (each with its reason; an entry that is no longer long
//! fails too, so that the list only shrinks).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

type Graph = BTreeMap<String, BTreeMap<String, BTreeSet<String>>>;

fn src_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn map_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/code-map.md")
}

/// The modules `lib.rs` declares (`mod x;`, `pub mod x;`), with their attributes' `cfg(test)`
/// ones left out.
fn declared_modules(lib: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut test_only = false;
    for line in lib.lines() {
        let line = line.trim();
        if line.starts_with("#[cfg(test)]") {
            test_only = true;
            continue;
        }
        let decl = line
            .strip_prefix("pub mod ")
            .or_else(|| line.strip_prefix("pub(crate) mod "))
            .or_else(|| line.strip_prefix("mod "));
        if let Some(rest) = decl.and_then(|r| r.strip_suffix(';'))
            && !test_only
        {
            out.insert(rest.trim().to_string());
        }
        if !line.starts_with("#[") {
            test_only = false;
        }
    }
    out
}

/// Removes `//` comments (line, doc and inner doc), block comments and the contents of string
/// literals, keeping the line structure.
fn strip_comments(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
            let mut depth = 0;
            while i < b.len() {
                if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                    depth += 1;
                    i += 2;
                } else if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    if b[i] == b'\n' {
                        out.push('\n');
                    }
                    i += 1;
                }
            }
        } else if b[i] == b'"' && (i == 0 || b[i - 1] != b'\'') {
            // a string literal (raw strings of this crate hold no `"` inside)
            out.push('"');
            i += 1;
            while i < b.len() && b[i] != b'"' {
                if b[i] == b'\\' {
                    i += 1;
                }
                if i < b.len() && b[i] == b'\n' {
                    out.push('\n');
                }
                i += 1;
            }
            out.push('"');
            i += 1;
        } else {
            let ch = src[i..].chars().next().expect("in bounds");
            out.push(ch);
            i += ch.len_utf8();
        }
    }
    out
}

/// The code of a file without its trailing test module.
fn without_tests(src: &str) -> &str {
    for marker in ["#[cfg(test)]\nmod tests", "#[cfg(test)]\nmod test "] {
        if let Some(i) = src.find(marker) {
            return &src[..i];
        }
    }
    src
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The names lib.rs re-exports at the root (`pub use x::y::{A, B as C};`), each with the module
/// it comes from: `crate::A` names module `x`.
fn root_reexports(lib: &str) -> BTreeMap<String, String> {
    let code = strip_comments(lib);
    let mut out = BTreeMap::new();
    let mut rest = code.as_str();
    while let Some(i) = rest.find("pub use ") {
        rest = &rest[i + "pub use ".len()..];
        let end = rest.find(';').unwrap_or(rest.len());
        let item = &rest[..end];
        let module: String = item.chars().take_while(|&c| is_ident(c)).collect();
        if !item[module.len()..].starts_with("::") {
            continue; // `pub use num_rational::..` names a crate: not re-exported from a module
        }
        // the leaves: the last segment of each path; after `as`, the alias
        let leaves: Vec<&str> = item
            .split([',', '{', '}'])
            .map(str::trim)
            .filter(|t| !t.is_empty())
            .filter_map(|t| {
                let words: Vec<&str> = t.split_whitespace().collect();
                match words.as_slice() {
                    [path, "as", alias] => Some((*alias, *path)),
                    [path] => Some((path.rsplit("::").next().unwrap_or(path), *path)),
                    _ => None,
                }
            })
            .filter(|(_, path)| !path.ends_with("::"))
            .map(|(leaf, _)| leaf)
            .collect();
        for leaf in leaves {
            out.insert(leaf.to_string(), module.clone());
        }
        rest = &rest[end..];
    }
    out
}

/// The top-level modules a piece of code names: `crate::x` paths and the first segments of
/// `use crate::{x, y::z, ..}` groups. A name the root re-exports (`crate::Patch`) names the
/// module it comes from; a name that is neither is ignored (a macro, `crate::self`).
fn named_modules(code: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let before = rest[..i].chars().next_back();
        rest = &rest[i + "crate::".len()..];
        if before.is_some_and(|c| is_ident(c) || c == '$') {
            continue; // `$crate::`, `my_crate::`
        }
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find(';').unwrap_or(group.len());
            let mut depth = 0;
            let mut at_start = true;
            let mut word = String::new();
            for c in group[..end].chars() {
                if is_ident(c) {
                    if at_start && depth == 0 {
                        word.push(c);
                    }
                    continue;
                }
                if !word.is_empty() && word != "self" {
                    out.insert(std::mem::take(&mut word));
                }
                word.clear();
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        at_start = true;
                        continue;
                    }
                    c if c.is_whitespace() => continue,
                    _ => {}
                }
                at_start = false;
            }
        } else {
            let word: String = rest.chars().take_while(|&c| is_ident(c)).collect();
            if !word.is_empty() {
                out.insert(word);
            }
        }
    }
    out
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// For every top-level module, the modules it names (directly, or through a name the root
/// re-exports), each with the files that name it.
fn library_graph(modules: &BTreeSet<String>, reexports: &BTreeMap<String, String>) -> Graph {
    let src = src_dir();
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut graph = Graph::new();
    for file in files {
        let rel = file.strip_prefix(&src).expect("under src");
        let first = rel
            .components()
            .next()
            .expect("a file")
            .as_os_str()
            .to_string_lossy()
            .to_string();
        let module = first.strip_suffix(".rs").unwrap_or(&first).to_string();
        if module == "lib" || !modules.contains(&module) {
            continue;
        }
        let name = file.file_name().expect("a name").to_string_lossy();
        if name == "tests.rs" || name.ends_with("_tests.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&file).expect("a source file");
        let code = strip_comments(&text);
        let entry = graph.entry(module.clone()).or_default();
        for named in named_modules(without_tests(&code)) {
            let named = match reexports.get(&named) {
                Some(m) if !modules.contains(&named) => m.clone(),
                _ => named,
            };
            if named != module && modules.contains(&named) {
                entry
                    .entry(named)
                    .or_default()
                    .insert(rel.display().to_string());
            }
        }
    }
    graph
}

/// The layers of docs/code-map.md: rows `| N | `module` | ... |` of its "Layers" table.
fn map_layers(map: &str) -> BTreeMap<String, u32> {
    let mut out = BTreeMap::new();
    for line in map.lines() {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        if cells.len() < 4 || !cells[0].is_empty() {
            continue;
        }
        let (Ok(layer), Some(name)) = (
            cells[1].parse::<u32>(),
            cells[2].strip_prefix('`').and_then(|s| s.strip_suffix('`')),
        ) else {
            continue;
        };
        let name = name.trim_end_matches('/').trim_end_matches(".rs");
        assert!(
            out.insert(name.to_string(), layer).is_none(),
            "docs/code-map.md places `{name}` twice"
        );
    }
    out
}

/// Every cycle (strongly connected component of more than one module), by Tarjan's algorithm.
fn cycles(graph: &Graph) -> Vec<Vec<String>> {
    struct State<'g> {
        graph: &'g Graph,
        index: BTreeMap<&'g str, usize>,
        low: BTreeMap<&'g str, usize>,
        stack: Vec<&'g str>,
        on: BTreeSet<&'g str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'g>(s: &mut State<'g>, v: &'g str) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        s.on.insert(v);
        if let Some(next) = s.graph.get(v) {
            for w in next.keys() {
                let w = w.as_str();
                if !s.index.contains_key(w) {
                    visit(s, w);
                    let lw = s.low[w];
                    let lv = s.low.get_mut(v).expect("visited");
                    *lv = (*lv).min(lw);
                } else if s.on.contains(w) {
                    let iw = s.index[w];
                    let lv = s.low.get_mut(v).expect("visited");
                    *lv = (*lv).min(iw);
                }
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = s.stack.pop().expect("on the stack");
                s.on.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                s.out.push(comp);
            }
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out
}

/// The crate-wide error enum (`tribez::Error`): it gathers the error of every layer, and every
/// public function of every layer returns it, so arrows into it are not layer arrows.
const EXEMPT: &[&str] = &["api_error"];

/// Every violation: cycles, imports that go up the layer order, modules the map does not place.
/// Arrows into [`EXEMPT`] modules are left out.
fn violations(graph: &Graph, layers: &BTreeMap<String, u32>) -> Vec<String> {
    let mut graph = graph.clone();
    for next in graph.values_mut() {
        next.retain(|b, _| !EXEMPT.contains(&b.as_str()));
    }
    let graph = &graph;
    let mut out = Vec::new();
    for comp in cycles(graph) {
        let mut text = format!("import cycle between {}:", comp.join(", "));
        for a in &comp {
            for (b, files) in &graph[a] {
                if comp.contains(b) {
                    let files: Vec<_> = files.iter().cloned().collect();
                    text += &format!("\n    {a} -> {b} ({})", files.join(", "));
                }
            }
        }
        out.push(text);
    }
    for (a, next) in graph {
        let Some(&la) = layers.get(a) else {
            out.push(format!("`{a}` has no layer in docs/code-map.md"));
            continue;
        };
        for (b, files) in next {
            if let Some(&lb) = layers.get(b)
                && lb > la
            {
                let files: Vec<_> = files.iter().cloned().collect();
                out.push(format!(
                    "`{a}` (layer {la}) imports `{b}` (layer {lb}), up the layer order: {}",
                    files.join(", ")
                ));
            }
        }
    }
    out
}

#[test]
fn the_library_layers_point_down_and_the_map_places_every_module() {
    let lib = std::fs::read_to_string(src_dir().join("lib.rs")).expect("lib.rs");
    let modules = declared_modules(&lib);
    let map = std::fs::read_to_string(map_path()).expect("docs/code-map.md");
    let layers = map_layers(&map);
    let mut problems = Vec::new();
    for m in &modules {
        if !layers.contains_key(m) {
            problems.push(format!(
                "module `{m}` (lib.rs) is not placed in docs/code-map.md's layer table"
            ));
        }
    }
    for m in layers.keys() {
        if !modules.contains(m) {
            problems.push(format!(
                "docs/code-map.md places `{m}`, which lib.rs does not declare"
            ));
        }
    }
    let graph = library_graph(&modules, &root_reexports(&lib));
    assert!(
        graph.len() > 20,
        "the library's modules were not read ({} found)",
        graph.len()
    );
    problems.extend(violations(&graph, &layers));
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

fn planted(edges: &[(&str, &str)]) -> Graph {
    let mut g = Graph::new();
    for (a, b) in edges {
        g.entry(a.to_string())
            .or_default()
            .entry(b.to_string())
            .or_default()
            .insert(format!("{a}.rs"));
        g.entry(b.to_string()).or_default();
    }
    g
}

#[test]
fn a_planted_cycle_and_an_upward_import_are_reported() {
    let layers: BTreeMap<String, u32> = [("a", 1), ("b", 2), ("c", 3)]
        .map(|(m, l)| (m.to_string(), l))
        .into();
    assert!(violations(&planted(&[("b", "a"), ("c", "b"), ("c", "a")]), &layers).is_empty());
    let found = violations(&planted(&[("b", "a"), ("c", "b"), ("a", "c")]), &layers);
    assert!(
        found
            .iter()
            .any(|v| v.starts_with("import cycle between a, b, c"))
    );
    assert!(
        found
            .iter()
            .any(|v| v.contains("`a` (layer 1) imports `c` (layer 3)"))
    );
    let found = violations(&planted(&[("a", "b")]), &layers);
    assert_eq!(found.len(), 1, "{found:?}");
    let found = violations(&planted(&[("d", "a")]), &layers);
    assert_eq!(found, ["`d` has no layer in docs/code-map.md"]);
}

#[test]
fn the_reader_finds_paths_and_groups_and_skips_comments() {
    let code = strip_comments(
        "use crate::a::B;\n/// [crate::doc]\nuse crate::{c, d::{E, F}, self};\n\
         // crate::comment\nfn f() { crate::g::h(); let s = \"crate::string\"; }\n\
         macro_rules! m { () => { $crate::i::j } }",
    );
    let found = named_modules(&code);
    let want: BTreeSet<String> = ["a", "c", "d", "g"].map(String::from).into();
    assert_eq!(found, want);
    let lib = "pub use a::{B, c::D as E};\npub use f::G;\npub use num::H;";
    let found = root_reexports(lib);
    let want: BTreeMap<String, String> = [("B", "a"), ("E", "a"), ("G", "f"), ("H", "num")]
        .map(|(n, m)| (n.to_string(), m.to_string()))
        .into();
    assert_eq!(found, want);
    let lib = "mod a;\npub mod b;\n#[cfg(test)]\nmod t;\npub(crate) mod c;";
    let want: BTreeSet<String> = ["a", "b", "c"].map(String::from).into();
    assert_eq!(declared_modules(lib), want);
}

/// The `.rs` files directly in `dir` (relative to the repository root), sorted.
fn files_in(root: &Path, dir: &str) -> Vec<String> {
    let mut out: Vec<String> = std::fs::read_dir(root.join(dir))
        .unwrap_or_else(|e| panic!("{dir}: {e}"))
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|e| e == "rs"))
        .map(|p| format!("{dir}/{}", p.file_name().expect("a name").to_string_lossy()))
        .collect();
    out.sort();
    out
}

#[test]
fn the_map_names_every_test_file_and_command_and_nothing_else() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let map = std::fs::read_to_string(map_path()).expect("docs/code-map.md");
    let mut problems = Vec::new();
    // every integration test file, by its path in the Tests table
    let named_tests: BTreeSet<String> = map
        .lines()
        .filter_map(|l| l.strip_prefix("| `"))
        .filter_map(|l| l.split('`').next())
        .filter(|p| p.contains("/tests/") && p.ends_with(".rs"))
        .map(String::from)
        .collect();
    let mut tests = files_in(&root, "crates/tribez/tests");
    tests.extend(files_in(&root, "crates/tribez-cli/tests"));
    for t in &tests {
        if !named_tests.contains(t) {
            problems.push(format!("test file {t} is not named in docs/code-map.md"));
        }
    }
    for t in &named_tests {
        if !tests.contains(t) {
            problems.push(format!("docs/code-map.md names {t}, which does not exist"));
        }
    }
    // every command file of the CLI, by its file name in the command line table
    for c in files_in(&root, "crates/tribez-cli/src/commands") {
        let name = c.rsplit('/').next().expect("a file name");
        if !map.contains(&format!("`{name}`")) && !map.contains(&format!("`commands/{name}`")) {
            problems.push(format!("command file {c} is not named in docs/code-map.md"));
        }
    }
    assert!(
        tests.len() > 20,
        "the test files were not read ({})",
        tests.len()
    );
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// The most lines a function may span, from its `fn` line to its closing brace.
const MAX_FN_LINES: usize = 150;

/// Functions allowed past [`MAX_FN_LINES`]: `(file under the repository root, function, why)`.
const LONG_FN_ALLOWED: &[(&str, &str, &str)] = &[(
    "crates/tribez/src/certify/filter/kernel.rs",
    "run_body",
    "numeric kernel: the compensated de Casteljau evaluation (error-free transformations), \
         one body inlined into every size, FMA and double-double variant",
)];

/// The name of the function a line declares (`pub(crate) const unsafe fn name<..>(..`), if it
/// declares one.
fn declared_fn(line: &str) -> Option<&str> {
    let mut rest = line.trim_start();
    if let Some(r) = rest.strip_prefix("pub") {
        rest = match r.strip_prefix('(') {
            Some(r) => r.split_once(')')?.1,
            None => r,
        }
        .trim_start();
    }
    for word in ["const ", "async ", "unsafe ", "extern \"C\" "] {
        rest = rest.strip_prefix(word).unwrap_or(rest);
    }
    let name = rest.strip_prefix("fn ")?;
    let end = name.find(|c: char| !is_ident(c)).unwrap_or(name.len());
    (end > 0).then(|| &name[..end])
}

/// The functions of `src` (test code left out: from a top-level `#[cfg(test)]` module on) with
/// their lengths in lines: from the `fn` line to the first line that is the same indentation
/// and `}`; a declaration ending in `;` or a body closed on its own line counts one.
fn fn_lengths(src: &str) -> Vec<(String, usize)> {
    let lines: Vec<&str> = src.lines().collect();
    let end = lines
        .windows(2)
        .position(|w| w[0] == "#[cfg(test)]" && w[1].starts_with("mod "))
        .unwrap_or(lines.len());
    let lines = &lines[..end];
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(name) = declared_fn(line) else {
            continue;
        };
        let indent = &line[..line.len() - line.trim_start().len()];
        let closing = format!("{indent}}}");
        let one_line = line.trim_end().ends_with(';') || line.trim_end().ends_with('}');
        let last = if one_line {
            i
        } else {
            (i..lines.len())
                .find(|&j| lines[j] == closing)
                .unwrap_or(lines.len() - 1)
        };
        out.push((name.to_string(), last - i + 1));
    }
    out
}

#[test]
fn no_function_outside_the_numeric_kernels_is_over_150_lines() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    rust_files(&root.join("crates/tribez/src"), &mut files);
    rust_files(&root.join("crates/tribez-cli/src"), &mut files);
    let mut problems = Vec::new();
    let mut long_allowed = BTreeSet::new();
    let mut counted = 0;
    for path in &files {
        let name = path.file_name().expect("a name").to_string_lossy();
        if name == "tests.rs" || name.ends_with("_tests.rs") {
            continue;
        }
        let rel = path
            .strip_prefix(&root)
            .expect("under the root")
            .to_string_lossy()
            .replace('\\', "/");
        let src = std::fs::read_to_string(path).expect("a source file");
        for (f, n) in fn_lengths(&src) {
            counted += 1;
            if n <= MAX_FN_LINES {
                continue;
            }
            if LONG_FN_ALLOWED
                .iter()
                .any(|(file, name, _)| *file == rel && *name == f)
            {
                long_allowed.insert((rel.clone(), f));
            } else {
                problems.push(format!(
                    "{rel}: fn {f} is {n} lines (at most {MAX_FN_LINES}): split it into named steps"
                ));
            }
        }
    }
    for (file, name, _) in LONG_FN_ALLOWED {
        if !long_allowed.contains(&(file.to_string(), name.to_string())) {
            problems.push(format!(
                "{file}: fn {name} is allowed to be long but is not (or is gone): remove it from LONG_FN_ALLOWED"
            ));
        }
    }
    assert!(counted > 1000, "the functions were not read ({counted})");
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

#[test]
fn the_function_reader_measures_from_fn_to_its_closing_brace() {
    let body = |n: usize| "    let x = 1;\n".repeat(n);
    let src = format!(
        "pub(crate) fn short() {{\n{}}}\n\nimpl A {{\n    pub const unsafe fn long(&self) {{\n{}    }}\n    fn one(&self) {{}}\n    fn decl(&self);\n}}\n#[cfg(test)]\nmod tests {{\n    fn in_tests() {{\n{}    }}\n}}\n",
        body(148),
        body(149),
        body(200)
    );
    assert_eq!(
        fn_lengths(&src),
        vec![
            ("short".to_string(), 150),
            ("long".to_string(), 151),
            ("one".to_string(), 1),
            ("decl".to_string(), 1),
        ]
    );
    assert_eq!(
        declared_fn("    pub(in crate::a) fn f<T>(x: T) {"),
        Some("f")
    );
    assert_eq!(declared_fn("    let fn_x = 1;"), None);
    assert_eq!(declared_fn("// fn g()"), None);
}
