//! hycon's own plane or axisymmetric [`Model`] as the bodies of a contact analysis: the field
//! is all `2 n_nodes` dofs, node ids are the mesh's, and `K_ff` is assembled and factored here.

use super::{Bodies, ElementView, Stiffness, contact_reach, lazy_on, load_key, lock, unlocked};
use crate::error::Result;
use crate::model::{LinearSystem, Model};
use crate::solver::{Backend, Reach};
use std::sync::Mutex;

/// hycon's model and its `K_ff`: factored with the contact dofs last, or (with a reach) in the
/// plain fill-reducing order, `F` then built lazily within the reach of the contact dofs.
pub struct ModelBodies {
    model: Box<Model>,
    /// Locked so that solves can run from `&self` queries, one at a time.
    system: Mutex<Box<LinearSystem>>,
    reach: Option<Box<Reach>>,
}

impl std::fmt::Debug for ModelBodies {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ModelBodies({:?})", lock(&self.system))
    }
}

impl ModelBodies {
    /// hycon's model with the contact dofs `contact` (global dofs). Eager
    /// (`lazy == false`): factored with them eliminated last, so that all of `F` is read off
    /// the factor's trailing block. Lazy (faer only): factored in the plain fill-reducing
    /// order, as a linear solve would be, and the columns of `F` computed when asked for
    /// ([`flexibility_times`](Bodies::flexibility_times)) by substitutions within the reach of
    /// the contact dofs in the elimination tree, on up to `threads` threads
    /// ([`Reach::with_threads`]).
    pub fn new(
        model: Model,
        contact: &[usize],
        backend: Backend,
        lazy: bool,
        threads: usize,
    ) -> Result<Self> {
        let lazy = lazy_on(backend, lazy);
        let trailing = if lazy { &[][..] } else { contact };
        let mut system = LinearSystem::with_trailing_on(&model, trailing, backend)?;
        let equations: Vec<usize> = contact
            .iter()
            .filter_map(|&d| system.dofs().equation(d))
            .collect();
        let reach = contact_reach(system.cholesky(), lazy, &equations, threads);
        Ok(ModelBodies {
            model: Box::new(model),
            system: Mutex::new(Box::new(system)),
            reach,
        })
    }
}

impl Bodies for ModelBodies {
    fn dim(&self) -> usize {
        2
    }

    fn positions(&self) -> &[f64] {
        self.model.mesh.nodes.as_flattened()
    }

    /// The identity on the mesh's nodes.
    fn local(&self, id: usize) -> Option<usize> {
        (id < self.model.mesh.n_nodes()).then_some(id)
    }

    fn external(&self, local: usize) -> usize {
        local
    }

    fn field_len(&self) -> usize {
        2 * self.model.mesh.n_nodes()
    }

    fn field_index(&self, d: usize) -> Option<usize> {
        Some(d)
    }

    fn equation(&self, d: usize) -> Option<usize> {
        lock(&self.system).dofs().equation(d)
    }

    fn stiffness(&mut self) -> Stiffness<'_> {
        Stiffness::Factor {
            cholesky: unlocked(&mut self.system).cholesky(),
            reach: self.reach.as_deref(),
        }
    }

    /// With a reach: the plain fill-reducing order.
    fn lazy_flexibility(&self) -> bool {
        self.reach.is_some()
    }

    fn factorizations(&self) -> usize {
        lock(&self.system).cholesky().factorizations()
    }

    fn refactorize(&mut self) -> Result<()> {
        unlocked(&mut self.system).refactorize(&self.model)
    }

    fn setup_seconds(&self) -> [f64; 2] {
        lock(&self.system).setup_seconds()
    }

    fn solve(&self, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        Ok(lock(&self.system).solve_for(&self.model, f, qp)?.q)
    }

    fn prescribed_len(&self) -> usize {
        self.field_len()
    }

    fn load_key(&self, f: &[f64], qp: &[f64]) -> Vec<f64> {
        let system = lock(&self.system);
        load_key(f, qp, |d| system.dofs().equation(d).is_some())
    }

    fn as_model(&self) -> Option<&Model> {
        Some(&self.model)
    }

    fn has_elements(&self) -> bool {
        true
    }

    /// The model itself (identity on the node ids).
    fn elements(&self, field: &[f64]) -> Option<ElementView<'_>> {
        Some((&self.model, field.to_vec(), Box::new(Some)))
    }
}
