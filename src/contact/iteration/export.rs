//! The local problem of the last converged increment ([`ContactAnalysis::local_problem`];
//! docs/method.md, "The local problem"): the contact conditions linearized at the converged
//! iterate, as the fallback's conditions are (`fallback.rs`), in FCLIB's signs.

use super::fallback::PlateBorder;
use super::plate::Border;
use super::small_system::Row;
use super::{ContactAnalysis, DMatrix, NodeState, dot};
use crate::contact::local::{LocalContact, LocalExport, LocalProblem, fclib_sign};
use crate::error::{Error, Result};

/// What an increment converged from, kept for its local problem: the converged contact
/// displacement it started from (the origin of its slips), its load solve at the contact dofs
/// and the border of a force-controlled plate.
#[derive(Debug, Clone)]
pub(super) struct IncrementStart {
    pub(super) startc: Vec<f64>,
    pub(super) u0c: Vec<f64>,
    pub(super) border: Option<Border>,
}

impl ContactAnalysis {
    /// The local problem of the last converged increment, `u = W r + q` with a Coulomb cone
    /// per contact (docs/method.md, "The local problem"), with its converged reactions.
    ///
    /// The contacts are the fallback's candidates at the converged state (`fallback.rs`): the
    /// covered A nodes closed there or penetrating and their covered neighbours along A, so
    /// that every contact zone is bordered by open contacts. Each has `dim` components
    /// (normal first, then one per tangent of its frame): a frictionless pair's contacts keep
    /// their tangential rows (`mu = 0` makes their reactions vanish), and a tangent dropped by
    /// a symmetry plane has a decoupled row (`W_jj = W_nn` of its contact, no coupling, `q_j = 0`),
    /// which forces that component of the reaction to zero. `W` is hycon's `S` over those
    /// rows, and with a force-controlled plate `S` with the plate's translations condensed out
    /// (its stiffness positive definite over the force-controlled directions).
    ///
    /// After an increment the automatic cutback took in sub-increments, it is the last
    /// sub-increment's problem (its slips counted from the sub-increment's start).
    ///
    /// Takes `&mut self` because the flexibility may gain columns (lazy `F` under small
    /// kinematics); the converged state is not changed.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] before the first increment and after a failed one (the state is
    /// then the last converged increment's, but not the increment asked for last), when no A
    /// node is in or near contact, or under a force-controlled plate that holds a floating
    /// body (its stiffness singular over the force-controlled directions: the plate's balance
    /// is then a constraint on the reactions, which FCLIB's local problem cannot state).
    pub fn local_problem(&mut self) -> Result<LocalExport> {
        let invalid = |what: &str| Err(Error::InvalidInput(format!("local problem: {what}")));
        let Some(start) = self.driver.linearized.clone() else {
            return if self.driver.increment == 0 {
                invalid("no increment has converged yet")
            } else {
                invalid(
                    "the last increment failed: the analysis holds the last converged \
                     increment's state, but not the increment asked for",
                )
            };
        };
        let surfaces = self.surfaces.current.clone();
        let states: Vec<Vec<NodeState>> = (self.nodes.iter())
            .map(|v| v.iter().map(|d| d.state).collect())
            .collect();
        let uc = self.boundary.qc.clone();
        let chosen = self.candidates(&surfaces, &states, &uc, &uc);
        // every contact with its normal and kept tangential rows
        let rows: Vec<Vec<NodeState>> = (chosen.iter())
            .map(|c| {
                (c.iter())
                    .map(|&c| if c { NodeState::Stick } else { NodeState::Open })
                    .collect()
            })
            .collect();
        let laws = &self.surfaces.laws;
        let system = (self.boundary).build_system(&surfaces, laws, &rows, &uc, &start.startc);
        if system.unknowns.is_empty() {
            return invalid("no A node is in or near contact");
        }
        let s = (self.boundary).dense_matrix(&mut *self.bodies, &self.surfaces, &system)?;
        let r: Vec<f64> = (system.rows.iter().zip(&system.b))
            .map(|(row, b)| b - dot(row, &start.u0c))
            .collect();
        let (s, r) = match &start.border {
            None => (s, r),
            Some(border) => match PlateBorder::new(border, &system).condensed(&s, &r) {
                Some(condensed) => condensed,
                None => {
                    return invalid(
                        "the force-controlled plate holds a floating body (its stiffness is \
                         singular over the force-controlled directions): its balance is a \
                         constraint on the reactions, which the local problem cannot state",
                    );
                }
            },
        };
        self.fclib_form(&system.unknowns, &s, &r)
    }

    /// The local problem in FCLIB's signs from hycon's conditions `S t - r = rho` over
    /// `unknowns` (docs/method.md, "The local problem"): per contact `D = diag(-1, 1, ..)`,
    /// `W = D S D`, `q = -D r`, the reactions `D t` from the converged tractions; decoupled
    /// rows for dropped tangents.
    fn fclib_form(
        &self,
        unknowns: &[(usize, usize, Row)],
        s: &DMatrix<f64>,
        r: &[f64],
    ) -> Result<LocalExport> {
        let d = self.dim();
        let mut contacts: Vec<LocalContact> = Vec::new();
        // the FCLIB index of each unknown
        let mut index = Vec::with_capacity(unknowns.len());
        for &(p, k, row) in unknowns {
            if row == Row::Normal {
                contacts.push(LocalContact {
                    pair: p,
                    node: k,
                    id: self.external_a((p, k)),
                });
            }
            let c = contacts.len() - 1;
            index.push(match row {
                Row::Normal => c * d,
                Row::Tangent(i) => c * d + 1 + i,
            });
        }
        let m = contacts.len() * d;
        let sign = |a: usize| fclib_sign(a, d);
        let mut w = DMatrix::zeros(m, m);
        let mut q = vec![0.0; m];
        let mut kept = vec![false; m];
        for (i, &a) in index.iter().enumerate() {
            kept[a] = true;
            q[a] = -sign(a) * r[i];
            for (j, &b) in index.iter().enumerate() {
                w[(a, b)] = sign(a) * s[(i, j)] * sign(b);
            }
        }
        for a in (0..m).filter(|&a| !kept[a]) {
            // a tangent dropped by symmetry: decoupled, `u_j = W_nn r_j`, so `r_j = 0`
            let normal = a - a % d;
            w[(a, a)] = w[(normal, normal)];
        }
        let mut mu = Vec::with_capacity(contacts.len());
        let mut solution = vec![0.0; m];
        for (c, contact) in contacts.iter().enumerate() {
            let law = self.node_law(contact.pair, contact.node);
            // the cone's slope: the stick limit under a unit compression
            mu.push(law.stick_limit(-1.0));
            let traction = self.nodes[contact.pair][contact.node].traction;
            solution[c * d] = -traction.normal;
            for (i, v) in traction.tangential.components().iter().enumerate() {
                if kept[c * d + 1 + i] {
                    solution[c * d + 1 + i] = *v;
                }
            }
        }
        let problem = LocalProblem::new(d, w, q, mu)?;
        let residual = problem.natural_map_residual(&solution);
        Ok(LocalExport {
            problem,
            solution,
            contacts,
            increment: self.driver.increment,
            residual,
        })
    }
}
