//! A host FE code's system as the bodies of a contact analysis ([`HostSystem`]): its contact
//! nodes (positions and equation numbers in its numbering) and either its stiffness in CSR,
//! factored here, a solve callback ([`HostSolve`]) so that the host factors `K` with its own
//! solver, or the condensed operator of its contact candidates ([`Condensed`]), computed by its
//! own solver in one factorization: the iteration then runs on it alone, and the host recovers
//! its displacements from the contact forces.
//!
//! The field is the host's `n` equations (`f` its right-hand side, which already holds the
//! effect of its prescribed displacements; no `qp`).

use super::{
    Bodies, CALLBACK_BATCH, ElementView, Stiffness, contact_reach, lazy_on, lock, unlocked,
};
use crate::contact::space::{MAX_DIM, Vector};
use crate::element::Formulation;
use crate::error::{Error, Result};
use crate::material::Material;
use crate::model::Model;
use crate::solver::{Backend, Reach, SparseCholesky};
use faer::Mat;
use faer::sparse::{SparseColMat, Triplet};
use nalgebra::DMatrix;
use std::sync::Mutex;

/// A host's linear solver: `K X = B` for many right-hand sides at once.
pub trait HostSolve: Send {
    /// Solve `K x_j = b_j` for the `nrhs` columns of `rhs` (`n x nrhs`, column-major), writing
    /// `x` (same layout). A failure is reported as [`Error::Callback`].
    fn solve(&mut self, nrhs: usize, rhs: &[f64], x: &mut [f64]) -> Result<()>;
}

/// Which triangle of a symmetric matrix a CSR array holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Triangle {
    /// Every entry (checked to be symmetric).
    Full,
    /// Entries with column <= row.
    Lower,
    /// Entries with column >= row.
    Upper,
}

/// A symmetric positive definite stiffness in compressed sparse row form, over the host's
/// equations (boundary conditions already applied).
#[derive(Debug, Clone, PartialEq)]
pub struct Csr {
    /// Order `n`.
    pub n: usize,
    /// Row starts, `n + 1` nondecreasing offsets into `columns` and `values`.
    pub row_ptr: Vec<usize>,
    /// Column of each entry.
    pub columns: Vec<usize>,
    /// Value of each entry.
    pub values: Vec<f64>,
    /// Which part of the matrix is stored.
    pub triangle: Triangle,
}

impl Csr {
    /// The lower triangle in compressed-column form (duplicates summed), after checking the
    /// structure, finiteness and, for [`Triangle::Full`], symmetry (relative `1e-10` of the
    /// largest entry).
    pub fn lower(&self) -> Result<SparseColMat<usize, f64>> {
        let n = self.n;
        if self.row_ptr.len() != n + 1 || self.row_ptr[0] != 0 {
            return Err(Error::InvalidInput(format!(
                "CSR row_ptr needs {} entries starting at 0",
                n + 1
            )));
        }
        let nnz = self.row_ptr[n];
        if self.row_ptr.windows(2).any(|w| w[0] > w[1])
            || self.columns.len() != nnz
            || self.values.len() != nnz
        {
            return Err(Error::InvalidInput(format!(
                "CSR row_ptr must be nondecreasing and end at the entry count ({} columns, {} \
                 values, row_ptr[n] = {nnz})",
                self.columns.len(),
                self.values.len()
            )));
        }
        let scale = self.values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut lower = Vec::with_capacity(nnz);
        let mut upper = Vec::new();
        for i in 0..n {
            for e in self.row_ptr[i]..self.row_ptr[i + 1] {
                let (j, v) = (self.columns[e], self.values[e]);
                if j >= n {
                    return Err(Error::InvalidInput(format!(
                        "CSR entry ({i}, {j}): column out of range (order {n})"
                    )));
                }
                if !v.is_finite() {
                    return Err(Error::InvalidInput(format!(
                        "CSR entry ({i}, {j}) = {v} is not finite"
                    )));
                }
                match (self.triangle, j.cmp(&i)) {
                    (Triangle::Lower, std::cmp::Ordering::Greater)
                    | (Triangle::Upper, std::cmp::Ordering::Less) => {
                        return Err(Error::InvalidInput(format!(
                            "CSR entry ({i}, {j}) lies outside the declared {:?} triangle",
                            self.triangle
                        )));
                    }
                    (Triangle::Upper, _) => lower.push(Triplet::new(j, i, v)),
                    (Triangle::Full, std::cmp::Ordering::Greater) => {
                        upper.push(Triplet::new(j, i, v))
                    }
                    _ => lower.push(Triplet::new(i, j, v)),
                }
            }
        }
        let matrix = SparseColMat::try_new_from_triplets(n, n, &lower)
            .map_err(|e| Error::InvalidInput(format!("CSR matrix: {e:?}")))?;
        if self.triangle == Triangle::Full {
            let mirror = SparseColMat::try_new_from_triplets(n, n, &upper)
                .map_err(|e| Error::InvalidInput(format!("CSR matrix: {e:?}")))?;
            check_symmetric(&matrix, &mirror, scale)?;
        }
        Ok(matrix)
    }
}

/// `lower` (entries on and below the diagonal) against `mirror` (the transposed strict upper
/// part): equal off the diagonal to `1e-10 scale`.
fn check_symmetric(
    lower: &SparseColMat<usize, f64>,
    mirror: &SparseColMat<usize, f64>,
    scale: f64,
) -> Result<()> {
    let dense = |m: &SparseColMat<usize, f64>, j: usize| -> Vec<(usize, f64)> {
        let (rows, vals) = (m.row_idx_of_col(j), m.val_of_col(j));
        rows.zip(vals.iter().copied())
            .filter(|&(i, _)| i != j)
            .collect()
    };
    for j in 0..lower.ncols() {
        let (a, b) = (dense(lower, j), dense(mirror, j));
        let mut merged: std::collections::BTreeMap<usize, f64> = a.into_iter().collect();
        for (i, v) in b {
            *merged.entry(i).or_insert(0.0) -= v;
        }
        if let Some((&i, &d)) = merged.iter().find(|(_, d)| d.abs() > 1e-10 * scale) {
            return Err(Error::InvalidInput(format!(
                "CSR matrix declared full is not symmetric: K[{i}][{j}] - K[{j}][{i}] = {d:e}"
            )));
        }
    }
    Ok(())
}

/// How the host's stiffness reaches the iteration.
pub enum HostStiffness {
    /// The matrix, factored here (fill-reducing order; with the contact equations last under
    /// finite kinematics).
    Csr(Csr),
    /// The host's own solver.
    Solver(Box<dyn HostSolve>),
    /// The condensed operator over the host's contact candidates, from its own solver.
    Condensed(Condensed),
}

/// Which operator a [`Condensed`] hand-over holds, over the candidate equations `c` (the
/// others `i`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CondensedKind {
    /// The stiffness Schur complement `S = K_cc - K_ci K_ii^-1 K_ic`, what a sparse direct
    /// solver's Schur interface gives (MUMPS through PETSc's `MatFactorSetSchurIS` /
    /// `MatFactorCreateSchurComplement`): hycon factors it by dense Cholesky and inverts the
    /// factor, `(K^-1)_cc = S^-1`.
    Stiffness,
    /// The flexibility block `(K^-1)_cc` itself, what one batched solve `K X = E_c` gives.
    Flexibility,
}

/// A host's condensed operator over its contact candidate equations: the iteration needs
/// `K^-1` only between the contact dofs, and this gives it in one piece, so that no solve is
/// asked for during an increment. The candidates hold every equation of the contact nodes
/// (which under finite kinematics must cover the whole sliding range: the pairs' polylines
/// do) and may hold more (a flexibility's extra rows are ignored, a Schur complement's extra
/// unknowns are condensed out).
#[derive(Debug, Clone, PartialEq)]
pub struct Condensed {
    /// Which operator `matrix` is.
    pub kind: CondensedKind,
    /// The candidate equations (host numbering), each once: the order of `matrix`'s rows and
    /// columns and of the load image of an increment.
    pub equations: Vec<usize>,
    /// `m x m`, column-major (`matrix[i + m j]` couples `equations[i]` and `equations[j]`),
    /// symmetric.
    pub matrix: Vec<f64>,
}

/// Relative asymmetry a condensed operator may show (of its largest entry): a host solver's
/// round-off, not a wrong layout.
const CONDENSED_SYMMETRY: f64 = 1e-6;

impl Condensed {
    /// Check the hand-over for a host of `n_equations` equations: `m^2` finite values,
    /// candidates in range and distinct, the matrix symmetric to `CONDENSED_SYMMETRY` (1e-6) of its
    /// largest entry.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the entry or the equation.
    pub fn check(&self, n_equations: usize) -> Result<()> {
        let m = self.equations.len();
        if m == 0 || m.checked_mul(m) != Some(self.matrix.len()) {
            return Err(Error::InvalidInput(format!(
                "the condensed operator has {} values for {m} candidate equations (needs m^2 > 0)",
                self.matrix.len()
            )));
        }
        let mut seen = vec![false; n_equations];
        for &e in &self.equations {
            if e >= n_equations || std::mem::replace(&mut seen[e], true) {
                return Err(Error::InvalidInput(format!(
                    "candidate equation {e} is out of range (n = {n_equations}) or given twice"
                )));
            }
        }
        if let Some(k) = self.matrix.iter().position(|v| !v.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "the condensed operator's entry ({}, {}) = {} is not finite",
                k % m,
                k / m,
                self.matrix[k]
            )));
        }
        let largest = self.matrix.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        for j in 0..m {
            for i in j + 1..m {
                let d = self.matrix[i + m * j] - self.matrix[j + m * i];
                if d.abs() > CONDENSED_SYMMETRY * largest {
                    return Err(Error::InvalidInput(format!(
                        "the condensed operator is not symmetric: entries ({i}, {j}) and \
                         ({j}, {i}) differ by {d:e} (largest entry {largest:e}); is it \
                         column-major over the candidates?"
                    )));
                }
            }
        }
        Ok(())
    }

    /// `(K^-1)` between the contact equations `contact` (all among the candidates): read off a
    /// flexibility block, or from `S^-1` by the dense Cholesky factor of a Schur complement
    /// (the same inversion the CSR path applies to its factor's trailing block). Symmetric:
    /// each pair of entries is averaged.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a contact equation that is no candidate,
    /// [`Error::Singular`] for a Schur complement that is not positive definite.
    fn flexibility(&self, contact: &[(usize, usize)]) -> Result<Mat<f64>> {
        let m = self.equations.len();
        let mut position = std::collections::HashMap::with_capacity(m);
        for (i, &e) in self.equations.iter().enumerate() {
            position.insert(e, i);
        }
        let rows: Vec<usize> = contact
            .iter()
            .map(|&(id, e)| {
                position.get(&e).copied().ok_or_else(|| {
                    Error::InvalidInput(format!(
                        "contact node {id}: its equation {e} is not among the condensed \
                         operator's candidates"
                    ))
                })
            })
            .collect::<Result<_>>()?;
        let given = faer::MatRef::from_column_major_slice(&self.matrix, m, m);
        let average = |a: &dyn Fn(usize, usize) -> f64| {
            Mat::<f64>::from_fn(rows.len(), rows.len(), |i, j| {
                0.5 * (a(rows[i], rows[j]) + a(rows[j], rows[i]))
            })
        };
        match self.kind {
            CondensedKind::Flexibility => Ok(average(&|i, j| given[(i, j)])),
            CondensedKind::Stiffness => {
                let s = Mat::<f64>::from_fn(m, m, |i, j| 0.5 * (given[(i, j)] + given[(j, i)]));
                let llt = s.llt(faer::Side::Lower).map_err(|_| {
                    Error::Singular(
                        "the condensed stiffness (Schur complement) is not positive definite: \
                         a body not held, or not a stiffness"
                            .into(),
                    )
                })?;
                let inverse = crate::solver::inverse_from_factor(llt.L());
                Ok(average(&|i, j| inverse[(i, j)]))
            }
        }
    }
}

impl std::fmt::Debug for HostStiffness {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HostStiffness::Csr(c) => write!(f, "Csr(n = {}, nnz = {})", c.n, c.values.len()),
            HostStiffness::Solver(_) => f.write_str("Solver(..)"),
            HostStiffness::Condensed(c) => {
                write!(f, "Condensed({:?}, m = {})", c.kind, c.equations.len())
            }
        }
    }
}

/// One contact node of a host: its id in the host's numbering, reference position, and the
/// host equation of each displacement component (`None`: held fixed at zero by the host).
/// Plane and axisymmetric hosts give 2 components, a 3D host 3; all nodes of one host have
/// one dimension (checked by [`HostBodies::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HostNode {
    /// Node id in the host's numbering (as used in the contact pairs).
    pub id: usize,
    /// Reference position (2 or 3 components).
    pub position: Vector,
    /// Host equations of the displacement components, one per component of `position`.
    pub equations: NodeEquations,
}

/// The host equations of a node's displacement components in order (`u_x, u_y [, u_z]`), 2 or
/// 3 of them (`None`: held fixed at zero by the host). Its own length, as a [`Vector`]'s, so
/// that a node cannot carry an equation for a component its position lacks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NodeEquations {
    len: u8,
    e: [Option<usize>; MAX_DIM],
}

impl NodeEquations {
    /// The equations `e` of the components in order.
    ///
    /// # Panics
    /// When `e` has not 2 or 3 entries (a programming error: the host's dimension fixes it).
    pub fn new(e: &[Option<usize>]) -> Self {
        assert!((2..=MAX_DIM).contains(&e.len()), "{} equations", e.len());
        let mut out = NodeEquations {
            len: e.len() as u8,
            e: [None; MAX_DIM],
        };
        out.e[..e.len()].copy_from_slice(e);
        out
    }

    /// The number of components (2 or 3).
    pub fn dim(&self) -> usize {
        usize::from(self.len)
    }

    /// The equation of each component.
    pub fn as_slice(&self) -> &[Option<usize>] {
        &self.e[..self.dim()]
    }

    /// The equation of component `i` (`None` when held fixed, or past the last component).
    pub fn get(&self, i: usize) -> Option<usize> {
        self.as_slice().get(i).copied().flatten()
    }

    /// The equations given (fixed components left out), in component order.
    pub fn given(&self) -> impl Iterator<Item = usize> + '_ {
        self.as_slice().iter().copied().flatten()
    }
}

/// The equations `e` in order.
///
/// # Panics
/// When `N` is not 2 or 3.
impl<const N: usize> From<[Option<usize>; N]> for NodeEquations {
    fn from(e: [Option<usize>; N]) -> Self {
        NodeEquations::new(&e)
    }
}

/// A host's linear system as the contact iteration needs it.
#[derive(Debug)]
pub struct HostSystem {
    /// Number of host equations `n`.
    pub equations: usize,
    /// Every node of every contact pair, each once.
    pub nodes: Vec<HostNode>,
    /// The stiffness over the `n` equations.
    pub stiffness: HostStiffness,
    /// Optionally, the elements along the A polylines, for tractions from element stresses.
    pub elements: Option<HostElements>,
    /// Per pair, a point inside body A (the multiplier side), or `None`; empty for none at
    /// all. Where a pair's surfaces touch (within half a segment of each other) the polylines
    /// alone cannot tell facing surfaces from back-to-back ones (both reversed): such a pair
    /// needs it, unless [`elements`](Self::elements) has an element on a segment of A (its
    /// centroid is then taken). A point given is checked to lie on A's body side of its
    /// polyline (see [`check_a_inside`](crate::contact::iteration::check_a_inside)). A 3D
    /// host ([`ContactAnalysis::solid_host`](crate::contact::iteration::ContactAnalysis::solid_host))
    /// gives points of 3 components, checked to lie on A's body side of its nearest A face.
    pub a_inside: Vec<Option<Vector>>,
    /// The section of each contact pair's A side, in the order of the pairs: its analysis kind
    /// (all pairs of one kind) and thickness. The contact integrals are weighted by its
    /// measure (the thickness in plane analysis, `2 pi r` in axisymmetry), so that the
    /// tractions are pressures and the contact forces are in the units of the host's stiffness
    /// (per thickness, or over the full circle); the [`elements`](Self::elements) along A are
    /// of their pair's section (checked, see [`handover`](crate::contact::handover)). Empty
    /// for a 3D host, as are its [`elements`](Self::elements).
    pub sections: Vec<crate::contact::handover::Section>,
}

/// Elements of a host along its A polylines (those owning the A segments), with hycon's element
/// formulations, so that hycon can recover the tractions from the element stresses (the
/// paper's way (a)) from the host's displacements. Host elements are plane (or axisymmetric)
/// elements: every node of `node_table` has 2 components and 2 equations (checked).
#[derive(Debug, Clone, PartialEq)]
pub struct HostElements {
    /// The elements' formulation.
    pub formulation: Formulation,
    /// Materials.
    pub materials: Vec<Material>,
    /// Material of each element.
    pub element_material: Vec<usize>,
    /// Element `e` has the node ids `nodes[offsets[e]..offsets[e + 1]]` (host numbering,
    /// counter-clockwise).
    pub offsets: Vec<usize>,
    /// Node ids of the elements.
    pub nodes: Vec<usize>,
    /// Every node the elements use: id, reference position, equations.
    pub node_table: Vec<HostNode>,
}

impl HostElements {
    /// The centroid of the first element that has a segment of the polyline `ids` (host ids)
    /// as an edge, either way round, if one does: a point inside that element's body, the
    /// nodes' mean position of a convex element. One pass over the elements.
    pub fn centroid_beside(&self, ids: &[usize]) -> Option<Vector> {
        let segments: std::collections::HashSet<(usize, usize)> = ids
            .windows(2)
            .map(|w| (w[0].min(w[1]), w[0].max(w[1])))
            .collect();
        let element = self
            .offsets
            .windows(2)
            .map(|w| &self.nodes[w[0]..w[1]])
            .find(|e| {
                (0..e.len()).any(|i| {
                    let (p, q) = (e[i], e[(i + 1) % e.len()]);
                    segments.contains(&(p.min(q), p.max(q)))
                })
            })?;
        let position = |id: usize| {
            self.node_table
                .iter()
                .find(|n| n.id == id)
                .map(|n| n.position)
        };
        let points: Vec<Vector> = element
            .iter()
            .map(|&n| position(n))
            .collect::<Option<_>>()?;
        let k = points.len() as f64;
        let mut centroid = Vector::zero(points.first()?.dim());
        for x in &points {
            for (c, x) in centroid.components_mut().iter_mut().zip(x.components()) {
                *c += x / k;
            }
        }
        Some(centroid)
    }
}

/// Check host elements as [`ContactAnalysis::host`](crate::contact::iteration::ContactAnalysis::host)
/// will: ids, equations, element shapes.
pub fn check_elements(elements: &HostElements, n_equations: usize) -> Result<()> {
    ElementPatch::new(elements.clone(), n_equations).map(|_| ())
}

/// Host elements ready for stress recovery: a model in a local numbering, the equations of its
/// nodes and the map from host ids.
struct ElementPatch {
    model: Model,
    equations: Vec<[Option<usize>; 2]>,
    local: std::collections::HashMap<usize, usize>,
}

impl ElementPatch {
    fn new(e: HostElements, n_equations: usize) -> Result<Self> {
        let mut local = std::collections::HashMap::new();
        let mut mesh = crate::mesh::Mesh::new();
        let mut equations = Vec::new();
        for node in &e.node_table {
            if local.insert(node.id, mesh.n_nodes()).is_some() {
                return Err(Error::InvalidInput(format!(
                    "element node {} is listed twice",
                    node.id
                )));
            }
            let (&[x, y], &[ex, ey]) = (node.position.components(), node.equations.as_slice())
            else {
                return Err(Error::InvalidInput(format!(
                    "element node {}: host elements are plane elements (2 components and 2 \
                     equations per node), it has {} and {}",
                    node.id,
                    node.position.dim(),
                    node.equations.dim()
                )));
            };
            if let Some(eq) = node.equations.given().find(|&q| q >= n_equations) {
                return Err(Error::InvalidInput(format!(
                    "element node {}: equation {eq} is out of range (n = {n_equations})",
                    node.id
                )));
            }
            mesh.push_node([x, y]);
            equations.push([ex, ey]);
        }
        mesh.element_offsets = e.offsets;
        mesh.element_nodes = e
            .nodes
            .iter()
            .map(|id| {
                local.get(id).copied().ok_or_else(|| {
                    Error::InvalidInput(format!("element node {id} is not in the node table"))
                })
            })
            .collect::<Result<_>>()?;
        mesh.element_material = e.element_material;
        let model = Model::new(mesh, e.materials, e.formulation);
        model.validate()?;
        Ok(ElementPatch {
            model,
            equations,
            local,
        })
    }
}

/// A host's system as the bodies of a contact analysis, after setup: nodes renumbered `0..m`
/// (local ids) in `nodes` order.
pub struct HostBodies {
    equations: usize,
    /// The nodes' number of components (all alike).
    dim: usize,
    nodes: Vec<HostNode>,
    /// The nodes' reference positions, flat (`dim` per node).
    positions: Vec<f64>,
    /// Locked so that solves (displacement recovery) can run from `&self` queries, one at a
    /// time: a host's callback is never entered concurrently.
    solver: Mutex<HostSolver>,
    elements: Option<ElementPatch>,
}

enum HostSolver {
    /// hycon's factor of the host's matrix (kept for refactorization); with a reach, factored
    /// in the plain fill-reducing order and `F` built lazily within the reach of the contact
    /// equations, else with the contact equations last.
    Factor {
        factor: Box<SparseCholesky>,
        lower: SparseColMat<usize, f64>,
        reach: Option<Box<Reach>>,
    },
    Callback(Box<dyn HostSolve>),
    /// The host's condensed operator: `F` between the contact equations (in node order), and
    /// for each contact dof the position of its equation among the candidates (the load
    /// image's order).
    Condensed {
        flexibility: Mat<f64>,
        candidate: Vec<Option<usize>>,
        candidates: usize,
    },
}

impl std::fmt::Debug for HostBodies {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "HostBodies({} equations, {} contact nodes)",
            self.equations,
            self.nodes.len()
        )
    }
}

impl HostBodies {
    /// A host's system: checks the nodes (unique ids, finite positions, one equation (or
    /// `None`) per component, all nodes of one dimension, equations in range and used once)
    /// and factors a CSR stiffness: the contact equations last (eager), or, when
    /// `lazy` (faer only), in the plain fill-reducing order with `F` built lazily as for
    /// [`ModelBodies::new`](super::ModelBodies::new) (on up to `threads` threads).
    pub fn new(system: HostSystem, backend: Backend, lazy: bool, threads: usize) -> Result<Self> {
        let HostSystem {
            equations,
            nodes,
            stiffness,
            elements,
            ..
        } = system;
        let elements = elements
            .map(|e| ElementPatch::new(e, equations))
            .transpose()?;
        let dim = check_dimension(&nodes)?;
        let mut seen_ids = std::collections::HashSet::new();
        let mut seen_eqs = std::collections::HashSet::new();
        for node in &nodes {
            if !seen_ids.insert(node.id) {
                return Err(Error::InvalidInput(format!(
                    "contact node {} is listed twice",
                    node.id
                )));
            }
            if !node.position.components().iter().all(|v| v.is_finite()) {
                return Err(Error::InvalidInput(format!(
                    "contact node {}: position {:?} is not finite",
                    node.id,
                    node.position.components()
                )));
            }
            for e in node.equations.given() {
                if e >= equations || !seen_eqs.insert(e) {
                    return Err(Error::InvalidInput(format!(
                        "contact node {}: equation {e} is out of range (n = {equations}) or \
                         used by another contact dof",
                        node.id
                    )));
                }
            }
        }
        let solver = match stiffness {
            HostStiffness::Csr(csr) => {
                if csr.n != equations {
                    return Err(Error::InvalidInput(format!(
                        "the CSR matrix has order {}, the host {equations} equations",
                        csr.n
                    )));
                }
                let lower = csr.lower()?;
                let contact: Vec<usize> = nodes.iter().flat_map(|n| n.equations.given()).collect();
                let lazy = lazy_on(backend, lazy);
                let trailing = if lazy { &[][..] } else { &contact[..] };
                let mut factor = SparseCholesky::analyze(lower.symbolic(), backend, trailing)?;
                factor.factorize(lower.as_ref())?;
                let reach = contact_reach(&factor, lazy, &contact, threads);
                HostSolver::Factor {
                    factor: Box::new(factor),
                    lower,
                    reach,
                }
            }
            HostStiffness::Solver(s) => HostSolver::Callback(s),
            HostStiffness::Condensed(c) => condensed_solver(&c, &nodes, equations)?,
        };
        let positions = nodes
            .iter()
            .flat_map(|n| n.position.components().iter().copied())
            .collect();
        Ok(HostBodies {
            equations,
            dim,
            nodes,
            positions,
            solver: Mutex::new(solver),
            elements,
        })
    }
}

/// The dimension of a host's contact nodes (2 for none): each node's position and equations
/// of one length, and all nodes alike.
///
/// # Errors
/// [`Error::InvalidInput`] naming the first node that differs.
fn check_dimension(nodes: &[HostNode]) -> Result<usize> {
    let Some(first) = nodes.first() else {
        return Ok(2);
    };
    let dim = first.position.dim();
    for node in nodes {
        let (p, e) = (node.position.dim(), node.equations.dim());
        if p != e {
            return Err(Error::InvalidInput(format!(
                "contact node {}: its position has {p} components but {e} equations are given",
                node.id
            )));
        }
        if p != dim {
            return Err(Error::InvalidInput(format!(
                "contact node {} has {p} components, contact node {} {dim}: all contact nodes \
                 of a host have one dimension",
                node.id, first.id
            )));
        }
    }
    Ok(dim)
}

impl Bodies for HostBodies {
    /// The nodes' number of components.
    fn dim(&self) -> usize {
        self.dim
    }

    fn positions(&self) -> &[f64] {
        &self.positions
    }

    /// The position in the node list.
    fn local(&self, id: usize) -> Option<usize> {
        self.nodes.iter().position(|n| n.id == id)
    }

    fn external(&self, local: usize) -> usize {
        self.nodes[local].id
    }

    /// The host's `n`.
    fn field_len(&self) -> usize {
        self.equations
    }

    /// The host's equation (`None`: held fixed at zero by the host).
    fn field_index(&self, d: usize) -> Option<usize> {
        let node = self.nodes.get(d / self.dim)?;
        node.equations.get(d % self.dim)
    }

    fn equation(&self, d: usize) -> Option<usize> {
        self.field_index(d)
    }

    fn stiffness(&mut self) -> Stiffness<'_> {
        match unlocked(&mut self.solver) {
            HostSolver::Factor { factor, reach, .. } => Stiffness::Factor {
                cholesky: factor.as_mut(),
                reach: reach.as_deref(),
            },
            HostSolver::Callback(s) => Stiffness::Callback {
                solver: s.as_mut(),
                equations: self.equations,
            },
            HostSolver::Condensed { flexibility, .. } => Stiffness::Condensed(flexibility),
        }
    }

    /// Through the solve callback, or from a factor in the plain fill-reducing order.
    fn lazy_flexibility(&self) -> bool {
        match &*lock(&self.solver) {
            HostSolver::Factor { reach, .. } => reach.is_some(),
            HostSolver::Callback(_) => true,
            HostSolver::Condensed { .. } => false,
        }
    }

    /// hycon's factorizations of the CSR matrix (0 for a host that solves itself).
    fn factorizations(&self) -> usize {
        match &*lock(&self.solver) {
            HostSolver::Factor { factor, .. } => factor.factorizations(),
            HostSolver::Callback(_) | HostSolver::Condensed { .. } => 0,
        }
    }

    /// A CSR matrix is factored again; a host's own solver keeps its factor.
    fn refactorize(&mut self) -> Result<()> {
        match unlocked(&mut self.solver) {
            HostSolver::Factor { factor, lower, .. } => factor.factorize(lower.as_ref()),
            HostSolver::Callback(_) | HostSolver::Condensed { .. } => Ok(()),
        }
    }

    /// `f` of `n` entries and no prescribed values.
    fn solve(&self, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        let n = self.equations;
        if f.len() != n || !qp.is_empty() {
            return Err(Error::InvalidInput(format!(
                "a host system takes a right-hand side of {n} entries and no prescribed values, \
                 got {} and {}",
                f.len(),
                qp.len()
            )));
        }
        let mut x = vec![0.0; n];
        match &mut *lock(&self.solver) {
            HostSolver::Factor { factor, .. } => {
                let mut rhs = Mat::from_fn(n, 1, |i, _| f[i]);
                factor.solve_in_place(rhs.as_mut())?;
                for (i, v) in x.iter_mut().enumerate() {
                    *v = rhs[(i, 0)];
                }
            }
            HostSolver::Callback(s) => checked_solve(s.as_mut(), 1, f, &mut x)?,
            HostSolver::Condensed { .. } => return Err(no_solver()),
        }
        Ok(x)
    }

    /// An error saying how the host recovers its displacement when it handed over its
    /// condensed operator.
    fn check_solver(&self) -> Result<()> {
        match &*lock(&self.solver) {
            HostSolver::Condensed { .. } => Err(no_solver()),
            _ => Ok(()),
        }
    }

    /// None: the host's right-hand side holds their effect.
    fn prescribed_len(&self) -> usize {
        0
    }

    fn load_key(&self, f: &[f64], _qp: &[f64]) -> Vec<f64> {
        f.to_vec()
    }

    /// The number of candidates (the load image's) for a host that handed over its condensed
    /// operator, else `n`.
    fn load_len(&self) -> usize {
        match &*lock(&self.solver) {
            HostSolver::Condensed { candidates, .. } => *candidates,
            _ => self.equations,
        }
    }

    fn condensed_image(&self, image: &[f64], dofs: &[usize]) -> Option<Vec<f64>> {
        match &*lock(&self.solver) {
            HostSolver::Condensed { candidate, .. } => Some(
                dofs.iter()
                    .map(|&d| candidate[d].map_or(0.0, |i| image[i]))
                    .collect(),
            ),
            _ => None,
        }
    }

    fn has_elements(&self) -> bool {
        self.elements.is_some()
    }

    /// The elements the host handed over, if it did.
    fn elements(&self, field: &[f64]) -> Option<ElementView<'_>> {
        let patch = self.elements.as_ref()?;
        let q = patch
            .equations
            .iter()
            .flat_map(|eq| eq.map(|e| e.map_or(0.0, |i| field[i])))
            .collect();
        let map = move |n: usize| {
            let id = self.nodes.get(n)?.id;
            patch.local.get(&id).copied()
        };
        Some((&patch.model, q, Box::new(map)))
    }
}

/// `F V` through a host's solve callback for the columns `V` given sparse over positions in
/// the contact dofs (`rows`: the host equation of each, `None` at a fixed dof): one right-hand
/// side per column, solved in batches of at most `CALLBACK_BATCH` columns and about 32 MB.
/// Rows at fixed dofs are zero, and fixed dofs of `v` are ignored.
pub(super) fn callback_times(
    solver: &mut dyn HostSolve,
    n: usize,
    rows: &[Option<usize>],
    vectors: &[Vec<(usize, f64)>],
) -> Result<DMatrix<f64>> {
    let mut out = DMatrix::zeros(rows.len(), vectors.len());
    let batch = CALLBACK_BATCH.min((4 << 20) / n.max(1)).max(1);
    // the right-hand sides and solutions, column-major, reused over the batches: only the
    // entries a batch set are zeroed again (a full-length copy per batch cost more than the
    // contact iteration itself at 76k equations)
    let (mut b, mut x) = (vec![0.0; n * batch], vec![0.0; n * batch]);
    for start in (0..vectors.len()).step_by(batch) {
        let cols = batch.min(vectors.len() - start);
        let set = |c: usize, add: &mut dyn FnMut(usize, f64)| {
            for &(j, w) in &vectors[start + c] {
                if let Some(e) = rows[j] {
                    add(e, w);
                }
            }
        };
        for c in 0..cols {
            set(c, &mut |r, w| b[c * n + r] += w);
        }
        checked_solve(solver, cols, &b[..n * cols], &mut x[..n * cols])?;
        for c in 0..cols {
            set(c, &mut |r, _| b[c * n + r] = 0.0);
            for (i, e) in rows.iter().enumerate() {
                if let Some(e) = e {
                    out[(i, start + c)] = x[c * n + *e];
                }
            }
        }
    }
    Ok(out)
}

/// The iteration's view of a host's condensed operator `c` (checked here) for its contact
/// `nodes`: `F` between their equations, in node order, and where each contact dof's equation
/// sits among the candidates.
fn condensed_solver(c: &Condensed, nodes: &[HostNode], n_equations: usize) -> Result<HostSolver> {
    c.check(n_equations)?;
    let contact: Vec<(usize, usize)> = nodes
        .iter()
        .flat_map(|n| n.equations.given().map(move |e| (n.id, e)))
        .collect();
    let flexibility = c.flexibility(&contact)?;
    let mut position = vec![None; n_equations];
    for (i, &e) in c.equations.iter().enumerate() {
        position[e] = Some(i);
    }
    let candidate = nodes
        .iter()
        .flat_map(|n| {
            n.equations
                .as_slice()
                .iter()
                .map(|e| e.and_then(|e| position[e]))
        })
        .collect();
    Ok(HostSolver::Condensed {
        flexibility,
        candidate,
        candidates: c.equations.len(),
    })
}

/// What a solve with the bodies of a condensed host gives: hycon holds no solver of theirs.
fn no_solver() -> Error {
    Error::InvalidInput(
        "the host handed over its condensed operator, so hycon has no solver of its K: the host \
         recovers the displacement itself, K u = load + contact forces"
            .into(),
    )
}

/// A host solve with its output checked for finiteness.
fn checked_solve(s: &mut dyn HostSolve, nrhs: usize, rhs: &[f64], x: &mut [f64]) -> Result<()> {
    s.solve(nrhs, rhs, x)?;
    match x.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Error::Callback(format!(
            "the solve callback returned a non-finite value at entry {i} of {nrhs} right-hand \
             side(s)"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::bodies::Bodies;

    /// A host of `n` equations, tridiagonal `K` (4 on the diagonal, -1 beside it: SPD by
    /// diagonal dominance), as a lower-triangle CSR.
    fn tridiagonal(n: usize) -> Csr {
        let (mut row_ptr, mut columns, mut values) = (vec![0], Vec::new(), Vec::new());
        for i in 0..n {
            if i > 0 {
                columns.push(i - 1);
                values.push(-1.0);
            }
            columns.push(i);
            values.push(4.0);
            row_ptr.push(columns.len());
        }
        Csr {
            n,
            row_ptr,
            columns,
            values,
            triangle: Triangle::Lower,
        }
    }

    /// Two 3D contact nodes, ids 10 and 11, their equations interleaved with an interior one
    /// (3) and one component of node 11 held fixed.
    fn solid_nodes() -> Vec<HostNode> {
        vec![
            HostNode {
                id: 10,
                position: Vector::solid(0.0, 0.0, 0.0),
                equations: [Some(0), Some(2), Some(4)].into(),
            },
            HostNode {
                id: 11,
                position: Vector::solid(1.0, 0.0, 0.5),
                equations: [Some(1), None, Some(5)].into(),
            },
        ]
    }

    fn system(nodes: Vec<HostNode>) -> HostSystem {
        HostSystem {
            equations: 6,
            nodes,
            stiffness: HostStiffness::Csr(tridiagonal(6)),
            elements: None,
            a_inside: Vec::new(),
            sections: Vec::new(),
        }
    }

    /// With 3 equations per node, `dim` is 3 and `F` between the contact dofs (`3 node +
    /// component`) is `K^-1` between their equations, zero at the fixed one; eager (the
    /// factor's trailing block) and lazy (unit solves) alike.
    #[test]
    fn solid_host_flexibility_is_the_inverse() {
        let inverse = nalgebra::DMatrix::from_fn(6, 6, |i, j| match i.abs_diff(j) {
            0 => 4.0,
            1 => -1.0,
            _ => 0.0,
        })
        .try_inverse()
        .unwrap();
        let equation = [Some(0), Some(2), Some(4), Some(1), None, Some(5)];
        let dofs: Vec<usize> = (0..6).collect();
        for lazy in [false, true] {
            let mut bodies =
                HostBodies::new(system(solid_nodes()), Backend::Faer, lazy, 1).unwrap();
            assert_eq!(bodies.dim(), 3);
            assert_eq!(bodies.positions(), &[0.0, 0.0, 0.0, 1.0, 0.0, 0.5]);
            assert_eq!((bodies.equation(4), bodies.equation(5)), (None, Some(5)));
            let flexibility = bodies.flexibility(&dofs).unwrap();
            let largest = inverse.amax();
            for (i, j) in dofs.iter().flat_map(|&i| dofs.iter().map(move |&j| (i, j))) {
                let expected = match (equation[i], equation[j]) {
                    (Some(a), Some(b)) => inverse[(a, b)],
                    _ => 0.0,
                };
                let error = (flexibility[(i, j)] - expected).abs();
                assert!(
                    error <= 1e-12 * largest,
                    "lazy {lazy}: F[{i}][{j}] = {} against {expected}",
                    flexibility[(i, j)]
                );
            }
        }
    }

    /// A host's nodes are of one dimension, each with one equation per component: a plane
    /// node among solid ones, or a position and equations of different lengths, is named.
    #[test]
    fn mixed_dimensions_are_named() {
        let message = |nodes| {
            HostBodies::new(system(nodes), Backend::Faer, false, 1)
                .unwrap_err()
                .to_string()
        };
        let mut mixed = solid_nodes();
        mixed[1].position = Vector::plane(1.0, 0.0);
        mixed[1].equations = [Some(1), Some(5)].into();
        let e = message(mixed);
        assert!(e.contains("contact node 11 has 2 components"), "{e}");
        let mut unequal = solid_nodes();
        unequal[0].equations = [Some(0), Some(2)].into();
        let e = message(unequal);
        assert!(
            e.contains("contact node 10: its position has 3 components but 2 equations"),
            "{e}"
        );
    }

    /// Host elements are plane elements, and a host's contact analysis is plane or
    /// axisymmetric: a 3D element node, or 3D contact nodes, are refused by name.
    #[test]
    fn plane_only_beyond_the_bodies() {
        use crate::contact::handover::Section;
        use crate::contact::iteration::{ContactAnalysis, ContactOptions, ContactPair};
        use crate::material::Analysis;
        let mut elements = HostElements {
            formulation: Formulation::Hybrid,
            materials: vec![Material::new(1.0, 0.3, 1.0, Analysis::PlaneStrain).unwrap()],
            element_material: vec![0],
            offsets: vec![0, 4],
            nodes: vec![0, 1, 2, 3],
            node_table: [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
                .iter()
                .enumerate()
                .map(|(id, &p)| HostNode {
                    id,
                    position: p.into(),
                    equations: [None, None].into(),
                })
                .collect(),
        };
        check_elements(&elements, 6).unwrap();
        elements.node_table[2].position = Vector::solid(1.0, 1.0, 0.0);
        let e = check_elements(&elements, 6).unwrap_err().to_string();
        assert!(
            e.contains("element node 2: host elements are plane elements"),
            "{e}"
        );

        let mut nodes = solid_nodes();
        for (id, x) in [(12, 1.0), (13, 0.0)] {
            nodes.push(HostNode {
                id,
                position: Vector::solid(x, 0.0, -0.1),
                equations: [None, None, None].into(),
            });
        }
        let mut host = system(nodes);
        host.sections = vec![Section::new(Analysis::PlaneStrain, 1.0).unwrap()];
        let pair = ContactPair {
            a: vec![10, 11],
            b: vec![12, 13],
            friction: 0.0,
        };
        let e = ContactAnalysis::host(host, vec![pair], ContactOptions::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("2 components per contact node"), "{e}");
    }
}
