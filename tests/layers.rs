//! The crate's layers point down only. Read from the sources as text (every `use`, every
//! `crate::`, `super::` and `self::` path, and paths through a module's own children):
//! - no files import each other in a circle, directly or through others;
//! - at every level of the tree, no sibling modules (files or folders) do;
//! - the core names no web or GPU type: only `render/` and `web/` may;
//! - the BlobTree engine needs nothing of the crate but the mesh.
//!
//! A failure names the circle and, for each step of it, a line that makes it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module path from the crate root (`["forms", "sweep", "surface"]`).
type Module = Vec<String>;

/// One source file of the crate.
struct Source {
    /// Its path below src/, with '/' between parts.
    path: String,
    /// The module it defines.
    module: Module,
    /// Its code with comments, strings and character literals blanked out.
    code: String,
}

/// The module a file below src/ defines: `lib.rs` is the root, `a/mod.rs` and `a.rs` are `a`.
fn module_of(path: &str) -> Module {
    let mut parts: Vec<String> = path
        .trim_end_matches(".rs")
        .split('/')
        .map(str::to_string)
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The code of `text` with comments, strings and character literals blanked (each replaced by
/// spaces or an empty literal), so that braces and paths in them are not read as code.
fn strip(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < chars.len() {
                if chars[i] == '/' && chars.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if chars[i] == '*' && chars.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            out.push(' ');
        } else if c == 'r' && matches!(next, Some('"' | '#')) && !ident_before(&chars, i) {
            let hashes = chars[i + 1..].iter().take_while(|&&h| h == '#').count();
            if chars.get(i + 1 + hashes) != Some(&'"') {
                out.push(c);
                i += 1;
                continue;
            }
            i += 2 + hashes;
            while i < chars.len() {
                if chars[i] == '"' && chars[i + 1..].iter().take(hashes).all(|&h| h == '#') {
                    i += 1 + hashes;
                    break;
                }
                i += 1;
            }
            out.push_str("\"\"");
        } else if c == '"' {
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                i += if chars[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if c == '\'' && next == Some('\\') {
            i += 2;
            while i < chars.len() && chars[i] != '\'' {
                i += 1;
            }
            i += 1;
            out.push_str("' '");
        } else if c == '\'' && chars.get(i + 2) == Some(&'\'') {
            i += 3;
            out.push_str("' '");
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// Whether the character before `i` continues an identifier (so an `r` there is no raw string).
fn ident_before(chars: &[char], i: usize) -> bool {
    i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_')
}

/// Splits `text` at the commas that are not inside braces.
fn top_level_items(text: &str) -> Vec<&str> {
    let (mut items, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, c) in text.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    items.push(&text[start..]);
    items
}

/// Every path a use tree names (`a::{b, c::{d, self}}` gives `a::b`, `a::c::d`, `a::c`).
fn expand_use(tree: &str, prefix: &str, out: &mut Vec<String>) {
    let tree = tree.trim();
    if tree.is_empty() {
        return;
    }
    if let Some(open) = tree.find('{') {
        let head = tree[..open].trim().trim_end_matches("::");
        let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
        let prefix = join(prefix, head);
        for item in top_level_items(inner) {
            expand_use(item, &prefix, out);
        }
    } else {
        let path = tree.split(" as ").next().unwrap_or(tree).trim();
        let path = path.trim_end_matches("::*");
        if path == "self" {
            out.push(prefix.to_string());
        } else {
            out.push(join(prefix, path));
        }
    }
}

fn join(prefix: &str, path: &str) -> String {
    match (prefix.is_empty(), path.is_empty()) {
        (true, _) => path.to_string(),
        (_, true) => prefix.to_string(),
        _ => format!("{prefix}::{path}"),
    }
}

/// A path that may name a module of this crate, with the line it stands on.
struct Reference {
    /// The module the code stands in (the file's, and any inline module's around it).
    within: Module,
    /// The path's segments as written.
    segments: Vec<String>,
    line: usize,
}

/// Every path in `source` that starts with `crate`, `super`, `self` or a child module the
/// file declares, read inside `use` trees too.
fn references(source: &Source) -> Vec<Reference> {
    let code = &source.code;
    let bytes = code.as_bytes();
    let children: BTreeSet<String> = declared_children(code);
    // The inline modules open at each byte: (name, brace depth inside it).
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut refs = Vec::new();
    let mut line = 1;
    let mut i = 0;
    let ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    while i < bytes.len() {
        let b = bytes[i];
        let starts_word = i == 0 || !(ident(bytes[i - 1]) || bytes[i - 1] == b':');
        if b == b'\n' {
            line += 1;
        } else if b == b'{' {
            depth += 1;
        } else if b == b'}' {
            if inline.last().is_some_and(|&(_, d)| d == depth) {
                inline.pop();
            }
            depth = depth.saturating_sub(1);
        } else if starts_word && code[i..].starts_with("mod ") {
            let rest = &code[i + 4..];
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let after = rest[name.len()..].trim_start();
            if after.starts_with('{') {
                inline.push((name, depth + 1));
            }
        } else if starts_word && code[i..].starts_with("use ") {
            let end = code[i..].find(';').map_or(code.len(), |e| i + e);
            let mut paths = Vec::new();
            expand_use(&code[i + 4..end], "", &mut paths);
            let within = within(&source.module, &inline);
            for path in paths {
                refs.push(Reference {
                    within: within.clone(),
                    segments: path.split("::").map(str::to_string).collect(),
                    line,
                });
            }
            line += code[i..end].matches('\n').count();
            i = end;
            continue;
        } else if starts_word && ident(b) {
            let end = code[i..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| i + e);
            let word = &code[i..end];
            let first = word.split("::").next().unwrap_or_default();
            if word.contains("::")
                && (matches!(first, "crate" | "super" | "self") || children.contains(first))
            {
                refs.push(Reference {
                    within: within(&source.module, &inline),
                    segments: word
                        .split("::")
                        .filter(|s| !s.is_empty())
                        .map(str::to_string)
                        .collect(),
                    line,
                });
            }
            i = end;
            continue;
        }
        i += 1;
    }
    refs
}

/// The module code stands in: the file's module and the inline modules open around it.
fn within(module: &Module, inline: &[(String, usize)]) -> Module {
    let mut m = module.clone();
    m.extend(inline.iter().map(|(name, _)| name.clone()));
    m
}

/// The modules a file declares as its children in files of their own (`mod x;`).
fn declared_children(code: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in code.lines() {
        let line = line.trim();
        let line = line
            .strip_prefix("pub(crate) ")
            .or_else(|| line.strip_prefix("pub "))
            .unwrap_or(line);
        if let Some(name) = line.strip_prefix("mod ").and_then(|r| r.strip_suffix(';')) {
            out.insert(name.trim().to_string());
        }
    }
    out
}

/// The module a reference names, from the crate root.
fn absolute(reference: &Reference, children: &BTreeSet<String>) -> Option<Module> {
    let mut segments = reference.segments.iter().peekable();
    let mut module = match segments.peek().map(|s| s.as_str()) {
        Some("crate") => {
            segments.next();
            Vec::new()
        }
        Some("super" | "self") => reference.within.clone(),
        Some(first) if children.contains(first) => reference.within.clone(),
        _ => return None,
    };
    for s in segments {
        match s.as_str() {
            "super" => {
                module.pop()?;
            }
            "self" => {}
            name => module.push(name.to_string()),
        }
    }
    Some(module)
}

/// One import between two files: the line of `from` that names `to`.
type Edges = BTreeMap<(String, String), usize>;

/// The imports between the files of the crate.
fn file_edges(sources: &[Source]) -> Edges {
    let files: BTreeMap<&Module, &str> = sources
        .iter()
        .map(|s| (&s.module, s.path.as_str()))
        .collect();
    let mut edges = Edges::new();
    for source in sources {
        let children = declared_children(&source.code);
        for reference in references(source) {
            let Some(mut module) = absolute(&reference, &children) else {
                continue;
            };
            // The longest prefix that is a file's module is the file named.
            let target = loop {
                if let Some(file) = files.get(&module) {
                    break Some(*file);
                }
                if module.pop().is_none() {
                    break None;
                }
            };
            match target {
                Some(to) if to != source.path && !module.is_empty() => {
                    edges
                        .entry((source.path.clone(), to.to_string()))
                        .or_insert(reference.line);
                }
                _ => {}
            }
        }
    }
    edges
}

/// The strongly connected sets of more than one node (Tarjan's algorithm): the circles.
fn circles(nodes: &BTreeSet<String>, edges: &BTreeSet<(String, String)>) -> Vec<Vec<String>> {
    struct Walk<'a> {
        next: BTreeMap<&'a str, Vec<&'a str>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        found: Vec<Vec<String>>,
    }
    impl<'a> Walk<'a> {
        fn visit(&mut self, v: &'a str) {
            let n = self.index.len();
            self.index.insert(v, n);
            self.low.insert(v, n);
            self.stack.push(v);
            self.on_stack.insert(v);
            for w in self.next.get(v).cloned().unwrap_or_default() {
                if !self.index.contains_key(w) {
                    self.visit(w);
                    let low = self.low[v].min(self.low[w]);
                    self.low.insert(v, low);
                } else if self.on_stack.contains(w) {
                    let low = self.low[v].min(self.index[w]);
                    self.low.insert(v, low);
                }
            }
            if self.low[v] == self.index[v] {
                let mut set = Vec::new();
                while let Some(w) = self.stack.pop() {
                    self.on_stack.remove(w);
                    set.push(w.to_string());
                    if w == v {
                        break;
                    }
                }
                if set.len() > 1 {
                    set.sort();
                    self.found.push(set);
                }
            }
        }
    }
    let mut walk = Walk {
        next: BTreeMap::new(),
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        found: Vec::new(),
    };
    for (a, b) in edges {
        walk.next.entry(a.as_str()).or_default().push(b.as_str());
    }
    for v in nodes {
        if !walk.index.contains_key(v.as_str()) {
            walk.visit(v);
        }
    }
    walk.found
}

/// Every circle of imports, between files and between the siblings of every folder, each
/// described with the lines that close it.
fn import_circles(sources: &[Source]) -> Vec<String> {
    let edges = file_edges(sources);
    let mut report = Vec::new();
    let files: BTreeSet<String> = sources.iter().map(|s| s.path.clone()).collect();
    let file_pairs: BTreeSet<(String, String)> = edges.keys().cloned().collect();
    for circle in circles(&files, &file_pairs) {
        let mut text = format!("files in a circle: {}", circle.join(", "));
        for ((from, to), line) in &edges {
            if circle.contains(from) && circle.contains(to) {
                text.push_str(&format!("\n    src/{from}:{line} names src/{to}"));
            }
        }
        report.push(text);
    }
    // Each folder's children: its files other than mod.rs and lib.rs, and its subfolders.
    let mut folders: BTreeSet<String> = BTreeSet::from([String::new()]);
    for f in &files {
        let mut parts: Vec<&str> = f.split('/').collect();
        parts.pop();
        for n in 1..=parts.len() {
            folders.insert(parts[..n].join("/"));
        }
    }
    for folder in &folders {
        let child = |file: &str| -> Option<String> {
            let rest = if folder.is_empty() {
                file
            } else {
                file.strip_prefix(folder.as_str())?.strip_prefix('/')?
            };
            match rest.split_once('/') {
                Some((dir, _)) => Some(format!("{dir}/")),
                None if rest == "mod.rs" || rest == "lib.rs" => None,
                None => Some(rest.to_string()),
            }
        };
        let mut units = BTreeSet::new();
        let mut pairs = BTreeSet::new();
        for (from, to) in edges.keys() {
            if let (Some(a), Some(b)) = (child(from), child(to)) {
                units.insert(a.clone());
                units.insert(b.clone());
                if a != b {
                    pairs.insert((a, b));
                }
            }
        }
        for circle in circles(&units, &pairs) {
            let mut text = format!("modules of src/{folder} in a circle: {}", circle.join(", "));
            for ((from, to), line) in &edges {
                if let (Some(a), Some(b)) = (child(from), child(to))
                    && a != b
                    && circle.contains(&a)
                    && circle.contains(&b)
                {
                    text.push_str(&format!(
                        "\n    {a} -> {b}: src/{from}:{line} names src/{to}"
                    ));
                }
            }
            report.push(text);
        }
    }
    report
}

/// The crate's sources below src/, but the command-line binary (a crate of its own).
fn crate_sources() -> Vec<Source> {
    fn walk(dir: &Path, root: &Path, out: &mut Vec<Source>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .expect("a readable folder")
            .map(|e| e.expect("a readable entry").path())
            .collect();
        entries.sort();
        for path in entries {
            let rel = path
                .strip_prefix(root)
                .expect("below src/")
                .to_string_lossy()
                .replace('\\', "/");
            if path.is_dir() {
                if rel != "bin" {
                    walk(&path, root, out);
                }
            } else if rel.ends_with(".rs") {
                let text = std::fs::read_to_string(&path).expect("a readable source");
                out.push(Source {
                    module: module_of(&rel),
                    code: strip(&text),
                    path: rel,
                });
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = Vec::new();
    walk(&root, &root, &mut out);
    out
}

#[test]
fn no_modules_import_each_other_in_a_circle() {
    let sources = crate_sources();
    assert!(sources.len() > 50, "{} sources read", sources.len());
    let edges = file_edges(&sources);
    assert!(edges.len() > 100, "only {} imports read", edges.len());
    let report = import_circles(&sources);
    assert!(report.is_empty(), "{}", report.join("\n"));
}

#[test]
fn the_core_names_no_web_or_gpu_type() {
    for source in crate_sources() {
        if source.path.starts_with("render/") || source.path.starts_with("web/") {
            continue;
        }
        for word in ["wgpu", "web_sys", "js_sys", "wasm_bindgen"] {
            let named = source
                .code
                .split(|c: char| !(c.is_alphanumeric() || c == '_'));
            assert!(
                !named.clone().any(|w| w == word),
                "src/{} names {word}: only render/ and web/ may",
                source.path
            );
        }
    }
}

#[test]
fn the_blobtree_engine_needs_only_the_mesh() {
    let sources = crate_sources();
    for ((from, to), line) in file_edges(&sources) {
        if from.starts_with("blobtree/") {
            assert!(
                to.starts_with("blobtree/") || to == "mesh.rs",
                "src/{from}:{line} names src/{to}: the engine knows nothing of shells"
            );
        }
    }
}

/// The README's "Adding a form" says what a new form touches. Every file that dispatches on
/// all kinds of form (it names `Form::Branching`, which a dispatch on every kind must) is
/// named there, and so is every function of `forms/mod.rs` that dispatches on `Form`: a list
/// that misses one sends the next form's author past a place that needs it.
#[test]
fn the_readmes_list_of_what_adding_a_form_touches_is_true() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
        .expect("the README");
    let start = readme
        .find("**Adding a form**")
        .expect("the README says how to add a form");
    let paragraph = &readme[start..];
    let paragraph = &paragraph[..paragraph.find("\n\n").unwrap_or(paragraph.len())];
    let named: BTreeSet<&str> = paragraph.split('`').skip(1).step_by(2).collect();
    let sources = crate_sources();
    let dispatching: Vec<&Source> = sources
        .iter()
        .filter(|s| s.code.contains("Form::Branching"))
        .collect();
    assert!(
        dispatching.len() >= 3,
        "{} files dispatch",
        dispatching.len()
    );
    for source in &dispatching {
        assert!(
            named.contains(source.path.as_str()),
            "src/{} dispatches on every kind of form; the README's \"Adding a form\" does not name it",
            source.path
        );
    }
    let forms = sources
        .iter()
        .find(|s| s.path == "forms/mod.rs")
        .expect("forms/mod.rs");
    let functions = forms.code.split("fn ").skip(1);
    let mut seen = 0;
    for function in functions {
        let name: String = function
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if function.contains("Form::") {
            seen += 1;
            assert!(
                named.contains(name.as_str()),
                "forms/mod.rs's {name} dispatches on Form; the README's \"Adding a form\" does not name it"
            );
        }
    }
    assert!(seen >= 4, "only {seen} functions of forms/mod.rs dispatch");
}

/// Sources given as (path, text), as if they were the crate's.
fn sources_of(files: &[(&str, &str)]) -> Vec<Source> {
    files
        .iter()
        .map(|(path, text)| Source {
            path: path.to_string(),
            module: module_of(path),
            code: strip(text),
        })
        .collect()
}

#[test]
fn the_check_finds_circles_of_every_kind_and_ignores_comments_and_strings() {
    // Two files naming each other through `super::` and a use tree.
    let files = sources_of(&[
        ("lib.rs", "pub mod a;"),
        ("a/mod.rs", "pub mod x;\npub mod y;"),
        ("a/x.rs", "use super::{y::Y, z};\npub struct X;"),
        ("a/y.rs", "pub struct Y(crate::a::x::X);"),
    ]);
    let report = import_circles(&files);
    assert!(
        report
            .iter()
            .any(|r| r.starts_with("files in a circle: a/x.rs, a/y.rs")),
        "{report:?}"
    );
    // Folders in a circle though no two files are: b/one -> c/two -> b/three.
    let files = sources_of(&[
        ("lib.rs", "pub mod b;\npub mod c;"),
        ("b/mod.rs", "pub mod one;\npub mod three;"),
        ("b/one.rs", "use crate::c::two::Two;"),
        ("b/three.rs", "pub struct Three;"),
        ("c/mod.rs", "pub mod two;"),
        ("c/two.rs", "pub struct Two(crate::b::three::Three);"),
    ]);
    let report = import_circles(&files);
    assert!(
        report
            .iter()
            .any(|r| r.starts_with("modules of src/ in a circle: b/, c/")),
        "{report:?}"
    );
    // A parent reaching its children by name, and a child reaching back up, is a circle too.
    let files = sources_of(&[
        ("lib.rs", "pub mod d;"),
        (
            "d/mod.rs",
            "pub mod e;\npub fn f() { e::g() }\npub struct H;",
        ),
        ("d/e.rs", "pub fn g() { let _ = super::H; }"),
    ]);
    assert_eq!(import_circles(&files).len(), 1, "d/mod.rs <-> d/e.rs");
    // Test modules inside a file: `super` is the file itself.
    let files = sources_of(&[
        ("lib.rs", "pub mod k;\npub mod m;"),
        (
            "k.rs",
            "pub fn k() {}\n#[cfg(test)]\nmod tests {\n    use super::*;\n}",
        ),
        (
            "m.rs",
            "// crate::k::k() in a comment\nconst S: &str = \"crate::k\";\nconst C: char = '{';\npub fn m() { let _ = r#\"}crate::k\"#; }",
        ),
    ]);
    assert!(import_circles(&files).is_empty());
    assert!(file_edges(&files).is_empty(), "{:?}", file_edges(&files));
}
