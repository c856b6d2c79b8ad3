//! Dof numbering and sparse assembly of the global stiffness.
//!
//! Node `i` carries the global dofs `2 i` (x) and `2 i + 1` (y). Prescribed dofs are eliminated:
//! [`DofMap`] numbers the free dofs `0..n_free` in node order. [`SparsePattern`] is the
//! lower-triangle compressed-column pattern of `K_ff` (free-free block), built once from the mesh
//! connectivity; [`SparsePattern::assemble`] refills its values from the element kernels, so the
//! pattern and the symbolic factorization built on it are reused whenever values change.

use crate::element::{self, ElementMatrix, Formulation, MAX_NODES};
use crate::error::{Error, Result};
use crate::material::Material;
use crate::mesh::Mesh;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};

/// Marker for a prescribed (eliminated) dof.
const PRESCRIBED: usize = usize::MAX;

/// Global dof index of node `node` in direction `dir` (0 = x, 1 = y).
pub fn dof(node: usize, dir: usize) -> usize {
    2 * node + dir
}

/// Free-dof numbering: `equation[d]` is the free index of global dof `d`, or none if prescribed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DofMap {
    equation: Vec<usize>,
    n_free: usize,
}

impl DofMap {
    /// Number the dofs of `n_nodes` nodes, leaving out the global dofs in `prescribed`.
    pub fn new(n_nodes: usize, prescribed: impl IntoIterator<Item = usize>) -> Self {
        let mut equation = vec![0; 2 * n_nodes];
        for d in prescribed {
            equation[d] = PRESCRIBED;
        }
        let mut n_free = 0;
        for e in equation.iter_mut().filter(|e| **e != PRESCRIBED) {
            *e = n_free;
            n_free += 1;
        }
        DofMap { equation, n_free }
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

    /// Global dof indices of an element's nodes, in element dof order, into `out`; returns `2 n`.
    pub fn element_dofs(nodes: &[usize], out: &mut [usize; 2 * MAX_NODES]) -> usize {
        for (i, &n) in nodes.iter().enumerate() {
            out[2 * i] = dof(n, 0);
            out[2 * i + 1] = dof(n, 1);
        }
        2 * nodes.len()
    }
}

/// Lower-triangle CSC pattern of the free-free stiffness block, with its values.
#[derive(Debug, Clone)]
pub struct SparsePattern {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
}

impl SparsePattern {
    /// Build the pattern from the node adjacency of `mesh` (two nodes are coupled when they share
    /// an element), expanded to the free dofs of `dofs`.
    pub fn new(mesh: &Mesh, dofs: &DofMap) -> Self {
        let adjacency = node_adjacency(mesh);
        let n = dofs.n_free();
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for (node, neighbours) in adjacency.iter().enumerate() {
            for dir in 0..2 {
                let Some(col) = dofs.equation(dof(node, dir)) else {
                    continue;
                };
                // neighbours are sorted by node id and free indices grow with node id and
                // direction, so rows come out sorted.
                for &other in neighbours {
                    for d in 0..2 {
                        if let Some(row) = dofs.equation(dof(other, d)).filter(|&r| r >= col) {
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

    /// Refill the values: `K_ff = sum over elements of the free-free part of the element `K``.
    /// Element shape errors carry the element index.
    pub fn assemble(
        &mut self,
        mesh: &Mesh,
        materials: &[Material],
        formulation: Formulation,
        dofs: &DofMap,
    ) -> Result<()> {
        self.values.fill(0.0);
        let mut ke = ElementMatrix::zeros();
        for_each_element_matrix(mesh, materials, formulation, &mut ke, |_, gd, nd, ke| {
            for a in 0..nd {
                let Some(col) = dofs.equation(gd[a]) else {
                    continue;
                };
                for b in 0..nd {
                    if let Some(row) = dofs.equation(gd[b]).filter(|&r| r >= col) {
                        let pos = self.position(row, col);
                        self.values[pos] += ke[(b, a)];
                    }
                }
            }
        })
    }

    /// Storage position of entry `(row, col)`, `row >= col`, which must be in the pattern.
    fn position(&self, row: usize, col: usize) -> usize {
        let (lo, hi) = (self.col_ptr[col], self.col_ptr[col + 1]);
        lo + self.row_idx[lo..hi]
            .binary_search(&row)
            .expect("entry outside the assembled pattern")
    }
}

/// Sorted node neighbour lists (each node is its own neighbour).
fn node_adjacency(mesh: &Mesh) -> Vec<Vec<usize>> {
    let mut adjacency = vec![Vec::new(); mesh.n_nodes()];
    for e in 0..mesh.n_elements() {
        let nodes = mesh.element(e);
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

/// Compute every element's stiffness in turn and hand it to `visit(element, global dofs, n_dof,
/// K_e)`. Stops at the first bad element, reported with its index.
pub fn for_each_element_matrix(
    mesh: &Mesh,
    materials: &[Material],
    formulation: Formulation,
    ke: &mut ElementMatrix,
    visit: impl FnMut(usize, &[usize; 2 * MAX_NODES], usize, &ElementMatrix),
) -> Result<()> {
    for_each_selected_element_matrix(mesh, materials, formulation, ke, |_| true, visit)
}

/// [`for_each_element_matrix`] over the elements whose global dofs `wanted` accepts; the
/// others' stiffness is not computed (nor checked).
pub(crate) fn for_each_selected_element_matrix(
    mesh: &Mesh,
    materials: &[Material],
    formulation: Formulation,
    ke: &mut ElementMatrix,
    mut wanted: impl FnMut(&[usize]) -> bool,
    mut visit: impl FnMut(usize, &[usize; 2 * MAX_NODES], usize, &ElementMatrix),
) -> Result<()> {
    let mut coords = [[0.0; 2]; MAX_NODES];
    let mut gd = [0; 2 * MAX_NODES];
    for e in 0..mesh.n_elements() {
        let element_dofs = DofMap::element_dofs(mesh.element(e), &mut gd);
        if !wanted(&gd[..element_dofs]) {
            continue;
        }
        let n = mesh.element_coords(e, &mut coords);
        let material = materials.get(mesh.element_material[e]).ok_or_else(|| {
            Error::InvalidInput(format!(
                "element {e} uses material {} but only {} are defined",
                mesh.element_material[e],
                materials.len()
            ))
        })?;
        let nd = element::stiffness_into(formulation, &coords[..n], material, ke)
            .map_err(|kind| Error::at_element(kind, e))?;
        visit(e, &gd, nd, ke);
    }
    Ok(())
}
