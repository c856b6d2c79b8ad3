//! A linear static 3D model of bricks: dof numbering (3 dofs per node), sparse assembly into the
//! sparse Cholesky with its symbolic analysis kept and reused, solve, stresses.
//!
//! # Why a parallel layer, and what is shared
//! The dof map here ([`NodalDofs`]) is the plane [`crate::assembly::DofMap`] with the number of
//! dofs per node as a value instead of the constant 2: one concept, written once, generic over
//! the dimension, so the plane map can become `NodalDofs` with `per_node = 2` at a later
//! refactor. The element loop stays parallel (plane elements have 4 to 6 nodes, a 2D material
//! with thickness and analysis kind, `MAX_DOF = 12` storage; bricks have 8 nodes, an
//! [`Isotropic`] material and 24 x 24 storage): merging the two loops would put a dimension
//! switch into every kernel call for no shared mathematics. The solver is shared unchanged:
//! [`SolidSystem`] analyses the pattern once with [`SparseCholesky::analyze`] and refactors
//! into the same symbolic structure whenever the values change (new materials, another
//! formulation), then solves any number of load cases.

use super::mesh::SolidMesh;
use super::{BrickFormulation, BrickMatrix, BrickStress, Isotropic, N_DOF, N_NODES};
use crate::error::{Error, Result};
use crate::solver::{Backend, FillOrdering, OrderingRule, SparseCholesky};
use faer::Mat;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};

/// Marker for a prescribed (eliminated) dof.
const PRESCRIBED: usize = usize::MAX;

/// Free-dof numbering for `per_node` dofs per node: global dof `per_node * node + dir`;
/// `equation(d)` is its free index, or `None` when prescribed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodalDofs {
    per_node: usize,
    equation: Vec<usize>,
    n_free: usize,
}

impl NodalDofs {
    /// Number the dofs of `n_nodes` nodes with `per_node` dofs each, leaving out the global dofs
    /// in `prescribed` (out-of-range indices are an error).
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
        Ok(NodalDofs {
            per_node,
            equation,
            n_free,
        })
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

    /// Total number of dofs.
    pub fn n_dofs(&self) -> usize {
        self.equation.len()
    }

    /// Global dofs of an element's nodes in element dof order (`per_node` per node) into `out`.
    pub fn element_dofs(&self, nodes: &[usize], out: &mut [usize]) {
        for (i, &n) in nodes.iter().enumerate() {
            for d in 0..self.per_node {
                out[self.per_node * i + d] = self.dof(n, d);
            }
        }
    }
}

/// The free-free stiffness (lower triangle, compressed columns), its analysed factorization and
/// the dof map: built once per mesh and set of prescribed dofs, refactored for new values.
#[derive(Debug)]
pub struct SolidSystem {
    dofs: NodalDofs,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
    cholesky: SparseCholesky,
}

impl SolidSystem {
    /// Pattern from the node adjacency of `mesh` expanded to the free dofs, and its symbolic
    /// analysis with `backend` (the ordering chosen by [`OrderingRule::Auto`]).
    pub fn new(mesh: &SolidMesh, dofs: NodalDofs, backend: Backend) -> Result<Self> {
        Self::with_ordering(mesh, dofs, backend, OrderingRule::Auto)
    }

    /// [`new`](Self::new) with the fill-reducing ordering chosen by `rule`.
    pub fn with_ordering(
        mesh: &SolidMesh,
        dofs: NodalDofs,
        backend: Backend,
        rule: OrderingRule<'_>,
    ) -> Result<Self> {
        let mut adjacency = vec![Vec::new(); mesh.n_nodes()];
        for el in &mesh.elements {
            for &a in el {
                adjacency[a].extend_from_slice(el);
            }
        }
        let mut col_ptr = vec![0];
        let mut row_idx = Vec::new();
        for (node, list) in adjacency.iter_mut().enumerate() {
            list.sort_unstable();
            list.dedup();
            for dir in 0..3 {
                let Some(col) = dofs.equation(dofs.dof(node, dir)) else {
                    continue;
                };
                for &other in list.iter() {
                    for d in 0..3 {
                        if let Some(row) = dofs.equation(dofs.dof(other, d)).filter(|&r| r >= col) {
                            row_idx.push(row);
                        }
                    }
                }
                col_ptr.push(row_idx.len());
            }
        }
        let n = dofs.n_free();
        let symbolic = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        let cholesky = SparseCholesky::analyze_ordered(symbolic, backend, &[], rule)?;
        let values = vec![0.0; row_idx.len()];
        Ok(SolidSystem {
            dofs,
            col_ptr,
            row_idx,
            values,
            cholesky,
        })
    }

    /// The dof map.
    pub fn dofs(&self) -> &NodalDofs {
        &self.dofs
    }

    /// Stored entries of the lower triangle of `K_ff`.
    pub fn nnz(&self) -> usize {
        self.row_idx.len()
    }

    /// The factorization (for its statistics: order, `nnz(L)`, factorization count).
    pub fn cholesky(&self) -> &SparseCholesky {
        &self.cholesky
    }

    /// Assemble `K_ff` from every brick and factor it (reusing the analysis). Returns the
    /// load correction `-K_fp u_p` of the prescribed values `prescribed` (global dof, value),
    /// indexed by free equation.
    pub fn assemble_and_factor(
        &mut self,
        mesh: &SolidMesh,
        materials: &[Isotropic],
        formulation: BrickFormulation,
        prescribed: &[(usize, f64)],
    ) -> Result<Vec<f64>> {
        let correction = self.assemble(mesh, materials, formulation, prescribed)?;
        self.factor()?;
        Ok(correction)
    }

    /// The assembly half of [`assemble_and_factor`](Self::assemble_and_factor).
    pub fn assemble(
        &mut self,
        mesh: &SolidMesh,
        materials: &[Isotropic],
        formulation: BrickFormulation,
        prescribed: &[(usize, f64)],
    ) -> Result<Vec<f64>> {
        let mut u_p = vec![0.0; self.dofs.n_dofs()];
        for &(d, v) in prescribed {
            u_p[d] = v;
        }
        let mut correction = vec![0.0; self.dofs.n_free()];
        self.values.fill(0.0);
        let mut ke = BrickMatrix::zeros();
        let mut gd = [0; N_DOF];
        for (e, el) in mesh.elements.iter().enumerate() {
            let material = materials.get(mesh.element_material[e]).ok_or_else(|| {
                Error::InvalidInput(format!(
                    "brick {e} uses material {} but only {} are defined",
                    mesh.element_material[e],
                    materials.len()
                ))
            })?;
            super::stiffness_into(formulation, &mesh.element_coords(e), material, &mut ke)
                .map_err(|kind| Error::at_element(kind, e))?;
            self.dofs.element_dofs(el, &mut gd);
            for a in 0..N_DOF {
                match self.dofs.equation(gd[a]) {
                    Some(col) => {
                        for b in 0..N_DOF {
                            if let Some(row) = self.dofs.equation(gd[b]).filter(|&r| r >= col) {
                                let pos = self.position(row, col);
                                self.values[pos] += ke[(b, a)];
                            }
                        }
                    }
                    None if u_p[gd[a]] != 0.0 => {
                        for b in 0..N_DOF {
                            if let Some(row) = self.dofs.equation(gd[b]) {
                                correction[row] -= ke[(b, a)] * u_p[gd[a]];
                            }
                        }
                    }
                    None => {}
                }
            }
        }
        Ok(correction)
    }

    /// Factor the assembled `K_ff` (reusing the analysis).
    pub fn factor(&mut self) -> Result<()> {
        let n = self.dofs.n_free();
        let symbolic =
            SymbolicSparseColMatRef::new_checked(n, n, &self.col_ptr, None, &self.row_idx);
        let matrix = SparseColMatRef::new(symbolic, &self.values);
        self.cholesky.factorize(matrix)
    }

    /// The assembled lower triangle of `K_ff`.
    pub fn matrix(&self) -> SparseColMatRef<'_, usize, f64> {
        let n = self.dofs.n_free();
        let symbolic =
            SymbolicSparseColMatRef::new_checked(n, n, &self.col_ptr, None, &self.row_idx);
        SparseColMatRef::new(symbolic, &self.values)
    }

    /// Solve `K_ff u_f = f_f` for each column of `rhs` (free equations), in place.
    pub fn solve_in_place(&mut self, rhs: &mut Mat<f64>) -> Result<()> {
        self.cholesky.solve_in_place(rhs.as_mut())
    }

    fn position(&self, row: usize, col: usize) -> usize {
        let (lo, hi) = (self.col_ptr[col], self.col_ptr[col + 1]);
        lo + self.row_idx[lo..hi]
            .binary_search(&row)
            .expect("entry outside the assembled pattern")
    }
}

/// A linear static problem on a brick mesh: prescribed displacements, nodal loads, one
/// formulation.
#[derive(Debug, Clone)]
pub struct SolidModel {
    /// The mesh.
    pub mesh: SolidMesh,
    /// Materials, indexed by `mesh.element_material`.
    pub materials: Vec<Isotropic>,
    /// The brick formulation.
    pub formulation: BrickFormulation,
    /// Prescribed values by global dof (ordered: the dof map and the load correction see them
    /// in dof order).
    prescribed: std::collections::BTreeMap<usize, f64>,
    loads: Vec<f64>,
}

/// The solution of a [`SolidModel`].
#[derive(Debug, Clone)]
pub struct SolidSolution {
    /// Displacements, 3 per node (`u, v, w`).
    pub displacements: Vec<f64>,
    /// Number of free dofs.
    pub n_free: usize,
    /// Stored entries of the Cholesky factor.
    pub nnz_l: usize,
    /// The factorization's fill-reducing ordering.
    pub ordering: FillOrdering,
}

impl SolidSolution {
    /// Displacement of `node`.
    pub fn at(&self, node: usize) -> [f64; 3] {
        let d = &self.displacements[3 * node..3 * node + 3];
        [d[0], d[1], d[2]]
    }
}

impl SolidModel {
    /// A model with no supports and no loads; checks the mesh and the materials.
    pub fn new(
        mesh: SolidMesh,
        materials: Vec<Isotropic>,
        formulation: BrickFormulation,
    ) -> Result<Self> {
        mesh.validate()?;
        for m in &materials {
            m.validate()?;
        }
        let loads = vec![0.0; 3 * mesh.n_nodes()];
        Ok(SolidModel {
            mesh,
            materials,
            formulation,
            prescribed: Default::default(),
            loads,
        })
    }

    /// Prescribe displacement `value` of `node` in direction `dir` (0, 1, 2 = x, y, z); a
    /// later call for the same dof replaces the value. A node beyond the mesh is reported by
    /// [`solve`](Self::solve). Panics if `dir > 2`.
    pub fn fix(&mut self, node: usize, dir: usize, value: f64) {
        assert!(dir < 3, "direction {dir} (0, 1, 2 = x, y, z)");
        self.prescribed.insert(3 * node + dir, value);
    }

    /// Add the force `f` to `node`. Panics if `node` is not a node of the mesh.
    pub fn load(&mut self, node: usize, f: [f64; 3]) {
        for (i, fi) in f.into_iter().enumerate() {
            self.loads[3 * node + i] += fi;
        }
    }

    /// Add the consistent nodal forces of a traction field on the faces `faces` (see
    /// [`SolidMesh::face_forces`]).
    pub fn load_faces(
        &mut self,
        faces: &[(usize, usize)],
        traction: impl Fn([f64; 3], [f64; 3]) -> [f64; 3],
    ) {
        for &(e, f) in faces {
            for (node, force) in self.mesh.face_forces(e, f, &traction) {
                self.load(node, force);
            }
        }
    }

    /// Assemble, factor (faer backend) and solve.
    pub fn solve(&self) -> Result<SolidSolution> {
        let dofs = NodalDofs::new(self.mesh.n_nodes(), 3, self.prescribed.keys().copied())?;
        let mut system = SolidSystem::new(&self.mesh, dofs, Backend::Faer)?;
        let correction = system.assemble_and_factor(
            &self.mesh,
            &self.materials,
            self.formulation,
            &self
                .prescribed
                .iter()
                .map(|(&d, &v)| (d, v))
                .collect::<Vec<_>>(),
        )?;
        let dofs = system.dofs().clone();
        let mut rhs = Mat::<f64>::zeros(dofs.n_free(), 1);
        for (d, &f) in self.loads.iter().enumerate() {
            if let Some(e) = dofs.equation(d) {
                rhs[(e, 0)] = f + correction[e];
            }
        }
        system.solve_in_place(&mut rhs)?;
        let mut displacements = vec![0.0; dofs.n_dofs()];
        for (d, u) in displacements.iter_mut().enumerate() {
            if let Some(e) = dofs.equation(d) {
                *u = rhs[(e, 0)];
            }
        }
        for (&d, &v) in &self.prescribed {
            displacements[d] = v;
        }
        Ok(SolidSolution {
            displacements,
            n_free: dofs.n_free(),
            nnz_l: system.cholesky().nnz_l(),
            ordering: system.cholesky().ordering(),
        })
    }

    /// The stress field of brick `e` from a solution.
    pub fn element_stress(&self, solution: &SolidSolution, e: usize) -> Result<BrickStress> {
        let el = self.mesh.elements[e];
        let mut q = [0.0; N_DOF];
        for k in 0..N_NODES {
            q[3 * k..3 * k + 3].copy_from_slice(&solution.displacements[3 * el[k]..3 * el[k] + 3]);
        }
        super::recover_stress(
            self.formulation,
            &self.mesh.element_coords(e),
            &self.materials[self.mesh.element_material[e]],
            &q,
        )
        .map_err(|kind| Error::at_element(kind, e))
    }
}
