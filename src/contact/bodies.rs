//! The elastic bodies as the contact iteration sees them: the reference positions of the
//! contact nodes, where their dofs sit in the linear system, and solves with the stiffness.
//!
//! Two sources:
//! * [`Bodies::model`]: hycon's own [`Model`], assembled and factored by hycon;
//! * [`Bodies::host`]: a host FE code's system ([`HostSystem`]): its contact nodes (positions
//!   and equation numbers in its numbering) and either its stiffness in CSR, factored here, a
//!   solve callback ([`HostSolve`]) so that the host factors `K` with its own solver, or the
//!   condensed operator of its contact candidates ([`Condensed`]), computed by its own solver
//!   in one factorization: the iteration then runs on it alone, and the host recovers its
//!   displacements from the contact forces.
//!
//! Either way the iteration needs three things, all linear in the loads:
//! * the contact-boundary flexibility `F = E^T K^-1 E` (`E` picks the contact dofs),
//! * `u0 = K^-1 f` for a load `f`, read at the contact dofs,
//! * the whole field `K^-1 (f + f_c)` with the converged contact forces `f_c`, on request.
//!
//! Vectors of loads and displacements live in the *field* space: all `2 n_nodes` dofs of a
//! model (`f` external forces, `qp` prescribed values), or the host's `n` equations (`f` its
//! right-hand side, which already holds the effect of its prescribed displacements; no `qp`).

use crate::element::Formulation;
use crate::error::{Error, Result};
use crate::material::Material;
use crate::model::{LinearSystem, Model};
use crate::solver::{Backend, Reach, SparseCholesky};
use faer::Mat;
use faer::sparse::{SparseColMat, Triplet};
use nalgebra::DMatrix;
use std::sync::{Mutex, MutexGuard, PoisonError};

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
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HostNode {
    /// Node id in the host's numbering (as used in the contact pairs).
    pub id: usize,
    /// Reference position.
    pub position: [f64; 2],
    /// Host equations of `u_x`, `u_y`.
    pub equations: [Option<usize>; 2],
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
    /// polyline (see [`check_a_inside`](crate::contact::iteration::check_a_inside)).
    pub a_inside: Vec<Option<[f64; 2]>>,
    /// The section of each contact pair's A side, in the order of the pairs: its analysis kind
    /// (all pairs of one kind) and thickness. The contact integrals are weighted by its
    /// measure (the thickness in plane analysis, `2 pi r` in axisymmetry), so that the
    /// tractions are pressures and the contact forces are in the units of the host's stiffness
    /// (per thickness, or over the full circle); the [`elements`](Self::elements) along A are
    /// of their pair's section (checked, see [`handover`](crate::contact::handover)).
    pub sections: Vec<crate::contact::handover::Section>,
}

/// Elements of a host along its A polylines (those owning the A segments), with hycon's element
/// formulations, so that hycon can recover the tractions from the element stresses (the
/// paper's way (a)) from the host's displacements.
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
    pub fn centroid_beside(&self, ids: &[usize]) -> Option<[f64; 2]> {
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
        let points: Vec<[f64; 2]> = element
            .iter()
            .map(|&n| position(n))
            .collect::<Option<_>>()?;
        let k = points.len() as f64;
        Some(
            points
                .iter()
                .fold([0.0, 0.0], |c, x| [c[0] + x[0] / k, c[1] + x[1] / k]),
        )
    }
}

/// Check host elements as [`ContactAnalysis::host`](super::iteration::ContactAnalysis::host)
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
            if let Some(eq) = node.equations.iter().flatten().find(|&&q| q >= n_equations) {
                return Err(Error::InvalidInput(format!(
                    "element node {}: equation {eq} is out of range (n = {n_equations})",
                    node.id
                )));
            }
            mesh.push_node(node.position);
            equations.push(node.equations);
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

/// The host's system after setup: nodes renumbered `0..m` (local ids) in `nodes` order.
struct Host {
    equations: usize,
    nodes: Vec<HostNode>,
    positions: Vec<[f64; 2]>,
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

/// The bodies of a contact analysis (see the [module docs](self)).
pub struct Bodies(Kind);

/// The images `W V = L^-1 P E V` of a batch of vectors in the factor's space, dense over the
/// rows of their elimination-tree reach ([`Bodies::images`]).
#[derive(Debug, Clone)]
pub struct Images {
    /// The factor column of each row, ascending.
    pub columns: Vec<usize>,
    /// One column per vector.
    pub values: Mat<f64>,
}

enum Kind {
    /// hycon's own model and `K_ff`: factored with the contact dofs last, or (with a reach)
    /// in the plain fill-reducing order, `F` then built lazily within the reach of the contact
    /// dofs.
    Model {
        model: Box<Model>,
        /// Locked so that solves can run from `&self` queries, one at a time.
        system: Mutex<Box<LinearSystem>>,
        reach: Option<Box<Reach>>,
    },
    /// A host's system.
    Host(Box<Host>),
}

impl std::fmt::Debug for Bodies {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.0 {
            Kind::Model { system, .. } => write!(f, "Bodies::Model({:?})", lock(system)),
            Kind::Host(h) => write!(
                f,
                "Bodies::Host({} equations, {} contact nodes)",
                h.equations,
                h.nodes.len()
            ),
        }
    }
}

/// Lock a solver for one solve. A panic inside an earlier solve (caught at the C boundary)
/// leaves the factor as it was (solves only use scratch space), so a poisoned lock is taken.
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The solver of a `&mut self` method: no lock needed.
fn unlocked<T>(m: &mut Mutex<T>) -> &mut T {
    m.get_mut().unwrap_or_else(PoisonError::into_inner)
}

/// Batch size of flexibility solves through a host callback: at most this many columns, and
/// at most about 32 MB of right-hand sides per call.
const CALLBACK_BATCH: usize = 64;

impl Bodies {
    /// hycon's model with the contact dofs `contact` (global dofs). Eager
    /// (`lazy == false`): factored with them eliminated last, so that all of `F` is read off
    /// the factor's trailing block. Lazy (faer only): factored in the plain fill-reducing
    /// order, as a linear solve would be, and the columns of `F` computed when asked for
    /// ([`flexibility_times`](Self::flexibility_times)) by substitutions within the reach of
    /// the contact dofs in the elimination tree, on up to `threads` threads
    /// ([`Reach::with_threads`]).
    pub fn model(
        model: Model,
        contact: &[usize],
        backend: Backend,
        lazy: bool,
        threads: usize,
    ) -> Result<Self> {
        let lazy = lazy && backend == Backend::Faer;
        let trailing = if lazy { &[][..] } else { contact };
        let mut system = LinearSystem::with_trailing_on(&model, trailing, backend)?;
        let reach = if lazy {
            let eqs: Vec<usize> = contact
                .iter()
                .filter_map(|&d| system.dofs().equation(d))
                .collect();
            system
                .cholesky()
                .reach(&eqs)
                .map(|r| Box::new(r.with_threads(threads)))
        } else {
            None
        };
        Ok(Bodies(Kind::Model {
            model: Box::new(model),
            system: Mutex::new(Box::new(system)),
            reach,
        }))
    }

    /// A host's system: checks the nodes (unique ids, finite positions, equations in range and
    /// used once) and factors a CSR stiffness: the contact equations last (eager), or, when
    /// `lazy` (faer only), in the plain fill-reducing order with `F` built lazily as for
    /// [`model`](Self::model) (on up to `threads` threads).
    pub fn host(system: HostSystem, backend: Backend, lazy: bool, threads: usize) -> Result<Self> {
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
        let mut seen_ids = std::collections::HashSet::new();
        let mut seen_eqs = std::collections::HashSet::new();
        for node in &nodes {
            if !seen_ids.insert(node.id) {
                return Err(Error::InvalidInput(format!(
                    "contact node {} is listed twice",
                    node.id
                )));
            }
            if !node.position.iter().all(|v| v.is_finite()) {
                return Err(Error::InvalidInput(format!(
                    "contact node {}: position {:?} is not finite",
                    node.id, node.position
                )));
            }
            for e in node.equations.iter().flatten() {
                if *e >= equations || !seen_eqs.insert(*e) {
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
                let contact: Vec<usize> = nodes
                    .iter()
                    .flat_map(|n| n.equations.into_iter().flatten())
                    .collect();
                let lazy = lazy && backend == Backend::Faer;
                let trailing = if lazy { &[][..] } else { &contact[..] };
                let mut factor = SparseCholesky::analyze(lower.symbolic(), backend, trailing)?;
                factor.factorize(lower.as_ref())?;
                let reach = if lazy {
                    factor
                        .reach(&contact)
                        .map(|r| Box::new(r.with_threads(threads)))
                } else {
                    None
                };
                HostSolver::Factor {
                    factor: Box::new(factor),
                    lower,
                    reach,
                }
            }
            HostStiffness::Solver(s) => HostSolver::Callback(s),
            HostStiffness::Condensed(c) => condensed_solver(&c, &nodes, equations)?,
        };
        let positions = nodes.iter().map(|n| n.position).collect();
        Ok(Bodies(Kind::Host(Box::new(Host {
            equations,
            nodes,
            positions,
            solver: Mutex::new(solver),
            elements,
        }))))
    }

    /// Translate a node id of the caller's numbering into the iteration's (identity for a
    /// model; the position in the node list for a host).
    pub fn local(&self, id: usize) -> Option<usize> {
        match &self.0 {
            Kind::Model { model, .. } => (id < model.mesh.n_nodes()).then_some(id),
            Kind::Host(h) => h.nodes.iter().position(|n| n.id == id),
        }
    }

    /// The caller's id of a node of the iteration's numbering.
    pub fn external(&self, local: usize) -> usize {
        match &self.0 {
            Kind::Model { .. } => local,
            Kind::Host(h) => h.nodes[local].id,
        }
    }

    /// Reference positions, indexed by the iteration's node ids.
    pub fn positions(&self) -> &[[f64; 2]] {
        match &self.0 {
            Kind::Model { model, .. } => &model.mesh.nodes,
            Kind::Host(h) => &h.positions,
        }
    }

    /// Length of load and displacement vectors (`2 n_nodes` or the host's `n`).
    pub fn field_len(&self) -> usize {
        match &self.0 {
            Kind::Model { model, .. } => 2 * model.mesh.n_nodes(),
            Kind::Host(h) => h.equations,
        }
    }

    /// Where dof `d` (`2 node + direction`, iteration numbering) sits in the field (`None`:
    /// held fixed at zero by a host).
    pub fn field_index(&self, d: usize) -> Option<usize> {
        match &self.0 {
            Kind::Model { .. } => Some(d),
            Kind::Host(h) => h.nodes.get(d / 2).and_then(|n| n.equations[d % 2]),
        }
    }

    /// Whether dof `d` is free (an unknown of `K`).
    pub fn is_free(&self, d: usize) -> bool {
        match &self.0 {
            Kind::Model { system, .. } => lock(system).dofs().equation(d).is_some(),
            Kind::Host(_) => self.field_index(d).is_some(),
        }
    }

    /// The model, if these are hycon's own bodies.
    pub fn as_model(&self) -> Option<&Model> {
        match &self.0 {
            Kind::Model { model, .. } => Some(model),
            Kind::Host(_) => None,
        }
    }

    /// Whether [`elements`](Self::elements) has elements to offer.
    pub fn has_elements(&self) -> bool {
        match &self.0 {
            Kind::Model { .. } => true,
            Kind::Host(h) => h.elements.is_some(),
        }
    }

    /// The elements for stress recovery with the displacement of `field` in their numbering,
    /// and the translation of a node id of the iteration into theirs: hycon's model (identity),
    /// or the elements a host handed over (`None` if it did not).
    #[allow(clippy::type_complexity)]
    pub fn elements(
        &self,
        field: &[f64],
    ) -> Option<(&Model, Vec<f64>, Box<dyn Fn(usize) -> Option<usize> + '_>)> {
        match &self.0 {
            Kind::Model { model, .. } => Some((model, field.to_vec(), Box::new(Some))),
            Kind::Host(h) => {
                let patch = h.elements.as_ref()?;
                let q = patch
                    .equations
                    .iter()
                    .flat_map(|eq| eq.map(|e| e.map_or(0.0, |i| field[i])))
                    .collect();
                let map = move |n: usize| {
                    let id = h.nodes.get(n)?.id;
                    patch.local.get(&id).copied()
                };
                Some((&patch.model, q, Box::new(map)))
            }
        }
    }

    /// `F = E^T K^-1 E` over the dofs `dofs` (iteration numbering, sorted; in the order given
    /// to the factorization as trailing unknowns): read off the factor, or assembled from
    /// batched host solves with unit right-hand sides. Zero rows and columns at fixed dofs.
    pub fn flexibility(&mut self, dofs: &[usize]) -> Result<DMatrix<f64>> {
        if self.lazy_flexibility() {
            let units: Vec<Vec<(usize, f64)>> = (0..dofs.len()).map(|j| vec![(j, 1.0)]).collect();
            return self.flexibility_times(dofs, &units);
        }
        let free: Vec<usize> = (0..dofs.len()).filter(|&i| self.is_free(dofs[i])).collect();
        let condensed = match &mut self.0 {
            Kind::Model { system, .. } => unlocked(system).condensed_flexibility()?,
            Kind::Host(h) => match unlocked(&mut h.solver) {
                HostSolver::Factor { factor, .. } => factor.condensed_inverse()?,
                HostSolver::Callback(s) => {
                    let eqs: Vec<usize> = free
                        .iter()
                        .filter_map(|&i| h.nodes[dofs[i] / 2].equations[dofs[i] % 2])
                        .collect();
                    callback_flexibility(s.as_mut(), h.equations, &eqs)?
                }
                HostSolver::Condensed { flexibility, .. } => flexibility.clone(),
            },
        };
        let mut flex = DMatrix::zeros(dofs.len(), dofs.len());
        for (a, &i) in free.iter().enumerate() {
            for (b, &j) in free.iter().enumerate() {
                flex[(i, j)] = condensed[(a, b)];
            }
        }
        Ok(flex)
    }

    /// Whether `F` is built as the iteration asks for it
    /// ([`flexibility_times`](Self::flexibility_times)): through a host's solve callback, or
    /// from a factor in the plain fill-reducing order. Otherwise the factor gives all of `F`
    /// at once ([`flexibility`](Self::flexibility)).
    pub fn lazy_flexibility(&self) -> bool {
        match &self.0 {
            Kind::Model { reach, .. } => reach.is_some(),
            Kind::Host(h) => match &*lock(&h.solver) {
                HostSolver::Factor { reach, .. } => reach.is_some(),
                HostSolver::Callback(_) => true,
                HostSolver::Condensed { .. } => false,
            },
        }
    }

    /// `F V = E^T K^-1 E V` over the dofs `dofs` (iteration numbering) for the columns `V`
    /// given sparse over positions in `dofs` (`dofs.len() x vectors.len()`): one right-hand
    /// side `E v` per column, solved in batches of `CALLBACK_BATCH`, through the host's
    /// callback (whole solves) or by substitution within the reach of the contact dofs
    /// ([`SparseCholesky::solve_within`]); read from the whole `F` of an eager factor. Rows at
    /// fixed dofs are zero, and fixed dofs of `v` are ignored.
    pub fn flexibility_times(
        &mut self,
        dofs: &[usize],
        vectors: &[Vec<(usize, f64)>],
    ) -> Result<DMatrix<f64>> {
        let mut out = DMatrix::zeros(dofs.len(), vectors.len());
        if !self.lazy_flexibility() {
            let all = self.flexibility(dofs)?;
            for (c, v) in vectors.iter().enumerate() {
                for &(j, w) in v {
                    for i in 0..dofs.len() {
                        out[(i, c)] += w * all[(i, j)];
                    }
                }
            }
            return Ok(out);
        }
        // the equation of each dof and the solver
        let rows: Vec<Option<usize>> = dofs.iter().map(|&d| self.equation(d)).collect();
        let (solver, reach, n): (Solver<'_>, Option<&Reach>, usize) = match &mut self.0 {
            Kind::Model { system, reach, .. } => {
                let system = unlocked(system);
                let n = system.dofs().n_free();
                (Solver::Factor(system.cholesky()), reach.as_deref(), n)
            }
            Kind::Host(h) => match unlocked(&mut h.solver) {
                HostSolver::Factor { factor, reach, .. } => (
                    Solver::Factor(factor.as_mut()),
                    reach.as_deref(),
                    h.equations,
                ),
                HostSolver::Callback(s) => (Solver::Callback(s.as_mut()), None, h.equations),
                HostSolver::Condensed { .. } => unreachable!("a condensed F is not lazy"),
            },
        };
        // the rows of a right-hand side: compact rows of the reach, or the equations
        let row = |e: usize| match reach {
            Some(r) => r.row(e).expect("the contact equations are in their reach"),
            None => e,
        };
        let len = reach.map_or(n, |r| r.len());
        let batch = CALLBACK_BATCH.min((4 << 20) / len.max(1)).max(1);
        let mut solver = solver;
        // a callback's right-hand sides and solutions, column-major, reused over the batches:
        // only the entries a batch set are zeroed again (a full-length copy per batch cost
        // more than the contact iteration itself at 76k equations)
        let (mut b, mut x) = match solver {
            Solver::Callback(_) => (vec![0.0; len * batch], vec![0.0; len * batch]),
            Solver::Factor(_) => (Vec::new(), Vec::new()),
        };
        for start in (0..vectors.len()).step_by(batch) {
            let cols = batch.min(vectors.len() - start);
            let set = |c: usize, add: &mut dyn FnMut(usize, f64)| {
                for &(j, w) in &vectors[start + c] {
                    if let Some(e) = rows[j] {
                        add(row(e), w);
                    }
                }
            };
            match &mut solver {
                Solver::Factor(f) => {
                    let mut rhs = Mat::<f64>::zeros(len, cols);
                    for c in 0..cols {
                        set(c, &mut |r, w| rhs[(r, c)] += w);
                    }
                    match reach {
                        Some(r) => f.solve_within(r, rhs.as_mut())?,
                        None => f.solve_in_place(rhs.as_mut())?,
                    }
                    for c in 0..cols {
                        for (i, e) in rows.iter().enumerate() {
                            if let Some(e) = e {
                                out[(i, start + c)] = rhs[(row(*e), c)];
                            }
                        }
                    }
                }
                Solver::Callback(s) => {
                    for c in 0..cols {
                        set(c, &mut |r, w| b[c * len + r] += w);
                    }
                    checked_solve(&mut **s, cols, &b[..len * cols], &mut x[..len * cols])?;
                    for c in 0..cols {
                        set(c, &mut |r, _| b[c * len + r] = 0.0);
                        for (i, e) in rows.iter().enumerate() {
                            if let Some(e) = e {
                                out[(i, start + c)] = x[c * len + row(*e)];
                            }
                        }
                    }
                }
            }
        }
        Ok(out)
    }

    /// The lazy faer factor and the contact dofs' reach, when the bodies have them (hycon's
    /// model or a host's CSR matrix, lazy, faer backend).
    fn lazy_factor(&mut self) -> Option<(&SparseCholesky, &Reach)> {
        match &mut self.0 {
            Kind::Model {
                system,
                reach: Some(reach),
                ..
            } => Some((unlocked(system).cholesky(), reach)),
            Kind::Host(h) => match unlocked(&mut h.solver) {
                HostSolver::Factor {
                    factor,
                    reach: Some(reach),
                    ..
                } => Some((factor, reach)),
                _ => None,
            },
            _ => None,
        }
    }

    /// Whether [`images`](Self::images) gives images (the bodies have a lazy faer factor).
    pub fn has_images(&mut self) -> bool {
        self.lazy_factor().is_some()
    }

    /// The images `W V = L^-1 P E V` in the factor's space of the columns `V` of each batch
    /// (sparse over positions in `dofs`, as for
    /// [`flexibility_times`](Self::flexibility_times)): per batch one forward substitution
    /// within its columns' own elimination-tree reach, so that `V^T F V = (W V)^T (W V)`
    /// (`F = E^T K^-1 E`, `K = P^T L L^T P`). The batches are shared among the threads of the
    /// contact dofs' reach ([`Reach::with_threads`]), each substituted whole by one thread:
    /// the images do not depend on the number of threads. `None` when the bodies have no lazy
    /// faer factor (a host's callback, CHOLMOD, or an eager factor).
    pub fn images(
        &mut self,
        dofs: &[usize],
        batches: &[Vec<Vec<(usize, f64)>>],
    ) -> Result<Option<Vec<Images>>> {
        let rows: Vec<Option<usize>> = dofs.iter().map(|&d| self.equation(d)).collect();
        let Some((factor, reach)) = self.lazy_factor() else {
            return Ok(None);
        };
        let rows = &rows;
        let one = move |vectors: &Vec<Vec<(usize, f64)>>| images_of(factor, rows, vectors);
        let threads = reach.threads().min(batches.len());
        if threads <= 1 {
            return batches.iter().map(one).collect::<Result<_>>().map(Some);
        }
        // each thread takes a run of consecutive batches
        let run = batches.len().div_ceil(threads);
        let images: Vec<Vec<Result<Images>>> = std::thread::scope(|scope| {
            let handles: Vec<_> = batches
                .chunks(run)
                .map(|run| scope.spawn(move || run.iter().map(one).collect::<Vec<_>>()))
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
                .collect()
        });
        images
            .into_iter()
            .flatten()
            .collect::<Result<_>>()
            .map(Some)
    }

    /// `E^T K^-1 E sum_i V_i c_i` at the dofs `dofs`, from the images `W V_i` of
    /// [`images`](Self::images) and their coefficients `c_i`: the images combined,
    /// `z = sum_i (W V_i) c_i`, and one backward substitution `P^T L^-T z` over the contact
    /// dofs' reach. Zero at fixed dofs.
    pub fn back_substitute(
        &mut self,
        dofs: &[usize],
        parts: &[(&Images, &[f64])],
    ) -> Result<Vec<f64>> {
        let rows: Vec<Option<usize>> = dofs.iter().map(|&d| self.equation(d)).collect();
        let (factor, reach) = self
            .lazy_factor()
            .ok_or_else(|| Error::Solver("images need a lazy faer factor".into()))?;
        let mut z = Mat::<f64>::zeros(reach.len(), 1);
        for &(images, coefficients) in parts {
            let c = Mat::<f64>::from_fn(coefficients.len(), 1, |i, _| coefficients[i]);
            let combined = &images.values * c;
            for (r, &column) in images.columns.iter().enumerate() {
                let row = reach
                    .row_of_column(column)
                    .expect("the contact dofs' reach holds every image");
                z[(row, 0)] += combined[(r, 0)];
            }
        }
        factor.backward_within(reach, z.as_mut())?;
        Ok(rows
            .iter()
            .map(|e| e.map_or(0.0, |e| z[(reach.row(e).expect("a contact dof"), 0)]))
            .collect())
    }

    /// The equation of dof `d` (iteration numbering) in `K`: a model's free-dof numbering or
    /// the host's equation; `None` at a fixed dof.
    fn equation(&self, d: usize) -> Option<usize> {
        match &self.0 {
            Kind::Model { system, .. } => lock(system).dofs().equation(d),
            Kind::Host(h) => h.nodes.get(d / 2).and_then(|n| n.equations[d % 2]),
        }
    }

    /// The displacement field for loads `f` (and, for a model, prescribed values `qp`, read at
    /// the prescribed dofs): one solve.
    /// Solves are serialized by a lock, so this takes `&self`.
    pub fn solve(&self, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        let n = self.field_len();
        match &self.0 {
            Kind::Model { model, system, .. } => Ok(lock(system).solve_for(model, f, qp)?.q),
            Kind::Host(h) => {
                if f.len() != n || !qp.is_empty() {
                    return Err(Error::InvalidInput(format!(
                        "a host system takes a right-hand side of {n} entries and no \
                         prescribed values, got {} and {}",
                        f.len(),
                        qp.len()
                    )));
                }
                let mut x = vec![0.0; n];
                match &mut *lock(&h.solver) {
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
        }
    }

    /// Whether hycon can solve with `K` ([`solve`](Self::solve)): an error saying how the
    /// host recovers its displacement when it handed over its condensed operator instead.
    pub fn check_solver(&self) -> Result<()> {
        match &self.0 {
            Kind::Host(h) if matches!(&*lock(&h.solver), HostSolver::Condensed { .. }) => {
                Err(no_solver())
            }
            _ => Ok(()),
        }
    }

    /// The load as the reuse of load solves compares it: `f`, followed for a model by `qp` at
    /// the prescribed dofs (zero elsewhere).
    pub fn load_key(&self, f: &[f64], qp: &[f64]) -> Vec<f64> {
        match &self.0 {
            Kind::Model { system, .. } => {
                let system = lock(system);
                let dofs = system.dofs();
                f.iter()
                    .copied()
                    .chain(
                        qp.iter().enumerate().map(
                            |(d, &v)| {
                                if dofs.equation(d).is_some() { 0.0 } else { v }
                            },
                        ),
                    )
                    .collect()
            }
            Kind::Host(_) => f.to_vec(),
        }
    }

    /// The length of an increment's load: the field's, or for a host that handed over its
    /// condensed operator the number of its candidates (the load image's).
    pub fn load_len(&self) -> usize {
        match &self.0 {
            Kind::Host(h) => match &*lock(&h.solver) {
                HostSolver::Condensed { candidates, .. } => *candidates,
                _ => h.equations,
            },
            Kind::Model { .. } => self.field_len(),
        }
    }

    /// For a host that handed over its condensed operator, `u0 = K^-1 f` at the dofs `dofs`
    /// (iteration numbering) read off the load image `image` (`u0` over the candidates, the
    /// host's own solve; zero at fixed dofs); `None` for bodies that solve themselves.
    pub fn condensed_image(&self, image: &[f64], dofs: &[usize]) -> Option<Vec<f64>> {
        let Kind::Host(h) = &self.0 else {
            return None;
        };
        match &*lock(&h.solver) {
            HostSolver::Condensed { candidate, .. } => Some(
                dofs.iter()
                    .map(|&d| candidate[d].map_or(0.0, |i| image[i]))
                    .collect(),
            ),
            _ => None,
        }
    }

    /// Numeric factorizations of `K` done by hycon (0 for a host that solves itself).
    pub fn factorizations(&self) -> usize {
        match &self.0 {
            Kind::Model { system, .. } => lock(system).cholesky().factorizations(),
            Kind::Host(h) => match &*lock(&h.solver) {
                HostSolver::Factor { factor, .. } => factor.factorizations(),
                HostSolver::Callback(_) | HostSolver::Condensed { .. } => 0,
            },
        }
    }

    /// Factor `K` again (assembling it again for a model); a host's own solver keeps its
    /// factor. Only the benchmark's refactor-every-iteration variant does this.
    pub fn refactorize(&mut self) -> Result<()> {
        match &mut self.0 {
            Kind::Model { model, system, .. } => unlocked(system).refactorize(model),
            Kind::Host(h) => match unlocked(&mut h.solver) {
                HostSolver::Factor { factor, lower, .. } => factor.factorize(lower.as_ref()),
                HostSolver::Callback(_) | HostSolver::Condensed { .. } => Ok(()),
            },
        }
    }

    /// Seconds spent on `[assembly, analysis + factorization]` when the bodies were set up.
    pub fn setup_seconds(&self) -> [f64; 2] {
        match &self.0 {
            Kind::Model { system, .. } => lock(system).setup_seconds(),
            Kind::Host(_) => [0.0; 2],
        }
    }
}

/// The iteration's view of a host's condensed operator `c` (checked here) for its contact
/// `nodes`: `F` between their equations, in node order, and where each contact dof's equation
/// sits among the candidates.
fn condensed_solver(c: &Condensed, nodes: &[HostNode], n_equations: usize) -> Result<HostSolver> {
    c.check(n_equations)?;
    let contact: Vec<(usize, usize)> = nodes
        .iter()
        .flat_map(|n| n.equations.into_iter().flatten().map(move |e| (n.id, e)))
        .collect();
    let flexibility = c.flexibility(&contact)?;
    let mut position = vec![None; n_equations];
    for (i, &e) in c.equations.iter().enumerate() {
        position[e] = Some(i);
    }
    let candidate = nodes
        .iter()
        .flat_map(|n| n.equations.map(|e| e.and_then(|e| position[e])))
        .collect();
    Ok(HostSolver::Condensed {
        flexibility,
        candidate,
        candidates: c.equations.len(),
    })
}

/// Who solves with `K` for [`Bodies::flexibility_times`].
enum Solver<'a> {
    Factor(&'a mut SparseCholesky),
    Callback(&'a mut dyn HostSolve),
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

/// `(K^-1)` between the equations `eqs`, from host solves with unit right-hand sides, in
/// batches (each call gets at most `CALLBACK_BATCH` columns and about 32 MB).
fn callback_flexibility(s: &mut dyn HostSolve, n: usize, eqs: &[usize]) -> Result<Mat<f64>> {
    let m = eqs.len();
    let batch = CALLBACK_BATCH.min((4 << 20) / n.max(1)).max(1);
    let mut out = Mat::zeros(m, m);
    let mut rhs = vec![0.0; n * batch];
    let mut x = vec![0.0; n * batch];
    for start in (0..m).step_by(batch) {
        let cols = batch.min(m - start);
        rhs.iter_mut().for_each(|v| *v = 0.0);
        for c in 0..cols {
            rhs[c * n + eqs[start + c]] = 1.0;
        }
        checked_solve(s, cols, &rhs[..n * cols], &mut x[..n * cols])?;
        for c in 0..cols {
            for (a, &e) in eqs.iter().enumerate() {
                out[(a, start + c)] = x[c * n + e];
            }
        }
    }
    // K^-1 is symmetric; average out the host solver's round-off
    for a in 0..m {
        for b in 0..a {
            let v = 0.5 * (out[(a, b)] + out[(b, a)]);
            out[(a, b)] = v;
            out[(b, a)] = v;
        }
    }
    Ok(out)
}

/// The images `W V = L^-1 P E V` of one batch of vectors `V` (sparse over the positions of
/// `rows`, the equation of each position): one forward substitution within their reach.
fn images_of(
    factor: &SparseCholesky,
    rows: &[Option<usize>],
    vectors: &[Vec<(usize, f64)>],
) -> Result<Images> {
    let equations: Vec<usize> = vectors
        .iter()
        .flatten()
        .filter_map(|&(j, _)| rows[j])
        .collect();
    let reach = factor
        .reach(&equations)
        .ok_or_else(|| Error::Solver("a lazy factor has a reach".into()))?;
    let mut values = Mat::<f64>::zeros(reach.len(), vectors.len());
    for (c, v) in vectors.iter().enumerate() {
        for &(j, w) in v {
            if let Some(r) = rows[j].and_then(|e| reach.row(e)) {
                values[(r, c)] += w;
            }
        }
    }
    factor.forward_within(&reach, values.as_mut())?;
    Ok(Images {
        columns: reach.columns(),
        values,
    })
}
