//! Dof numbering, sparse assembly of the global stiffness and its factored free-free block,
//! for plane (2 dofs per node) and solid (3 per node) models alike.
//!
//! Node `i` carries the global dofs `p i + dir` (`p` dofs per node: `2 i` (x) and `2 i + 1`
//! (y) in the plane). Prescribed dofs are eliminated: [`DofMap`] numbers the free dofs
//! `0..n_free` in node order. [`SparsePattern`] is the lower-triangle compressed-column pattern
//! of `K_ff` (free-free block), built once from the mesh connectivity; [`SparsePattern::add`]
//! sums element matrices into its values, so the pattern and the symbolic factorization built
//! on it are reused whenever values change. [`FactoredSystem`] holds the three with the sparse
//! Cholesky factor: one factorization for any number of load cases, and the flexibility of
//! trailing unknowns read off the factor. The loops over the elements (assembly, element
//! forces) are in [`elements`], generic over the element kind.

pub mod elements;

use crate::element::{ElementMatrix, Formulation, MAX_NODES};
use crate::error::{Error, Result};
use crate::material::Material;
use crate::mesh::Mesh;
use crate::model::PlaneElements;
use crate::solver::{Backend, OrderingRule, SparseCholesky};
use elements::ElementSet;
use faer::Mat;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};

/// Marker for a prescribed (eliminated) dof.
const PRESCRIBED: usize = usize::MAX;

/// Global dof index of node `node` in direction `dir` (0 = x, 1 = y) of a plane model.
pub fn dof(node: usize, dir: usize) -> usize {
    2 * node + dir
}

/// Free-dof numbering for `per_node` dofs per node (2 plane, 3 solid): global dof
/// `per_node node + dir`; `equation(d)` is its free index, or `None` when prescribed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DofMap {
    per_node: usize,
    equation: Vec<usize>,
    n_free: usize,
}

impl DofMap {
    /// Number the dofs of `n_nodes` nodes with `per_node` dofs each, leaving out the global
    /// dofs in `prescribed`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a prescribed dof out of range.
    pub fn new(
        n_nodes: usize,
        per_node: usize,
        prescribed: impl IntoIterator<Item = usize>,
    ) -> Result<Self> {
        let mut equation = vec![0; per_node * n_nodes];
        for d in prescribed {
            let len = equation.len();
            *equation.get_mut(d).ok_or_else(|| {
                Error::InvalidInput(format!("prescribed dof {d} out of range ({len} dofs)"))
            })? = PRESCRIBED;
        }
        let mut n_free = 0;
        for e in equation.iter_mut().filter(|e| **e != PRESCRIBED) {
            *e = n_free;
            n_free += 1;
        }
        Ok(DofMap {
            per_node,
            equation,
            n_free,
        })
    }

    /// Dofs per node.
    pub fn per_node(&self) -> usize {
        self.per_node
    }

    /// Global dof of `node` in direction `dir`.
    #[inline]
    pub fn dof(&self, node: usize, dir: usize) -> usize {
        self.per_node * node + dir
    }

    /// Free index of global dof `d`, `None` if it is prescribed.
    #[inline]
    pub fn equation(&self, d: usize) -> Option<usize> {
        let e = self.equation[d];
        (e != PRESCRIBED).then_some(e)
    }

    /// Number of free dofs.
    pub fn n_free(&self) -> usize {
        self.n_free
    }

    /// Total number of dofs (free and prescribed).
    pub fn n_dofs(&self) -> usize {
        self.equation.len()
    }

    /// Global dofs of an element's nodes in element dof order (`per_node` per node) into
    /// `out`; returns their number.
    pub fn element_dofs(&self, nodes: &[usize], out: &mut [usize]) -> usize {
        element_dofs(self.per_node, nodes, out)
    }
}

/// Global dofs of the nodes `nodes` with `per_node` dofs each, in element dof order, into
/// `out`; returns their number.
pub(crate) fn element_dofs(per_node: usize, nodes: &[usize], out: &mut [usize]) -> usize {
    for (i, &n) in nodes.iter().enumerate() {
        for d in 0..per_node {
            out[per_node * i + d] = per_node * n + d;
        }
    }
    per_node * nodes.len()
}

/// A vector of `n` zeros with `v` at dof `d` for every `(d, v)` of `values` (a later value at
/// the same dof replaces an earlier one): prescribed values over all dofs.
pub fn scatter(n: usize, values: impl IntoIterator<Item = (usize, f64)>) -> Vec<f64> {
    let mut q = vec![0.0; n];
    for (d, v) in values {
        q[d] = v;
    }
    q
}

/// Lower-triangle CSC pattern of the free-free stiffness block, with its values.
#[derive(Debug, Clone)]
pub struct SparsePattern {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
}

impl SparsePattern {
    /// Build the pattern from the node adjacency of a plane `mesh` (two nodes are coupled when
    /// they share an element), expanded to the free dofs of `dofs`.
    pub fn new(mesh: &Mesh, dofs: &DofMap) -> Self {
        Self::from_elements(
            mesh.n_nodes(),
            (0..mesh.n_elements()).map(|e| mesh.element(e)),
            dofs,
        )
    }

    /// Build the pattern of the elements `elements` (node lists) over `n_nodes` nodes, expanded
    /// to the free dofs of `dofs` (`dofs.per_node()` per node).
    pub fn from_elements<'a>(
        n_nodes: usize,
        elements: impl Iterator<Item = &'a [usize]>,
        dofs: &DofMap,
    ) -> Self {
        let adjacency = node_adjacency(n_nodes, elements);
        let n = dofs.n_free();
        let p = dofs.per_node();
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for (node, neighbours) in adjacency.iter().enumerate() {
            for dir in 0..p {
                let Some(col) = dofs.equation(dofs.dof(node, dir)) else {
                    continue;
                };
                // neighbours are sorted by node id and free indices grow with node id and
                // direction, so rows come out sorted.
                for &other in neighbours {
                    for d in 0..p {
                        if let Some(row) = dofs.equation(dofs.dof(other, d)).filter(|&r| r >= col) {
                            row_idx.push(row);
                        }
                    }
                }
                col_ptr.push(row_idx.len());
            }
        }
        let nnz = row_idx.len();
        SparsePattern {
            col_ptr,
            row_idx,
            values: vec![0.0; nnz],
        }
    }

    /// Order of the matrix.
    pub fn n(&self) -> usize {
        self.col_ptr.len() - 1
    }

    /// Stored entries (lower triangle).
    pub fn nnz(&self) -> usize {
        self.row_idx.len()
    }

    /// The symbolic pattern, for the factorization's analysis.
    pub fn symbolic(&self) -> SymbolicSparseColMatRef<'_, usize> {
        SymbolicSparseColMatRef::new_checked(self.n(), self.n(), &self.col_ptr, None, &self.row_idx)
    }

    /// The matrix with its current values.
    pub fn matrix(&self) -> SparseColMatRef<'_, usize, f64> {
        SparseColMatRef::new(self.symbolic(), &self.values)
    }

    /// Zero the values, before [`add`](Self::add)ing the elements again.
    pub fn clear(&mut self) {
        self.values.fill(0.0);
    }

    /// Add the free-free part of an element matrix `ke(b, a)` (row `b`, column `a`, element
    /// dof order) over the global dofs `gd` of the element.
    pub fn add(&mut self, dofs: &DofMap, gd: &[usize], ke: impl Fn(usize, usize) -> f64) {
        for (a, &da) in gd.iter().enumerate() {
            let Some(col) = dofs.equation(da) else {
                continue;
            };
            for (b, &db) in gd.iter().enumerate() {
                if let Some(row) = dofs.equation(db).filter(|&r| r >= col) {
                    let pos = self.position(row, col);
                    self.values[pos] += ke(b, a);
                }
            }
        }
    }

    /// Refill the values from a plane mesh: `K_ff`, the free-free block of
    /// `K = sum_e A_e^T K_e A_e` ([`elements::assemble`]). Element shape errors carry the
    /// element index.
    pub fn assemble(
        &mut self,
        mesh: &Mesh,
        materials: &[Material],
        formulation: Formulation,
        dofs: &DofMap,
    ) -> Result<()> {
        let set = PlaneElements::new(mesh, materials, formulation);
        elements::assemble(&set, self, dofs, |_, _| ())
    }

    /// Storage position of entry `(row, col)`, `row >= col`, which must be in the pattern.
    fn position(&self, row: usize, col: usize) -> usize {
        let (lo, hi) = (self.col_ptr[col], self.col_ptr[col + 1]);
        lo + self.row_idx[lo..hi]
            .binary_search(&row)
            .expect("entry outside the assembled pattern")
    }
}

/// Sorted node neighbour lists (each node of an element is its own neighbour).
fn node_adjacency<'a>(
    n_nodes: usize,
    elements: impl Iterator<Item = &'a [usize]>,
) -> Vec<Vec<usize>> {
    let mut adjacency = vec![Vec::new(); n_nodes];
    for nodes in elements {
        for &a in nodes {
            adjacency[a].extend_from_slice(nodes);
        }
    }
    for list in &mut adjacency {
        list.sort_unstable();
        list.dedup();
    }
    adjacency
}

/// The free-free stiffness `K_ff` of a model (plane or solid) over its dof map, with its sparse
/// Cholesky factor: analysed once (optionally with trailing unknowns), factored again whenever
/// the values change, and solved for any number of loads.
#[derive(Debug)]
pub struct FactoredSystem {
    dofs: DofMap,
    pattern: SparsePattern,
    cholesky: SparseCholesky,
}

impl FactoredSystem {
    /// Analyse `pattern` over `dofs` with `backend` and the fill-reducing ordering `rule`, the
    /// free ones among the global dofs `trailing` eliminated last (in that order) so that
    /// [`condensed_flexibility`](Self::condensed_flexibility) reads their flexibility off the
    /// factor. Not factored yet ([`factor`](Self::factor)).
    pub fn analyze(
        dofs: DofMap,
        pattern: SparsePattern,
        backend: Backend,
        trailing: &[usize],
        rule: OrderingRule<'_>,
    ) -> Result<Self> {
        let trailing_free: Vec<usize> = trailing.iter().filter_map(|&d| dofs.equation(d)).collect();
        let cholesky =
            SparseCholesky::analyze_ordered(pattern.symbolic(), backend, &trailing_free, rule)?;
        Ok(FactoredSystem {
            dofs,
            pattern,
            cholesky,
        })
    }

    /// The dof map.
    pub fn dofs(&self) -> &DofMap {
        &self.dofs
    }

    /// The pattern and its values.
    pub fn pattern(&self) -> &SparsePattern {
        &self.pattern
    }

    /// The pattern, to assemble new values into (then [`factor`](Self::factor)), with the dof
    /// map.
    pub fn pattern_mut(&mut self) -> (&mut SparsePattern, &DofMap) {
        (&mut self.pattern, &self.dofs)
    }

    /// The factorization.
    pub fn cholesky(&mut self) -> &mut SparseCholesky {
        &mut self.cholesky
    }

    /// The factorization, read only.
    pub fn factorization(&self) -> &SparseCholesky {
        &self.cholesky
    }

    /// Factor the assembled `K_ff` (reusing the analysis).
    pub fn factor(&mut self) -> Result<()> {
        self.cholesky.factorize(self.pattern.matrix())
    }

    /// Assemble `K_ff` of `set` (the elements the pattern was built from) and factor it again,
    /// reusing the analysis.
    pub fn refactor<const ND: usize>(&mut self, set: &impl ElementSet<ND>) -> Result<()> {
        elements::assemble(set, &mut self.pattern, &self.dofs, |_, _| ())?;
        self.factor()
    }

    /// The flexibility `(K^-1)` between the free dofs among the `trailing` dofs given to
    /// [`analyze`](Self::analyze) (in that order, prescribed ones skipped), read off the
    /// factor: no solves.
    pub fn condensed_flexibility(&self) -> Result<Mat<f64>> {
        self.cholesky.condensed_inverse()
    }

    /// Solve `K_ff q_f = b_f` with `b_f` given by `load(d, i)` at each free global dof `d`
    /// (free index `i`), writing `q_f` into `q` (over all dofs) at the free dofs.
    pub fn solve_into(&mut self, load: impl Fn(usize, usize) -> f64, q: &mut [f64]) -> Result<()> {
        let mut rhs = Mat::<f64>::zeros(self.dofs.n_free(), 1);
        for d in 0..self.dofs.n_dofs() {
            if let Some(i) = self.dofs.equation(d) {
                rhs[(i, 0)] = load(d, i);
            }
        }
        self.cholesky.solve_in_place(rhs.as_mut())?;
        for (d, v) in q.iter_mut().enumerate() {
            if let Some(i) = self.dofs.equation(d) {
                *v = rhs[(i, 0)];
            }
        }
        Ok(())
    }

    /// Solve `K_ff q_f = f_f - K_fp q_p` for external forces `f` and prescribed values `qp`,
    /// both over all dofs (`qp` read at the prescribed dofs only), with `internal(q)` the
    /// element forces `K q` over all dofs (asked for only when some `q_p` is not zero): one
    /// solve with the kept factor; the displacement over all dofs.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for vectors of the wrong length, [`Error::Solver`] for a
    /// non-finite displacement.
    pub fn solve_for(
        &mut self,
        f: &[f64],
        qp: &[f64],
        internal: impl FnOnce(&[f64]) -> Result<Vec<f64>>,
    ) -> Result<Vec<f64>> {
        let n = self.dofs.n_dofs();
        if f.len() != n || qp.len() != n {
            return Err(Error::InvalidInput(format!(
                "force and prescribed vectors need {n} entries, got {} and {}",
                f.len(),
                qp.len()
            )));
        }
        let mut q: Vec<f64> = (0..n)
            .map(|d| {
                if self.dofs.equation(d).is_some() {
                    0.0
                } else {
                    qp[d]
                }
            })
            .collect();
        // f_f - K_fp q_p: the element forces of the prescribed motion, at the free dofs.
        let kq = if q.iter().any(|&v| v != 0.0) {
            internal(&q)?
        } else {
            vec![0.0; n]
        };
        self.solve_into(|d, _| f[d] - kq[d], &mut q)?;
        if let Some(d) = q.iter().position(|v| !v.is_finite()) {
            return Err(Error::Solver(format!("non-finite displacement at dof {d}")));
        }
        Ok(q)
    }
}

/// Compute every plane element's stiffness in turn and hand it to `visit(element, global dofs,
/// n_dof, K_e)` ([`elements::for_each_selected`] over every element). Stops at the first bad
/// element, reported with its index.
pub fn for_each_element_matrix(
    mesh: &Mesh,
    materials: &[Material],
    formulation: Formulation,
    ke: &mut ElementMatrix,
    visit: impl FnMut(usize, &[usize; 2 * MAX_NODES], usize, &ElementMatrix),
) -> Result<()> {
    let set = PlaneElements::new(mesh, materials, formulation);
    elements::for_each_selected(&set, ke, |_| true, visit)
}
