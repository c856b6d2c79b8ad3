//! The elastic bodies as the contact iteration sees them ([`Bodies`]): the reference positions
//! of the contact nodes, where their dofs sit in the linear system, and solves with the
//! stiffness.
//!
//! Three implementors:
//! * [`ModelBodies`]: hycon's own plane or axisymmetric [`Model`], assembled and factored by
//!   hycon ([`OwnBodies`] of a [`Model`]);
//! * [`HostBodies`]: a host FE code's system ([`HostSystem`]): its stiffness in CSR (factored
//!   here), a solve callback, or its condensed operator;
//! * [`SolidBodies`]: hycon's own 3D brick model ([`SolidModel`](crate::solid::model::SolidModel)),
//!   the same [`OwnBodies`] with 3 equations per node: what the 3D contact iteration plugs in.
//!
//! The iteration needs three things of any of them, all linear in the loads:
//! * the contact-boundary flexibility `F = E^T K^-1 E` (`E` picks the contact dofs),
//! * `u0 = K^-1 f` for a load `f`, read at the contact dofs,
//! * the whole field `K^-1 (f + f_c)` with the converged contact forces `f_c`, on request.
//!
//! Vectors of loads and displacements live in the *field* space: all `dim n_nodes` dofs of a
//! model (`f` external forces, `qp` prescribed values), or the host's `n` equations (`f` its
//! right-hand side, which already holds the effect of its prescribed displacements; no `qp`).
//! A dof of the iteration's numbering is `dim node + direction`.

mod factor;
mod host;
mod model;
mod solid;

pub use host::{
    Condensed, CondensedKind, Csr, HostBodies, HostElements, HostNode, HostSolve, HostStiffness,
    HostSystem, NodeEquations, Triangle, check_elements,
};
pub use model::{ModelBodies, OwnBodies, OwnModel};
pub use solid::SolidBodies;

use crate::error::{Error, Result};
use crate::model::Model;
use crate::solver::{Backend, Reach, SparseCholesky};
use faer::Mat;
use nalgebra::DMatrix;
use std::sync::{Mutex, MutexGuard, PoisonError};

/// Elements for stress recovery ([`Bodies::elements`]): a plane model, the displacement of the
/// field in its numbering, and the translation of a node id of the iteration into its own.
pub type ElementView<'a> = (
    &'a Model,
    Vec<f64>,
    Box<dyn Fn(usize) -> Option<usize> + 'a>,
);

/// Seconds the bodies' setup took ([`Bodies::setup_seconds`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SetupSeconds {
    /// Assembling `K`.
    pub assembly: f64,
    /// Its symbolic analysis and numeric factorization.
    pub factorization: f64,
}

/// How the bodies solve with their stiffness `K` when the iteration builds `F`.
pub enum Stiffness<'a> {
    /// hycon's sparse Cholesky factor: eager (the contact equations eliminated last, `F` read
    /// off the trailing block, `reach` none) or lazy (plain fill-reducing order, `F` built by
    /// substitutions within the `reach` of the contact equations).
    Factor {
        /// The factor of `K`.
        cholesky: &'a SparseCholesky,
        /// The contact equations' reach in the elimination tree, when lazy.
        reach: Option<&'a Reach>,
    },
    /// A host's solve callback over its `equations` equations (always lazy).
    Callback {
        /// The host's solver.
        solver: &'a mut dyn HostSolve,
        /// The host's `n`.
        equations: usize,
    },
    /// `F` between the free contact dofs, handed over whole by a host.
    Condensed(&'a Mat<f64>),
}

/// The images `W V = L^-1 P E V` of a batch of vectors in the factor's space, dense over the
/// rows of their elimination-tree reach ([`Bodies::images`]).
#[derive(Debug, Clone)]
pub struct Images {
    /// The factor column of each row, ascending.
    pub columns: Vec<usize>,
    /// One column per vector.
    pub values: Mat<f64>,
}

/// The elastic bodies of a contact analysis, whatever holds their stiffness (see the
/// [module docs](self)). Dofs are of the iteration's numbering, `dim() node + direction`.
pub trait Bodies: Send + Sync + std::fmt::Debug {
    /// Equations per node: 2 for plane and axisymmetric bodies, 3 for solid ones.
    fn dim(&self) -> usize;

    /// Reference positions, flat: `dim()` values per node, indexed by the iteration's node ids.
    fn positions(&self) -> &[f64];

    /// Translate a node id of the caller's numbering into the iteration's (identity for
    /// hycon's models).
    fn local(&self, id: usize) -> Option<usize>;

    /// The caller's id of a node of the iteration's numbering.
    fn external(&self, local: usize) -> usize;

    /// Length of load and displacement vectors (`dim() n_nodes`, or a host's `n`).
    fn field_len(&self) -> usize;

    /// Where dof `d` sits in the field (`None`: held fixed at zero by a host).
    fn field_index(&self, d: usize) -> Option<usize>;

    /// The equation of dof `d` in `K` (free-dof numbering, or a host's equation); `None` at a
    /// fixed dof.
    fn equation(&self, d: usize) -> Option<usize>;

    /// Whether dof `d` is free (an unknown of `K`).
    fn is_free(&self, d: usize) -> bool {
        self.equation(d).is_some()
    }

    /// Who solves with `K` when `F` is built.
    fn stiffness(&mut self) -> Stiffness<'_>;

    /// Whether `F` is built as the iteration asks for it
    /// ([`flexibility_times`](Self::flexibility_times)). Otherwise all of `F` comes at once
    /// ([`flexibility`](Self::flexibility)).
    fn lazy_flexibility(&self) -> bool;

    /// `F = E^T K^-1 E` over the dofs `dofs` (sorted; in the order given to the factorization
    /// as trailing unknowns): read off the factor or the condensed operator, else built from
    /// unit columns ([`flexibility_times`](Self::flexibility_times)). Zero rows and columns at
    /// fixed dofs.
    fn flexibility(&mut self, dofs: &[usize]) -> Result<DMatrix<f64>> {
        if self.lazy_flexibility() {
            let units: Vec<Vec<(usize, f64)>> = (0..dofs.len()).map(|j| vec![(j, 1.0)]).collect();
            return self.flexibility_times(dofs, &units);
        }
        let free: Vec<usize> = (0..dofs.len()).filter(|&i| self.is_free(dofs[i])).collect();
        let condensed = match self.stiffness() {
            Stiffness::Factor { cholesky, .. } => cholesky.condensed_inverse()?,
            Stiffness::Condensed(flexibility) => flexibility.clone(),
            Stiffness::Callback { .. } => unreachable!("a callback's F is lazy"),
        };
        let mut flex = DMatrix::zeros(dofs.len(), dofs.len());
        for (a, &i) in free.iter().enumerate() {
            for (b, &j) in free.iter().enumerate() {
                flex[(i, j)] = condensed[(a, b)];
            }
        }
        Ok(flex)
    }

    /// `F V = E^T K^-1 E V` over the dofs `dofs` for the columns `V` given sparse over
    /// positions in `dofs` (`dofs.len() x vectors.len()`): one right-hand side `E v` per
    /// column, solved in batches, through a host's callback (whole solves) or by substitution
    /// within the reach of the contact dofs ([`SparseCholesky::solve_within`]); read from the
    /// whole `F` when it comes at once. Rows at fixed dofs are zero, and fixed dofs of `v` are
    /// ignored.
    fn flexibility_times(
        &mut self,
        dofs: &[usize],
        vectors: &[Vec<(usize, f64)>],
    ) -> Result<DMatrix<f64>> {
        if !self.lazy_flexibility() {
            let all = self.flexibility(dofs)?;
            return Ok(factor::times_whole(&all, vectors));
        }
        let rows: Vec<Option<usize>> = dofs.iter().map(|&d| self.equation(d)).collect();
        match self.stiffness() {
            Stiffness::Factor {
                cholesky,
                reach: Some(reach),
            } => factor::times_within(cholesky, reach, &rows, vectors),
            Stiffness::Callback { solver, equations } => {
                host::callback_times(solver, equations, &rows, vectors)
            }
            _ => unreachable!("an F that comes at once is not lazy"),
        }
    }

    /// Whether [`images`](Self::images) gives images (the bodies have a lazy faer factor).
    fn has_images(&mut self) -> bool {
        matches!(self.stiffness(), Stiffness::Factor { reach: Some(_), .. })
    }

    /// The images `W V = L^-1 P E V` in the factor's space of the columns `V` of each batch
    /// (sparse over positions in `dofs`, as for
    /// [`flexibility_times`](Self::flexibility_times)), so that `V^T F V = (W V)^T (W V)`
    /// (`F = E^T K^-1 E`, `K = P^T L L^T P`): per batch one forward substitution within its
    /// columns' own elimination-tree reach, the batches shared among the threads of the
    /// contact dofs' reach ([`Reach::with_threads`]; the images do not depend on their number).
    /// `None` when the bodies have no lazy faer factor (a host's callback, CHOLMOD, or an
    /// eager factor).
    fn images(
        &mut self,
        dofs: &[usize],
        batches: &[Vec<Vec<(usize, f64)>>],
    ) -> Result<Option<Vec<Images>>> {
        let rows: Vec<Option<usize>> = dofs.iter().map(|&d| self.equation(d)).collect();
        match self.stiffness() {
            Stiffness::Factor {
                cholesky,
                reach: Some(reach),
            } => factor::images(cholesky, reach, &rows, batches).map(Some),
            _ => Ok(None),
        }
    }

    /// `E^T K^-1 E sum_i V_i c_i` at the dofs `dofs`, from the images `W V_i` of
    /// [`images`](Self::images) and their coefficients `c_i`: the images combined,
    /// `z = sum_i (W V_i) c_i`, and one backward substitution `P^T L^-T z` over the contact
    /// dofs' reach. Zero at fixed dofs.
    fn back_substitute(&mut self, dofs: &[usize], parts: &[(&Images, &[f64])]) -> Result<Vec<f64>> {
        let rows: Vec<Option<usize>> = dofs.iter().map(|&d| self.equation(d)).collect();
        match self.stiffness() {
            Stiffness::Factor {
                cholesky,
                reach: Some(reach),
            } => factor::back_substitute(cholesky, reach, &rows, parts),
            _ => Err(crate::error::Error::Solver(
                "images need a lazy faer factor".into(),
            )),
        }
    }

    /// Numeric factorizations of `K` done by hycon (0 for a host that solves itself).
    fn factorizations(&self) -> usize;

    /// Factor `K` again (assembling it again for hycon's models); a host's own solver keeps
    /// its factor. Only the benchmark's refactor-every-iteration variant does this.
    fn refactorize(&mut self) -> Result<()>;

    /// Seconds spent on assembly and on analysis + factorization when the bodies were set up
    /// (zero where hycon did not assemble).
    fn setup_seconds(&self) -> SetupSeconds {
        SetupSeconds::default()
    }

    /// The displacement field for loads `f` (and, for hycon's models, prescribed values `qp`,
    /// read at the prescribed dofs): one solve. Solves are serialized by a lock, so this takes
    /// `&self`.
    fn solve(&self, f: &[f64], qp: &[f64]) -> Result<Vec<f64>>;

    /// Whether hycon can solve with `K` ([`solve`](Self::solve)): an error saying how the host
    /// recovers its displacement when it handed over its condensed operator instead.
    fn check_solver(&self) -> Result<()> {
        Ok(())
    }

    /// Length of the prescribed values an increment takes: the field's for hycon's models,
    /// none for a host.
    fn prescribed_len(&self) -> usize;

    /// The load as the reuse of load solves compares it: `f`, followed for hycon's models by
    /// `qp` at the prescribed dofs (zero elsewhere).
    fn load_key(&self, f: &[f64], qp: &[f64]) -> Vec<f64>;

    /// The length of an increment's load: the field's, or for a host that handed over its
    /// condensed operator the number of its candidates (the load image's).
    fn load_len(&self) -> usize {
        self.field_len()
    }

    /// For a host that handed over its condensed operator, `u0 = K^-1 f` at the dofs `dofs`
    /// read off the load image `image` (`u0` over the candidates, the host's own solve; zero
    /// at fixed dofs); `None` for bodies that solve themselves.
    fn condensed_image(&self, _image: &[f64], _dofs: &[usize]) -> Option<Vec<f64>> {
        None
    }

    /// Element forces `K q` over the field for displacements `q` over the field (the rigid
    /// plate's forces: the reactions `K q - f` at its nodes): hycon's own models; an error for
    /// a host's system, whose elements hycon does not have.
    fn internal_forces(&self, _q: &[f64]) -> Result<Vec<f64>> {
        Err(Error::InvalidInput(
            "this analysis runs on a host's system: hycon has no elements to take forces from"
                .into(),
        ))
    }

    /// A stiffness (force per length) of the bodies' scale, against which the rigid plate's own
    /// stiffness counts as zero: the largest `E t` of a plane model, the largest `E` times the
    /// mesh's extent of a brick model; `None` for a host.
    fn stiffness_scale(&self) -> Option<f64> {
        None
    }

    /// The plane model, if these are hycon's own plane bodies: plane-specific
    /// ([`ContactAnalysis::model`], stress recovery).
    ///
    /// [`ContactAnalysis::model`]: crate::contact::iteration::ContactAnalysis::model
    fn as_model(&self) -> Option<&Model> {
        None
    }

    /// Whether [`elements`](Self::elements) has elements to offer.
    fn has_elements(&self) -> bool {
        false
    }

    /// The plane elements for stress recovery with the displacement of `field` in their
    /// numbering ([`ElementView`]): hycon's plane model, or the elements a host handed over
    /// (`None` if it did not, and for solid bodies, whose tractions come another way).
    fn elements(&self, _field: &[f64]) -> Option<ElementView<'_>> {
        None
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

/// Batch size of flexibility solves: at most this many columns, and at most about 32 MB of
/// right-hand sides per batch.
const CALLBACK_BATCH: usize = 64;

/// The load as the reuse of load solves compares it ([`Bodies::load_key`]) for hycon's models:
/// `f`, followed by `qp` at the prescribed dofs (those `free` rejects), zero elsewhere.
fn load_key(f: &[f64], qp: &[f64], free: impl Fn(usize) -> bool) -> Vec<f64> {
    f.iter()
        .copied()
        .chain(
            qp.iter()
                .enumerate()
                .map(|(d, &v)| if free(d) { 0.0 } else { v }),
        )
        .collect()
}

/// Whether `F` is built lazily: asked for, and the backend is faer.
fn lazy_on(backend: Backend, lazy: bool) -> bool {
    lazy && backend == Backend::Faer
}

/// The reach of the contact equations `equations` in the factor's elimination tree, shared
/// among up to `threads` threads ([`Reach::with_threads`]), when `F` is built lazily.
fn contact_reach(
    factor: &SparseCholesky,
    lazy: bool,
    equations: &[usize],
    threads: usize,
) -> Option<Box<Reach>> {
    if lazy {
        factor
            .reach(equations)
            .map(|r| Box::new(r.with_threads(threads)))
    } else {
        None
    }
}
