//! A linear static 3D model of bricks: dof numbering (3 dofs per node), sparse assembly into the
//! sparse Cholesky with its symbolic analysis kept and reused, solve, stresses.
//!
//! # What is shared with the plane model
//! The dof map ([`DofMap`]), the lower-triangle pattern ([`SparsePattern`]), the factored
//! free-free system with its trailing unknowns and solves ([`FactoredSystem`]) and the loops
//! over the elements (assembly `K = sum_e A_e^T K_e A_e` and element forces
//! `K q = sum_e A_e^T K_e q_e`, [`elements`]) are the plane model's, with 3 dofs per node: what
//! differs, the brick kernel, its 8 nodes, its [`Isotropic`] material and its 24 x 24 storage,
//! is [`Bricks`], the solid [`ElementSet`]. [`SolidSystem`] analyses the pattern once and
//! refactors into the same symbolic structure whenever the values change (new materials, another
//! formulation), then solves any number of load cases; with trailing unknowns its factor gives
//! their flexibility (what contact needs of the bodies, see
//! [`SolidBodies`](crate::contact::bodies::SolidBodies)).

use super::mesh::SolidMesh;
use super::{BrickFormulation, BrickMatrix, BrickStress, Isotropic, N_DOF};
use crate::assembly::elements::{self, ElementSet, element_material, gather};
use crate::assembly::{DofMap, FactoredSystem, SparsePattern, scatter};
use crate::error::{Error, Result};
use crate::solver::{Backend, FillOrdering, OrderingRule, SparseCholesky};
use faer::Mat;
use faer::sparse::SparseColMatRef;

/// The free-free stiffness of a brick mesh over its dof map (3 dofs per node), its analysed
/// factorization: built once per mesh and set of prescribed dofs, refactored for new values.
#[derive(Debug)]
pub struct SolidSystem {
    system: FactoredSystem,
    /// `[assembly, analysis + factorization]` seconds of [`with_trailing_on`](Self::with_trailing_on).
    seconds: [f64; 2],
}

impl SolidSystem {
    /// Pattern from the node adjacency of `mesh` expanded to the free dofs, and its symbolic
    /// analysis with `backend` (the ordering chosen by [`OrderingRule::Auto`]).
    pub fn new(mesh: &SolidMesh, dofs: DofMap, backend: Backend) -> Result<Self> {
        Self::with_ordering(mesh, dofs, backend, OrderingRule::Auto)
    }

    /// [`new`](Self::new) with the fill-reducing ordering chosen by `rule`.
    pub fn with_ordering(
        mesh: &SolidMesh,
        dofs: DofMap,
        backend: Backend,
        rule: OrderingRule<'_>,
    ) -> Result<Self> {
        let pattern = Self::pattern(mesh, &dofs);
        Ok(SolidSystem {
            system: FactoredSystem::analyze(dofs, pattern, backend, &[], rule)?,
            seconds: [0.0; 2],
        })
    }

    /// The system of `model` (its prescribed dofs left out), assembled and factored with
    /// `backend`, the free ones among the global dofs `trailing` eliminated last so that
    /// [`condensed_flexibility`](Self::condensed_flexibility) reads their flexibility off the
    /// factor (as the plane [`LinearSystem::with_trailing_on`](crate::model::LinearSystem::with_trailing_on)).
    /// Loads then go through [`solve_for`](Self::solve_for). The seconds of the assembly (the
    /// pattern and its values) and of the factorization (symbolic and numeric) are kept
    /// ([`setup_seconds`](Self::setup_seconds)).
    pub fn with_trailing_on(
        model: &SolidModel,
        trailing: &[usize],
        backend: Backend,
    ) -> Result<Self> {
        backend.check_available()?;
        let clock = std::time::Instant::now();
        let dofs = model.dof_map()?;
        let mut pattern = Self::pattern(&model.mesh, &dofs);
        elements::assemble(&model.elements(), &mut pattern, &dofs, |_, _| ())?;
        let assembly = clock.elapsed().as_secs_f64();
        let mut system =
            FactoredSystem::analyze(dofs, pattern, backend, trailing, OrderingRule::Auto)?;
        system.factor()?;
        Ok(SolidSystem {
            system,
            seconds: [assembly, clock.elapsed().as_secs_f64() - assembly],
        })
    }

    /// Wall-clock seconds of `[assembly, analysis + factorization]` when the system was built
    /// by [`with_trailing_on`](Self::with_trailing_on) (zero otherwise).
    pub fn setup_seconds(&self) -> [f64; 2] {
        self.seconds
    }

    /// The lower-triangle pattern of `K_ff` from the node adjacency of `mesh`.
    fn pattern(mesh: &SolidMesh, dofs: &DofMap) -> SparsePattern {
        let elements = mesh.elements.iter().map(|e| &e[..]);
        SparsePattern::from_elements(mesh.n_nodes(), elements, dofs)
    }

    /// The dof map.
    pub fn dofs(&self) -> &DofMap {
        self.system.dofs()
    }

    /// Stored entries of the lower triangle of `K_ff`.
    pub fn nnz(&self) -> usize {
        self.system.pattern().nnz()
    }

    /// The factorization (for its statistics: order, `nnz(L)`, factorization count).
    pub fn cholesky(&self) -> &SparseCholesky {
        self.system.factorization()
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

    /// The assembly half of [`assemble_and_factor`](Self::assemble_and_factor):
    /// [`elements::assemble`] over the bricks, and the load correction of the prescribed values.
    pub fn assemble(
        &mut self,
        mesh: &SolidMesh,
        materials: &[Isotropic],
        formulation: BrickFormulation,
        prescribed: &[(usize, f64)],
    ) -> Result<Vec<f64>> {
        let bricks = Bricks::new(mesh, materials, formulation);
        let (pattern, dofs) = self.system.pattern_mut();
        let u_p = scatter(dofs.n_dofs(), prescribed.iter().copied());
        let mut correction = vec![0.0; dofs.n_free()];
        elements::assemble(&bricks, pattern, dofs, |gd, ke| {
            subtract_prescribed_motion(dofs, gd, ke, &u_p, &mut correction);
        })?;
        Ok(correction)
    }

    /// Factor the assembled `K_ff` (reusing the analysis).
    pub fn factor(&mut self) -> Result<()> {
        self.system.factor()
    }

    /// Assemble `K_ff` of `model` (the one the system was built from) and factor it again,
    /// reusing the analysis.
    pub fn refactorize(&mut self, model: &SolidModel) -> Result<()> {
        self.system.refactor(&model.elements())
    }

    /// The assembled lower triangle of `K_ff`.
    pub fn matrix(&self) -> SparseColMatRef<'_, usize, f64> {
        self.system.pattern().matrix()
    }

    /// Solve `K_ff u_f = f_f` for each column of `rhs` (free equations), in place.
    pub fn solve_in_place(&mut self, rhs: &mut Mat<f64>) -> Result<()> {
        self.system.cholesky().solve_in_place(rhs.as_mut())
    }

    /// The flexibility `(K^-1)` between the free dofs among the `trailing` dofs given to
    /// [`with_trailing_on`](Self::with_trailing_on) (in that order, prescribed ones skipped),
    /// read off the factor: no solves.
    pub fn condensed_flexibility(&self) -> Result<Mat<f64>> {
        self.system.condensed_flexibility()
    }

    /// Solve `K_ff u_f = f_f - K_fp u_p` for external forces `f` and prescribed values `qp`,
    /// both over all `3 n_nodes` dofs (`qp` read at the prescribed dofs only), with the kept
    /// factor of `model` (the one the system was built from): the displacement over all dofs.
    pub fn solve_for(&mut self, model: &SolidModel, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        self.system.solve_for(f, qp, |q| model.internal_forces(q))
    }
}

/// `correction_f -= K_e,fp u_p,e`: the load of the prescribed values `u_p` (over all dofs) at the
/// free dofs of one brick with global dofs `gd` and stiffness `ke`, summed over its prescribed,
/// non-zero columns.
fn subtract_prescribed_motion(
    dofs: &DofMap,
    gd: &[usize],
    ke: &BrickMatrix,
    u_p: &[f64],
    correction: &mut [f64],
) {
    for (a, &da) in gd.iter().enumerate() {
        if dofs.equation(da).is_some() || u_p[da] == 0.0 {
            continue;
        }
        for (b, &db) in gd.iter().enumerate() {
            if let Some(row) = dofs.equation(db) {
                correction[row] -= ke[(b, a)] * u_p[da];
            }
        }
    }
}

/// The bricks of a mesh with their materials and one formulation: the solid case of the element
/// loops ([`ElementSet`]; 3 dofs per node, [`N_DOF`] per brick).
#[derive(Debug, Clone, Copy)]
pub struct Bricks<'a> {
    /// The mesh.
    pub mesh: &'a SolidMesh,
    /// Materials, indexed by `mesh.element_material`.
    pub materials: &'a [Isotropic],
    /// The formulation of every brick.
    pub formulation: BrickFormulation,
}

impl ElementSet<N_DOF> for Bricks<'_> {
    const PER_NODE: usize = 3;

    fn n_elements(&self) -> usize {
        self.mesh.n_elements()
    }

    fn nodes(&self, e: usize) -> &[usize] {
        &self.mesh.elements[e]
    }

    fn stiffness_into(&self, e: usize, ke: &mut BrickMatrix) -> Result<usize> {
        let material = self.material(e)?;
        super::stiffness_into(self.formulation, &self.mesh.element_coords(e), material, ke)
            .map_err(|kind| Error::at_element(kind, e))?;
        Ok(N_DOF)
    }
}

impl<'a> Bricks<'a> {
    /// The bricks of `mesh`, with `materials` and `formulation`.
    pub fn new(
        mesh: &'a SolidMesh,
        materials: &'a [Isotropic],
        formulation: BrickFormulation,
    ) -> Self {
        Bricks {
            mesh,
            materials,
            formulation,
        }
    }

    /// The material of brick `e`, or an error naming it.
    pub fn material(&self, e: usize) -> Result<&'a Isotropic> {
        let index = self.mesh.element_material[e];
        element_material(self.materials, index, "brick", e)
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
        let bricks = Bricks::new(&mesh, &materials, formulation);
        for e in 0..mesh.n_elements() {
            bricks.material(e)?;
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

    /// Prescribe the displacement of every node in `nodes` in every direction of `directions`
    /// (0, 1, 2 = x, y, z) to zero, the values to be given later (a contact analysis takes
    /// them per increment).
    ///
    /// Checked here, atomically (on an error nothing is prescribed): every node exists, every
    /// direction is 0, 1 or 2, and no component is prescribed twice (within the call or by an
    /// earlier one).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the node or the direction.
    pub fn prescribe(&mut self, nodes: &[usize], directions: &[usize]) -> Result<()> {
        let n = self.mesh.n_nodes();
        if let Some(&node) = nodes.iter().find(|&&node| node >= n) {
            return Err(Error::InvalidInput(format!(
                "unknown node {node} (the model has {n} nodes)"
            )));
        }
        if let Some(&dir) = directions.iter().find(|&&d| d > 2) {
            return Err(Error::InvalidInput(format!(
                "direction {dir} (0, 1, 2 = x, y, z)"
            )));
        }
        let mut added = std::collections::BTreeSet::new();
        for &node in nodes {
            for &dir in directions {
                let dof = 3 * node + dir;
                if self.prescribed.contains_key(&dof) || !added.insert(dof) {
                    return Err(Error::InvalidInput(format!(
                        "node {node} direction {} is prescribed twice",
                        ["x", "y", "z"][dir]
                    )));
                }
            }
        }
        for dof in added {
            self.prescribed.insert(dof, 0.0);
        }
        Ok(())
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

    /// Displacement components prescribed: global dof (`3 node + dir`) and value, in dof order.
    pub fn prescribed(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.prescribed.iter().map(|(&d, &v)| (d, v))
    }

    /// Prescribed values over all dofs (zero where free).
    pub fn prescribed_values(&self) -> Vec<f64> {
        scatter(self.loads.len(), self.prescribed())
    }

    /// The nodal loads over all dofs (`3 n_nodes`).
    pub fn external_forces(&self) -> &[f64] {
        &self.loads
    }

    /// The free-dof numbering: the prescribed dofs left out.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a prescribed node beyond the mesh.
    pub fn dof_map(&self) -> Result<DofMap> {
        DofMap::new(self.mesh.n_nodes(), 3, self.prescribed.keys().copied())
    }

    /// Element forces `K q = sum_e A_e^T K_e q_e` over all dofs (length `3 n_nodes`,
    /// [`elements::internal_forces`]); a brick whose displacements are all zero adds nothing and
    /// is skipped.
    pub fn internal_forces(&self, q: &[f64]) -> Result<Vec<f64>> {
        elements::internal_forces(&self.elements(), q)
    }

    /// The model's bricks with their materials and formulation, for the element loops.
    pub fn elements(&self) -> Bricks<'_> {
        Bricks::new(&self.mesh, &self.materials, self.formulation)
    }

    /// Assemble, factor (faer backend) and solve.
    pub fn solve(&self) -> Result<SolidSolution> {
        let mut system = SolidSystem::new(&self.mesh, self.dof_map()?, Backend::Faer)?;
        let prescribed: Vec<(usize, f64)> = self.prescribed().collect();
        let correction = system.assemble_and_factor(
            &self.mesh,
            &self.materials,
            self.formulation,
            &prescribed,
        )?;
        let mut displacements = vec![0.0; system.dofs().n_dofs()];
        system
            .system
            .solve_into(|d, e| self.loads[d] + correction[e], &mut displacements)?;
        for (d, v) in prescribed {
            displacements[d] = v;
        }
        Ok(SolidSolution {
            displacements,
            n_free: system.dofs().n_free(),
            nnz_l: system.cholesky().nnz_l(),
            ordering: system.cholesky().ordering(),
        })
    }

    /// The stress field of brick `e` from a solution.
    pub fn element_stress(&self, solution: &SolidSolution, e: usize) -> Result<BrickStress> {
        let mut q = [0.0; N_DOF];
        gather(3, &self.mesh.elements[e], &solution.displacements, &mut q);
        super::recover_stress(
            self.formulation,
            &self.mesh.element_coords(e),
            self.elements().material(e)?,
            &q,
        )
        .map_err(|kind| Error::at_element(kind, e))
    }
}
