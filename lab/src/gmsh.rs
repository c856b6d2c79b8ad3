//! A reader for Gmsh's MSH 4.1 ASCII format, enough for 2D contact models: nodes, 4-node
//! quadrilaterals, 2-node lines, points, and physical groups with their names
//! (`$PhysicalNames`, mapped to elements through `$Entities`).
//!
//! Why not the `mshio` crate: it has been unmaintained since 2020 and drops the physical
//! names, which are how a scene file refers to bodies and boundaries; the subset needed here
//! is a few hundred lines, and owning it lets every error name the file and the line.
//!
//! Conventions of what it returns ([`GmshMesh`]):
//! * quadrilaterals are counter-clockwise (a clockwise one is reversed; a degenerate one is an
//!   error), the convention of hycon's elements;
//! * lines keep Gmsh's direction, which is arbitrary: [`boundary_chain`] orders a group of lines
//!   into one polyline with the body it bounds on the left (hycon's contact convention);
//! * triangles and second-order elements are rejected with a message on how to get
//!   quadrilaterals (recombination), since hycon's 2D elements are 4-node quadrilaterals.
//!
//! Every error is a [`GmshError`] naming the file and the line; corrupted or truncated input
//! gives an error, never a panic.

use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::path::{Path, PathBuf};

/// A reading error: the file, the 1-based line and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GmshError {
    /// The file read.
    pub file: PathBuf,
    /// The 1-based line (0: the file as a whole, e.g. it cannot be opened).
    pub line: usize,
    /// What is wrong there.
    pub message: String,
}

impl fmt::Display for GmshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.file.display(), self.message)
        } else {
            write!(f, "{}:{}: {}", self.file.display(), self.line, self.message)
        }
    }
}

impl std::error::Error for GmshError {}

/// A physical group: its dimension, tag, name and elements (node indices into
/// [`GmshMesh::nodes`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Group {
    /// 0 (points), 1 (curves) or 2 (surfaces).
    pub dim: usize,
    /// Gmsh's physical tag.
    pub tag: i64,
    /// Counter-clockwise quadrilaterals (dimension 2).
    pub quads: Vec<[usize; 4]>,
    /// Line segments in Gmsh's direction (dimension 1).
    pub lines: Vec<[usize; 2]>,
    /// Points (dimension 0).
    pub points: Vec<usize>,
}

impl Group {
    /// Every node of the group's elements, sorted, once each.
    pub fn nodes(&self) -> Vec<usize> {
        let mut v: Vec<usize> = self
            .quads
            .iter()
            .flatten()
            .chain(self.lines.iter().flatten())
            .chain(&self.points)
            .copied()
            .collect();
        v.sort_unstable();
        v.dedup();
        v
    }

    /// Number of elements (quadrilaterals, lines or points).
    pub fn len(&self) -> usize {
        self.quads.len() + self.lines.len() + self.points.len()
    }

    /// Whether the group has no elements.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// What a MSH file holds for a 2D model.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GmshMesh {
    /// The file it was read from.
    pub file: PathBuf,
    /// Node coordinates `(x, y)` (z is dropped; it must be 0).
    pub nodes: Vec<[f64; 2]>,
    /// Gmsh's tag of each node.
    pub node_tags: Vec<u64>,
    /// Physical groups by name; a group without a name in `$PhysicalNames` is named by its
    /// dimension and tag, e.g. `"2:7"`.
    pub groups: BTreeMap<String, Group>,
}

/// Read a MSH 4.1 ASCII file.
///
/// # Errors
/// [`GmshError`] naming the file and line.
pub fn read(path: &Path) -> Result<GmshMesh, GmshError> {
    let fail = |line: usize, message: String| GmshError {
        file: path.to_path_buf(),
        line,
        message,
    };
    let bytes = std::fs::read(path).map_err(|e| {
        let how = if path.is_dir() {
            "It is a folder: give the .msh file"
        } else {
            "Check the path: a scene's mesh is relative to the scene file's folder"
        };
        fail(0, format!("cannot read the mesh: {e}. {how}. {EXPORT}"))
    })?;
    match String::from_utf8(bytes) {
        Ok(text) => parse(&text, path),
        Err(e) => {
            let bytes = e.as_bytes();
            // the line of the first byte that is not text
            let line = 1 + bytes[..e.utf8_error().valid_up_to()]
                .iter()
                .filter(|&&b| b == b'\n')
                .count();
            let binary = bytes.starts_with(b"$MeshFormat") && {
                let second = bytes.split(|&b| b == b'\n').nth(1).unwrap_or_default();
                String::from_utf8_lossy(second)
                    .split_whitespace()
                    .nth(1)
                    .is_some_and(|t| t != "0")
            };
            Err(fail(
                line,
                if binary {
                    format!("binary MSH: this reader takes ASCII. {EXPORT}")
                } else {
                    format!("not a text file (a MSH 4.1 ASCII mesh is text). {EXPORT}")
                },
            ))
        }
    }
}

/// How to get a mesh this reader takes, for the errors.
const EXPORT: &str = "To write one in Gmsh: File > Export, format `Mesh - Gmsh MSH (*.msh)`, \
                      version 4.1 ASCII; or `Mesh.MshFileVersion = 4.1; Mesh.Binary = 0;` in \
                      the .geo; or `gmsh model.geo -2 -format msh41 -o model.msh` (without \
                      -bin)";

/// Parse MSH 4.1 ASCII text (`file` names it in errors).
///
/// # Errors
/// [`GmshError`] naming the file and line.
pub fn parse(text: &str, file: &Path) -> Result<GmshMesh, GmshError> {
    Parser::new(text, file).run()
}

/// Gmsh element types and their node counts (those this reader recognises, to say what they are).
fn element_kind(t: u32) -> Option<(&'static str, usize)> {
    Some(match t {
        1 => ("2-node line", 2),
        2 => ("3-node triangle", 3),
        3 => ("4-node quadrilateral", 4),
        4 => ("4-node tetrahedron", 4),
        5 => ("8-node hexahedron", 8),
        8 => ("3-node line (second order)", 3),
        9 => ("6-node triangle (second order)", 6),
        10 => ("9-node quadrilateral (second order)", 9),
        15 => ("point", 1),
        16 => ("8-node quadrilateral (second order)", 8),
        _ => return None,
    })
}

const RECOMBINE: &str = "hycon's 2D elements are 4-node quadrilaterals: in Gmsh recombine the \
     surfaces into quadrilaterals (`Recombine Surface{:};` in the .geo, or \
     `Mesh.RecombineAll = 1;` with `Mesh.RecombinationAlgorithm = 1;`, or -setnumber \
     Mesh.RecombineAll 1) and keep first order (`Mesh.ElementOrder = 1;`)";

struct Parser<'a> {
    lines: Vec<&'a str>,
    /// Index of the next line to read.
    next: usize,
    file: &'a Path,
}

/// Whitespace-separated tokens of one line, with its 1-based number.
struct Tokens<'a> {
    it: std::str::SplitWhitespace<'a>,
    line: usize,
}

impl<'a> Parser<'a> {
    fn new(text: &'a str, file: &'a Path) -> Self {
        Parser {
            lines: text.lines().collect(),
            next: 0,
            file,
        }
    }

    fn err<T>(&self, line: usize, message: impl Into<String>) -> Result<T, GmshError> {
        Err(GmshError {
            file: self.file.to_path_buf(),
            line,
            message: message.into(),
        })
    }

    /// The next non-blank line, as tokens; an error at the end of the file.
    fn line(&mut self, what: &str) -> Result<Tokens<'a>, GmshError> {
        while self.next < self.lines.len() {
            let l = self.lines[self.next];
            self.next += 1;
            if !l.trim().is_empty() {
                return Ok(Tokens {
                    it: l.split_whitespace(),
                    line: self.next,
                });
            }
        }
        self.err(
            self.lines.len(),
            format!("the file ends early (truncated?): expected {what}"),
        )
    }

    fn raw_line(&mut self, what: &str) -> Result<(&'a str, usize), GmshError> {
        let t = self.line(what)?;
        Ok((self.lines[t.line - 1].trim(), t.line))
    }

    fn num<T: std::str::FromStr>(&self, t: &mut Tokens<'_>, what: &str) -> Result<T, GmshError> {
        match t.it.next() {
            None => self.err(t.line, format!("expected {what}, the line ends")),
            Some(s) => s
                .parse()
                .or_else(|_| self.err(t.line, format!("expected {what}, found `{s}`"))),
        }
    }

    /// A count, bounded by the lines left (so corrupted counts cannot allocate without bound).
    fn count(&self, t: &mut Tokens<'_>, what: &str, per_line: usize) -> Result<usize, GmshError> {
        let n: usize = self.num(t, what)?;
        let left = self.lines.len().saturating_sub(self.next) + 1;
        if n.div_ceil(per_line.max(1)) > left {
            return self.err(
                t.line,
                format!(
                    "{what} is {n}, more than the file has lines left (truncated or corrupted)"
                ),
            );
        }
        Ok(n)
    }

    fn end(&mut self, name: &str) -> Result<(), GmshError> {
        let (l, line) = self.raw_line(&format!("$End{name}"))?;
        if l != format!("$End{name}") {
            return self.err(line, format!("expected $End{name}, found `{l}`"));
        }
        Ok(())
    }

    fn run(mut self) -> Result<GmshMesh, GmshError> {
        let mut names: HashMap<(usize, i64), String> = HashMap::new();
        // (dim, entity tag) -> physical tags
        let mut entities: HashMap<(usize, i64), Vec<i64>> = HashMap::new();
        let mut mesh = GmshMesh {
            file: self.file.to_path_buf(),
            ..GmshMesh::default()
        };
        let mut index: HashMap<u64, usize> = HashMap::new();
        let mut seen_format = false;
        let mut seen_elements = false;
        while self.next < self.lines.len() {
            let (l, line) = match self.raw_line("a section") {
                Ok(x) => x,
                Err(_) => break,
            };
            match l {
                "$MeshFormat" => {
                    let mut t = self.line("the format line")?;
                    let version: String = self.num(&mut t, "the version")?;
                    if version != "4.1" {
                        return self.err(
                            t.line,
                            format!(
                                "MSH version {version}: this reader takes 4.1 (in Gmsh: \
                                 `Mesh.MshFileVersion = 4.1;`, or -format msh41)"
                            ),
                        );
                    }
                    let binary: u32 = self.num(&mut t, "the file type (0 = ASCII)")?;
                    if binary != 0 {
                        return self.err(
                            t.line,
                            format!("binary MSH: this reader takes ASCII. {EXPORT}"),
                        );
                    }
                    self.end("MeshFormat")?;
                    seen_format = true;
                }
                "$PhysicalNames" => self.physical_names(&mut names)?,
                "$Entities" => self.entities(&mut entities)?,
                "$Nodes" => self.nodes(&mut mesh, &mut index)?,
                "$Elements" => {
                    if !seen_format {
                        return self.err(line, "$Elements before $MeshFormat");
                    }
                    self.elements(&mut mesh, &index, &entities, &names)?;
                    seen_elements = true;
                }
                s if s.starts_with("$End") => {
                    return self.err(line, format!("unexpected `{s}`"));
                }
                s if s.starts_with('$') => self.skip_section(&s[1..], line)?,
                s => return self.err(line, format!("expected a section ($Name), found `{s}`")),
            }
        }
        if !seen_format {
            return self.err(1, "not a MSH file: no $MeshFormat section");
        }
        if !seen_elements {
            return self.err(self.lines.len(), "no $Elements section");
        }
        // named groups without elements are kept (a body or surface that was not meshed)
        for (&(dim, tag), name) in &names {
            mesh.groups.entry(name.clone()).or_insert_with(|| Group {
                dim,
                tag,
                ..Group::default()
            });
        }
        Ok(mesh)
    }

    fn skip_section(&mut self, name: &str, line: usize) -> Result<(), GmshError> {
        let end = format!("$End{name}");
        while self.next < self.lines.len() {
            let l = self.lines[self.next].trim();
            self.next += 1;
            if l == end {
                return Ok(());
            }
        }
        self.err(line, format!("section ${name} has no {end} (truncated?)"))
    }

    fn physical_names(
        &mut self,
        names: &mut HashMap<(usize, i64), String>,
    ) -> Result<(), GmshError> {
        let mut t = self.line("the number of physical names")?;
        let n = self.count(&mut t, "the number of physical names", 1)?;
        for _ in 0..n {
            let mut t = self.line("a physical name")?;
            let dim: usize = self.num(&mut t, "the dimension")?;
            let tag: i64 = self.num(&mut t, "the physical tag")?;
            let text = self.lines[t.line - 1];
            let (Some(a), Some(b)) = (text.find('"'), text.rfind('"')) else {
                return self.err(t.line, "expected a quoted name");
            };
            if a == b {
                return self.err(t.line, "the name's closing quote is missing");
            }
            if dim > 3 {
                return self.err(t.line, format!("dimension {dim} (0 to 3)"));
            }
            names.insert((dim, tag), text[a + 1..b].to_string());
        }
        self.end("PhysicalNames")
    }

    fn entities(
        &mut self,
        entities: &mut HashMap<(usize, i64), Vec<i64>>,
    ) -> Result<(), GmshError> {
        let mut t = self.line("the entity counts")?;
        let mut counts = [0usize; 4];
        for (d, c) in counts.iter_mut().enumerate() {
            *c = self.count(&mut t, &format!("the number of {d}D entities"), 1)?;
        }
        for (dim, &n) in counts.iter().enumerate() {
            for _ in 0..n {
                let mut t = self.line(&format!("a {dim}D entity"))?;
                let tag: i64 = self.num(&mut t, "the entity tag")?;
                let coords = if dim == 0 { 3 } else { 6 };
                for _ in 0..coords {
                    let _: f64 = self.num(&mut t, "a bounding coordinate")?;
                }
                let np: usize = self.num(&mut t, "the number of physical tags")?;
                if np > 1024 {
                    return self.err(t.line, format!("{np} physical tags on one entity"));
                }
                let mut tags = Vec::with_capacity(np);
                for _ in 0..np {
                    tags.push(self.num(&mut t, "a physical tag")?);
                }
                entities.insert((dim, tag), tags);
            }
        }
        self.end("Entities")
    }

    fn nodes(
        &mut self,
        mesh: &mut GmshMesh,
        index: &mut HashMap<u64, usize>,
    ) -> Result<(), GmshError> {
        let mut t = self.line("the node counts")?;
        let blocks = self.count(&mut t, "the number of node blocks", 1)?;
        let total = self.count(&mut t, "the number of nodes", 2)?;
        mesh.nodes.reserve(total);
        for _ in 0..blocks {
            let mut t = self.line("a node block header")?;
            let _dim: usize = self.num(&mut t, "the entity dimension")?;
            let _tag: i64 = self.num(&mut t, "the entity tag")?;
            let parametric: u32 = self.num(&mut t, "the parametric flag")?;
            let n = self.count(&mut t, "the number of nodes in the block", 2)?;
            if parametric != 0 {
                return self.err(
                    t.line,
                    "parametric nodes: save without them (`Mesh.SaveParametric = 0;`)",
                );
            }
            let mut tags = Vec::with_capacity(n);
            for _ in 0..n {
                let mut t = self.line("a node tag")?;
                tags.push((self.num::<u64>(&mut t, "a node tag")?, t.line));
            }
            for (tag, tag_line) in tags {
                let mut t = self.line("node coordinates")?;
                let x: f64 = self.num(&mut t, "x")?;
                let y: f64 = self.num(&mut t, "y")?;
                let z: f64 = self.num(&mut t, "z")?;
                if !(x.is_finite() && y.is_finite() && z.is_finite()) {
                    return self.err(t.line, "a coordinate is not finite");
                }
                if z != 0.0 {
                    return self.err(
                        t.line,
                        format!("node {tag} has z = {z}: a 2D model lies in z = 0"),
                    );
                }
                if index.insert(tag, mesh.nodes.len()).is_some() {
                    return self.err(tag_line, format!("node tag {tag} appears twice"));
                }
                mesh.nodes.push([x, y]);
                mesh.node_tags.push(tag);
            }
        }
        if mesh.nodes.len() != total {
            return self.err(
                t.line,
                format!("{total} nodes announced, {} read", mesh.nodes.len()),
            );
        }
        self.end("Nodes")
    }

    fn elements(
        &mut self,
        mesh: &mut GmshMesh,
        index: &HashMap<u64, usize>,
        entities: &HashMap<(usize, i64), Vec<i64>>,
        names: &HashMap<(usize, i64), String>,
    ) -> Result<(), GmshError> {
        let mut t = self.line("the element counts")?;
        let blocks = self.count(&mut t, "the number of element blocks", 1)?;
        for _ in 0..blocks {
            let mut t = self.line("an element block header")?;
            let dim: usize = self.num(&mut t, "the entity dimension")?;
            let tag: i64 = self.num(&mut t, "the entity tag")?;
            let kind: u32 = self.num(&mut t, "the element type")?;
            let n = self.count(&mut t, "the number of elements in the block", 1)?;
            let header = t.line;
            let Some((kind_name, nn)) = element_kind(kind) else {
                return self.err(
                    header,
                    format!("element type {kind} is not supported. {RECOMBINE}"),
                );
            };
            if !matches!(kind, 1 | 3 | 15) {
                return self.err(
                    header,
                    format!(
                        "{kind_name} elements (entity {dim}D {tag}) are not supported. {RECOMBINE}"
                    ),
                );
            }
            let want_dim = match kind {
                15 => 0,
                1 => 1,
                _ => 2,
            };
            if dim != want_dim {
                return self.err(header, format!("{kind_name} elements on a {dim}D entity"));
            }
            let Some(physical) = entities.get(&(dim, tag)) else {
                return self.err(
                    header,
                    format!("entity {dim}D {tag} is not in $Entities (or $Entities is missing)"),
                );
            };
            let mut elements = Vec::with_capacity(n);
            for _ in 0..n {
                let mut t = self.line("an element")?;
                let _etag: u64 = self.num(&mut t, "the element tag")?;
                let mut ids = [0usize; 4];
                for id in ids.iter_mut().take(nn) {
                    let node: u64 = self.num(&mut t, "a node tag")?;
                    let Some(&i) = index.get(&node) else {
                        return self.err(t.line, format!("node tag {node} is not in $Nodes"));
                    };
                    *id = i;
                }
                if kind == 3 {
                    ids = ccw(ids, &mesh.nodes).or_else(|m| self.err(t.line, m))?;
                }
                elements.push(ids);
            }
            for &p in physical {
                let name = names
                    .get(&(dim, p))
                    .cloned()
                    .unwrap_or_else(|| format!("{dim}:{p}"));
                let g = mesh.groups.entry(name).or_insert_with(|| Group {
                    dim,
                    tag: p,
                    ..Group::default()
                });
                match kind {
                    3 => g.quads.extend(elements.iter().copied()),
                    1 => g.lines.extend(elements.iter().map(|e| [e[0], e[1]])),
                    _ => g.points.extend(elements.iter().map(|e| e[0])),
                }
            }
        }
        self.end("Elements")
    }
}

/// The quadrilateral counter-clockwise (reversed if clockwise); an error message if it is
/// degenerate (zero area) or self-crossing.
fn ccw(q: [usize; 4], x: &[[f64; 2]]) -> Result<[usize; 4], String> {
    let area2 = |q: &[usize; 4]| {
        (0..4)
            .map(|i| {
                let (p, r) = (x[q[i]], x[q[(i + 1) % 4]]);
                p[0] * r[1] - r[0] * p[1]
            })
            .sum::<f64>()
    };
    let a = area2(&q);
    let scale = (0..4)
        .map(|i| {
            let (p, r) = (x[q[i]], x[q[(i + 1) % 4]]);
            (r[0] - p[0]).hypot(r[1] - p[1])
        })
        .fold(0.0_f64, f64::max);
    // NaN areas (non-finite coordinates are rejected earlier) fall here too
    if a.abs().is_nan() || a.abs() <= 1e-12 * scale * scale {
        return Err("a quadrilateral with zero area (degenerate or self-crossing)".into());
    }
    Ok(if a > 0.0 { q } else { [q[0], q[3], q[2], q[1]] })
}

/// Why a group of lines is not one boundary chain.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ChainError {
    /// A segment that is no edge of any element's boundary (its nodes' tags).
    NotAnEdge([u64; 2]),
    /// A segment that is an interior edge (shared by two elements).
    Interior([u64; 2]),
    /// The segments form more than one piece, a branch, or a closed loop (the message says).
    NotAChain(String),
}

impl fmt::Display for ChainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ChainError::NotAnEdge([a, b]) => write!(
                f,
                "the line between nodes {a} and {b} is not an edge of any quadrilateral"
            ),
            ChainError::Interior([a, b]) => write!(
                f,
                "the line between nodes {a} and {b} is inside a body (an edge of two elements), \
                 not on its boundary"
            ),
            ChainError::NotAChain(m) => f.write_str(m),
        }
    }
}

/// Order the segments `lines` into one polyline (node indices) with the body on the left: each
/// segment is turned to run along its element's counter-clockwise boundary (the body on the
/// left), then the segments are linked end to start. `edges` maps a directed element edge
/// `(i, j)` (counter-clockwise) to anything (see [`hycon::mesh::Mesh::directed_edges`]).
///
/// # Errors
/// [`ChainError`] when a segment is not a boundary edge, or the segments are not one open
/// chain.
pub fn boundary_chain<V>(
    lines: &[[usize; 2]],
    edges: &HashMap<(usize, usize), V>,
    tags: &[u64],
) -> Result<Vec<usize>, ChainError> {
    let tag = |i: usize| tags.get(i).copied().unwrap_or(i as u64);
    let mut next: HashMap<usize, usize> = HashMap::new();
    let mut has_prev: HashMap<usize, bool> = HashMap::new();
    for &[p, q] in lines {
        let (fwd, back) = (edges.contains_key(&(p, q)), edges.contains_key(&(q, p)));
        let (s, e) = match (fwd, back) {
            (true, false) => (p, q),
            (false, true) => (q, p),
            (true, true) => return Err(ChainError::Interior([tag(p), tag(q)])),
            (false, false) => return Err(ChainError::NotAnEdge([tag(p), tag(q)])),
        };
        if next.insert(s, e).is_some() {
            return Err(ChainError::NotAChain(format!(
                "the lines branch at node {} (a chain has no forks)",
                tag(s)
            )));
        }
        if has_prev.insert(e, true) == Some(true) {
            return Err(ChainError::NotAChain(format!(
                "the lines meet at node {} from two sides (a chain has no forks)",
                tag(e)
            )));
        }
        has_prev.entry(s).or_insert(false);
    }
    let starts: Vec<usize> = has_prev.iter().filter(|e| !*e.1).map(|e| *e.0).collect();
    if lines.is_empty() {
        return Err(ChainError::NotAChain("the group has no lines".into()));
    }
    let start = match starts.as_slice() {
        [s] => *s,
        [] => {
            return Err(ChainError::NotAChain(
                "the lines form a closed loop: split it into open curves (a contact surface \
                 is an open chain)"
                    .into(),
            ));
        }
        _ => {
            return Err(ChainError::NotAChain(format!(
                "the lines form {} separate pieces (a boundary group must be one chain)",
                starts.len()
            )));
        }
    };
    let mut chain = vec![start];
    let mut at = start;
    while let Some(&n) = next.get(&at) {
        chain.push(n);
        at = n;
        if chain.len() > lines.len() + 1 {
            break;
        }
    }
    if chain.len() != lines.len() + 1 {
        return Err(ChainError::NotAChain(
            "the lines form a chain and a separate closed loop".into(),
        ));
    }
    Ok(chain)
}

/// A physical group to write: its name and elements (node ids of the mesh written).
#[derive(Debug, Clone, PartialEq)]
pub enum WriteGroup {
    /// A 2D group: the mesh's elements of this material index (4-node elements only).
    Surface(String, usize),
    /// A 1D group: a polyline through these nodes.
    Curve(String, Vec<usize>),
    /// A 0D group: these nodes.
    Points(String, Vec<usize>),
}

/// MSH 4.1 ASCII text of `mesh` with the physical groups `groups` (one entity per group), the
/// inverse of [`parse`] for 4-node meshes: how the lab turns its generated scenes into
/// scene-file meshes.
///
/// # Errors
/// A message when an element of a surface group does not have 4 nodes.
pub fn write(mesh: &hycon::mesh::Mesh, groups: &[WriteGroup]) -> Result<String, String> {
    use std::fmt::Write as _;
    let mut s = String::from("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n");
    let dim = |g: &WriteGroup| match g {
        WriteGroup::Surface(..) => 2,
        WriteGroup::Curve(..) => 1,
        WriteGroup::Points(..) => 0,
    };
    let name = |g: &WriteGroup| match g {
        WriteGroup::Surface(n, _) | WriteGroup::Curve(n, _) | WriteGroup::Points(n, _) => n.clone(),
    };
    let _ = writeln!(s, "{}", groups.len());
    for (k, g) in groups.iter().enumerate() {
        let _ = writeln!(s, "{} {} \"{}\"", dim(g), k + 1, name(g));
    }
    s.push_str("$EndPhysicalNames\n$Entities\n");
    let count = |d: usize| groups.iter().filter(|g| dim(g) == d).count();
    let _ = writeln!(s, "{} {} {} 0", count(0), count(1), count(2));
    // entity tag = physical tag (unique across dimensions here)
    for d in 0..3 {
        for (k, _) in groups.iter().enumerate().filter(|(_, g)| dim(g) == d) {
            let bbox = if d == 0 { "0 0 0" } else { "0 0 0 0 0 0" };
            let tail = if d == 0 { "" } else { " 0" };
            let _ = writeln!(s, "{} {bbox} 1 {}{tail}", k + 1, k + 1);
        }
    }
    let n = mesh.n_nodes();
    let _ = writeln!(s, "$EndEntities\n$Nodes\n1 {n} 1 {n}\n2 0 0 {n}");
    for i in 0..n {
        let _ = writeln!(s, "{}", i + 1);
    }
    for p in &mesh.nodes {
        let _ = writeln!(s, "{:e} {:e} 0", p[0], p[1]);
    }
    s.push_str("$EndNodes\n");
    let mut blocks: Vec<(usize, usize, u32, Vec<Vec<usize>>)> = Vec::new();
    for (k, g) in groups.iter().enumerate() {
        let els: Vec<Vec<usize>> = match g {
            WriteGroup::Surface(_, m) => {
                let mut v = Vec::new();
                for e in 0..mesh.n_elements() {
                    if mesh.element_material[e] == *m {
                        if mesh.element(e).len() != 4 {
                            return Err(format!("element {e} has {} nodes", mesh.element(e).len()));
                        }
                        v.push(mesh.element(e).to_vec());
                    }
                }
                v
            }
            WriteGroup::Curve(_, ids) => ids.windows(2).map(|w| w.to_vec()).collect(),
            WriteGroup::Points(_, ids) => ids.iter().map(|&i| vec![i]).collect(),
        };
        let kind = [15, 1, 3][dim(g)];
        blocks.push((dim(g), k + 1, kind, els));
    }
    let total: usize = blocks.iter().map(|b| b.3.len()).sum();
    let _ = writeln!(s, "$Elements\n{} {total} 1 {total}", blocks.len());
    let mut tag = 1;
    for (d, ent, kind, els) in blocks {
        let _ = writeln!(s, "{d} {ent} {kind} {}", els.len());
        for e in els {
            let _ = write!(s, "{tag}");
            for i in e {
                let _ = write!(s, " {}", i + 1);
            }
            s.push('\n');
            tag += 1;
        }
    }
    s.push_str("$EndElements\n");
    Ok(s)
}
