//! The local frictional contact problem of one increment, as the Friction Contact Library
//! (FCLIB) states it and Siconos' `fc3d` solvers take it (docs/method.md, "The local
//! problem").
//!
//! Over `n` contacts of `d` components each (`d = 3` on a face, `2` in the plane), normal
//! first, the reactions `r` and the relative displacements (FCLIB's velocities) `u` are
//! related by the condensed operator `W` and the free term `q`:
//!
//! `u = W r + q`,
//!
//! and at every contact `i` the reaction lies in the Coulomb cone
//! `K_i = { r : |r_T| <= mu_i r_N }`, the modified displacement
//! `û_i = u_i + mu_i |u_T,i| e_N` in its dual cone `K_i* = { v : mu_i |v_T| <= v_N }`, and
//! `r_i . û_i = 0`: open (`r = 0`, `u_N >= 0`), sticking (`r` inside the cone, `u = 0`) or
//! slipping (`r` on the cone, `u_N = 0`, `u_T` against `r_T`).
//!
//! hycon solves it two ways: [`LocalProblem::solve_newton`] (the fallback's semi-smooth Newton
//! method) and [`LocalProblem::solve_rules`] (the paper's rules on the condensed conditions);
//! [`ContactAnalysis::local_problem`](crate::contact::iteration::ContactAnalysis::local_problem)
//! exports a converged increment as such a problem ([`LocalExport`]).
//!
//! hycon's own conditions (the fallback's `S t - rho = r`, `tn <= 0`, `rho_n <= 0`: compression
//! and closure negative) are this problem with the normal components' signs turned:
//! `r = D t`, `u = D rho`, `W = D S D`, `q = -D r_h`, `D = diag(-1, 1, .., 1)` per contact.

use crate::contact::friction::{Coulomb, FrictionLaw};
use crate::contact::iteration::{solve_by_rules, solve_conditions};
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};

/// FCLIB's local problem (module docs): `u = W r + q` over contacts of `dim` components,
/// normal first, with a Coulomb coefficient per contact.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalProblem {
    dim: usize,
    w: DMatrix<f64>,
    q: Vec<f64>,
    mu: Vec<f64>,
}

/// A solution of a [`LocalProblem`] by one of hycon's solvers.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalSolve {
    /// The reactions `r`, `dim` per contact, normal first.
    pub r: Vec<f64>,
    /// The relative displacements `u = W r + q`.
    pub u: Vec<f64>,
    /// Whether the solver met its own stopping rule (else `r` is its last iterate).
    pub settled: bool,
    /// The natural-map residual of `r` ([`LocalProblem::natural_map_residual`]).
    pub residual: f64,
    /// The iterations: the semi-smooth Newton steps ([`LocalProblem::solve_newton`]) or the
    /// rules' iterations ([`LocalProblem::solve_rules`]), each one dense linear solve.
    pub iterations: usize,
    /// The projected Gauss-Seidel sweeps (the Newton method's start, and its continuation
    /// where it does not settle; none for the rules).
    pub sweeps: usize,
}

/// The local problem of a converged increment of a contact analysis
/// ([`ContactAnalysis::local_problem`](crate::contact::iteration::ContactAnalysis::local_problem)),
/// with the analysis' converged reactions.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalExport {
    /// The problem, one contact per entry of `contacts`.
    pub problem: LocalProblem,
    /// The converged reactions in FCLIB's signs (`r_N = -tn >= 0`), `dim` per contact.
    pub solution: Vec<f64>,
    /// Which A node each contact is.
    pub contacts: Vec<LocalContact>,
    /// The number of the converged increment.
    pub increment: usize,
    /// The natural-map residual of `solution` ([`LocalProblem::natural_map_residual`]): how
    /// exactly the converged reactions solve the problem (the analysis judges its own
    /// convergence to `1e-4` per condition, docs/method.md "The checks at convergence").
    pub residual: f64,
}

/// One contact of a [`LocalExport`]: an A node of a contact pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LocalContact {
    /// The pair's index.
    pub pair: usize,
    /// The node's index along the pair's A side.
    pub node: usize,
    /// The caller's id of the node.
    pub id: usize,
}

impl LocalProblem {
    /// The problem `u = W r + q` over `mu.len()` contacts of `dim` components each.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] unless `dim` is 2 or 3, `W` is square of side
    /// `dim * mu.len()` and symmetric (to `1e-12` of its largest entry: hycon's solvers use its
    /// rows as its columns), `q` has that length, every value is finite and every `mu >= 0`.
    pub fn new(dim: usize, w: DMatrix<f64>, q: Vec<f64>, mu: Vec<f64>) -> Result<Self> {
        let invalid = |what: String| Err(Error::InvalidInput(format!("local problem: {what}")));
        if dim != 2 && dim != 3 {
            return invalid(format!("{dim} components per contact: FCLIB takes 2 or 3"));
        }
        let m = dim * mu.len();
        if w.nrows() != m || w.ncols() != m || q.len() != m {
            return invalid(format!(
                "W is {}x{} and q has {} entries, {} contacts of {dim} need {m}",
                w.nrows(),
                w.ncols(),
                q.len(),
                mu.len()
            ));
        }
        if let Some(i) = mu.iter().position(|m| !(m.is_finite() && *m >= 0.0)) {
            return invalid(format!(
                "mu of contact {i} is {}, not finite and >= 0",
                mu[i]
            ));
        }
        if w.iter().chain(&q).any(|v| !v.is_finite()) {
            return invalid("W or q holds a value that is not finite".into());
        }
        let largest = w.amax();
        let asymmetry = (&w - w.transpose()).amax();
        if asymmetry > 1e-12 * largest {
            return invalid(format!(
                "W is not symmetric (|W - W^T| reaches {asymmetry:.3e} against a largest \
                 entry of {largest:.3e})"
            ));
        }
        Ok(LocalProblem { dim, w, q, mu })
    }

    /// Components per contact (2 or 3).
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The number of contacts.
    pub fn contacts(&self) -> usize {
        self.mu.len()
    }

    /// The condensed operator `W`.
    pub fn w(&self) -> &DMatrix<f64> {
        &self.w
    }

    /// The free term `q`.
    pub fn q(&self) -> &[f64] {
        &self.q
    }

    /// The Coulomb coefficient of each contact.
    pub fn mu(&self) -> &[f64] {
        &self.mu
    }

    /// `u = W r + q`.
    pub fn velocity(&self, r: &[f64]) -> Vec<f64> {
        let u = &self.w * DVector::from_column_slice(r) + DVector::from_column_slice(&self.q);
        u.iter().copied().collect()
    }

    /// The natural-map residual of the reactions `r`: the norm `e` of Siconos'
    /// `fc3d_compute_error` relative to the free term, `e / |q|` with
    /// `e = sqrt(sum_i |r_i - P_K_i(r_i - û_i)|^2)` (not divided where `|q|` is zero; Siconos
    /// 4.4 divides the same `e` by `max(|q|, |r|, |u|)`, libfclib's merit by `1 + sqrt|q|`),
    /// `û_i = u_i + mu_i |u_T,i| e_N` with `u = W r + q`, `P_K_i` the closest point of the
    /// Coulomb cone. It vanishes exactly at a solution.
    pub fn natural_map_residual(&self, r: &[f64]) -> f64 {
        let u = self.velocity(r);
        let d = self.dim;
        let sum: f64 = (0..self.contacts())
            .map(|i| {
                let (ri, ui) = (&r[i * d..(i + 1) * d], &u[i * d..(i + 1) * d]);
                let ut = ui[1..].iter().map(|v| v * v).sum::<f64>().sqrt();
                let mut x: Vec<f64> = (0..d).map(|j| ri[j] - ui[j]).collect();
                x[0] -= self.mu[i] * ut;
                let p = project_on_cone(&x, self.mu[i]);
                (0..d).map(|j| (ri[j] - p[j]).powi(2)).sum::<f64>()
            })
            .sum();
        let norm_q = self.q.iter().map(|v| v * v).sum::<f64>().sqrt();
        let error = sum.sqrt();
        if norm_q > f64::EPSILON {
            error / norm_q
        } else {
            error
        }
    }

    /// The solution by the semi-smooth Newton method on the conditions (the primal-dual
    /// active set method of the fallback, docs/method.md "The fallback"), from 10 projected
    /// Gauss-Seidel sweeps within 8 steps and, where that does not settle, from the
    /// fallback's long start; in hycon's signs (module docs) and back.
    pub fn solve_newton(&self) -> LocalSolve {
        let (s, rh, laws) = self.hycon_form();
        let laws: Vec<&dyn FrictionLaw> = laws.iter().map(|l| l as &dyn FrictionLaw).collect();
        let solve = solve_conditions(s, rh, &laws, self.dim - 1);
        self.solved(&solve.t, solve.settled, solve.steps, solve.sweeps)
    }

    /// The solution by the paper's rules (the contact-set iteration of docs/method.md, "The
    /// rules", with the 3D direction update, on the condensed conditions; docs/method.md "The
    /// local problem"), from every contact open, in hycon's signs (module docs) and back.
    /// `settled` is false when the states cycle or do not repeat within 200 iterations.
    pub fn solve_rules(&self) -> LocalSolve {
        let (s, rh, laws) = self.hycon_form();
        let laws: Vec<&dyn FrictionLaw> = laws.iter().map(|l| l as &dyn FrictionLaw).collect();
        let solve = solve_by_rules(s, rh, &laws, self.dim - 1);
        self.solved(&solve.t, solve.settled, solve.iterations, 0)
    }

    /// The sign of component `j` between FCLIB's and hycon's signs ([`fclib_sign`]).
    fn flip(&self, j: usize) -> f64 {
        fclib_sign(j, self.dim)
    }

    /// The problem in hycon's signs (module docs): `S = D W D`, `r_h = -D q` and a Coulomb law
    /// per contact.
    fn hycon_form(&self) -> (DMatrix<f64>, Vec<f64>, Vec<Coulomb>) {
        let m = self.q.len();
        let s = DMatrix::from_fn(m, m, |i, j| self.flip(i) * self.w[(i, j)] * self.flip(j));
        let rh: Vec<f64> = (0..m).map(|j| -self.flip(j) * self.q[j]).collect();
        let laws: Vec<Coulomb> = (self.mu.iter())
            .map(|&mu| Coulomb::new(mu).expect("checked by new"))
            .collect();
        (s, rh, laws)
    }

    /// The solve of hycon's tractions `t`, in FCLIB's signs.
    fn solved(&self, t: &[f64], settled: bool, iterations: usize, sweeps: usize) -> LocalSolve {
        let r: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(j, v)| self.flip(j) * v)
            .collect();
        LocalSolve {
            u: self.velocity(&r),
            residual: self.natural_map_residual(&r),
            r,
            settled,
            iterations,
            sweeps,
        }
    }
}

/// The sign of component `j` of contacts of `dim` components between FCLIB's and hycon's
/// signs (module docs: `D`): `-1` on a normal, `1` on a tangent.
pub(crate) fn fclib_sign(j: usize, dim: usize) -> f64 {
    if j.is_multiple_of(dim) { -1.0 } else { 1.0 }
}

/// The closest point of the cone `|x_T| <= mu x_N` to `x` (normal first).
fn project_on_cone(x: &[f64], mu: f64) -> Vec<f64> {
    let (n, t) = (x[0], x[1..].iter().map(|v| v * v).sum::<f64>().sqrt());
    // the polar cone first: with mu = 0 a point (n < 0, 0) lies in both tests
    if mu * t <= -n {
        return vec![0.0; x.len()];
    }
    if t <= mu * n {
        return x.to_vec();
    }
    let n_cone = (n + mu * t) / (1.0 + mu * mu);
    let mut p = vec![n_cone; 1];
    p.extend(x[1..].iter().map(|v| mu * n_cone * v / t));
    p
}
