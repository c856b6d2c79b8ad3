//! hycon's own models as the bodies of a contact analysis ([`OwnBodies`]): the plane or
//! axisymmetric [`Model`] ([`ModelBodies`]) and the brick model ([`SolidBodies`], in
//! `solid.rs`). The field is all `dim n_nodes` dofs, node ids are the mesh's, and `K_ff` is
//! assembled and factored here, with the contact dofs last (eager) or with `F` built lazily
//! within their reach.

use super::{
    Bodies, ElementView, SetupSeconds, Stiffness, contact_reach, lazy_on, load_key, lock, unlocked,
};
use crate::assembly::DofMap;
use crate::error::Result;
use crate::model::{LinearSystem, Model};
use crate::solver::{Backend, Reach, SparseCholesky};
use std::sync::Mutex;

/// A model hycon assembles and factors itself: what its bodies ([`OwnBodies`]) ask of it and
/// of its factored system.
pub trait OwnModel: Send + Sync + 'static {
    /// The model's factored free-free stiffness.
    type System: Send + std::fmt::Debug;
    /// Equations per node.
    const DIM: usize;
    /// Reference positions, flat (`DIM` per node).
    fn positions(&self) -> &[f64];
    /// Validate, assemble and factor `K_ff`, the free ones among the global dofs `trailing`
    /// eliminated last.
    fn factored(&self, trailing: &[usize], backend: Backend) -> Result<Self::System>;
    /// The system's free-dof numbering.
    fn dofs(system: &Self::System) -> &DofMap;
    /// The system's factor.
    fn cholesky(system: &mut Self::System) -> &SparseCholesky;
    /// Assemble and factor `K_ff` again.
    fn refactorize(&self, system: &mut Self::System) -> Result<()>;
    /// `K_ff q_f = f_f - K_fp q_p` solved with the kept factor: the displacement over all dofs.
    fn solve(&self, system: &mut Self::System, f: &[f64], qp: &[f64]) -> Result<Vec<f64>>;
    /// Seconds of assembly and of analysis + factorization of the system (zero if not timed).
    fn setup_seconds(_system: &Self::System) -> SetupSeconds {
        SetupSeconds::default()
    }
    /// Element forces `K q` over all dofs ([`Bodies::internal_forces`]).
    fn internal_forces(&self, q: &[f64]) -> Result<Vec<f64>>;
    /// A stiffness (force per length) of the bodies' scale ([`Bodies::stiffness_scale`]).
    fn stiffness_scale(&self) -> f64;
    /// The plane model, for what stays plane-specific ([`Bodies::as_model`]).
    fn as_plane(&self) -> Option<&Model> {
        None
    }
}

/// A model of hycon's and its `K_ff`: factored with the contact dofs last, or (with a reach)
/// in the plain fill-reducing order, `F` then built lazily within the reach of the contact
/// dofs.
pub struct OwnBodies<M: OwnModel> {
    model: Box<M>,
    /// Locked so that solves can run from `&self` queries, one at a time.
    system: Mutex<Box<M::System>>,
    reach: Option<Box<Reach>>,
}

/// hycon's plane or axisymmetric model as contact bodies.
pub type ModelBodies = OwnBodies<Model>;

impl<M: OwnModel> std::fmt::Debug for OwnBodies<M> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "OwnBodies({:?})", lock(&self.system))
    }
}

impl<M: OwnModel> OwnBodies<M> {
    /// The model with the contact dofs `contact` (global dofs). Eager (`lazy == false`):
    /// factored with them eliminated last, so that all of `F` is read off the factor's trailing
    /// block. Lazy (faer only): factored in the plain fill-reducing order, as a linear solve
    /// would be, and the columns of `F` computed when asked for
    /// ([`flexibility_times`](Bodies::flexibility_times)) by substitutions within the reach of
    /// the contact dofs in the elimination tree, on up to `threads` threads
    /// ([`Reach::with_threads`]).
    pub fn new(
        model: M,
        contact: &[usize],
        backend: Backend,
        lazy: bool,
        threads: usize,
    ) -> Result<Self> {
        let lazy = lazy_on(backend, lazy);
        let trailing = if lazy { &[][..] } else { contact };
        let mut system = model.factored(trailing, backend)?;
        let equations: Vec<usize> = contact
            .iter()
            .filter_map(|&d| M::dofs(&system).equation(d))
            .collect();
        let reach = contact_reach(M::cholesky(&mut system), lazy, &equations, threads);
        Ok(OwnBodies {
            model: Box::new(model),
            system: Mutex::new(Box::new(system)),
            reach,
        })
    }
}

impl<M: OwnModel> Bodies for OwnBodies<M> {
    fn dim(&self) -> usize {
        M::DIM
    }

    fn positions(&self) -> &[f64] {
        self.model.positions()
    }

    /// The identity on the mesh's nodes.
    fn local(&self, id: usize) -> Option<usize> {
        (id < self.positions().len() / M::DIM).then_some(id)
    }

    fn external(&self, local: usize) -> usize {
        local
    }

    fn field_len(&self) -> usize {
        self.positions().len()
    }

    fn field_index(&self, d: usize) -> Option<usize> {
        Some(d)
    }

    fn equation(&self, d: usize) -> Option<usize> {
        M::dofs(&lock(&self.system)).equation(d)
    }

    fn stiffness(&mut self) -> Stiffness<'_> {
        Stiffness::Factor {
            cholesky: M::cholesky(unlocked(&mut self.system).as_mut()),
            reach: self.reach.as_deref(),
        }
    }

    /// With a reach: the plain fill-reducing order.
    fn lazy_flexibility(&self) -> bool {
        self.reach.is_some()
    }

    fn factorizations(&self) -> usize {
        M::cholesky(&mut lock(&self.system)).factorizations()
    }

    fn refactorize(&mut self) -> Result<()> {
        self.model.refactorize(unlocked(&mut self.system).as_mut())
    }

    fn setup_seconds(&self) -> SetupSeconds {
        M::setup_seconds(&lock(&self.system))
    }

    fn solve(&self, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        self.model.solve(&mut lock(&self.system), f, qp)
    }

    fn prescribed_len(&self) -> usize {
        self.field_len()
    }

    fn load_key(&self, f: &[f64], qp: &[f64]) -> Vec<f64> {
        let system = lock(&self.system);
        load_key(f, qp, |d| M::dofs(&system).equation(d).is_some())
    }

    fn internal_forces(&self, q: &[f64]) -> Result<Vec<f64>> {
        self.model.internal_forces(q)
    }

    fn stiffness_scale(&self) -> Option<f64> {
        Some(self.model.stiffness_scale())
    }

    fn as_model(&self) -> Option<&Model> {
        self.model.as_plane()
    }

    fn has_elements(&self) -> bool {
        self.model.as_plane().is_some()
    }

    /// The plane model itself (identity on the node ids).
    fn elements(&self, field: &[f64]) -> Option<ElementView<'_>> {
        let model = self.model.as_plane()?;
        Some((model, field.to_vec(), Box::new(Some)))
    }
}

impl OwnModel for Model {
    type System = LinearSystem;
    const DIM: usize = 2;

    fn positions(&self) -> &[f64] {
        self.mesh.nodes.as_flattened()
    }

    fn factored(&self, trailing: &[usize], backend: Backend) -> Result<LinearSystem> {
        LinearSystem::with_trailing_on(self, trailing, backend)
    }

    fn dofs(system: &LinearSystem) -> &DofMap {
        system.dofs()
    }

    fn cholesky(system: &mut LinearSystem) -> &SparseCholesky {
        system.cholesky()
    }

    fn refactorize(&self, system: &mut LinearSystem) -> Result<()> {
        system.refactorize(self)
    }

    fn solve(&self, system: &mut LinearSystem, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        Ok(system.solve_for(self, f, qp)?.q)
    }

    fn setup_seconds(system: &LinearSystem) -> SetupSeconds {
        let [assembly, factorization] = system.setup_seconds();
        SetupSeconds {
            assembly,
            factorization,
        }
    }

    fn internal_forces(&self, q: &[f64]) -> Result<Vec<f64>> {
        Model::internal_forces(self, q)
    }

    /// The largest `E t` of the materials.
    fn stiffness_scale(&self) -> f64 {
        (self.materials.iter())
            .map(|m| m.youngs * m.thickness)
            .fold(0.0, f64::max)
    }

    fn as_plane(&self) -> Option<&Model> {
        Some(self)
    }
}
