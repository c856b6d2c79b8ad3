//! Test oracles (feature `oracles`, which the lab and its tests enable; not in the API hosts
//! link by default): the dense reference algebra of hycon 0.3, which the tests compare the
//! product's algebra with, and the benchmark's control that factors `K` again in every
//! iteration.

use super::boundary::{self, Boundary};
use super::small_system::SmallSystem;
use super::{Border, ContactAnalysis, Flexibility, Result};

impl ContactAnalysis {
    /// Run the iteration on the dense reference algebra (`true`) or on the lazy, cached one
    /// (`false`, the default). The reference builds every column of `F` up front (a host's
    /// callback then solves for every contact dof), forms `F col_j` and `F f` from `F` in every
    /// iteration and factors the small system with nalgebra's unblocked LU: the algebra of
    /// hycon 0.3, kept so that tests can show that both give the same contact states and
    /// tractions.
    ///
    /// # Errors
    /// A failed host solve while building the missing columns of `F`.
    pub fn set_reference_algebra(&mut self, on: bool) -> Result<()> {
        if on && !self.boundary.flexibility.is_full() {
            let all = 0..self.boundary.dofs.len();
            self.boundary.ensure_columns(&mut *self.bodies, all)?;
        }
        self.boundary.reference_algebra = on;
        Ok(())
    }

    /// Factor `K` and rebuild the boundary flexibility in every iteration instead of once per
    /// analysis. Never needed (`K` does not change): a benchmark's control, not an option, so
    /// that `hycon bench skip` can show what factoring once saves.
    pub fn set_refactor_each_iteration(&mut self, on: bool) {
        self.boundary.refactor_each_iteration = on;
    }

    /// Factor `K` again and forget `F` (the refactor-every-iteration control); returns the
    /// seconds it took.
    pub(super) fn refactor(&mut self) -> Result<f64> {
        let clock = std::time::Instant::now();
        self.bodies.refactorize()?;
        self.boundary.flexibility = if self.bodies.lazy_flexibility() {
            Flexibility::lazy(self.boundary.dofs.len())
        } else {
            Flexibility::full(self.bodies.flexibility(&self.boundary.dofs)?)
        };
        self.boundary.forget_directions();
        Ok(clock.elapsed().as_secs_f64())
    }
}

impl Boundary {
    /// One iteration on the reference algebra: `SmallSystem::solve` on the full `F`, then
    /// `u = u0 + F f + sum_e U_e w_e` over the contact dofs.
    pub(super) fn solve_reference(
        &mut self,
        system: &SmallSystem,
        u0c: &[f64],
        border: Option<&Border>,
    ) -> Result<boundary::Solution> {
        let (tau, plate_motion, condition) = system.solve(u0c, &self.flexibility.matrix, border)?;
        let forces = system.forces(&tau, self.dofs.len());
        // u = u0 + F f over the contact dofs (f is zero away from the active nodes)
        let mut uc = u0c.to_vec();
        for (j, &fj) in forces.iter().enumerate().filter(|(_, f)| **f != 0.0) {
            for (u, c) in uc.iter_mut().zip(self.flexibility.column(j)) {
                *u += c * fj;
            }
        }
        if let Some(b) = border {
            for (&d, &m) in b.directions.iter().zip(&plate_motion) {
                for (u, w) in uc.iter_mut().zip(&b.response[d]) {
                    *u += m * w;
                }
            }
        }
        Ok((tau, plate_motion, condition, uc))
    }
}
