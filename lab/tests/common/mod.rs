//! What several test modules share.

pub mod l2;

use hycon::contact::bodies::HostSolve;
use hycon::solver::SparseCholesky;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A host's own solver behind the solve callback: faer's Cholesky of its `K`, counting the
/// right-hand sides it is asked for (`columns`, shared so that a test reads it after handing
/// the solver over).
pub struct OwnSolver {
    pub factor: SparseCholesky,
    pub columns: Arc<AtomicUsize>,
}

impl HostSolve for OwnSolver {
    /// `x_j = K^-1 rhs_j` for the `nrhs` column-major right-hand sides.
    fn solve(&mut self, nrhs: usize, rhs: &[f64], x: &mut [f64]) -> hycon::Result<()> {
        let n = rhs.len() / nrhs;
        let mut b = faer::Mat::from_fn(n, nrhs, |i, j| rhs[j * n + i]);
        self.factor.solve_in_place(b.as_mut())?;
        for j in 0..nrhs {
            for i in 0..n {
                x[j * n + i] = b[(i, j)];
            }
        }
        self.columns.fetch_add(nrhs, Ordering::Relaxed);
        Ok(())
    }
}
