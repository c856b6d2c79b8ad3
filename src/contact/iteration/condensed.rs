//! The paper's rules on a condensed problem (docs/method.md, "The local problem"): the
//! contact-set iteration of the analysis (docs/method.md, "The rules") run on the conditions
//! `S t - r = rho` of a local problem in hycon's signs, the solver of
//! [`LocalProblem::solve_rules`](crate::contact::local::LocalProblem::solve_rules).
//!
//! Each contact is open, stick, slip (with a direction) or frictionless (closed under
//! `mu = 0`). Every iteration solves the linear conditions of its states (the fallback's
//! semi-smooth Newton step, [`Linearized::step`]: open `t = 0`; closed `rho_n = 0`; stick
//! `rho_t = 0`; slip `ts = c tn`, `c` the law's slip coefficients of its direction;
//! frictionless `ts = 0`), then applies the rules to the solution: an open contact that
//! penetrates (`rho_n > 0`, FCLIB's `u_N < 0`) closes at rest (stick; frictionless under
//! `mu = 0`); a closed one in tension (`tn > 0`, FCLIB's `r_N < 0`) opens; stick beyond the
//! cone slips opposing its traction; slip whose slip `rho_t` turned against its direction
//! sticks, and otherwise its direction follows that slip at every iteration (the 3D
//! direction update; the analysis' [`closed_next`]). It stops when the states repeat, slip
//! directions to [`SAME_DIRECTION`](crate::contact::tangent::SAME_DIRECTION) (the solution
//! then satisfies every condition to that angle), and fails on a cycle or after
//! [`RULES_ITERATIONS`]. A contact alternating between stick and slip is locked in slip, one
//! alternating between open and closed locked open, by the analysis' own [`ActiveSet`]
//! (docs/method.md, "Locks and cycles"), and when the states repeat a locked contact must
//! hold its lock to the analysis' hair (`1e-4` of the gap scale, the largest normal `|r_n|`,
//! for a contact locked open that penetrates; of the slip scale, the largest `|r|`, for one
//! locked in slip that slides against its friction), or the solve is unsettled. Unlike the analysis it closes every penetrating
//! contact at once (the paper's rule: a local problem has no adjacency for closing by runs).
//!
//! On a face with friction the direction update is a fixed-point iteration on the slip
//! directions, which need not settle: it is why the analysis proposes its states from the
//! linearized conditions there (docs/method.md, "The solver order on a face"), and the
//! problems of `hycon_lab::local_problems` where contacts slip on faces show it.

use super::active_set::{
    ActiveSet, Commit, Locks, NodeFacts, Tolerances, closed_at_rest, closed_next,
};
use super::fallback::{Condition, Linearized, node_unknowns};
use super::{DMatrix, FrictionLaw, NodeState, Traction};

/// The rules' iterations at most.
const RULES_ITERATIONS: usize = 200;

/// The lock rounds (the analysis' default `lock_rounds`): a contact alternating between stick
/// and slip is locked in slip, one alternating between open and closed is locked open, as in
/// the analysis (docs/method.md, "Locks and cycles").
const LOCK_ROUNDS: usize = 3;

/// The rules' tolerances, relative: a contact opens when `tn > RULES_TOLERANCE tn_max`, a stick
/// contact slips beyond `(1 + RULES_TOLERANCE)` times its cone, a penetration counts beyond
/// `RULES_TOLERANCE` of the largest normal free term `|r_n|` (the gap scale), a reversed slip
/// beyond `RULES_TOLERANCE` of the largest `|r|` (the slip scale).
const RULES_TOLERANCE: f64 = 1e-12;

/// The rules' solution of the conditions.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RulesSolve {
    /// The tractions of the last iteration.
    pub(crate) t: Vec<f64>,
    /// Whether the states repeated (else a cycle or the cap stopped it).
    pub(crate) settled: bool,
    /// The iterations (linear solves).
    pub(crate) iterations: usize,
}

/// The paper's rules (module docs) on the conditions `S t - r = rho` of `laws.len()` contacts,
/// each its normal unknown followed by `tangents` tangential ones, from every contact open.
pub(crate) fn solve_by_rules(
    s: DMatrix<f64>,
    r: Vec<f64>,
    laws: &[&dyn FrictionLaw],
    tangents: usize,
) -> RulesSolve {
    // the scales of the gaps and of the slips: the largest normal and tangential free terms
    let largest = |normal: bool| {
        (r.iter().enumerate())
            .filter(|(j, _)| (j % (1 + tangents) == 0) == normal)
            .fold(0.0f64, |m, (_, v)| m.max(v.abs()))
    };
    let gap_scale = largest(true);
    let slip_scale = largest(false).max(gap_scale);
    let tolerances = Tolerances {
        gap: RULES_TOLERANCE * gap_scale,
        slip: RULES_TOLERANCE * slip_scale,
        tension: RULES_TOLERANCE,
        friction: RULES_TOLERANCE,
    };
    let (unknowns, laws) = node_unknowns(laws, tangents);
    let m = unknowns.len();
    let c = Linearized::new(&unknowns, &laws, |_, _| tangents, s, r);
    let open = vec![NodeState::Open; c.nodes.len()];
    let mut set = ActiveSet::new(vec![open], Locks::default(), LOCK_ROUNDS);
    let mut t = vec![0.0; m];
    for iteration in 1..=RULES_ITERATIONS {
        let states = &set.states()[0];
        t = match c.step(&conditions(&c, states, m)) {
            Some(t) => t,
            None => {
                return RulesSolve {
                    t,
                    settled: false,
                    iterations: iteration,
                };
            }
        };
        let rho = c.residual(&t);
        let tn_max = (c.nodes.iter()).fold(0.0f64, |a, n| a.max(t[n.normal].abs()));
        let next: Vec<NodeState> = (c.nodes.iter().zip(states).enumerate())
            .map(|(k, (node, &state))| {
                let facts = NodeFacts {
                    traction: Traction {
                        normal: t[node.normal],
                        tangential: node.tangential(&t),
                    },
                    gap: -rho[node.normal],
                    slip: node.trial(|j| rho[j]),
                    law: node.law,
                };
                match state {
                    NodeState::Open if facts.gap < -tolerances.gap && set.may_close((0, k)) => {
                        closed_at_rest(node.law)
                    }
                    _ => closed_next(state, &facts, &tolerances, tn_max, set.may_stick((0, k))),
                }
            })
            .collect();
        let next = vec![next];
        if set.changes(&next) == 0 {
            // a locked contact must hold its lock to its hair, as at the analysis' convergence
            let node = |k: usize| &c.nodes[k];
            let breach = set
                .edge_penetration(|(_, k)| (-rho[node(k).normal], gap_scale))
                .or_else(|| set.slip_reversal(|(_, k)| (node(k).trial(|j| rho[j]), slip_scale)));
            return RulesSolve {
                t,
                settled: breach.is_none(),
                iterations: iteration,
            };
        }
        if let Commit::Cycle { .. } = set.commit(next) {
            return RulesSolve {
                t,
                settled: false,
                iterations: iteration,
            };
        }
    }
    RulesSolve {
        t,
        settled: false,
        iterations: RULES_ITERATIONS,
    }
}

/// What each unknown takes in the linear solve of `states` (module docs).
fn conditions(c: &Linearized<'_>, states: &[NodeState], m: usize) -> Vec<Condition> {
    let mut out = vec![Condition::Zero; m];
    for (node, state) in c.nodes.iter().zip(states) {
        let i = node.normal;
        match *state {
            NodeState::Open => {}
            NodeState::Frictionless => out[i] = Condition::Row,
            NodeState::Stick => {
                out[i] = Condition::Row;
                node.tangent_unknowns()
                    .for_each(|(j, _)| out[j] = Condition::Row);
            }
            NodeState::Slip { direction } => {
                out[i] = Condition::Row;
                let coefficients = node.law.slip_coefficients(direction);
                for (j, ci) in node.tangent_unknowns() {
                    out[j] = Condition::Cone(i, coefficients.components()[ci]);
                }
            }
        }
    }
    out
}
