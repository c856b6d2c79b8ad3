//! Scene files: a contact model written in TOML over a Gmsh mesh ([`crate::gmsh`]), checked
//! ([`load`]), described without solving ([`dry_run`]) and run ([`run`]). The format is
//! documented in docs/scene-files.md and by [`SceneSpec`].
//!
//! Every set-up mistake is a [`SceneError`] that names the scene file and the group, body,
//! pair or step at fault (mesh errors name the mesh file and line); likely unit mistakes are
//! warnings ([`Scene::warnings`]).

use crate::gmsh::{self, GmshMesh, Group};
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, Kinematics, NodeResult, NodeState, PlateControl,
};
use hycon::contact::plane::facing;
use hycon::element::Formulation;
use hycon::material::{Analysis, Material};
use hycon::mesh::Mesh;
use hycon::model::{LinearSystem, Model};
use hycon::solver::Backend;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A set-up mistake: the scene file and what is wrong (naming the group, body, pair or step).
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The scene file (or the mesh file for a mesh error).
    pub file: PathBuf,
    /// What is wrong and, where it can, how to fix it.
    pub message: String,
}

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.file.display(), self.message)
    }
}

impl std::error::Error for SceneError {}

impl From<gmsh::GmshError> for SceneError {
    fn from(e: gmsh::GmshError) -> Self {
        SceneError {
            message: if e.line == 0 {
                e.message
            } else {
                format!("line {}: {}", e.line, e.message)
            },
            file: e.file,
        }
    }
}

type Result<T> = std::result::Result<T, SceneError>;

/// The scene file as written (TOML). Unknown keys are errors (a misspelt key would otherwise
/// be ignored silently).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// The Gmsh MSH 4.1 ASCII mesh, relative to the scene file.
    pub mesh: PathBuf,
    /// `"plane_strain"` (default), `"plane_stress"` or `"axisymmetric"` (x = r >= 0, y = z;
    /// thickness 1, loads and forces over the full circle).
    #[serde(default = "plane_strain")]
    pub analysis: String,
    /// The bodies (at least one).
    #[serde(default)]
    pub body: Vec<BodySpec>,
    /// Prescribed displacements on groups.
    #[serde(default)]
    pub support: Vec<SupportSpec>,
    /// Edge pressures, tractions and nodal forces on groups.
    #[serde(default)]
    pub load: Vec<LoadSpec>,
    /// Contact pairs between boundary groups.
    #[serde(default)]
    pub contact: Vec<ContactSpec>,
    /// Load steps: each a table of totals, `curve = factor` (every support value and load is
    /// multiplied by its curve's factor; the default curve is `load`).
    #[serde(default)]
    pub step: Vec<BTreeMap<String, f64>>,
    /// Analysis options (per analysis, not per pair).
    #[serde(default)]
    pub options: OptionsSpec,
    /// What to write.
    #[serde(default)]
    pub output: OutputSpec,
    /// A rigid plate: the nodes of a group moved together, each direction controlled by a
    /// displacement or a force (the built-in scenes' force control).
    pub plate: Option<PlateSpec>,
}

/// A rigid plate on a group (its nodes must carry no other support).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PlateSpec {
    /// The physical group (points or lines) tied to the plate.
    pub group: String,
    /// `"displacement"` or `"force"`: what controls the plate in x.
    pub x: String,
    /// The same in y.
    pub y: String,
    /// The controls' totals at factor 1 of the curve `[x, y]` (a force is the total on the
    /// plate).
    pub value: [f64; 2],
    /// The curve that scales them (default `load`).
    pub curve: Option<String>,
}

fn plane_strain() -> String {
    "plane_strain".into()
}

/// A body: a 2D physical group of quadrilaterals with a material and an element formulation.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// The physical group (2D).
    pub group: String,
    /// Its name in reports (default: the group).
    pub name: Option<String>,
    /// The material (required).
    pub material: Option<MaterialSpec>,
    /// `"hybrid"` (default), `"pian-sumihara"` or `"q4"`; one for every body.
    pub formulation: Option<String>,
}

/// Isotropic linear elasticity.
#[derive(Debug, Clone, Copy, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus.
    #[serde(rename = "E")]
    pub youngs: f64,
    /// Poisson's ratio.
    pub nu: f64,
    /// Thickness (plane analyses; 1 in axisymmetry).
    #[serde(default = "one")]
    pub thickness: f64,
}

fn one() -> f64 {
    1.0
}

/// Prescribed displacement components on every node of a group (`x`, `y`: the value at
/// factor 1 of the curve; 0 holds the node).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SupportSpec {
    /// The physical group (points or lines).
    pub group: String,
    /// Displacement in x (r), if prescribed.
    pub x: Option<f64>,
    /// Displacement in y (z), if prescribed.
    pub y: Option<f64>,
    /// The curve that scales the values (default `load`).
    pub curve: Option<String>,
}

/// A load on a group: exactly one of `pressure` (on lines, pushing into the body), `traction`
/// (on lines, force per unit area in x and y) or `force` (on every node of the group).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// The physical group.
    pub group: String,
    /// Normal pressure (force per area, positive pushing into the body).
    pub pressure: Option<f64>,
    /// Traction `[tx, ty]` (force per area).
    pub traction: Option<[f64; 2]>,
    /// Nodal force `[fx, fy]` on each node of the group.
    pub force: Option<[f64; 2]>,
    /// The curve that scales the load (default `load`).
    pub curve: Option<String>,
}

/// A contact pair: side `a` carries the multipliers (tractions are reported on it).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// The multiplier side: a 1D group, one chain of boundary edges.
    pub a: String,
    /// The opposite side: a 1D group on another body.
    pub b: String,
    /// Coulomb friction coefficient (default 0).
    #[serde(default)]
    pub friction: f64,
}

/// Analysis options; every key optional (hycon's defaults).
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OptionsSpec {
    /// `"small"` (default) or `"finite"`.
    pub kinematics: Option<String>,
    /// Search distance relative to the mean A segment length.
    pub search_distance: Option<f64>,
    /// `"faer"` (default) or `"cholmod"`.
    pub backend: Option<String>,
    /// Threads for the contact boundary's substitutions.
    pub threads: Option<usize>,
    /// Convergence tolerance.
    pub tolerance: Option<f64>,
    /// Iteration cap per increment.
    pub max_iterations: Option<usize>,
    /// Penetration tolerance.
    pub gap_tolerance: Option<f64>,
    /// Tension tolerance.
    pub tension_tolerance: Option<f64>,
    /// Friction-cone tolerance.
    pub friction_tolerance: Option<f64>,
    /// Cycle-locking rounds.
    pub lock_rounds: Option<usize>,
    /// Automatic cutback: how many halvings (0: off).
    pub cutback_depth: Option<usize>,
    /// Shortest sub-increment, a fraction of the increment.
    pub cutback_min_fraction: Option<f64>,
}

/// Outputs (all on by default), written into `dir` (relative to the scene file; default: the
/// scene's stem followed by `-out`).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// Output folder.
    pub dir: Option<PathBuf>,
    /// VTU field per step.
    #[serde(default = "yes")]
    pub vtu: bool,
    /// SVG plots of pressure and shear along each pair's A side.
    #[serde(default = "yes")]
    pub svg: bool,
    /// CSV of the contact tractions per step.
    #[serde(default = "yes")]
    pub csv: bool,
    /// JSON summary.
    #[serde(default = "yes")]
    pub json: bool,
}

impl Default for OutputSpec {
    fn default() -> Self {
        OutputSpec {
            dir: None,
            vtu: true,
            svg: true,
            csv: true,
            json: true,
        }
    }
}

fn yes() -> bool {
    true
}

/// A body as built.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Report name.
    pub name: String,
    /// Physical group.
    pub group: String,
    /// Elements.
    pub elements: usize,
    /// Nodes.
    pub nodes: usize,
    /// Material.
    pub material: Material,
}

/// A contact pair as built, with what the dry run reports.
#[derive(Debug, Clone, PartialEq)]
pub struct Pair {
    /// Group names `(a, b)`.
    pub groups: (String, String),
    /// Body indices `(a, b)`.
    pub bodies: (usize, usize),
    /// The pair in model node ids (chains with the body on the left).
    pub pair: ContactPair,
    /// Polyline lengths `(a, b)`.
    pub lengths: (f64, f64),
    /// Least and largest signed distance of an A node from B (negative: overlap), over the A
    /// nodes that project onto B.
    pub gap_range: Option<(f64, f64)>,
    /// How the A nodes see B within the search distance.
    pub facing: facing::Facing,
    /// The search distance in length units (`search_distance` times the mean A segment).
    pub reach: f64,
}

/// A rigid plate as built.
#[derive(Debug, Clone, PartialEq)]
pub struct Plate {
    /// Its group.
    pub group: String,
    /// Its nodes (model ids).
    pub nodes: Vec<usize>,
    /// Force control (else displacement) per direction.
    pub force: [bool; 2],
    /// The controls at factor 1.
    pub value: [f64; 2],
    /// The curve (index into [`Scene::curves`]).
    pub curve: usize,
}

/// The largest element strain of the dry run's linear first step beyond which it warns of a
/// likely unit mistake.
pub const STRAIN_WARNING: f64 = 0.05;

/// The nominal strain under a force-controlled plate below which the dry run warns that the
/// load is likely too small for its units (a contact of a node or two).
pub const TINY_STRAIN: f64 = 1e-9;

/// A loaded, checked scene, ready to run.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The scene file.
    pub file: PathBuf,
    /// What it says.
    pub spec: SceneSpec,
    /// The model (every body, supports; loads are applied per step).
    pub model: Model,
    /// The bodies in order (the material index of their elements).
    pub bodies: Vec<Body>,
    /// One line per support, for the dry run.
    pub supports: Vec<String>,
    /// One line per load, for the dry run.
    pub loads: Vec<String>,
    /// The contact pairs.
    pub pairs: Vec<Pair>,
    /// Curve names (the step table's columns).
    pub curves: Vec<String>,
    /// External forces at factor 1 of each curve.
    pub forces: Vec<Vec<f64>>,
    /// Prescribed `(dof, value at factor 1, curve)`.
    pub prescribed: Vec<(usize, f64, usize)>,
    /// Factors per step and curve.
    pub steps: Vec<Vec<f64>>,
    /// The rigid plate, if any.
    pub plate: Option<Plate>,
    /// The analysis options.
    pub options: ContactOptions,
    /// Likely mistakes that do not stop the run (units, a pair out of reach).
    pub warnings: Vec<String>,
    /// What the scene changed on the way and why (a contact side's end nodes left to the
    /// plate).
    pub notes: Vec<String>,
    /// The mesh's node tag of every model node (messages and outputs name nodes by these).
    pub tags: Vec<u64>,
}

/// Read and check a scene file and its mesh.
///
/// # Errors
/// [`SceneError`] for the first set-up mistake found (see the table of docs/scene-files.md).
pub fn load(path: &Path) -> Result<Scene> {
    let text = std::fs::read_to_string(path).map_err(|e| SceneError {
        file: path.to_path_buf(),
        message: format!("cannot read the scene: {e}"),
    })?;
    let spec: SceneSpec = toml::from_str(&text).map_err(|e| {
        let mut message = e.to_string().trim_end().to_string();
        if message.ends_with("missing field `mesh`") {
            message.push_str(
                ": add mesh = \"model.msh\" at the top (the Gmsh MSH 4.1 ASCII mesh, relative to \
                 the scene file's folder)",
            );
        }
        SceneError {
            file: path.to_path_buf(),
            message,
        }
    })?;
    // the lines of the items, for the messages (the spec parsed, this cannot fail)
    let lines: ItemLines = toml::from_str(&text).unwrap_or_default();
    let mesh_line = lines.mesh.as_ref().map_or(String::new(), |m| {
        format!(
            " (line {})",
            1 + text[..m.span().start].matches('\n').count()
        )
    });
    if spec.mesh.as_os_str().is_empty() {
        return fail(
            path,
            format!(
                "mesh = \"\"{mesh_line}: give the Gmsh mesh, e.g. mesh = \"model.msh\" (relative \
                 to the scene file's folder)"
            ),
        );
    }
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let gmsh = gmsh::read(&folder.join(&spec.mesh)).map_err(|e| {
        let mut e = SceneError::from(e);
        if !mesh_line.is_empty() && e.message.starts_with("cannot read") {
            e.message = format!(
                "mesh = {:?} in {}{mesh_line}: {}",
                spec.mesh.display().to_string(),
                path.display(),
                e.message
            );
        }
        e
    })?;
    let line_of = |items: &[ItemLine]| -> Vec<usize> {
        items
            .iter()
            .map(|i| {
                i.group
                    .as_ref()
                    .or(i.a.as_ref())
                    .map_or(0, |g| 1 + text[..g.span().start].matches('\n').count())
            })
            .collect()
    };
    Builder {
        file: path,
        gmsh: &gmsh,
        lines: [
            line_of(&lines.body),
            line_of(&lines.support),
            line_of(&lines.load),
            line_of(&lines.contact),
            line_of(lines.plate.as_slice()),
        ],
    }
    .build(spec)
}

/// Where each item's `group` (or a pair's `a`) is written, read in a second pass.
#[derive(Debug, Default, Deserialize)]
struct ItemLines {
    mesh: Option<toml::Spanned<toml::Value>>,
    #[serde(default)]
    body: Vec<ItemLine>,
    #[serde(default)]
    support: Vec<ItemLine>,
    #[serde(default)]
    load: Vec<ItemLine>,
    #[serde(default)]
    contact: Vec<ItemLine>,
    plate: Option<ItemLine>,
}

#[derive(Debug, Deserialize)]
struct ItemLine {
    group: Option<toml::Spanned<toml::Value>>,
    a: Option<toml::Spanned<toml::Value>>,
}

struct Builder<'a> {
    file: &'a Path,
    gmsh: &'a GmshMesh,
    /// Lines of the bodies, supports, loads, contact pairs and the plate (0: unknown).
    lines: [Vec<usize>; 5],
}

/// Shorthand for an error in the scene file.
fn fail<T>(file: &Path, message: impl Into<String>) -> Result<T> {
    Err(SceneError {
        file: file.to_path_buf(),
        message: message.into(),
    })
}

/// The unit check of a force-controlled plate, which the dry run's linear solve cannot make
/// (the plate's force reaches the body only through contact): the mean stress
/// `sigma = |F| / A` under the plate's lines (their area `A = t L`, `A = sum 2 pi r ds` in
/// axisymmetry) against the least Young's modulus `E` of the bodies they bound. A warning
/// when the nominal strain `sigma / E` exceeds [`STRAIN_WARNING`] (far beyond small strain)
/// or lies below [`TINY_STRAIN`] (a contact of a node or two): a likely unit mistake.
fn plate_strain(
    what: &str,
    p: &PlateSpec,
    model: &Model,
    edges: &HashMap<(usize, usize), (usize, usize)>,
    lines: impl Iterator<Item = [usize; 2]>,
) -> Option<String> {
    let x = &model.mesh.nodes;
    let (mut length, mut area, mut youngs) = (0.0, 0.0, f64::INFINITY);
    for [u, v] in lines {
        let el = edges.get(&(u, v)).or_else(|| edges.get(&(v, u)))?.0;
        let m = &model.materials[model.mesh.element_material[el]];
        let ds = (x[v][0] - x[u][0]).hypot(x[v][1] - x[u][1]);
        length += ds;
        area += ds
            * if m.analysis == Analysis::Axisymmetric {
                std::f64::consts::PI * (x[u][0] + x[v][0])
            } else {
                m.thickness
            };
        youngs = youngs.min(m.youngs);
    }
    let force = (0..2)
        .filter(|&d| p.x == "force" && d == 0 || p.y == "force" && d == 1)
        .map(|d| p.value[d].abs())
        .fold(0.0, f64::max);
    if force == 0.0 || area == 0.0 {
        return None;
    }
    let strain = force / (youngs * area);
    let (size, effect) = if strain > STRAIN_WARNING {
        ("far beyond small strain", "")
    } else if strain < TINY_STRAIN {
        (
            "implausibly small for a loaded part",
            " (a contact of a node or two)",
        )
    } else {
        return None;
    };
    Some(format!(
        "{what}: the force {force:e} over the plate's {length:.4e} long lines is a mean strain \
         of about {strain:.1e} (force / (E area), E = {youngs:e}), {size}{effect} at factor 1 \
         (units? e.g. E in Pa with lengths in mm, or in MPa with N and m)"
    ))
}

fn parse_analysis(s: &str) -> Option<Analysis> {
    Some(match s {
        "plane_strain" => Analysis::PlaneStrain,
        "plane_stress" => Analysis::PlaneStress,
        "axisymmetric" => Analysis::Axisymmetric,
        _ => return None,
    })
}

fn parse_formulation(s: &str) -> Option<Formulation> {
    Formulation::ALL.into_iter().find(|f| f.name() == s)
}

fn dims(d: usize) -> &'static str {
    match d {
        0 => "0D (points)",
        1 => "1D (lines)",
        2 => "2D (surfaces)",
        _ => "3D (volumes)",
    }
}

impl Builder<'_> {
    fn err<T>(&self, message: impl Into<String>) -> Result<T> {
        fail(self.file, message)
    }

    /// `" (line N)"` for item `k` of kind `kind` (0 body, 1 support, 2 load, 3 contact,
    /// 4 plate), or nothing when unknown.
    fn at(&self, kind: usize, k: usize) -> String {
        match self.lines[kind].get(k) {
            Some(&l) if l > 0 => format!(" (line {l})"),
            _ => String::new(),
        }
    }

    /// The group `name`, of one of the dimensions `want` (`what` says what it is for).
    fn group(&self, name: &str, want: &[usize], what: &str) -> Result<&Group> {
        let Some(g) = self.gmsh.groups.get(name) else {
            let known: Vec<String> = self
                .gmsh
                .groups
                .iter()
                .map(|(n, g)| format!("{n:?} ({}D)", g.dim))
                .collect();
            return self.err(format!(
                "{what}: unknown physical group {name:?} in {} (its groups: {})",
                self.gmsh.file.display(),
                if known.is_empty() {
                    "none: add Physical Surface/Curve/Point in the .geo".to_string()
                } else {
                    known.join(", ")
                }
            ));
        };
        if !want.contains(&g.dim) {
            let wanted: Vec<&str> = want.iter().map(|&d| dims(d)).collect();
            return self.err(format!(
                "{what}: group {name:?} is {}, this needs {}",
                dims(g.dim),
                wanted.join(" or ")
            ));
        }
        Ok(g)
    }

    fn build(&self, spec: SceneSpec) -> Result<Scene> {
        let Some(analysis) = parse_analysis(&spec.analysis) else {
            return self.err(format!(
                "analysis = {:?}: plane_strain, plane_stress or axisymmetric",
                spec.analysis
            ));
        };
        if spec.body.is_empty() {
            return self.err("no [[body]]: a scene needs at least one body");
        }
        // bodies: materials, formulation, the mesh renumbered over the bodies' nodes
        let mut formulation: Option<(Formulation, String)> = None;
        let mut materials = Vec::new();
        let mut mesh = Mesh::new();
        let mut id: Vec<Option<usize>> = vec![None; self.gmsh.nodes.len()];
        let mut bodies = Vec::new();
        for (k, b) in spec.body.iter().enumerate() {
            let name = b.name.clone().unwrap_or_else(|| b.group.clone());
            let what = format!("body {name:?}{}", self.at(0, k));
            let g = self.group(&b.group, &[2], &what)?;
            if g.quads.is_empty() {
                return self.err(format!("{what}: group {:?} has no elements", b.group));
            }
            let Some(m) = b.material else {
                return self.err(format!(
                    "{what}: no material (add material = {{ E = ..., nu = ..., thickness = ... }})"
                ));
            };
            let material = Material::new(m.youngs, m.nu, m.thickness, analysis)
                .or_else(|e| self.err(format!("{what}: material: {e}")))?;
            let f_name = b.formulation.clone().unwrap_or_else(|| "hybrid".into());
            let Some(f) = parse_formulation(&f_name) else {
                return self.err(format!(
                    "{what}: formulation {f_name:?} (hybrid, pian-sumihara or q4)"
                ));
            };
            match &formulation {
                Some((f0, first)) if *f0 != f => {
                    return self.err(format!(
                        "{what}: formulation {f_name}, but body {first:?} has {}: one formulation \
                         per model",
                        f0.name()
                    ));
                }
                Some(_) => {}
                None => formulation = Some((f, name.clone())),
            }
            let index = materials.len();
            materials.push(material);
            let mut nodes = BTreeSet::new();
            for q in &g.quads {
                let ids: Vec<usize> = q
                    .iter()
                    .map(|&n| {
                        nodes.insert(n);
                        *id[n].get_or_insert_with(|| mesh.push_node(self.gmsh.nodes[n]))
                    })
                    .collect();
                mesh.push_element(&ids, index);
            }
            if analysis == Analysis::Axisymmetric
                && let Some(&n) = nodes.iter().find(|&&n| self.gmsh.nodes[n][0] < 0.0)
            {
                return self.err(format!(
                    "{what}: node {} has x = {} < 0 (axisymmetric: x = r >= 0)",
                    self.gmsh.node_tags[n], self.gmsh.nodes[n][0]
                ));
            }
            bodies.push(Body {
                name,
                group: b.group.clone(),
                elements: g.quads.len(),
                nodes: nodes.len(),
                material,
            });
        }
        let formulation = formulation.map_or(Formulation::Hybrid, |f| f.0);
        let mut model = Model::new(mesh, materials, formulation);
        model
            .validate()
            .or_else(|e| self.err(format!("the bodies' mesh: {e}")))?;
        let edges = model.mesh.directed_edges();
        // the mesh's node tag of every model node, for the messages and outputs
        let mut tags: Vec<u64> = vec![0; model.mesh.n_nodes()];
        for (n, i) in id.iter().enumerate() {
            if let Some(i) = i {
                tags[*i] = self.gmsh.node_tags[n];
            }
        }

        // the nodes of a group, in model ids; an error if one is on no body
        let model_nodes = |g: &Group, name: &str, what: &str| -> Result<Vec<usize>> {
            g.nodes()
                .into_iter()
                .map(|n| {
                    id[n].ok_or_else(|| SceneError {
                        file: self.file.to_path_buf(),
                        message: format!(
                            "{what}: node {} of group {name:?} is on no body",
                            self.gmsh.node_tags[n]
                        ),
                    })
                })
                .collect()
        };
        let mut curves: Vec<String> = Vec::new();
        let mut curve_of = |c: &Option<String>| -> usize {
            let c = c.clone().unwrap_or_else(|| "load".into());
            curves.iter().position(|x| *x == c).unwrap_or_else(|| {
                curves.push(c);
                curves.len() - 1
            })
        };

        // supports
        let mut warnings = Vec::new();
        let mut supports = Vec::new();
        let mut prescribed = Vec::new();
        let mut extent = 0.0_f64;
        for (k, s) in spec.support.iter().enumerate() {
            let what = format!("support on {:?}{}", s.group, self.at(1, k));
            let g = self.group(&s.group, &[0, 1], &what)?;
            let nodes = model_nodes(g, &s.group, &what)?;
            if s.x.is_none() && s.y.is_none() {
                return self.err(format!("{what}: holds nothing (give x, y or both)"));
            }
            // a support that only holds (all values 0) needs no curve
            let moves = [s.x, s.y].iter().flatten().any(|&v| v != 0.0);
            let curve = (moves || s.curve.is_some()).then(|| curve_of(&s.curve));
            for (dir, v) in [(0, s.x), (1, s.y)] {
                let Some(v) = v else { continue };
                if !v.is_finite() {
                    return self.err(format!("{what}: value {v} is not finite"));
                }
                model
                    .fix_dir(&nodes, dir, v)
                    .or_else(|e| self.err(format!("{what}: {e} (two supports on one node?)")))?;
                if let Some(curve) = curve {
                    prescribed.extend(nodes.iter().map(|&n| (2 * n + dir, v, curve)));
                }
                extent = extent.max(v.abs());
            }
            let values: Vec<String> = [("x", s.x), ("y", s.y)]
                .iter()
                .filter_map(|(d, v)| v.map(|v| format!("u{d} = {v}")))
                .collect();
            supports.push(format!(
                "{:?}: {} nodes, {}{}",
                s.group,
                nodes.len(),
                values.join(", "),
                s.curve
                    .as_ref()
                    .map_or(String::new(), |c| format!(" (curve {c})"))
            ));
        }
        let plate = match &spec.plate {
            None => None,
            Some(p) => {
                let what = format!("plate on {:?}{}", p.group, self.at(4, 0));
                let g = self.group(&p.group, &[0, 1], &what)?;
                let nodes = model_nodes(g, &p.group, &what)?;
                let mut force = [false; 2];
                for (d, kind) in [&p.x, &p.y].into_iter().enumerate() {
                    force[d] = match kind.as_str() {
                        "force" => true,
                        "displacement" => false,
                        _ => {
                            return self
                                .err(format!("{what}: control {kind:?} (displacement or force)"));
                        }
                    };
                }
                if p.value.iter().any(|v| !v.is_finite()) {
                    return self.err(format!("{what}: a value is not finite"));
                }
                model.fix(&nodes, [0.0, 0.0]).or_else(|e| {
                    self.err(format!("{what}: {e} (a plate node has a support too?)"))
                })?;
                supports.push(format!(
                    "{:?}: {} nodes on a rigid plate, x by {} {}, y by {} {}",
                    p.group,
                    nodes.len(),
                    p.x,
                    p.value[0],
                    p.y,
                    p.value[1]
                ));
                let ends = g.lines.iter().filter_map(|&[u, v]| Some([id[u]?, id[v]?]));
                if let Some(w) = plate_strain(&what, p, &model, &edges, ends) {
                    warnings.push(w);
                }
                Some(Plate {
                    group: p.group.clone(),
                    nodes,
                    force,
                    value: p.value,
                    curve: curve_of(&p.curve),
                })
            }
        };
        self.check_held(&model, &bodies, analysis)?;

        // loads: one force vector per curve
        let n_dof = 2 * model.mesh.n_nodes();
        let mut loads = Vec::new();
        let mut per_curve: Vec<(usize, Model)> = Vec::new();
        for (k, l) in spec.load.iter().enumerate() {
            let what = format!("load on {:?}{}", l.group, self.at(2, k));
            let given = [
                l.pressure.is_some(),
                l.traction.is_some(),
                l.force.is_some(),
            ];
            if given.iter().filter(|&&g| g).count() != 1 {
                return self.err(format!(
                    "{what}: give exactly one of pressure, traction or force"
                ));
            }
            let values: Vec<f64> = l
                .pressure
                .into_iter()
                .chain(l.traction.into_iter().flatten())
                .chain(l.force.into_iter().flatten())
                .collect();
            if values.iter().any(|v| !v.is_finite()) {
                return self.err(format!("{what}: a value is not finite"));
            }
            let curve = curve_of(&l.curve);
            let mut scratch = Model::new(model.mesh.clone(), model.materials.clone(), formulation);
            let g;
            if let Some(f) = l.force {
                g = self.group(&l.group, &[0, 1], &what)?;
                let nodes = model_nodes(g, &l.group, &what)?;
                scratch.nodal_forces = nodes.iter().map(|&n| (n, f)).collect();
                loads.push(format!(
                    "{:?}: force {f:?} on each of {} nodes",
                    l.group,
                    nodes.len()
                ));
            } else {
                g = self.group(&l.group, &[1], &what)?;
                let mut body_e = f64::INFINITY;
                for &[p, q] in &g.lines {
                    let (Some(p), Some(q)) = (id[p], id[q]) else {
                        return self.err(format!("{what}: a line of {:?} is on no body", l.group));
                    };
                    let (s, e) = if let Some(&(el, _)) = edges.get(&(p, q)) {
                        body_e =
                            body_e.min(model.materials[model.mesh.element_material[el]].youngs);
                        (p, q)
                    } else if let Some(&(el, _)) = edges.get(&(q, p)) {
                        body_e =
                            body_e.min(model.materials[model.mesh.element_material[el]].youngs);
                        (q, p)
                    } else {
                        return self.err(format!(
                            "{what}: the line {}-{} is on no element's boundary",
                            self.gmsh.node_tags[g.lines[0][0]], self.gmsh.node_tags[g.lines[0][1]]
                        ));
                    };
                    let t = match (l.pressure, l.traction) {
                        (Some(pr), _) => {
                            let (a, b) = (model.mesh.nodes[s], model.mesh.nodes[e]);
                            let d = [b[0] - a[0], b[1] - a[1]];
                            let len = d[0].hypot(d[1]);
                            // outward normal (d_y, -d_x) / |d|; a pressure pushes inward
                            [-pr * d[1] / len, pr * d[0] / len]
                        }
                        (_, Some(t)) => t,
                        _ => unreachable!("one of pressure or traction is given"),
                    };
                    scratch.load_edges(&[[s, e]], t);
                }
                let magnitude = values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
                if magnitude > 0.05 * body_e {
                    warnings.push(format!(
                        "{what}: {magnitude} is {:.1}% of E = {body_e}: strains far beyond small \
                         strain (units? e.g. MPa against Pa)",
                        100.0 * magnitude / body_e
                    ));
                }
                loads.push(format!(
                    "{:?}: {} on {} lines",
                    l.group,
                    l.pressure.map_or_else(
                        || format!("traction {:?}", l.traction.unwrap_or_default()),
                        |p| format!("pressure {p}")
                    ),
                    g.lines.len()
                ));
            }
            if let Some(c) = &l.curve {
                let last = loads.len() - 1;
                let _ = write!(loads[last], " (curve {c})");
            }
            per_curve.push((curve, scratch));
        }

        // contact pairs
        let options = self.options(&spec.options)?;
        let mut pairs: Vec<Pair> = Vec::new();
        // segments already carrying multipliers (A) or opposite to them (B), and by which pair:
        // a segment may be B of several pairs (one base under two punches), never A twice nor
        // A of one pair and B of another
        let mut used: HashMap<(usize, usize), (bool, String)> = HashMap::new();
        let mut notes = Vec::new();
        for (k, c) in spec.contact.iter().enumerate() {
            let what = format!(
                "contact pair {} ({:?} on {:?}){}",
                k + 1,
                c.a,
                c.b,
                self.at(3, k)
            );
            if !(c.friction.is_finite() && c.friction >= 0.0) {
                return self.err(format!("{what}: friction {} (finite, >= 0)", c.friction));
            }
            if c.a == c.b {
                return self.err(format!(
                    "{what}: a and b are both group {:?}: a pair joins two sides, each on its own \
                     body (a: the multiplier side, b: the opposite side)",
                    c.a
                ));
            }
            let mut sides = Vec::new();
            for (name, is_a) in [(&c.a, true), (&c.b, false)] {
                let g = self.group(name, &[1], &what)?;
                if g.lines.is_empty() {
                    return self.err(format!("{what}: group {name:?} has no lines"));
                }
                let mut lines = Vec::with_capacity(g.lines.len());
                for &[p, q] in &g.lines {
                    match (id[p], id[q]) {
                        (Some(p), Some(q)) => lines.push([p, q]),
                        _ => {
                            return self
                                .err(format!("{what}: group {name:?} has a line on no body"));
                        }
                    }
                }
                let chain = gmsh::boundary_chain(&lines, &edges, &tags).or_else(|e| {
                    self.err(format!(
                        "{what}: group {name:?} is not a boundary chain: {e}"
                    ))
                })?;
                let chain = match &plate {
                    Some(p) => self.off_plate(chain, p, &tags, (&what, name), &mut notes)?,
                    None => chain,
                };
                let body = model.mesh.element_material[edges[&(chain[0], chain[1])].0];
                if chain
                    .windows(2)
                    .any(|w| model.mesh.element_material[edges[&(w[0], w[1])].0] != body)
                {
                    return self.err(format!("{what}: group {name:?} runs over two bodies"));
                }
                for w in chain.windows(2) {
                    let key = (w[0].min(w[1]), w[0].max(w[1]));
                    match used.get(&key) {
                        Some((was_a, other)) if is_a || *was_a => {
                            return self.err(format!(
                                "{what}: group {name:?} overlaps {other} (a boundary segment \
                                 on the multiplier side A of one pair is in another pair too)"
                            ));
                        }
                        Some(_) => {}
                        None => {
                            used.insert(key, (is_a, what.clone()));
                        }
                    }
                }
                sides.push((chain, body));
            }
            let ((a, body_a), (b, body_b)) = (sides[0].clone(), sides[1].clone());
            if body_a == body_b {
                return self.err(format!(
                    "{what}: both sides are on body {:?}: a pair is between two bodies",
                    bodies[body_a].name
                ));
            }
            let x = &model.mesh.nodes;
            let length = |ids: &[usize]| -> f64 {
                ids.windows(2)
                    .map(|w| (x[w[1]][0] - x[w[0]][0]).hypot(x[w[1]][1] - x[w[0]][1]))
                    .sum()
            };
            let (la, lb) = (length(&a), length(&b));
            let reach = options.search_distance * la / (a.len() - 1) as f64;
            let seen = facing::facing(&a, &b, x, reach);
            let gaps: Vec<f64> = a
                .iter()
                .filter_map(|&n| facing::side(&b, x, x[n]))
                .collect();
            let gap_range = gaps.iter().fold(None, |r: Option<(f64, f64)>, &g| {
                Some(r.map_or((g, g), |(lo, hi)| (lo.min(g), hi.max(g))))
            });
            // judged at any distance: sides that face each other nowhere never close, however
            // wide the search
            let anywhere = facing::facing(&a, &b, x, f64::INFINITY);
            if anywhere.facing + anywhere.touching == 0 && anywhere.same_way + anywhere.behind > 0 {
                return self.err(format!(
                    "{what}: these sides never face each other: of the A nodes, {} see the \
                     nearest B segment facing the same way and {} see it behind them (back to \
                     back), none in front: check the groups (a: the multiplier side, b: the \
                     side it touches)",
                    anywhere.same_way, anywhere.behind
                ));
            }
            if seen.facing + seen.touching == 0 {
                warnings.push(format!(
                    "{what}: no A node finds a B segment within the search distance ({reach:.3e}) \
                     in the initial configuration: the pair activates only if the bodies approach \
                     (raise options.search_distance if they should touch)"
                ));
            }
            pairs.push(Pair {
                groups: (c.a.clone(), c.b.clone()),
                bodies: (body_a, body_b),
                pair: ContactPair {
                    a,
                    b,
                    friction: c.friction,
                },
                lengths: (la, lb),
                gap_range,
                facing: seen,
                reach,
            });
        }

        // steps
        if spec.step.is_empty() {
            return self.err("no [[step]]: give at least one step (e.g. [[step]] load = 1.0)");
        }
        let mut steps = Vec::new();
        for (k, s) in spec.step.iter().enumerate() {
            if let Some(name) = s.keys().find(|n| !curves.contains(n)) {
                return self.err(format!(
                    "step {}: curve {name:?} is not used by any support or load (curves: {})",
                    k + 1,
                    curves.join(", ")
                ));
            }
            let mut row = Vec::new();
            for c in &curves {
                let Some(&v) = s.get(c) else {
                    return self.err(format!(
                        "step {}: no factor for curve {c:?} (every step gives every curve's total)",
                        k + 1
                    ));
                };
                if !v.is_finite() {
                    return self.err(format!("step {}: {c} = {v} is not finite", k + 1));
                }
                row.push(v);
            }
            steps.push(row);
        }
        let forces: Vec<Vec<f64>> = (0..curves.len())
            .map(|c| {
                let mut f = vec![0.0; n_dof];
                for (_, m) in per_curve.iter().filter(|(k, _)| *k == c) {
                    for (fi, v) in f.iter_mut().zip(m.external_forces()) {
                        *fi += v;
                    }
                }
                f
            })
            .collect();
        // a prescribed motion beyond 5% of the model's size is a likely unit mistake
        let bb = model.mesh.bounding_box();
        let size = (bb[2] - bb[0]).hypot(bb[3] - bb[1]);
        let top = steps.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
        if extent * top > 0.05 * size {
            warnings.push(format!(
                "a prescribed displacement reaches {:.3e}, {:.0}% of the model's size {size:.3e}: \
                 strains far beyond small strain (units? e.g. mm against m)",
                extent * top,
                100.0 * extent * top / size
            ));
        }
        Ok(Scene {
            file: self.file.to_path_buf(),
            spec,
            model,
            bodies,
            supports,
            loads,
            pairs,
            curves,
            forces,
            prescribed,
            steps,
            options,
            plate,
            warnings,
            notes,
            tags,
        })
    }

    /// A contact side `chain` (model ids) with the nodes it shares with the rigid plate taken
    /// off its ends (the plate holds them: a half disk's arc ends at its flat cut), a note in
    /// `notes` saying so. An error naming both groups when a plate node is inside the chain
    /// or the chain keeps fewer than two nodes.
    fn off_plate(
        &self,
        mut chain: Vec<usize>,
        plate: &Plate,
        tags: &[u64],
        (what, name): (&str, &str),
        notes: &mut Vec<String>,
    ) -> Result<Vec<usize>> {
        let on = |n: &usize| plate.nodes.contains(n);
        let mut dropped = Vec::new();
        while chain.first().is_some_and(on) {
            dropped.push(tags[chain.remove(0)]);
        }
        while chain.last().is_some_and(on) {
            dropped.push(tags[chain.pop().unwrap_or_default()]);
        }
        let plate_group = &plate.group;
        if let Some(&n) = chain.iter().find(|n| on(n)) {
            return self.err(format!(
                "{what}: node {} of group {name:?} is also on the plate's group {plate_group:?}: \
                 a plate node cannot carry contact (inside a contact side it would hold the \
                 surface rigid); make the plate's group and the contact side share at most \
                 their end nodes",
                tags[n]
            ));
        }
        if chain.len() < 2 {
            return self.err(format!(
                "{what}: group {name:?} lies on the plate's group {plate_group:?}: a plate node \
                 cannot carry contact; put the plate on another group"
            ));
        }
        if !dropped.is_empty() {
            let list: Vec<String> = dropped.iter().map(u64::to_string).collect();
            notes.push(format!(
                "{what}: node{} {} of group {name:?} {} on the plate's group {plate_group:?}: \
                 the plate holds {}, so the contact side starts one segment in (leave it so \
                 when the contact stays away from there; otherwise put the plate elsewhere)",
                if dropped.len() > 1 { "s" } else { "" },
                list.join(" and "),
                if dropped.len() > 1 {
                    "are also"
                } else {
                    "is also"
                },
                if dropped.len() > 1 { "them" } else { "it" },
            ));
        }
        Ok(chain)
    }

    fn options(&self, o: &OptionsSpec) -> Result<ContactOptions> {
        let mut opt = ContactOptions::default();
        if let Some(k) = &o.kinematics {
            opt.kinematics = k
                .parse::<Kinematics>()
                .or_else(|e| self.err(format!("options: {e}")))?;
        }
        if let Some(b) = &o.backend {
            opt.backend = match b.as_str() {
                "faer" => Backend::Faer,
                "cholmod" => Backend::Cholmod,
                _ => return self.err(format!("options: backend {b:?} (faer or cholmod)")),
            };
            if !opt.backend.available() {
                return self.err(format!(
                    "options: backend {b:?} is not in this build (build with --features suitesparse)"
                ));
            }
        }
        macro_rules! set {
            ($($f:ident),*) => { $( if let Some(v) = o.$f { opt.$f = v; } )* };
        }
        set!(
            search_distance,
            threads,
            tolerance,
            max_iterations,
            gap_tolerance,
            tension_tolerance,
            friction_tolerance,
            lock_rounds,
            cutback_depth,
            cutback_min_fraction
        );
        opt.validate()
            .or_else(|e| self.err(format!("options: {e}")))?;
        Ok(opt)
    }

    /// Every body held against rigid motion by its own supports (hycon factors `K` before any
    /// contact closes): x and y translation and the rotation in plane analyses, the axial
    /// translation in axisymmetry. Checked on the constraint rows of the rigid motions
    /// `u = (tx - w y, ty + w x)` at the held dofs.
    fn check_held(&self, model: &Model, bodies: &[Body], analysis: Analysis) -> Result<()> {
        let mut held = vec![[false; 2]; model.mesh.n_nodes()];
        for p in &model.prescribed {
            held[p.node][p.dir] = true;
        }
        // connected pieces of elements (sharing nodes): each must be held on its own
        let mesh = &model.mesh;
        let mut parent: Vec<usize> = (0..mesh.n_nodes()).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for e in 0..mesh.n_elements() {
            let el = mesh.element(e);
            for w in el.windows(2) {
                let (a, b) = (root(&mut parent, w[0]), root(&mut parent, w[1]));
                parent[a] = b;
            }
        }
        let mut pieces: BTreeMap<usize, (usize, usize, BTreeSet<usize>)> = BTreeMap::new();
        for e in 0..mesh.n_elements() {
            let r = root(&mut parent, mesh.element(e)[0]);
            let piece = pieces
                .entry(r)
                .or_insert_with(|| (mesh.element_material[e], 0, BTreeSet::new()));
            piece.1 += 1;
            piece.2.extend(mesh.element(e).iter().copied());
        }
        let mut per_body = vec![0usize; bodies.len()];
        for (b, _, _) in pieces.values() {
            per_body[*b] += 1;
        }
        for (b, elements, nodes) in pieces.values() {
            let body = &bodies[*b];
            let x = &model.mesh.nodes;
            let n = nodes.len() as f64;
            let c = nodes
                .iter()
                .fold([0.0, 0.0], |c, &i| [c[0] + x[i][0] / n, c[1] + x[i][1] / n]);
            let size = nodes
                .iter()
                .map(|&i| (x[i][0] - c[0]).hypot(x[i][1] - c[1]))
                .fold(0.0_f64, f64::max)
                .max(f64::MIN_POSITIVE);
            // Gram matrix of the rows (1, 0, -y) for held x and (0, 1, x) for held y
            let mut g = [[0.0_f64; 3]; 3];
            for &i in nodes {
                let (dx, dy) = ((x[i][0] - c[0]) / size, (x[i][1] - c[1]) / size);
                for (dir, row) in [(0, [1.0, 0.0, -dy]), (1, [0.0, 1.0, dx])] {
                    if held[i][dir] {
                        for r in 0..3 {
                            for s in 0..3 {
                                g[r][s] += row[r] * row[s];
                            }
                        }
                    }
                }
            }
            let free = if analysis == Analysis::Axisymmetric {
                (g[1][1] == 0.0).then_some("the translation in y (z, along the axis)")
            } else if g[0][0] == 0.0 {
                Some("the translation in x")
            } else if g[1][1] == 0.0 {
                Some("the translation in y")
            } else {
                let det = g[0][0] * (g[1][1] * g[2][2] - g[1][2] * g[2][1])
                    - g[0][1] * (g[1][0] * g[2][2] - g[1][2] * g[2][0])
                    + g[0][2] * (g[1][0] * g[2][1] - g[1][1] * g[2][0]);
                let scale = g[0][0] * g[1][1] * g[2][2].max(1e-300);
                (det <= 1e-10 * scale.max(1e-300) || det <= 1e-12).then_some(
                    "the rotation in the plane (hold a second point, or the other direction)",
                )
            };
            if let Some(motion) = free {
                let piece = if per_body[*b] > 1 {
                    format!(
                        " (its piece of {elements} elements around ({:.4e}, {:.4e}); the body has \
                         {} separate pieces, each needs supports)",
                        c[0], c[1], per_body[*b]
                    )
                } else {
                    String::new()
                };
                return self.err(format!(
                    "body {:?}{piece} is not held against rigid motion: its supports leave \
                     {motion} free. hycon factors K before contact closes, so every body needs \
                     supports of its own; a load (traction, pressure, force) holds nothing. A \
                     body pushed only through contact: put a [plate] on the group where the \
                     load goes in, with that direction controlled by force (y = \"force\", \
                     value = [0.0, -F]) and the other by displacement, or hold that group with \
                     a prescribed displacement",
                    body.name
                ));
            }
        }
        Ok(())
    }
}

impl Scene {
    /// The text of the dry run: bodies, supports, loads, pairs, steps, options, warnings and the
    /// verdict.
    pub fn describe(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "scene {} ({}, {} elements, {} nodes, formulation {})",
            self.file.display(),
            self.model.analysis().name(),
            self.model.mesh.n_elements(),
            self.model.mesh.n_nodes(),
            self.model.formulation.name()
        );
        let _ = writeln!(s, "bodies:");
        for b in &self.bodies {
            let _ = writeln!(
                s,
                "  {:<12} group {:?}: {} elements, {} nodes, E = {}, nu = {}, t = {}",
                b.name,
                b.group,
                b.elements,
                b.nodes,
                b.material.youngs,
                b.material.poisson,
                b.material.thickness
            );
        }
        let _ = writeln!(s, "supports:");
        for l in &self.supports {
            let _ = writeln!(s, "  {l}");
        }
        let _ = writeln!(s, "loads:");
        if self.loads.is_empty() {
            let _ = writeln!(s, "  none");
        }
        for l in &self.loads {
            let _ = writeln!(s, "  {l}");
        }
        let _ = writeln!(s, "contact pairs:");
        for (k, p) in self.pairs.iter().enumerate() {
            let f = p.facing;
            let _ = writeln!(
                s,
                "  {}: A {:?} (body {}, {} nodes, length {:.4e}) on B {:?} (body {}, {} nodes, \
                 length {:.4e}), friction {}",
                k + 1,
                p.groups.0,
                self.bodies[p.bodies.0].name,
                p.pair.a.len(),
                p.lengths.0,
                p.groups.1,
                self.bodies[p.bodies.1].name,
                p.pair.b.len(),
                p.lengths.1,
                p.pair.friction
            );
            let _ = writeln!(
                s,
                "     initial gap {}; within the search distance {:.3e}: {} of {} A nodes find B \
                 ({} facing, {} touching, {} same way, {} behind): {}",
                p.gap_range.map_or(
                    "not defined (A does not project onto B)".into(),
                    |(lo, hi)| { format!("from {lo:.4e} to {hi:.4e}") }
                ),
                p.reach,
                f.facing + f.touching + f.same_way + f.behind,
                p.pair.a.len(),
                f.facing,
                f.touching,
                f.same_way,
                f.behind,
                if f.facing + f.touching > 0 {
                    "the sides face each other"
                } else {
                    "no facing nodes yet"
                }
            );
        }
        let _ = writeln!(s, "steps (totals per curve: {}):", self.curves.join(", "));
        for (k, row) in self.steps.iter().enumerate() {
            let cols: Vec<String> = self
                .curves
                .iter()
                .zip(row)
                .map(|(c, v)| format!("{c} = {v}"))
                .collect();
            let _ = writeln!(s, "  {}: {}", k + 1, cols.join(", "));
        }
        let o = &self.options;
        let _ = writeln!(
            s,
            "options: kinematics {}, search distance {}, backend {}, threads {}, tolerance {}, \
             max iterations {}, cutback depth {}, min fraction {}",
            o.kinematics.name(),
            o.search_distance,
            o.backend.name(),
            o.threads,
            o.tolerance,
            o.max_iterations,
            o.cutback_depth,
            o.cutback_min_fraction
        );
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        for w in &self.warnings {
            let _ = writeln!(s, "warning: {w}");
        }
        let _ = writeln!(
            s,
            "verdict: ready to run{}",
            match self.warnings.len() {
                0 => String::new(),
                1 => " (1 warning above)".into(),
                n => format!(" ({n} warnings above)"),
            }
        );
        s
    }

    /// The dry run's unit check: step 1 solved linearly without contact (every body is held on
    /// its own, checked at load; a rigid plate's nodes move with its prescribed displacement and
    /// are held where it is force controlled) and, when the largest element strain (the largest
    /// principal strain in magnitude at an element's centre, the hoop strain included in
    /// axisymmetry) exceeds [`STRAIN_WARNING`], a warning added to [`Scene::warnings`] naming
    /// the body. Returns the largest strain and its body, if the solve succeeded (a failure is a
    /// warning too: the run would fail the same way).
    pub fn check_first_solve(&mut self) -> Option<(f64, usize)> {
        match self.first_solve_strain() {
            Ok(Some((strain, b))) => {
                if strain > STRAIN_WARNING {
                    self.warnings.push(format!(
                        "step 1 solved linearly without contact: largest strain {strain:.3e} in \
                         body {:?} (E = {}), far beyond small strain (units? e.g. E in MPa with \
                         loads in N and lengths in m)",
                        self.bodies[b].name, self.bodies[b].material.youngs
                    ));
                }
                Some((strain, b))
            }
            Ok(None) => None,
            Err(e) => {
                self.warnings.push(format!(
                    "step 1 solved linearly without contact failed: {e}"
                ));
                None
            }
        }
    }

    fn first_solve_strain(&self) -> hycon::Result<Option<(f64, usize)>> {
        if self.steps.is_empty() {
            return Ok(None);
        }
        let (f, mut qp) = self.step_loads(0);
        if let Some(p) = &self.plate {
            let s = self.steps[0][p.curve];
            for d in 0..2 {
                if !p.force[d] {
                    for &n in &p.nodes {
                        qp[2 * n + d] = s * p.value[d];
                    }
                }
            }
        }
        let model = &self.model;
        let mut system = LinearSystem::with_trailing_on(model, &[], self.options.backend)?;
        let solution = system.solve_for(model, &f, &qp)?;
        let mut worst: Option<(f64, usize)> = None;
        for e in 0..model.mesh.n_elements() {
            let b = model.mesh.element_material[e];
            let m = &model.materials[b];
            let [sx, sy, txy, s4] = solution.stress_field(model, e)?.at_centre_full();
            let (ex, ey, gxy, eth) = if m.analysis == Analysis::Axisymmetric {
                let c = m.compliance_axisymmetric();
                let v =
                    |i: usize| c[(i, 0)] * sx + c[(i, 1)] * sy + c[(i, 2)] * txy + c[(i, 3)] * s4;
                (v(0), v(1), v(2), v(3))
            } else {
                let c = m.compliance();
                let v = |i: usize| c[(i, 0)] * sx + c[(i, 1)] * sy + c[(i, 2)] * txy;
                (v(0), v(1), v(2), 0.0)
            };
            let strain = ((ex + ey) / 2.0).abs() + ((ex - ey) / 2.0).hypot(gxy / 2.0);
            let strain = strain.max(eth.abs());
            if strain.is_finite() && worst.is_none_or(|(w, _)| strain > w) {
                worst = Some((strain, b));
            }
        }
        Ok(worst)
    }

    /// The external forces and prescribed values of step `k` (totals).
    pub fn step_loads(&self, k: usize) -> (Vec<f64>, Vec<f64>) {
        let n = 2 * self.model.mesh.n_nodes();
        let mut f = vec![0.0; n];
        for (c, fc) in self.forces.iter().enumerate() {
            let s = self.steps[k][c];
            for (fi, v) in f.iter_mut().zip(fc) {
                *fi += s * v;
            }
        }
        let mut qp = vec![0.0; n];
        for &(dof, v, c) in &self.prescribed {
            qp[dof] = v * self.steps[k][c];
        }
        (f, qp)
    }

    /// The output folder: `output.dir` relative to the scene file, or `STEM-out` beside it.
    pub fn output_dir(&self) -> PathBuf {
        let base = self.file.parent().unwrap_or(Path::new("."));
        match &self.spec.output.dir {
            Some(d) => base.join(d),
            None => base.join(format!(
                "{}-out",
                self.file
                    .file_stem()
                    .map_or("scene".into(), |s| s.to_string_lossy())
            )),
        }
    }
}

/// Contact results of one pair at one step.
#[derive(Debug, Clone, Serialize)]
pub struct PairStep {
    /// Pair number (1-based).
    pub pair: usize,
    /// Length of A in contact (sum of the tributary lengths of closed nodes).
    pub contact_length: f64,
    /// Largest pressure `-tn`.
    pub peak_pressure: f64,
    /// Sum of the A nodes' contact forces `[fx, fy]`.
    pub total_force: [f64; 2],
    /// Closed nodes.
    pub active: usize,
    /// Slipping nodes.
    pub slip: usize,
}

/// One converged step.
#[derive(Debug, Clone, Serialize)]
pub struct StepResult {
    /// Step number (1-based).
    pub step: usize,
    /// Contact iterations.
    pub iterations: usize,
    /// Cutback sub-increments (1: none).
    pub sub_increments: usize,
    /// Per pair.
    pub pairs: Vec<PairStep>,
}

/// What [`run`] returns.
#[derive(Debug, Clone, Serialize)]
pub struct RunSummary {
    /// The scene file.
    pub scene: PathBuf,
    /// Steps that converged.
    pub steps: Vec<StepResult>,
    /// The error that stopped the run, if any.
    pub error: Option<String>,
    /// What the run suggests is wrong although it converged: a pair that never closed, a
    /// contact zone narrower than two elements (`hycon run --strict` fails on these).
    pub warnings: Vec<String>,
    /// Files written.
    pub files: Vec<PathBuf>,
}

/// What a converged run suggests is wrong: per pair, that it never closed over the run's
/// steps (a push of the wrong sign, bodies far apart), or that its contact zone at the last
/// step where it is closed spans fewer than two elements (fewer than three closed nodes: the
/// mesh cannot resolve the pressure, or the load is tiny for its units).
fn run_warnings(scene: &Scene, steps: &[StepResult]) -> Vec<String> {
    let mut warnings = Vec::new();
    if steps.is_empty() {
        return warnings;
    }
    for (p, pair) in scene.pairs.iter().enumerate() {
        let what = format!(
            "contact pair {} ({:?} on {:?})",
            p + 1,
            pair.groups.0,
            pair.groups.1
        );
        match steps.iter().rev().find(|s| s.pairs[p].active > 0) {
            None => warnings.push(format!(
                "{what} never closed in {} step{}: no A node touched B (a push of the wrong \
                 sign? bodies too far apart? see the initial gap in hycon run --dry-run)",
                steps.len(),
                if steps.len() > 1 { "s" } else { "" }
            )),
            Some(s) if s.pairs[p].active < 3 => warnings.push(format!(
                "{what}: at step {} the contact zone is {} node{} wide, narrower than two \
                 elements: the mesh does not resolve the pressure there (refine both sides \
                 near the contact, or check the units: a load tiny against E gives a tiny \
                 contact)",
                s.step,
                s.pairs[p].active,
                if s.pairs[p].active > 1 { "s" } else { "" }
            )),
            Some(_) => {}
        }
    }
    warnings
}

/// The message of a failed increment, with the mesh's node tags in place of the model ids the
/// contact errors name, and for an active node whose support B does not cover
/// ([`uncovered_advice`]) what to change.
fn failure(scene: &Scene, e: &hycon::Error) -> String {
    use hycon::ContactError as C;
    let hycon::Error::Contact(c) = e else {
        return e.to_string();
    };
    let tags = &scene.tags;
    if let C::Uncovered { node, coverage } = c {
        return format!(
            "contact: contact node {} is active but {:.1e} of its support is not covered by the \
             opposite surface: {}",
            tags.get(*node).copied().unwrap_or(*node as u64),
            1.0 - coverage,
            uncovered_advice(scene, *node)
        );
    }
    let tag = |n: &mut usize| *n = tags.get(*n).map_or(*n, |&t| t as usize);
    let mut c = c.clone();
    match &mut c {
        C::Cycling { node, .. }
        | C::EdgePenetration { node, .. }
        | C::SlipReversal { node, .. }
        | C::ConditionViolated { node, .. }
        | C::Unresolved { node, .. }
        | C::SmallSlidingExceeded { node, .. } => tag(node),
        C::BeyondSearchDistance { node, element, .. } => {
            tag(node);
            element.iter_mut().for_each(tag);
        }
        _ => {}
    }
    hycon::Error::Contact(c).to_string()
}

/// What to change when the A node `node` closed with part of its support uncovered by B.
/// Beyond an end of B (the node does not lie over B): extend B. Over B: the search window
/// (`search_distance` times A's mean segment, measured along A's normal) ends inside the
/// node's support, the surfaces being far apart there: the value of `search_distance` is
/// the cause, not B.
fn uncovered_advice(scene: &Scene, node: usize) -> String {
    let x = &scene.model.mesh.nodes;
    let Some(pair) = scene.pairs.iter().find(|p| p.pair.a.contains(&node)) else {
        return "extend the B polyline".into();
    };
    let b = &pair.groups.1;
    match facing::side(&pair.pair.b, x, x[node]) {
        None => format!(
            "it lies beyond an end of B: extend the B side (group {b:?}) past it, or shorten A \
             (group {:?})",
            pair.groups.0
        ),
        Some(distance) => {
            let segment = pair.reach / scene.options.search_distance;
            format!(
                "B (group {b:?}) runs on under it, {:.3e} away, so B's end is not the cause: the \
                 search window (search_distance = {} A segments = {:.3e}, measured along A's \
                 normal) ends inside the node's support. Change options.search_distance (a \
                 multiple of A's mean segment length) so that it clears the support, e.g. {:.0}, \
                 or make the flatter side A",
                distance.abs(),
                scene.options.search_distance,
                pair.reach,
                (2.0 * distance.abs() / segment)
                    .ceil()
                    .max(scene.options.search_distance + 1.0)
            )
        }
    }
}

fn pair_step(k: usize, rows: &[NodeResult]) -> PairStep {
    let closed = |r: &&NodeResult| !matches!(r.state, NodeState::Open);
    PairStep {
        pair: k + 1,
        // (+ 0.0: an empty sum is -0.0)
        contact_length: rows.iter().filter(closed).map(|r| r.weight).sum::<f64>() + 0.0,
        peak_pressure: rows.iter().map(|r| -r.tn).fold(0.0, f64::max),
        total_force: rows
            .iter()
            .fold([0.0, 0.0], |f, r| [f[0] + r.force[0], f[1] + r.force[1]])
            .map(|f| f + 0.0),
        active: rows.iter().filter(closed).count(),
        slip: rows
            .iter()
            .filter(|r| matches!(r.state, NodeState::Slip { .. }))
            .count(),
    }
}

/// Run the scene: every step as one increment of the contact analysis (loads and prescribed
/// values are totals), progress lines on `out`, the files of `spec.output` in
/// [`Scene::output_dir`]. A step that fails stops the run; the summary says which and why
/// (and the files of the converged steps are written).
///
/// # Errors
/// [`SceneError`] when the analysis cannot be set up or a file cannot be written.
pub fn run(scene: &Scene, out: &mut dyn std::io::Write) -> Result<RunSummary> {
    let err = |m: String| SceneError {
        file: scene.file.clone(),
        message: m,
    };
    let dir = scene.output_dir();
    std::fs::create_dir_all(&dir)
        .map_err(|e| err(format!("cannot create {}: {e}", dir.display())))?;
    let pairs: Vec<ContactPair> = scene.pairs.iter().map(|p| p.pair.clone()).collect();
    let _ = writeln!(
        out,
        "setting up: {} elements, {} nodes, {} pairs",
        scene.model.mesh.n_elements(),
        scene.model.mesh.n_nodes(),
        pairs.len()
    );
    let mut analysis = match &scene.plate {
        None => ContactAnalysis::new(scene.model.clone(), pairs, scene.options),
        Some(p) => {
            ContactAnalysis::with_plate(scene.model.clone(), pairs, scene.options, p.nodes.clone())
        }
    }
    .map_err(|e| err(format!("setting up the analysis: {e}")))?;
    let stem = scene
        .file
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy().to_string());
    let mut summary = RunSummary {
        scene: scene.file.clone(),
        steps: Vec::new(),
        error: None,
        warnings: Vec::new(),
        files: Vec::new(),
    };
    let mut csv = String::from("step,pair,node,x0,y0,x,y,state,tn,ts,pressure,gap,fx,fy\n");
    let mut history: Vec<Vec<Vec<NodeResult>>> = Vec::new();
    let _ = writeln!(
        out,
        "{:>4} {:>5} {:>4} {:>4} {:>12} {:>12} {:>12} {:>12}",
        "step", "iter", "sub", "pair", "contact len", "peak p", "force x", "force y"
    );
    for k in 0..scene.steps.len() {
        let (f, qp) = scene.step_loads(k);
        let step = match &scene.plate {
            None => analysis.increment(&f, &qp),
            Some(p) => {
                let s = scene.steps[k][p.curve];
                let c = |d: usize| {
                    if p.force[d] {
                        PlateControl::Force(s * p.value[d])
                    } else {
                        PlateControl::Displacement(s * p.value[d])
                    }
                };
                analysis.increment_with_plate(&f, &qp, &[c(0), c(1)])
            }
        };
        let info = match step {
            Ok(i) => i,
            Err(e) => {
                let m = format!("step {} did not converge: {}", k + 1, failure(scene, &e));
                let _ = writeln!(out, "{m}");
                summary.error = Some(m);
                break;
            }
        };
        let mut rows_k = Vec::new();
        let mut result = StepResult {
            step: k + 1,
            iterations: info.iterations,
            sub_increments: info.sub_increments,
            pairs: Vec::new(),
        };
        for p in 0..scene.pairs.len() {
            let rows = analysis
                .node_results(p)
                .map_err(|e| err(format!("step {}: {e}", k + 1)))?;
            let ps = pair_step(p, &rows);
            let _ = writeln!(
                out,
                "{:>4} {:>5} {:>4} {:>4} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e}",
                k + 1,
                info.iterations,
                info.sub_increments,
                p + 1,
                ps.contact_length,
                ps.peak_pressure,
                ps.total_force[0],
                ps.total_force[1]
            );
            for r in &rows {
                let x0 = scene.model.mesh.nodes[r.node];
                let _ = writeln!(
                    csv,
                    "{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                    k + 1,
                    p + 1,
                    scene.tags[r.node],
                    x0[0],
                    x0[1],
                    r.position[0],
                    r.position[1],
                    r.state.name(),
                    r.tn,
                    r.ts.components()[0],
                    -r.tn,
                    r.gap,
                    r.force[0],
                    r.force[1]
                );
            }
            result.pairs.push(ps);
            rows_k.push(rows);
        }
        if scene.pairs.is_empty() {
            let _ = writeln!(
                out,
                "{:>4} {:>5} {:>4}",
                k + 1,
                info.iterations,
                info.sub_increments
            );
        }
        if scene.spec.output.vtu {
            let path = dir.join(format!("{stem}-{:02}.vtu", k + 1));
            let q = analysis
                .displacement()
                .map_err(|e| err(format!("step {}: {e}", k + 1)))?;
            crate::report::vtu::write(&path, &scene.model, q).map_err(|e| err(e.to_string()))?;
            summary.files.push(path);
        }
        history.push(rows_k);
        summary.steps.push(result);
    }
    summary.warnings = run_warnings(scene, &summary.steps);
    for w in &summary.warnings {
        let _ = writeln!(out, "warning: {w}");
    }
    let write = |path: PathBuf, text: &str, files: &mut Vec<PathBuf>| -> Result<()> {
        std::fs::write(&path, text)
            .map_err(|e| err(format!("cannot write {}: {e}", path.display())))?;
        files.push(path);
        Ok(())
    };
    if scene.spec.output.csv && !scene.pairs.is_empty() {
        write(
            dir.join(format!("{stem}-contact.csv")),
            &csv,
            &mut summary.files,
        )?;
    }
    if scene.spec.output.svg {
        for p in 0..scene.pairs.len() {
            let svg = plot_pair(scene, p, &history)
                .map_err(|e| err(format!("plot of pair {}: {e}", p + 1)))?;
            write(
                dir.join(format!("{stem}-pair{}.svg", p + 1)),
                &svg,
                &mut summary.files,
            )?;
        }
    }
    if scene.spec.output.json {
        let path = dir.join(format!("{stem}-summary.json"));
        let mut files = summary.files.clone();
        files.push(path.clone());
        let text = serde_json::to_string_pretty(&RunSummary {
            files,
            ..summary.clone()
        })
        .map_err(|e| err(e.to_string()))?;
        write(path, &text, &mut summary.files)?;
    }
    for f in &summary.files {
        let _ = writeln!(out, "wrote {}", f.display());
    }
    Ok(summary)
}

/// SVG plot of pressure (top) and shear (bottom) along pair `p`'s A side (arc length from its
/// first node), one curve per step.
fn plot_pair(
    scene: &Scene,
    p: usize,
    history: &[Vec<Vec<NodeResult>>],
) -> std::result::Result<String, Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let x = &scene.model.mesh.nodes;
    let a = &scene.pairs[p].pair.a;
    let mut s = vec![0.0];
    for w in a.windows(2) {
        let d = (x[w[1]][0] - x[w[0]][0]).hypot(x[w[1]][1] - x[w[0]][1]);
        s.push(s.last().copied().unwrap_or(0.0) + d);
    }
    let series: Vec<Vec<(f64, f64, f64)>> = history
        .iter()
        .map(|step| {
            step[p]
                .iter()
                .zip(&s)
                .map(|(r, &si)| (si, -r.tn, r.ts.components()[0]))
                .collect()
        })
        .collect();
    let max_p = series
        .iter()
        .flatten()
        .fold(0.0_f64, |m, v| m.max(v.1.abs()).max(v.2.abs()))
        .max(1e-300);
    let len = s.last().copied().unwrap_or(1.0).max(1e-300);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 720)).into_drawing_area();
        root.fill(&WHITE)?;
        let panels = root.split_evenly((2, 1));
        let n = series.len().max(1);
        for (panel, (label, pick)) in panels
            .iter()
            .zip([("pressure -tn", 1usize), ("shear ts", 2usize)])
        {
            let lo = if pick == 1 { 0.0 } else { -1.05 * max_p };
            let mut chart = ChartBuilder::on(panel)
                .caption(
                    format!(
                        "pair {}: {} along A ({})",
                        p + 1,
                        label,
                        scene.pairs[p].groups.0
                    ),
                    ("sans-serif", 16),
                )
                .margin(10)
                .x_label_area_size(30)
                .y_label_area_size(60)
                .build_cartesian_2d(0.0..len, lo..1.05 * max_p)?;
            chart
                .configure_mesh()
                .x_desc("arc length along A")
                .y_desc(label)
                .draw()?;
            for (k, pts) in series.iter().enumerate() {
                let t = if n > 1 {
                    k as f64 / (n - 1) as f64
                } else {
                    1.0
                };
                let colour = HSLColor(0.66 * (1.0 - t), 0.8, 0.45);
                chart.draw_series(LineSeries::new(
                    pts.iter().map(|v| (v.0, if pick == 1 { v.1 } else { v.2 })),
                    colour.stroke_width(2),
                ))?;
            }
        }
        root.present()?;
    }
    Ok(svg)
}

/// Load `path`, solve step 1 linearly for the unit check ([`Scene::check_first_solve`]) and
/// return the dry run's text (or the error).
///
/// # Errors
/// The first set-up mistake.
pub fn dry_run(path: &Path) -> Result<String> {
    let mut scene = load(path)?;
    scene.check_first_solve();
    Ok(scene.describe())
}
