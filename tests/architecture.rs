//! The architecture of the workspace, checked on its source.
//!
//! The test reads every crate's `crates/*/src` and builds the crate's module graph: a node is a
//! module file (`foo.rs` or `foo/mod.rs`; `lib.rs` or `main.rs` is the crate root), an edge runs
//! from a file to each other module file it names a path into. It then enforces:
//!
//! - **No import cycle** between the module files of any crate. Files in a cycle can only be read,
//!   tested and moved together; a cycle is reported as its files and the names that tie them.
//! - **The core's layers** ([`CORE_LAYERS`]). From the ground up: the error types and the float
//!   trait; the inputs (what the user describes and its validation); one contact; one ball; the
//!   whole screw; the real-time evaluator and the torque map. A module file may import from its own
//!   layer and from the layers below, never from above, so each layer can be read and checked
//!   against the paper without anything built on it. `lib.rs` is exempt: it re-exports. A new
//!   top-level module of the core fails the test until it is placed in the layer list.
//! - **The core's folders are hubs.** A folder's `mod.rs` declares its files, says what the
//!   folder is and re-exports; no file of the folder imports from it (what the files share lives
//!   in a file of its own), so the folder's files form no cycle through it.
//! - **The command line's commands are shells.** A command (`crates/cli/src/commands/*.rs`) only
//!   translates: flags into core calls, results into output, through the shared modules of the
//!   command line. So no command imports another command, and no shared module imports a command;
//!   only `main.rs` (which dispatches) and `commands/mod.rs` (which declares them and holds what
//!   every command needs) may.
//! - **The command line's figures are leaves.** A figure (`crates/cli/src/plots/*.rs`) draws what
//!   a command hands it; only commands import a figure (and `main.rs`, `plots/mod.rs`), and a
//!   figure imports no other figure, only what every figure shares (`plots/figure.rs`), so each
//!   figure can change without touching another.
//!
//! How the source is read (std only, no parser crate):
//! - comments (`//`, `///`, `//!`, `/* */`) and string, byte-string, raw-string and char literals
//!   are dropped before anything is read, so doc links and messages make no edges;
//! - an item annotated `#[cfg(test)]` that is a module (`mod tests { .. }`) or a `use` is skipped
//!   whole: test code may import freely;
//! - edges come from `use` items of any visibility (brace groups expanded, `self` in a group is
//!   the module itself) and from paths anywhere in code that start at `crate::`, `super::`,
//!   `self::`, a child module, or a name a `use` brought into scope; `super::` and `self::` resolve
//!   from the module the path is written in (inline `mod name { .. }` blocks included);
//!   `mod foo;` declarations are not edges;
//! - a path resolves to the longest prefix of it that is a module file. When the next name is one
//!   that file only brings in with a `use` (a re-export such as `pub use`), the path follows it to
//!   the file that defines the name (none if that is outside the crate), so re-export hubs
//!   (`lib.rs`, a folder's `mod.rs`) neither hide a dependency nor make a false cycle. An edge to
//!   the file's own module is ignored;
//! - a crate's src/bin folder is not read (each binary there is a crate of its own).
//!
//! Run with `--nocapture` to see the module and edge counts per crate.
#![expect(clippy::std_instead_of_alloc, reason = "a std test program: the no_std lints are for the library crates")]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The core's top-level modules in layers, from the ground up. A module file may import from its
/// own layer and from the layers below it, never from a layer above. A new top-level module of
/// the core must be placed here (the test fails until it is).
const CORE_LAYERS: &[&[&str]] = &[
    // Foundation: the error types and the float trait (f64, f32) every layer shares.
    &["error", "real"],
    // What the user describes (geometry, operating point, options, extensions) and its validation.
    &["input"],
    // One contact: Hertz, creepages, creep forces, saturation, FASTSIM.
    &["contact"],
    // One ball's quasi-static balance and its solvers.
    &["ball"],
    // The load of every ball and the torque of the whole screw.
    &["screw"],
    // The torque for a control loop (the evaluator) and the torque map.
    &["realtime"],
];

/// The folder of the command line's commands, under `crates/cli/src`.
const CLI_COMMANDS: &str = "commands";

/// The folder of the command line's figures, under `crates/cli/src`, and its module of what every
/// figure shares.
const CLI_PLOTS: &str = "plots";
const CLI_PLOTS_SHARED: &str = "figure";

// ---------------------------------------------------------------------------------------------
// Tokens: the source without comments and literals.
// ---------------------------------------------------------------------------------------------

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Ident,
    Punct,
    Literal,
}

#[derive(Debug, Clone)]
struct Token {
    kind: Kind,
    text: String,
    line: usize,
}

impl Token {
    /// Whether this is the identifier or punctuation `s` (never a literal).
    fn is(&self, s: &str) -> bool {
        self.kind != Kind::Literal && self.text == s
    }
}

/// Whether token `i` exists and is `s`.
fn at(tokens: &[Token], i: usize, s: &str) -> bool {
    tokens.get(i).is_some_and(|t| t.is(s))
}

fn is_ident_start(c: char) -> bool {
    c == '_' || c.is_alphabetic()
}

fn is_ident_continue(c: char) -> bool {
    c == '_' || c.is_alphanumeric()
}

/// Splits Rust source into identifiers, punctuation (`::` as one token) and literals; comments
/// are dropped and every literal becomes an empty `Literal` token.
fn tokenize(src: &str) -> Vec<Token> {
    let chars: Vec<char> = src.chars().collect();
    let mut tokens = Vec::new();
    let mut line = 1;
    let mut i = 0;
    let literal = |line| Token { kind: Kind::Literal, text: String::new(), line };
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            i = skip_block_comment(&chars, i, &mut line);
        } else if c == '"' {
            tokens.push(literal(line));
            i = skip_string(&chars, i + 1, &mut line);
        } else if c == '\'' {
            match char_literal_end(&chars, i) {
                Some(end) => {
                    tokens.push(literal(line));
                    i = end;
                }
                None => {
                    // A lifetime or a label: the quote, then its name as an identifier.
                    tokens.push(Token { kind: Kind::Punct, text: "'".into(), line });
                    i += 1;
                }
            }
        } else if is_ident_start(c) {
            let start = i;
            while i < chars.len() && is_ident_continue(chars[i]) {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            match (word.as_str(), chars.get(i).copied()) {
                ("b" | "c", Some('"')) => {
                    tokens.push(literal(line));
                    i = skip_string(&chars, i + 1, &mut line);
                }
                ("b", Some('\'')) => {
                    tokens.push(literal(line));
                    i = char_literal_end(&chars, i).unwrap_or(i + 1);
                }
                ("r" | "br" | "cr", Some('"' | '#')) => {
                    let hashes = chars[i..].iter().take_while(|&&c| c == '#').count();
                    if chars.get(i + hashes) == Some(&'"') {
                        tokens.push(literal(line));
                        i = skip_raw_string(&chars, i + hashes + 1, hashes, &mut line);
                    } else if word == "r" && hashes == 1 {
                        // A raw identifier, `r#type`: the identifier without its prefix.
                        let start = i + 1;
                        i = start;
                        while i < chars.len() && is_ident_continue(chars[i]) {
                            i += 1;
                        }
                        tokens.push(Token { kind: Kind::Ident, text: chars[start..i].iter().collect(), line });
                    } else {
                        tokens.push(Token { kind: Kind::Ident, text: word, line });
                    }
                }
                _ => tokens.push(Token { kind: Kind::Ident, text: word, line }),
            }
        } else if c.is_ascii_digit() {
            while i < chars.len()
                && (is_ident_continue(chars[i])
                    || (chars[i] == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)))
            {
                i += 1;
            }
            tokens.push(literal(line));
        } else if c == ':' && next == Some(':') {
            tokens.push(Token { kind: Kind::Punct, text: "::".into(), line });
            i += 2;
        } else {
            tokens.push(Token { kind: Kind::Punct, text: c.to_string(), line });
            i += 1;
        }
    }
    tokens
}

/// Past the (nested) block comment opening at `i`.
fn skip_block_comment(chars: &[char], mut i: usize, line: &mut usize) -> usize {
    let mut depth = 0;
    while i < chars.len() {
        match (chars[i], chars.get(i + 1).copied()) {
            ('/', Some('*')) => {
                depth += 1;
                i += 2;
            }
            ('*', Some('/')) => {
                depth -= 1;
                i += 2;
                if depth == 0 {
                    return i;
                }
            }
            (c, _) => {
                if c == '\n' {
                    *line += 1;
                }
                i += 1;
            }
        }
    }
    i
}

/// Past the closing quote of a string whose content starts at `i`.
fn skip_string(chars: &[char], mut i: usize, line: &mut usize) -> usize {
    while i < chars.len() {
        match chars[i] {
            '\\' => {
                if chars.get(i + 1) == Some(&'\n') {
                    *line += 1;
                }
                i += 2;
            }
            '"' => return i + 1,
            c => {
                if c == '\n' {
                    *line += 1;
                }
                i += 1;
            }
        }
    }
    i
}

/// Past the end (`"` and `hashes` hashes) of a raw string whose content starts at `i`.
fn skip_raw_string(chars: &[char], mut i: usize, hashes: usize, line: &mut usize) -> usize {
    while i < chars.len() {
        if chars[i] == '"' && chars[i + 1..].iter().take(hashes).filter(|&&c| c == '#').count() == hashes {
            return i + 1 + hashes;
        }
        if chars[i] == '\n' {
            *line += 1;
        }
        i += 1;
    }
    i
}

/// The end of the char literal whose quote is at `i`, or `None` for a lifetime or label.
fn char_literal_end(chars: &[char], i: usize) -> Option<usize> {
    if chars.get(i + 1) == Some(&'\\') {
        // An escape: `'\n'`, `'\''`, `'\u{41}'`.
        let close = chars[i + 3..].iter().position(|&c| c == '\'')?;
        Some(i + 3 + close + 1)
    } else if chars.get(i + 2) == Some(&'\'') {
        Some(i + 3)
    } else {
        None
    }
}

/// The tokens without the items annotated exactly `#[cfg(test)]` that are a module (to the end of
/// its block) or a `use` (to its `;`).
fn without_test_items(tokens: &[Token]) -> Vec<Token> {
    const CFG_TEST: [&str; 7] = ["#", "[", "cfg", "(", "test", ")", "]"];
    let mut kept = Vec::with_capacity(tokens.len());
    let mut i = 0;
    while i < tokens.len() {
        let is_cfg_test = CFG_TEST.iter().enumerate().all(|(k, s)| at(tokens, i + k, s));
        let test_item = if is_cfg_test { test_item_end(tokens, i + CFG_TEST.len()) } else { None };
        if let Some(end) = test_item {
            i = end;
            continue;
        }
        kept.push(tokens[i].clone());
        i += 1;
    }
    kept
}

/// Past the end of the item starting at `i` (after its `#[cfg(test)]`) if it is a module or a
/// `use`.
fn test_item_end(tokens: &[Token], mut i: usize) -> Option<usize> {
    while at(tokens, i, "#") && at(tokens, i + 1, "[") {
        i = matching_close(tokens, i + 1, "[", "]")? + 1;
    }
    if at(tokens, i, "pub") {
        i += 1;
        if at(tokens, i, "(") {
            i = matching_close(tokens, i, "(", ")")? + 1;
        }
    }
    if at(tokens, i, "mod") {
        match tokens.get(i + 2) {
            Some(t) if t.is("{") => Some(matching_close(tokens, i + 2, "{", "}")? + 1),
            Some(t) if t.is(";") => Some(i + 3),
            _ => None,
        }
    } else if at(tokens, i, "use") {
        Some((i..tokens.len()).find(|&k| at(tokens, k, ";"))? + 1)
    } else {
        None
    }
}

/// The index of the `close` matching the `open` at `i`.
fn matching_close(tokens: &[Token], i: usize, open: &str, close: &str) -> Option<usize> {
    let mut depth = 0;
    for (k, t) in tokens.iter().enumerate().skip(i) {
        if t.is(open) {
            depth += 1;
        } else if t.is(close) {
            depth -= 1;
            if depth == 0 {
                return Some(k);
            }
        }
    }
    None
}

// ---------------------------------------------------------------------------------------------
// One file: the paths it names and the names its `use` items bring into scope.
// ---------------------------------------------------------------------------------------------

/// A path written in a file, as written, with the module it is written in.
#[derive(Debug, Clone)]
struct PathRef {
    scope: Vec<String>,
    segments: Vec<String>,
    line: usize,
}

/// One leaf of a `use` tree: its full path (a leading `::` kept as a segment) and its alias.
#[derive(Debug)]
struct UseLeaf {
    segments: Vec<String>,
    alias: Option<String>,
    line: usize,
}

impl UseLeaf {
    /// The name this leaf brings into scope (none for a glob or `as _`).
    fn bound_name(&self) -> Option<&str> {
        match (&self.alias, self.segments.last()) {
            (Some(alias), _) if alias == "_" => None,
            (Some(alias), _) => Some(alias),
            (None, Some(last)) if last != "*" && last != "::" => Some(last),
            _ => None,
        }
    }
}

#[derive(Debug, Default)]
struct ParsedFile {
    /// Every path the file names (`use` leaves and paths in code).
    paths: Vec<PathRef>,
    /// (scope, name, path as written): the names `use` items bring into scope.
    bindings: Vec<(Vec<String>, String, Vec<String>)>,
    /// Inline modules (`mod name { .. }`), by full module path.
    inline_modules: Vec<Vec<String>>,
}

/// Reads the paths of the file whose module path is `module`.
fn parse_file(module: &[String], src: &str) -> ParsedFile {
    let tokens = without_test_items(&tokenize(src));
    let mut parsed = ParsedFile::default();
    // Open inline modules: (name, brace depth inside its block).
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0;
    let mut i = 0;
    while i < tokens.len() {
        let scope: Vec<String> = module.iter().cloned().chain(inline.iter().map(|(name, _)| name.clone())).collect();
        let token = &tokens[i];
        if token.kind == Kind::Ident && token.text == "use" {
            let mut leaves = Vec::new();
            i = parse_use_tree(&tokens, i + 1, &[], &mut leaves);
            while i < tokens.len() && !tokens[i].is(";") && !tokens[i].is("}") {
                i += 1;
            }
            for mut leaf in leaves {
                if leaf.segments.len() > 1 && leaf.segments.last().is_some_and(|s| s == "self") {
                    leaf.segments.pop();
                }
                if let Some(name) = leaf.bound_name() {
                    parsed.bindings.push((scope.clone(), name.to_string(), leaf.segments.clone()));
                }
                parsed.paths.push(PathRef { scope: scope.clone(), segments: leaf.segments, line: leaf.line });
            }
            continue;
        }
        if token.is("mod") && tokens.get(i + 1).is_some_and(|t| t.kind == Kind::Ident) && at(&tokens, i + 2, "{") {
            let name = tokens[i + 1].text.clone();
            parsed.inline_modules.push(scope.iter().cloned().chain([name.clone()]).collect());
            inline.push((name, depth + 1));
            i += 2;
            continue;
        }
        if token.is("{") {
            depth += 1;
        } else if token.is("}") {
            if inline.last().is_some_and(|&(_, d)| d == depth) {
                inline.pop();
            }
            depth = depth.saturating_sub(1);
        } else if let Some((segments, end)) = path_at(&tokens, i) {
            parsed.paths.push(PathRef { scope, segments, line: token.line });
            i = end;
            continue;
        }
        i += 1;
    }
    parsed
}

/// Reads the `use` tree starting at `i` under `prefix` into `leaves`; returns the index past it.
fn parse_use_tree(tokens: &[Token], mut i: usize, prefix: &[String], leaves: &mut Vec<UseLeaf>) -> usize {
    let mut path = prefix.to_vec();
    if at(tokens, i, "::") {
        // `use ::name`: an external crate.
        path.push("::".into());
        i += 1;
    }
    loop {
        let Some(token) = tokens.get(i) else { return i };
        if token.is("{") {
            i += 1;
            while i < tokens.len() && !tokens[i].is("}") {
                let next = parse_use_tree(tokens, i, &path, leaves);
                if next == i {
                    break;
                }
                i = next;
                if at(tokens, i, ",") {
                    i += 1;
                }
            }
            return i + 1;
        } else if token.is("*") {
            path.push("*".into());
            leaves.push(UseLeaf { segments: path, alias: None, line: token.line });
            return i + 1;
        } else if token.kind == Kind::Ident {
            path.push(token.text.clone());
            i += 1;
            if at(tokens, i, "::") {
                i += 1;
                continue;
            }
            let mut alias = None;
            if at(tokens, i, "as") {
                alias = tokens.get(i + 1).map(|name| name.text.clone());
                i += 2;
            }
            leaves.push(UseLeaf { segments: path, alias, line: token.line });
            return i;
        } else {
            return i;
        }
    }
}

/// The path of two or more segments (`a::b::c`) that starts at token `i`, and the index past it.
fn path_at(tokens: &[Token], i: usize) -> Option<(Vec<String>, usize)> {
    let is_ident = |k: usize| tokens.get(k).is_some_and(|t| t.kind == Kind::Ident);
    if !is_ident(i) || !at(tokens, i + 1, "::") || !is_ident(i + 2) {
        return None;
    }
    if i > 0 {
        let before = &tokens[i - 1];
        // Inside a longer path, a macro's `$crate`, a method call, or `pub(in path)`.
        if before.is("::") || before.is("$") || before.is(".") || (before.is("in") && i > 1 && at(tokens, i - 2, "(")) {
            return None;
        }
    }
    let mut segments = vec![tokens[i].text.clone()];
    let mut k = i + 1;
    while at(tokens, k, "::") && is_ident(k + 1) {
        segments.push(tokens[k + 1].text.clone());
        k += 2;
    }
    Some((segments, k))
}

// ---------------------------------------------------------------------------------------------
// One crate: its module files and the edges between them.
// ---------------------------------------------------------------------------------------------

/// An edge between two module files: the names that tie them and the first line naming one.
#[derive(Debug, Clone, Default)]
struct Edge {
    names: BTreeSet<String>,
    line: usize,
}

#[derive(Debug)]
struct Crate {
    /// `crates/<name>` on disk.
    name: String,
    /// The files, relative to `src/`, and their module paths (the root's is empty).
    files: Vec<String>,
    modules: Vec<Vec<String>>,
    /// (from, to) file indices to the edge.
    edges: BTreeMap<(usize, usize), Edge>,
}

/// Name resolution inside one crate.
struct Resolver<'a> {
    index: BTreeMap<&'a [String], usize>,
    /// Scope (module path) to the child module names declared in it (files and inline).
    children: BTreeMap<Vec<String>, BTreeSet<String>>,
    /// Scope to name to the path as written in that scope: what its `use` items bring in.
    bindings: BTreeMap<Vec<String>, BTreeMap<String, Vec<String>>>,
}

impl Resolver<'_> {
    /// The path from the crate root, or `None` if it leads outside the crate.
    fn absolute(&self, scope: &[String], segments: &[String], hops: usize) -> Option<Vec<String>> {
        if hops > 16 {
            return None;
        }
        let (first, rest) = segments.split_first()?;
        let mut base: Vec<String> = match first.as_str() {
            "crate" => Vec::new(),
            "self" => scope.to_vec(),
            "super" => {
                let mut base = scope.to_vec();
                base.pop()?;
                let supers = rest.iter().take_while(|s| *s == "super").count();
                for _ in 0..supers {
                    base.pop()?;
                }
                base.extend(rest[supers..].iter().cloned());
                return Some(base);
            }
            name if self.children.get(scope).is_some_and(|c| c.contains(name)) => {
                scope.iter().cloned().chain([name.to_string()]).collect()
            }
            name => {
                let written = self.bindings.get(scope)?.get(name)?;
                if written.len() == 1 && written[0] == *name {
                    return None;
                }
                self.absolute(scope, written, hops + 1)?
            }
        };
        base.extend(rest.iter().cloned());
        Some(base)
    }

    /// The module file an absolute path lands in (through re-exports), and the name it names
    /// there; `None` if a re-export leads outside the crate.
    fn target(&self, mut path: Vec<String>) -> Option<(usize, String)> {
        for _ in 0..16 {
            let k = (0..=path.len()).rev().find(|&k| self.index.contains_key(&path[..k]))?;
            let file = self.index[&path[..k]];
            let Some(item) = path.get(k) else {
                return Some((file, path.last().cloned().unwrap_or_else(|| "crate".into())));
            };
            let Some(written) = self.bindings.get(&path[..k]).and_then(|b| b.get(item)) else {
                return Some((file, item.clone()));
            };
            let mut next = self.absolute(&path[..k], written, 0)?;
            next.extend(path[k + 1..].iter().cloned());
            if next == path {
                return Some((file, item.clone()));
            }
            path = next;
        }
        None
    }
}

/// The module path of a file given relative to `src/`.
fn module_path(file: &str) -> Vec<String> {
    if file == "lib.rs" || file == "main.rs" {
        return Vec::new();
    }
    let mut parts: Vec<String> = file.trim_end_matches(".rs").split('/').map(String::from).collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

impl Crate {
    /// The crate from its sources: (path relative to `src/`, text).
    fn from_sources(name: &str, sources: &[(String, String)]) -> Self {
        let files: Vec<String> = sources.iter().map(|(file, _)| file.clone()).collect();
        let modules: Vec<Vec<String>> = files.iter().map(|f| module_path(f)).collect();
        let mut index = BTreeMap::new();
        for (i, module) in modules.iter().enumerate() {
            if let Some(other) = index.insert(module.as_slice(), i) {
                panic!(
                    "crates/{name}: {} and {} are the same module; the checker reads one crate root per \
                     package and one file per module",
                    files[other], files[i]
                );
            }
        }
        let parsed: Vec<ParsedFile> = sources.iter().zip(&modules).map(|((_, text), m)| parse_file(m, text)).collect();
        let mut children: BTreeMap<Vec<String>, BTreeSet<String>> = BTreeMap::new();
        for module in modules.iter().chain(parsed.iter().flat_map(|p| &p.inline_modules)) {
            if let Some((last, parent)) = module.split_last() {
                children.entry(parent.to_vec()).or_default().insert(last.clone());
            }
        }
        let mut bindings: BTreeMap<Vec<String>, BTreeMap<String, Vec<String>>> = BTreeMap::new();
        for (scope, name, written) in parsed.iter().flat_map(|p| &p.bindings) {
            bindings.entry(scope.clone()).or_default().entry(name.clone()).or_insert_with(|| written.clone());
        }
        let resolver = Resolver { index, children, bindings };
        let mut edges: BTreeMap<(usize, usize), Edge> = BTreeMap::new();
        for (from, file) in parsed.iter().enumerate() {
            for path in &file.paths {
                let Some(absolute) = resolver.absolute(&path.scope, &path.segments, 0) else { continue };
                let Some((to, name)) = resolver.target(absolute) else { continue };
                if to != from {
                    let edge = edges.entry((from, to)).or_insert_with(|| Edge { line: path.line, ..Edge::default() });
                    edge.names.insert(name);
                    edge.line = edge.line.min(path.line);
                }
            }
        }
        Crate { name: name.to_string(), files, modules, edges }
    }

    /// The crate `crates/<name>` from disk (its src/bin folder left out: each binary there is a crate
    /// of its own).
    fn load(dir: &Path) -> Self {
        let src = dir.join("src");
        let mut paths = Vec::new();
        collect_rs_files(&src, &mut paths);
        let mut sources: Vec<(String, String)> = paths
            .iter()
            .map(|path| {
                let rel = path.strip_prefix(&src).unwrap();
                let rel = rel.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/");
                let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                (rel, text)
            })
            .filter(|(rel, _)| !rel.starts_with("bin/"))
            .collect();
        sources.sort();
        Self::from_sources(&dir.file_name().unwrap().to_string_lossy(), &sources)
    }

    /// Where file `i` is, for messages.
    fn path(&self, i: usize) -> String {
        format!("crates/{}/src/{}", self.name, self.files[i])
    }

    /// One message per import cycle (strongly connected set of files): its files and the names
    /// that tie them.
    fn cycles(&self) -> Vec<String> {
        let mut next: Vec<Vec<usize>> = vec![Vec::new(); self.files.len()];
        for &(from, to) in self.edges.keys() {
            next[from].push(to);
        }
        strongly_connected(&next)
            .into_iter()
            .filter(|component| component.len() > 1)
            .map(|component| {
                let mut files: Vec<usize> = component.clone();
                files.sort_by(|&a, &b| self.files[a].cmp(&self.files[b]));
                let list: Vec<&str> = files.iter().map(|&f| self.files[f].as_str()).collect();
                let mut message =
                    format!("crates/{}/src: import cycle among {} files: {}", self.name, files.len(), list.join(", "));
                for (&(from, to), edge) in &self.edges {
                    if component.contains(&from) && component.contains(&to) {
                        let names: Vec<&str> = edge.names.iter().map(String::as_str).collect();
                        message += &format!("\n    {} -> {} ({})", self.files[from], self.files[to], names.join(", "));
                    }
                }
                message
            })
            .collect()
    }
}

/// Every `.rs` file under `dir`.
fn collect_rs_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let entries = std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for entry in entries {
        let path = entry.unwrap().path();
        if path.is_dir() {
            collect_rs_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The strongly connected components of a directed graph (Tarjan).
fn strongly_connected(next: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct Tarjan<'a> {
        next: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on_stack: Vec<bool>,
        stack: Vec<usize>,
        counter: usize,
        components: Vec<Vec<usize>>,
    }
    impl Tarjan<'_> {
        fn visit(&mut self, v: usize) {
            self.index[v] = Some(self.counter);
            self.low[v] = self.counter;
            self.counter += 1;
            self.stack.push(v);
            self.on_stack[v] = true;
            for k in 0..self.next[v].len() {
                let w = self.next[v][k];
                match self.index[w] {
                    None => {
                        self.visit(w);
                        self.low[v] = self.low[v].min(self.low[w]);
                    }
                    Some(index) if self.on_stack[w] => self.low[v] = self.low[v].min(index),
                    Some(_) => {}
                }
            }
            if Some(self.low[v]) == self.index[v] {
                let mut component = Vec::new();
                while let Some(w) = self.stack.pop() {
                    self.on_stack[w] = false;
                    component.push(w);
                    if w == v {
                        break;
                    }
                }
                self.components.push(component);
            }
        }
    }
    let n = next.len();
    let mut tarjan = Tarjan {
        next,
        index: vec![None; n],
        low: vec![0; n],
        on_stack: vec![false; n],
        stack: Vec::new(),
        counter: 0,
        components: Vec::new(),
    };
    for v in 0..n {
        if tarjan.index[v].is_none() {
            tarjan.visit(v);
        }
    }
    tarjan.components
}

// ---------------------------------------------------------------------------------------------
// The rules.
// ---------------------------------------------------------------------------------------------

/// The core's layer rule: one message per file in no layer and per import from a layer above.
fn layer_violations(core: &Crate, layers: &[&[&str]]) -> Vec<String> {
    let layer_name = |layer: usize| match layers.get(layer) {
        Some(names) => names.join("/"),
        None => "none".to_string(),
    };
    // `None`: the crate root (exempt); `Some(Err)`: a top-level module in no layer.
    let layer_of = |file: usize| -> Option<Result<usize, String>> {
        let top = core.modules[file].first()?;
        let layer = layers.iter().position(|names| names.contains(&top.as_str()));
        Some(match layer {
            Some(layer) => Ok(layer),
            None => Err(top.clone()),
        })
    };
    let mut violations = Vec::new();
    let mut unplaced = BTreeSet::new();
    for file in 0..core.files.len() {
        let Some(Err(top)) = layer_of(file) else { continue };
        if unplaced.insert(top.clone()) {
            violations.push(format!(
                "{}: the core's top-level module `{top}` is in no layer: place it in CORE_LAYERS at the top of \
                 tests/architecture.rs",
                core.path(file)
            ));
        }
    }
    for (&(from, to), edge) in &core.edges {
        let (Some(Ok(from_layer)), Some(Ok(to_layer))) = (layer_of(from), layer_of(to)) else { continue };
        if to_layer > from_layer {
            let names: Vec<&str> = edge.names.iter().map(String::as_str).collect();
            violations.push(format!(
                "{}:{} (layer {}) imports {} (layer {}, above it): {}",
                core.path(from),
                edge.line,
                layer_name(from_layer),
                core.files[to],
                layer_name(to_layer),
                names.join(", ")
            ));
        }
    }
    violations
}

/// The command line's shell rule: one message per import of a command by another command or by a
/// shared module.
fn command_violations(cli: &Crate, commands: &str) -> Vec<String> {
    // The command a file belongs to (`commands/<name>.rs` or `commands/<name>/..`).
    let command_of = |file: usize| {
        let module = &cli.modules[file];
        (module.len() >= 2 && module[0] == commands).then(|| module[1].clone())
    };
    let mut violations = Vec::new();
    for (&(from, to), edge) in &cli.edges {
        let Some(target) = command_of(to) else { continue };
        let names: Vec<&str> = edge.names.iter().map(String::as_str).collect();
        let what = match (command_of(from), cli.modules[from].as_slice()) {
            (Some(source), _) if source != target => "a command imports another command",
            (Some(_), _) => continue,
            // The root dispatches, `commands/mod.rs` declares them.
            (None, []) => continue,
            (None, [folder]) if folder == commands => continue,
            (None, _) => "a shared module imports a command",
        };
        violations.push(format!("{}:{}: {what}: {} ({})", cli.path(from), edge.line, cli.files[to], names.join(", ")));
    }
    violations
}

/// The command line's figure rule: one message per import of a figure by another figure or by a
/// module that is not a command.
fn figure_violations(cli: &Crate, plots: &str, shared: &str, commands: &str) -> Vec<String> {
    // The figure a file is (`plots/<name>.rs`, not the shared module).
    let figure_of = |file: usize| {
        let module = &cli.modules[file];
        (module.len() >= 2 && module[0] == plots && module[1] != shared).then(|| module[1].clone())
    };
    let mut violations = Vec::new();
    for (&(from, to), edge) in &cli.edges {
        let Some(target) = figure_of(to) else { continue };
        let names: Vec<&str> = edge.names.iter().map(String::as_str).collect();
        let what = match (figure_of(from), cli.modules[from].as_slice()) {
            (Some(source), _) if source == target => continue,
            (Some(_), _) => "a figure imports another figure",
            // The root, the commands, and `plots/mod.rs`, which declares the figures.
            (None, []) => continue,
            (None, [folder, ..]) if folder == commands => continue,
            (None, [folder]) if folder == plots => continue,
            (None, _) => "a module that is not a command imports a figure",
        };
        violations.push(format!("{}:{}: {what}: {} ({})", cli.path(from), edge.line, cli.files[to], names.join(", ")));
    }
    violations
}

/// The core's folder rule: a folder's `mod.rs` declares its files, says what the folder is and
/// re-exports; it defines nothing its own files import. One message per file of a folder that
/// imports from the folder's `mod.rs` (with the edges back through the re-exports, that is an
/// import cycle in the making: the evaluator's files, split out of one file, first had one).
fn hub_violations(c: &Crate) -> Vec<String> {
    let mut violations = Vec::new();
    for (&(from, to), edge) in &c.edges {
        let folder = &c.modules[to];
        if folder.is_empty() || !c.files[to].ends_with("mod.rs") {
            continue;
        }
        let inside = c.modules[from].len() > folder.len() && c.modules[from].starts_with(folder);
        if inside {
            let names: Vec<&str> = edge.names.iter().map(String::as_str).collect();
            violations.push(format!(
                "{}:{}: a file imports its own folder's mod.rs: {} ({})",
                c.path(from),
                edge.line,
                c.files[to],
                names.join(", ")
            ));
        }
    }
    violations
}

// ---------------------------------------------------------------------------------------------
// The workspace's tests.
// ---------------------------------------------------------------------------------------------

/// Every crate of the workspace, read once.
fn workspace() -> &'static [Crate] {
    static CRATES: OnceLock<Vec<Crate>> = OnceLock::new();
    CRATES.get_or_init(|| {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates");
        let mut dirs: Vec<PathBuf> = std::fs::read_dir(&root)
            .unwrap_or_else(|e| panic!("{}: {e}", root.display()))
            .map(|entry| entry.unwrap().path())
            .filter(|dir| dir.join("src").is_dir())
            .collect();
        dirs.sort();
        dirs.iter().map(|dir| Crate::load(dir)).collect()
    })
}

/// The crate `crates/<name>`, which must exist (a rule that finds no crate checks nothing).
fn krate(name: &str) -> &'static Crate {
    workspace().iter().find(|c| c.name == name).unwrap_or_else(|| panic!("crates/{name} not found"))
}

fn fail_on(violations: &[String], rule: &str) {
    assert!(violations.is_empty(), "{rule}: {} violation(s)\n{}", violations.len(), violations.join("\n"));
}

#[test]
fn no_import_cycles() {
    let cycles: Vec<String> = workspace().iter().flat_map(Crate::cycles).collect();
    fail_on(&cycles, "import cycles between module files");
}

#[test]
fn core_layers() {
    fail_on(&layer_violations(krate("core"), CORE_LAYERS), "the core's layers");
}

#[test]
fn cli_commands_are_shells() {
    fail_on(&command_violations(krate("cli"), CLI_COMMANDS), "the command line's commands");
}

#[test]
fn cli_figures_are_leaves() {
    let cli = krate("cli");
    assert!(
        cli.modules.iter().any(|m| m.len() == 2 && m[0] == CLI_PLOTS && m[1] == CLI_PLOTS_SHARED),
        "crates/cli/src/{CLI_PLOTS}/{CLI_PLOTS_SHARED}.rs not found: the rule checks nothing"
    );
    fail_on(&figure_violations(cli, CLI_PLOTS, CLI_PLOTS_SHARED, CLI_COMMANDS), "the command line's figures");
}

#[test]
fn core_folders_are_hubs() {
    fail_on(&hub_violations(krate("core")), "the core's folders: a mod.rs defines nothing its files import");
}

#[test]
fn summary() {
    for c in workspace() {
        println!("crates/{}: {} module files, {} edges", c.name, c.files.len(), c.edges.len());
    }
    let core = krate("core");
    // The checker sees the graph at all: the core's layers import one another.
    assert!(!core.edges.is_empty() && !krate("cli").edges.is_empty(), "no edges found: the checker reads nothing");
}

// ---------------------------------------------------------------------------------------------
// The checker checked, on small sources.
// ---------------------------------------------------------------------------------------------

mod checker {
    use super::*;

    fn krate(sources: &[(&str, &str)]) -> Crate {
        let sources: Vec<(String, String)> = sources.iter().map(|(f, t)| (f.to_string(), t.to_string())).collect();
        Crate::from_sources("t", &sources)
    }

    /// The edges as `from -> to (names)`.
    fn edges(c: &Crate) -> Vec<String> {
        c.edges
            .iter()
            .map(|(&(from, to), edge)| {
                let names: Vec<&str> = edge.names.iter().map(String::as_str).collect();
                format!("{} -> {} ({})", c.files[from], c.files[to], names.join(", "))
            })
            .collect()
    }

    #[test]
    fn finds_a_cycle_with_its_names() {
        let c = krate(&[
            ("lib.rs", "mod a; mod b; mod c;"),
            ("a.rs", "use crate::b::B;\npub struct A;"),
            ("b.rs", "pub struct B(crate::c::C);"),
            ("c.rs", "pub fn c() -> crate::a::A { todo!() }"),
        ]);
        let cycles = c.cycles();
        assert_eq!(cycles.len(), 1, "{cycles:?}");
        assert!(cycles[0].contains("3 files: a.rs, b.rs, c.rs"), "{}", cycles[0]);
        for tie in ["a.rs -> b.rs (B)", "b.rs -> c.rs (C)", "c.rs -> a.rs (A)"] {
            assert!(cycles[0].contains(tie), "{tie} in {}", cycles[0]);
        }
        let acyclic = krate(&[("lib.rs", ""), ("a.rs", "use crate::b::B;"), ("b.rs", "pub struct B;")]);
        assert!(acyclic.cycles().is_empty());
    }

    #[test]
    fn brace_groups_expand() {
        let c = krate(&[
            ("lib.rs", ""),
            ("x.rs", "use crate::a::{b::{C, D as Dee}, e, self};\nuse crate::{f::F, g::*};"),
            ("a/mod.rs", "pub fn e() {}"),
            ("a/b.rs", "pub struct C; pub struct D;"),
            ("f.rs", ""),
            ("g.rs", ""),
        ]);
        assert_eq!(
            edges(&c),
            ["x.rs -> a/mod.rs (a, e)", "x.rs -> a/b.rs (C, D)", "x.rs -> f.rs (F)", "x.rs -> g.rs (*)"]
        );
    }

    #[test]
    fn comments_and_literals_are_ignored() {
        let src = r##"
            // use crate::b::B;
            /// See [`crate::b::B`].
            //! crate::b::B
            /* crate::b::B /* nested */ crate::b::B */
            const S: &str = "use crate::b::B; \" crate::b::B";
            const R: &str = r#"crate::b::B " crate::b::B"#;
            const BYTES: &[u8] = b"crate::b::B";
            const Q: char = '"';
            fn f<'a>(x: &'a str) -> crate::c::C { let _ = '\''; todo!() }
        "##;
        let c = krate(&[("lib.rs", ""), ("a.rs", src), ("b.rs", ""), ("c.rs", "")]);
        assert_eq!(edges(&c), ["a.rs -> c.rs (C)"]);
    }

    #[test]
    fn super_and_self_resolve_from_the_module() {
        let c = krate(&[
            ("lib.rs", ""),
            ("top.rs", "pub struct T;"),
            ("a/mod.rs", "pub struct Shared; pub mod x; pub mod y;"),
            ("a/x.rs", "use super::y::Y;\nuse super::Shared;\nfn f() -> super::super::top::T { todo!() }"),
            ("a/y.rs", "pub struct Y;\nmod inner { use super::Y; use self::deep::Z; mod deep { pub struct Z; } }"),
        ]);
        assert_eq!(edges(&c), ["a/x.rs -> top.rs (T)", "a/x.rs -> a/mod.rs (Shared)", "a/x.rs -> a/y.rs (Y)"]);
    }

    #[test]
    fn uniform_paths_and_reexports_resolve_to_the_defining_file() {
        let c = krate(&[
            ("main.rs", "mod commands;\nuse commands::run::{self, Args};\nfn main() { run::go(); }"),
            ("commands/mod.rs", "pub mod run;\npub use run::Args as RunArgs;"),
            ("commands/run.rs", "pub struct Args; pub fn go() {}"),
            ("shared.rs", "use crate::commands::RunArgs;"),
        ]);
        assert_eq!(
            edges(&c),
            [
                "main.rs -> commands/run.rs (Args, go, run)",
                "commands/mod.rs -> commands/run.rs (Args)",
                "shared.rs -> commands/run.rs (Args)",
            ]
        );
    }

    #[test]
    fn the_test_module_is_skipped() {
        let src = "use crate::b::B;\n\n#[cfg(test)]\nmod tests {\n    use super::*;\n    use crate::c::C;\n    \
                   fn f() { crate::c::C; }\n}\n";
        let c = krate(&[("lib.rs", ""), ("a.rs", src), ("b.rs", ""), ("c.rs", "")]);
        assert_eq!(edges(&c), ["a.rs -> b.rs (B)"]);
    }

    #[test]
    fn mod_declarations_are_not_edges() {
        let c = krate(&[("lib.rs", "pub mod a;\nmod b;"), ("a.rs", ""), ("b.rs", "")]);
        assert!(c.edges.is_empty());
    }

    #[test]
    fn finds_a_file_importing_its_folders_hub() {
        let c = krate(&[
            ("lib.rs", "pub mod a;"),
            ("a/mod.rs", "mod x; mod y; pub struct Shared; pub use y::Y;"),
            ("a/x.rs", "use super::Shared;\nuse super::Y;"),
            ("a/y.rs", "pub struct Y;"),
        ]);
        assert_eq!(
            hub_violations(&c),
            ["crates/t/src/a/x.rs:1: a file imports its own folder's mod.rs: a/mod.rs (Shared)"]
        );
    }

    #[test]
    fn finds_a_layer_violation() {
        let layers: &[&[&str]] = &[&["error"], &["contact"], &["screw"]];
        let c = krate(&[
            ("lib.rs", "pub mod contact; pub mod error; pub mod screw;\npub use screw::model::Model;"),
            ("error.rs", ""),
            ("contact/mod.rs", "pub mod hertz;"),
            ("contact/hertz.rs", "use crate::error::Error;\nfn f(m: &crate::Model) {}"),
            ("screw/mod.rs", "pub mod model;"),
            ("screw/model.rs", "use crate::contact::hertz;\npub struct Model;"),
        ]);
        let violations = layer_violations(&c, layers);
        assert_eq!(
            violations,
            ["crates/t/src/contact/hertz.rs:2 (layer contact) imports screw/model.rs (layer screw, above it): Model"]
        );
    }

    #[test]
    fn an_unplaced_module_fails() {
        let layers: &[&[&str]] = &[&["error"], &["contact"]];
        let c = krate(&[
            ("lib.rs", ""),
            ("error.rs", ""),
            ("contact.rs", "use crate::error::E;"),
            ("fresh.rs", "use crate::contact::K;"),
        ]);
        let violations = layer_violations(&c, layers);
        assert_eq!(violations.len(), 1, "{violations:?}");
        assert!(violations[0].contains("`fresh` is in no layer: place it in CORE_LAYERS"), "{}", violations[0]);
    }

    #[test]
    fn finds_commands_that_are_not_shells() {
        let c = krate(&[
            ("main.rs", "mod commands; mod plot;\nuse commands::a::A;"),
            ("commands/mod.rs", "pub mod a; pub mod b;\nuse crate::commands::a::A;"),
            ("commands/a.rs", "use super::b::B;\nuse crate::plot::P;"),
            ("commands/b.rs", "use super::Context;"),
            ("plot.rs", "use crate::commands::b::B;"),
        ]);
        assert_eq!(
            command_violations(&c, "commands"),
            [
                "crates/t/src/commands/a.rs:1: a command imports another command: commands/b.rs (B)",
                "crates/t/src/plot.rs:1: a shared module imports a command: commands/b.rs (B)",
            ]
        );
    }

    #[test]
    fn finds_figures_that_are_not_leaves() {
        let c = krate(&[
            ("main.rs", "mod commands; mod plots; mod report;"),
            ("commands/mod.rs", "pub mod a;"),
            ("commands/a.rs", "use crate::plots::a;\nfn f() { a::svg(); }"),
            ("plots/mod.rs", "pub mod a; pub mod b; pub mod figure;"),
            ("plots/figure.rs", "pub fn page() {}"),
            ("plots/a.rs", "use super::figure::page;\npub fn svg() { crate::plots::b::svg(); }"),
            ("plots/b.rs", "pub fn svg() {}"),
            ("report.rs", "use crate::plots::b::svg;"),
        ]);
        assert_eq!(
            figure_violations(&c, "plots", "figure", "commands"),
            [
                "crates/t/src/plots/a.rs:2: a figure imports another figure: plots/b.rs (svg)",
                "crates/t/src/report.rs:1: a module that is not a command imports a figure: plots/b.rs (svg)",
            ]
        );
    }
}
