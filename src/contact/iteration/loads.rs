//! Load solves `u0 = K^-1 (f - K_fp q_p)` at the contact dofs, reused when a load is a
//! combination of recent ones (proportional loading, a slide on a fixed approach); a host that
//! handed over its condensed operator gives `u0` itself (its load image).

use super::boundary::Boundary;
use super::{ContactError, DMatrix, DVector, Error, Result, checks};
use crate::contact::bodies::Bodies;
use crate::contact::space::Vector;

/// `u0 = K^-1 (f - K_fp q_p)` at the contact dofs for one load `(f, q_p)`.
#[derive(Debug, Clone)]
pub(super) struct LoadSolve {
    /// `f` and `q_p` (zero at free dofs), concatenated.
    pub(super) load: Vec<f64>,
    /// `u0` at the contact dofs.
    u0c: Vec<f64>,
    /// The force the plate exerts on the body in the `u0` solution (zero without a plate).
    pub(super) plate_force: Vector,
}

/// Coefficients `c` with `new = sum_i c_i old_i` to round-off (relative 1e-13), if the loads
/// `old` span `new` without cancellation (`sum |c_i| |old_i| <= 4 |new|`, so that combining
/// their solutions loses no accuracy).
pub(super) fn combination(new: &[f64], old: &[std::sync::Arc<LoadSolve>]) -> Option<Vec<f64>> {
    let k = old.len();
    if k == 0 {
        return None;
    }
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let gram = DMatrix::from_fn(k, k, |i, j| dot(&old[i].load, &old[j].load));
    let rhs = DVector::from_fn(k, |i, _| dot(&old[i].load, new));
    let c = gram.lu().solve(&rhs)?;
    let norm = checks::norm2;
    let new_norm = norm(new);
    let mut residual = new.to_vec();
    for (ci, o) in c.iter().zip(old) {
        for (r, v) in residual.iter_mut().zip(&o.load) {
            *r -= ci * v;
        }
    }
    let spread: f64 = c
        .iter()
        .zip(old)
        .map(|(ci, o)| ci.abs() * norm(&o.load))
        .sum();
    // (a comparison with NaN, from loads beyond the range of the Gram matrix, is false)
    (norm(&residual) <= 1e-13 * new_norm && spread <= 4.0 * new_norm)
        .then(|| c.iter().copied().collect())
}

/// What [`Boundary::load_solve`] gives an increment.
pub(super) struct Solved {
    /// `u0` at the contact dofs.
    pub(super) u0c: Vec<f64>,
    /// The force the plate exerts on the body in the `u0` solution (zero without a plate).
    pub(super) plate_force: Vector,
    /// The load as compared between increments: `f` and `q_p` at the prescribed dofs.
    pub(super) load: Vec<f64>,
}

/// How many load solves are kept for reuse.
pub(super) const KEPT_LOADS: usize = 4;

/// Largest magnitude of a load or prescribed value an increment takes: beyond it the sums
/// derived from the load (the load plus the contact forces, the stresses) may overflow. (Moduli
/// and thicknesses have their own range, [`crate::material::SCALE_RANGE`].)
pub const LOAD_LIMIT: f64 = 1e300;

impl Boundary {
    /// `u0 = K^-1 (f - K_fp q_p)` at the contact dofs of `bodies`: one solve, or none when the
    /// load is a combination of recent ones (`u0` is linear in the load: proportional loading,
    /// or a slide superposed on a fixed approach, costs one or two solves in all), in
    /// increment `number`. `plate_force` gives the force a plate exerts on the body in the
    /// solution `u0` of a solve (over the field).
    pub(super) fn load_solve(
        &mut self,
        bodies: &dyn Bodies,
        (f, qp): (&[f64], &[f64]),
        number: usize,
        plate_force: impl FnOnce(&[f64]) -> Result<Vector>,
    ) -> Result<Solved> {
        let n = bodies.load_len();
        let n_qp = bodies.prescribed_len();
        if f.len() != n || qp.len() != n_qp {
            let image = if n == bodies.field_len() {
                ""
            } else {
                " (a condensed host's load image: u0 = K^-1 f at its candidate equations)"
            };
            return Err(Error::InvalidInput(format!(
                "the load vector needs {n} entries{image} and the prescribed vector {n_qp}, got \
                 {} and {}",
                f.len(),
                qp.len()
            )));
        }
        // the key holds `f` and `qp` at the prescribed dofs only: the other entries of `qp` are
        // ignored, whatever they hold
        let load = bodies.load_key(f, qp);
        if let Some(i) = load
            .iter()
            .position(|v| !v.is_finite() || v.abs() > LOAD_LIMIT)
        {
            let (name, index, value) = if i < n {
                ("load", i, f[i])
            } else {
                ("prescribed", i - n, qp[i - n])
            };
            return Err(Error::InvalidInput(if value.is_finite() {
                format!(
                    "{name}[{index}] = {value:e} is beyond {LOAD_LIMIT:e} in magnitude, where \
                     the sums derived from it (load plus contact forces, stresses) may overflow: \
                     choose other units"
                )
            } else {
                format!("{name}[{index}] = {value} is not finite")
            }));
        }
        if let Some(u0c) = bodies.condensed_image(f, &self.dofs) {
            // the host solved for its load: the image is u0 itself
            return Ok(Solved {
                u0c,
                plate_force: Vector::zero(bodies.dim()),
                load,
            });
        }
        if let Some(c) = combination(&load, &self.loads) {
            let mut u0c = vec![0.0; self.dofs.len()];
            let mut force = Vector::zero(bodies.dim());
            for (ci, cached) in c.iter().zip(&self.loads) {
                for (u, v) in u0c.iter_mut().zip(&cached.u0c) {
                    *u += ci * v;
                }
                force = force.add_scaled(*ci, &cached.plate_force);
            }
            return Ok(Solved {
                u0c,
                plate_force: force,
                load,
            });
        }
        let clock = std::time::Instant::now();
        let u0 = bodies.solve(f, qp)?;
        if u0.iter().any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite {
                increment: number,
                iteration: 0,
            }
            .into());
        }
        let plate_force = plate_force(&u0)?;
        self.load_seconds += clock.elapsed().as_secs_f64();
        let u0c: Vec<f64> = self
            .dofs
            .iter()
            .map(|&d| bodies.field_index(d).map_or(0.0, |i| u0[i]))
            .collect();
        if self.loads.len() == KEPT_LOADS {
            self.loads.remove(0);
        }
        self.loads.push(std::sync::Arc::new(LoadSolve {
            load: load.clone(),
            u0c: u0c.clone(),
            plate_force,
        }));
        Ok(Solved {
            u0c,
            plate_force,
            load,
        })
    }
}
