//! The fallback: when the paper's rules do not settle an increment, it starts again from the
//! states of the solution of the linearized contact conditions (docs/method.md, "The
//! fallback").
//!
//! Why the rules can fail: they move one way only from a slip node that slides with its
//! friction: it stays in slip. At the first all-stick iterate the stick shear of the linear
//! multipliers alternates in sign from node to node (the oscillation that shows at the Hertz
//! edge), many nodes exceed the cone at once and all of them turn to slip; a node whose
//! violation was only that oscillation then slides consistently and never returns, while its
//! neighbour alternates between stick (outside the cone) and slip (sliding against its
//! friction). The cycle guard locks the neighbour in slip and the increment fails with a slip
//! reversal; the same happens to the normal states at the edge of a zone (a node locked open
//! that penetrates).
//!
//! When the rules fail for such a reason (`Failure::fallback_may_settle`, `driver.rs`), the
//! increment starts again from the states of the solution of the same conditions, linearized
//! at the start of the increment, over the candidate nodes (closed at the start, or
//! penetrating under the load alone, and their neighbours along A, from the geometry's
//! `Adjacency`): with every candidate's normal and tangent rows, `S t - r = rho`
//! (`rho_n = n . R_C` the weighted gap with its sign reversed, `rho_t` the weighted slip),
//! solve `tn <= 0`, `rho_n <= 0`, `tn rho_n = 0`, `|ts| <= mu |tn|`, `ts` opposing `rho_t`
//! where it is on the cone and `rho_t = 0` inside ([`Linearized`]). A thousand sweeps of
//! projected block Gauss-Seidel over the nodes (for a fixed `|tn|` the problem is the minimum
//! of a convex quadratic over the cone, so each sweep lowers it; the friction bound follows
//! `tn`) give a start from which the semi-smooth Newton method (primal-dual active set, the
//! cone through `FrictionLaw::project` and `trial_slip`) solves the conditions exactly in a
//! few dense solves; where it does not settle, Gauss-Seidel goes on to convergence
//! (Gauss-Seidel alone needs up to `cond(S)` sweeps, and with a large `mu` may not converge at
//! all). Its states (closed where `tn < 0`, slip where `|ts|` is on the cone, opposing `ts`:
//! the active set's `linearized_state`) start the paper's iteration again, which then settles
//! in a few iterations and checks every condition as usual. The paper's rules keep their
//! results wherever they settle: the fallback runs only after they failed. (Its measured
//! effect on `hycon bench presses` is in the CHANGELOG, 0.7.0 and 0.8.1.)
//!
//! On a face with friction the same solution, linearized at every iterate instead of the
//! start ([`ContactAnalysis::linearized_states`]), proposes the states of every iteration
//! (the driver's `Proposer::Linearized`; docs/method.md, "The solver order on a face"): the
//! slip directions are then the trial tractions' at every iterate.
//!
//! Under a force-controlled rigid plate the conditions are bordered by the plate's
//! force-controlled translations `U` and its force balance ([`PlateBorder`]; docs/method.md,
//! "Floating bodies and the rigid plate"), as the iteration's small system is.

use super::driver::Attempt;
use super::small_system::{Row, SmallSystem};
use super::{
    Border, ContactAnalysis, ContactSurface, DMatrix, DVector, FrictionLaw, LINEARIZED_CONE,
    NodeState, Result, Tangential, closed_at_rest, column, dot, linearized_state, plate,
};
use crate::contact::tangent::{MAX_TANGENTS, SAME_DIRECTION};
use faer::linalg::solvers::Solve;
use plate::dot_dense;

/// The work of the fallback's projected Gauss-Seidel, at most: `sweeps m^2 <= FALLBACK_WORK`
/// for `m` unknowns (a few seconds). Gauss-Seidel contracts by about `1 - 1/cond(S)` per
/// sweep, and with one body 1,000 times stiffer than the other `cond(S)` reaches `5e6`: press
/// 1076 of seed 4 of `hycon bench presses --count 2000` (`m = 38`) needs 826,000 sweeps.
/// 0.7.0 stopped after 20,000, with the tractions still changing by `4e-6` of the largest per
/// sweep, and the states of that point were ones the paper's iteration left again: every
/// increment and sub-increment through the first touch failed, while the converged solution's
/// states settle the whole press in one increment.
const FALLBACK_WORK: f64 = 4e9;

/// The sweeps stop early when the largest change has not fallen over this many sweeps: the
/// projected iteration does not converge (with a large `mu` the friction bounds that follow
/// `tn` can keep it cycling), and more sweeps would not help.
const FALLBACK_WINDOW: usize = 20_000;

/// Gauss-Seidel's tractions that did not settle are taken as they are when they satisfy the
/// conditions to this ([`Linearized::breach`]: sweeps at the round-off floor of a rotated
/// model), else the Newton method with turning directions is tried
/// ([`Linearized::solution`]).
const GAUSS_SEIDEL_BREACH: f64 = 1e-6;

/// Projected Gauss-Seidel sweeps before the semi-smooth Newton method starts from their
/// tractions.
const START_SWEEPS: usize = 1000;

/// Projected Gauss-Seidel sweeps before the local solver's first semi-smooth Newton attempt,
/// and the steps that attempt may take ([`Linearized::warm_solution`]).
const WARM_SWEEPS: usize = 10;
const WARM_STEPS: usize = 8;

/// The sweeps stop when no traction changes by more than this, relative to the largest.
const FALLBACK_TOLERANCE: f64 = 1e-12;

impl ContactAnalysis {
    /// The fallback's start states for `attempt` (module docs): the candidates' conditions
    /// linearized at the start of the increment, solved ([`Linearized::solution`]).
    pub(super) fn fallback_states(&mut self, attempt: &Attempt<'_>) -> Result<Vec<Vec<NodeState>>> {
        let surfaces = self.surfaces.current.clone();
        let states: Vec<Vec<NodeState>> = (self.nodes.iter())
            .map(|v| v.iter().map(|d| d.state).collect())
            .collect();
        let startc = &attempt.startc;
        let at = Linearization {
            uc: startc,
            probe: attempt.u0c,
            startc,
            u0c: attempt.u0c,
            border: attempt.border,
        };
        self.linearized_states(&surfaces, &states, at)
    }

    /// The states of the solution of the contact conditions linearized at the iterate `at.uc`
    /// (its geometry `surfaces`), over the candidate nodes: closed in `states`, or penetrating
    /// at `at.probe` (by the gap linearized at `at.uc`), and their covered neighbours along A
    /// (module docs). The fallback linearizes at the start of the increment and probes with
    /// the load solve; the iteration on a face (the driver's `Proposer::Linearized`) at every
    /// iterate, probing with the iterate itself.
    pub(super) fn linearized_states(
        &mut self,
        surfaces: &[ContactSurface],
        states: &[Vec<NodeState>],
        at: Linearization<'_>,
    ) -> Result<Vec<Vec<NodeState>>> {
        let Linearization {
            uc,
            probe,
            startc,
            u0c,
            border,
        } = at;
        let closed_state = |p: usize, k: usize| closed_at_rest(self.node_law(p, k));
        let candidates: Vec<Vec<NodeState>> = (self.candidates(surfaces, states, uc, probe))
            .iter()
            .enumerate()
            .map(|(p, chosen)| {
                (chosen.iter().enumerate())
                    .map(|(k, &c)| {
                        if c {
                            closed_state(p, k)
                        } else {
                            NodeState::Open
                        }
                    })
                    .collect()
            })
            .collect();
        let laws = &self.surfaces.laws;
        let system = (self.boundary).build_system(surfaces, laws, &candidates, uc, startc);
        let s = (self.boundary).dense_matrix(&mut *self.bodies, &self.surfaces, &system)?;
        let r: Vec<f64> = system
            .rows
            .iter()
            .zip(&system.b)
            .map(|(row, b)| b - dot(row, u0c))
            .collect();
        let laws: Vec<&dyn FrictionLaw> = (system.unknowns.iter())
            .map(|&(p, k, _)| self.node_law(p, k))
            .collect();
        let frame_tangents = |p: usize, k: usize| surfaces[p].nodes[k].frame.tangents().len();
        let mut linearized = Linearized::new(&system.unknowns, &laws, frame_tangents, s, r);
        linearized.border = border.map(|b| PlateBorder::new(b, &system));
        let t = linearized.solution();
        let tn_max = (linearized.nodes.iter()).fold(0.0f64, |m, node| m.max(t[node.normal].abs()));
        let mut out: Vec<Vec<NodeState>> = candidates
            .iter()
            .map(|s| vec![NodeState::Open; s.len()])
            .collect();
        for node in &linearized.nodes {
            let (p, k, _) = system.unknowns[node.normal];
            let ts = (node.tangents > 0).then(|| node.tangential(&t));
            out[p][k] =
                linearized_state(t[node.normal], ts, node.law, -FALLBACK_TOLERANCE * tn_max);
        }
        Ok(out)
    }

    /// The candidate nodes of the linearized conditions, per pair, per A node: covered, and
    /// closed in `states` or penetrating at `probe` (by the gap linearized at the iterate
    /// `uc`, geometry `surfaces`), or a neighbour along A of such a node (module docs).
    pub(super) fn candidates(
        &self,
        surfaces: &[ContactSurface],
        states: &[Vec<NodeState>],
        uc: &[f64],
        probe: &[f64],
    ) -> Vec<Vec<bool>> {
        let mut candidates = Vec::with_capacity(surfaces.len());
        for (p, surface) in surfaces.iter().enumerate() {
            let nodes = &surface.nodes;
            let penetrates: Vec<bool> = nodes
                .iter()
                .enumerate()
                .map(|(k, node)| {
                    if states[p][k] != NodeState::Open {
                        return true;
                    }
                    if !node.is_covered() {
                        return false;
                    }
                    let row = self.boundary.directed(&node.coupling, &node.frame.normal());
                    let rg = node.gap.dot(&node.frame.normal());
                    rg + dot(&row, probe) - dot(&row, uc) > 0.0
                })
                .collect();
            let adjacency = self.surfaces.geometries[p].adjacency();
            let candidate = |k: usize| {
                nodes[k].is_covered()
                    && (penetrates[k] || adjacency.neighbours(k).iter().any(|&j| penetrates[j]))
            };
            candidates.push((0..nodes.len()).map(candidate).collect());
        }
        candidates
    }
}

/// The conditions `S t - r = rho` of `laws.len()` nodes, each with its normal unknown followed
/// by `tangents` tangential ones (`S` symmetric), solved as the fallback solves them
/// ([`Linearized::solution`]) but from a shorter start first ([`Linearized::warm_solution`]).
/// The solver of [`crate::contact::local`].
pub(crate) fn solve_conditions(
    s: DMatrix<f64>,
    r: Vec<f64>,
    laws: &[&dyn FrictionLaw],
    tangents: usize,
) -> ConditionsSolve {
    let (unknowns, laws) = node_unknowns(laws, tangents);
    Linearized::new(&unknowns, &laws, |_, _| tangents, s, r).warm_solution()
}

/// The unknowns `(pair, node, row)` of some nodes and the friction law of each.
pub(super) type NodeUnknowns<'a> = (Vec<(usize, usize, Row)>, Vec<&'a dyn FrictionLaw>);

/// The unknowns of `laws.len()` nodes of one pair, each its normal followed by `tangents`
/// tangential ones, and the law of each unknown.
pub(super) fn node_unknowns<'a>(laws: &[&'a dyn FrictionLaw], tangents: usize) -> NodeUnknowns<'a> {
    let per_node = 1 + tangents;
    let unknowns: Vec<(usize, usize, Row)> = (0..laws.len())
        .flat_map(|k| {
            std::iter::once(Row::Normal)
                .chain((0..tangents).map(Row::Tangent))
                .map(move |row| (0, k, row))
        })
        .collect();
    let laws = (0..unknowns.len()).map(|i| laws[i / per_node]).collect();
    (unknowns, laws)
}

/// The fallback's solution of the conditions ([`Linearized::unbordered_solution`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ConditionsSolve {
    /// The tractions.
    pub(crate) t: Vec<f64>,
    /// Whether the semi-smooth Newton method settled (else `t` is projected Gauss-Seidel's
    /// last sweep).
    pub(crate) settled: bool,
    /// The semi-smooth Newton steps taken.
    pub(crate) steps: usize,
    /// The projected Gauss-Seidel sweeps taken (the start's and any after the Newton steps).
    pub(crate) sweeps: usize,
}

/// Where [`ContactAnalysis::linearized_states`] linearizes the contact conditions: the
/// iterate `uc` (the geometry's), the displacement `probe` at which open nodes are judged
/// penetrating, the increment's start `startc` (the slips' origin) and the load solve `u0c`,
/// all at the contact dofs, and the border of a force-controlled plate (`u0c` holds its
/// force-controlled translations at zero: they are unknowns, [`PlateBorder`]).
#[derive(Clone, Copy)]
pub(super) struct Linearization<'a> {
    pub(super) uc: &'a [f64],
    pub(super) probe: &'a [f64],
    pub(super) startc: &'a [f64],
    pub(super) u0c: &'a [f64],
    pub(super) border: Option<&'a Border>,
}

/// The fallback's linearized conditions `S t - r = rho` (module docs), node by node; with a
/// force-controlled plate, `S t + G U - r = rho` and the plate's balance ([`PlateBorder`]).
pub(super) struct Linearized<'a> {
    s: DMatrix<f64>,
    r: Vec<f64>,
    /// The candidate nodes.
    pub(super) nodes: Vec<Candidate<'a>>,
    border: Option<PlateBorder>,
}

/// The force-controlled translations `U` of a plate as unknowns of the linearized conditions
/// (docs/method.md, "Floating bodies and the rigid plate"): with `w_d` the contact dofs'
/// response to a unit translation in direction `d`, the contact residuals gain
/// `G U` (`G_ia = row_i . w_d`), and the plate's balance `D U - H^T t = F - F0`
/// (`H_ja = col_j . w_d`, `D` the plate's stiffness over the force-controlled directions)
/// joins the conditions, as in the iteration's bordered small system (`Border::fill`). `D`
/// is zero for a body held only by the plate and by contact: the balance is then a
/// constraint on the tractions with `U` its multiplier, so the semi-smooth Newton method
/// solves for `t` and `U` together.
pub(super) struct PlateBorder {
    g: DMatrix<f64>,
    h: DMatrix<f64>,
    d: DMatrix<f64>,
    rhs: Vec<f64>,
    /// The bodies' stiffness scale, against which `D` counts as singular.
    stiffness_scale: f64,
}

impl PlateBorder {
    /// The border of `system`'s conditions for the plate directions of `border`.
    pub(super) fn new(border: &Border, system: &SmallSystem) -> Self {
        let directions = &border.directions;
        let k = directions.len();
        let response = |sparse: &[super::Sparse]| {
            DMatrix::from_fn(sparse.len(), k, |i, a| {
                dot(&sparse[i], &border.response[directions[a]])
            })
        };
        PlateBorder {
            g: response(&system.rows),
            h: response(&system.cols),
            d: DMatrix::from_fn(k, k, |a, c| {
                border.stiffness[(directions[a], directions[c])]
            }),
            rhs: border.rhs.clone(),
            stiffness_scale: border.stiffness_scale,
        }
    }

    fn len(&self) -> usize {
        self.rhs.len()
    }

    /// The conditions with `U` condensed out where `D` is positive definite (not small
    /// against the bodies' stiffness): `U = D^-1 (F - F0 + H^T t)`, so
    /// `S' = S + H D^-T G^T` (in the columns' convention of [`Linearized::residual`]) and
    /// `r' = r - G D^-1 (F - F0)`. `None` for a floating body (`D` singular).
    pub(super) fn condensed(
        &self,
        s: &DMatrix<f64>,
        r: &[f64],
    ) -> Option<(DMatrix<f64>, Vec<f64>)> {
        let smallest = self.d.clone().symmetric_eigen().eigenvalues.min();
        if smallest <= 1e-10 * self.stiffness_scale {
            return None;
        }
        let inverse = self.d.clone().try_inverse()?;
        let s = s + &self.h * inverse.transpose() * self.g.transpose();
        let shift = &self.g * &inverse * DVector::from_column_slice(&self.rhs);
        let r = r.iter().zip(shift.iter()).map(|(a, b)| a - b).collect();
        Some((s, r))
    }

    /// `U = D^-1 (F - F0 + H^T t)`.
    fn motion(&self, t: &[f64]) -> Option<DVector<f64>> {
        let ht = self.h.transpose() * DVector::from_column_slice(t);
        let rhs = DVector::from_column_slice(&self.rhs) + ht;
        self.d.clone().lu().solve(&rhs)
    }
}

/// A candidate node of the linearized conditions: its unknowns and its friction law.
#[derive(Debug, Clone, Copy)]
pub(super) struct Candidate<'a> {
    /// The index of its normal unknown.
    pub(super) normal: usize,
    /// How many tangential unknowns follow it (0 without friction, one per kept tangent).
    pub(super) tangents: usize,
    /// The frame tangent `s_i` of each tangential unknown (`i` of `Row::Tangent(i)`: a
    /// tangent dropped by symmetry has no unknown).
    components: [usize; MAX_TANGENTS],
    /// How many tangents its frame has (the length of its tangential vectors).
    frame_tangents: usize,
    pub(super) law: &'a dyn FrictionLaw,
}

impl Candidate<'_> {
    /// Its tangential unknowns `j` with the frame tangent `i` of each.
    pub(super) fn tangent_unknowns(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        (self.normal + 1..self.normal + 1 + self.tangents).zip(self.components)
    }

    /// The scale of its tangential trial tractions, `sigma = sum_i S_(t_i t_i)`, the trace
    /// of its tangential block of `S` (at least the block's largest eigenvalue; in the plane
    /// `S_tt`). One scale for every tangent makes the cone condition the fixed point of the
    /// semi-smooth Newton method: on the cone `ts` is parallel to the trial
    /// `ts - rho_t / sigma`, so it opposes `rho_t` (with a scale per tangent it would oppose
    /// `rho_t` scaled component by component).
    fn tangent_scale(&self, s: &DMatrix<f64>) -> f64 {
        self.tangent_unknowns().map(|(j, _)| s[(j, j)]).sum()
    }

    /// On a face (both tangents kept), the Newton linearization of its slip condition
    /// ([`TurningCone`]) at the tractions `t` with normal `tn`, trial tangential traction `at`,
    /// slip coefficients `c` and tangent scale `sigma`, into `conditions`.
    fn turning(
        &self,
        tn: f64,
        at: Tangential,
        c: Tangential,
        sigma: f64,
        conditions: &mut [Condition],
    ) {
        let (mu, size) = (c.norm(), at.norm());
        let q = at.scaled(1.0 / size);
        let first = self.normal + 1;
        for (j, cj) in self.tangent_unknowns() {
            let mut w = [0.0; MAX_TANGENTS];
            for (k, ck) in self.tangent_unknowns() {
                let delta = if j == k { 1.0 } else { 0.0 };
                let (qj, qk) = (q.components()[cj], q.components()[ck]);
                w[k - first] = mu * tn * (delta - qj * qk) / size;
            }
            conditions[j] = Condition::TurningCone(TurningCone {
                normal: self.normal,
                c: c.components()[cj],
                first,
                w,
                sigma,
            });
        }
    }

    /// Its tangential traction in `t`.
    pub(super) fn tangential(&self, t: &[f64]) -> Tangential {
        self.trial(|j| t[j])
    }

    /// The tangential vector of `value` over its tangential unknowns, one component per
    /// frame tangent (zero along a dropped one).
    pub(super) fn trial(&self, value: impl Fn(usize) -> f64) -> Tangential {
        let mut v = Tangential::zero(self.frame_tangents);
        for (j, i) in self.tangent_unknowns() {
            v.components_mut()[i] = value(j);
        }
        v
    }
}

/// What a semi-smooth Newton step ([`Linearized::active_set`]) takes for an unknown: its own
/// row of `S t = r` (`rho = 0`: a closed normal, a sticking tangent), zero (open), or the
/// tangential traction on the cone (`ts_i = c_i tn`, `c` the law's slip coefficients, with
/// the index of the node's normal unknown); a plate's translation takes its balance
/// ([`PlateBorder`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Condition {
    Row,
    Zero,
    Cone(usize, f64),
    TurningCone(TurningCone),
    Balance,
}

/// The Newton linearization of a face node's slip condition (two tangential unknowns):
/// `ts = c(at) tn` with `c = -mu at / |at|` turning with the trial traction `at = ts - rho_t /
/// sigma`, so that the direction converges quadratically with the tractions (a direction held
/// from the last step, as [`Condition::Cone`] does in the plane, converges linearly at best,
/// and on a face of 20 slipping nodes it wandered for the whole step budget:
/// `solid_randomized` seed 1 round 106). Row `j` of a node's tangential unknowns:
/// `dts_j - c_j dtn + sum_k w_k d(at_k) = -(ts_j - c_j tn)`, with
/// `w_k = mu tn (delta_jk - q_j q_k) / |at|`, `q = at / |at|` and `d(at_k) = dt_k - (S_k dt +
/// G_k dU) / sigma`; for `t + dt` it reads `ts_j - c_j tn + sum_k w_k (t_k - (S_k t + G_k U) /
/// sigma) = -sum_k w_k r_k / sigma` (`P(q) at = 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct TurningCone {
    /// The node's normal unknown.
    normal: usize,
    /// `c_j`.
    c: f64,
    /// The node's first tangential unknown (they follow each other).
    first: usize,
    /// `w_k` per tangential unknown of the node.
    w: [f64; MAX_TANGENTS],
    /// The node's tangent scale ([`Candidate::tangent_scale`]).
    sigma: f64,
}

/// A step's turning slip coefficients ([`TurningCone`]) that agree with the last's to this,
/// relative to their size, make the same choice: the Newton steps converge quadratically down
/// to round-off, whose floor was `1e-11` to `2e-10` in `solid_randomized` seed 1 round 106 in
/// other units (with [`SAME_DIRECTION`] they never stopped); `1e-9` of a slip across its
/// direction is far below the slip tolerance.
const TURNING_DIRECTION: f64 = 1e-9;

/// Whether a step makes the same choice as the last: the same kind of condition per unknown,
/// and on the cone slip coefficients equal to [`SAME_DIRECTION`] of their size
/// ([`TURNING_DIRECTION`] for turning ones). In the plane
/// the coefficients are exactly `+mu` or `-mu`, so the choice is the same or not; on a face
/// (two tangents) the direction of the slip turns continuously from step to step, and a
/// solution of conditions whose directions agree to round-off satisfies them to round-off.
fn same_conditions(a: &[Condition], b: &[Condition]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| match (*x, *y) {
            (Condition::Cone(i, c), Condition::Cone(j, d)) => {
                i == j && (c - d).abs() <= SAME_DIRECTION * (c.abs() + d.abs())
            }
            (Condition::TurningCone(a), Condition::TurningCone(b)) => {
                a.normal == b.normal
                    && (a.c - b.c).abs() <= TURNING_DIRECTION * (a.c.abs() + b.c.abs())
            }
            _ => x == y,
        })
}

/// The semi-smooth Newton steps of the fallback, at most.
const ACTIVE_SET_STEPS: usize = 100;

impl<'a> Linearized<'a> {
    /// The conditions over `unknowns` (a node's tangential unknowns, one per kept tangent,
    /// follow its normal one), `laws` per unknown, `frame_tangents(p, k)` the number of
    /// tangents of node `k` of pair `p`.
    pub(super) fn new(
        unknowns: &[(usize, usize, Row)],
        laws: &[&'a dyn FrictionLaw],
        frame_tangents: impl Fn(usize, usize) -> usize,
        s: DMatrix<f64>,
        r: Vec<f64>,
    ) -> Self {
        let nodes = (0..unknowns.len())
            .filter(|&i| unknowns[i].2 == Row::Normal)
            .map(|i| {
                let (p, k, _) = unknowns[i];
                let mut node = Candidate {
                    normal: i,
                    tangents: 0,
                    components: [0; MAX_TANGENTS],
                    frame_tangents: frame_tangents(p, k),
                    law: laws[i],
                };
                for u in unknowns[i + 1..].iter() {
                    match *u {
                        (q, l, Row::Tangent(c)) if (q, l) == (p, k) => {
                            node.components[node.tangents] = c;
                            node.tangents += 1;
                        }
                        _ => break,
                    }
                }
                node
            })
            .collect();
        Self {
            s,
            r,
            nodes,
            border: None,
        }
    }

    /// The solution: a rough start by projected Gauss-Seidel ([`START_SWEEPS`]), then exact
    /// by the semi-smooth Newton method; where that does not settle, Gauss-Seidel on to
    /// convergence (within [`FALLBACK_WORK`]); where that does not settle either (with the
    /// friction bounds following `tn` the sweeps can cycle, in one order of the nodes and not
    /// in another), the Newton method again from the start with a face node's slip direction
    /// linearized too ([`TurningCone`]), and Gauss-Seidel's last tractions if that fails.
    /// (Not the turning directions first: where the held ones settle, at a zero increment
    /// whose slip nodes sit on the cone with no slip, the turning ones settled on stick or
    /// slip by round-off from iterate to iterate, and the contact set cycled in 3 of
    /// `solid_randomized`'s first 150 rounds of seed 1.)
    fn solution(&self) -> Vec<f64> {
        if let Some(border) = &self.border {
            return self.bordered_solution(border);
        }
        self.unbordered_solution().t
    }

    /// [`solution`](Self::solution) without a plate border, with whether the semi-smooth
    /// Newton method settled (else the tractions are projected Gauss-Seidel's last sweep) and
    /// the steps and sweeps it took.
    fn unbordered_solution(&self) -> ConditionsSolve {
        let m = self.r.len();
        let (start, sweeps, _) = self.projected(vec![0.0; m], START_SWEEPS);
        let (outcome, steps) = self.counted_active_set(start.clone(), ACTIVE_SET_STEPS, false);
        if let Some(t) = outcome {
            return ConditionsSolve {
                t,
                settled: true,
                steps,
                sweeps,
            };
        }
        let more = (FALLBACK_WORK / (m * m).max(1) as f64) as usize;
        let (t, after, settled) = self.projected(start.clone(), more.max(FALLBACK_WINDOW));
        let sweeps = sweeps + after;
        if settled || !self.on_a_face() || self.breach(&t) <= GAUSS_SEIDEL_BREACH {
            return ConditionsSolve {
                t,
                settled,
                steps,
                sweeps,
            };
        }
        let (turned, more_steps) = self.counted_active_set(start, ACTIVE_SET_STEPS, true);
        ConditionsSolve {
            settled: turned.is_some(),
            t: turned.unwrap_or(t),
            steps: steps + more_steps,
            sweeps,
        }
    }

    /// The local solver's order ([`solve_conditions`]): the semi-smooth Newton method with
    /// the slip directions linearized ([`TurningCone`]) from a warm start of [`WARM_SWEEPS`]
    /// projected sweeps (as Siconos starts its Newton method from a few extragradient
    /// iterations), within [`WARM_STEPS`]; where it does not settle there, the fallback's
    /// order ([`unbordered_solution`](Self::unbordered_solution)). The fallback itself keeps
    /// its long start and its held directions first: it runs once an increment has failed,
    /// where a robust start matters more than its sweeps.
    fn warm_solution(&self) -> ConditionsSolve {
        let m = self.r.len();
        let (warm, sweeps, _) = self.projected(vec![0.0; m], WARM_SWEEPS);
        match self.counted_active_set(warm, WARM_STEPS, true) {
            (Some(t), steps) => ConditionsSolve {
                t,
                settled: true,
                steps,
                sweeps,
            },
            (None, steps) => {
                let full = self.unbordered_solution();
                ConditionsSolve {
                    steps: steps + full.steps,
                    sweeps: sweeps + full.sweeps,
                    ..full
                }
            }
        }
    }

    /// Whether a candidate has two tangential unknowns (a face node with both tangents kept).
    fn on_a_face(&self) -> bool {
        self.nodes.iter().any(|n| n.tangents == MAX_TANGENTS)
    }

    /// How far the tractions `t` are from satisfying the conditions, node by node, each in
    /// its own units: tractions relative to the largest `|t|` (`tn <= 0`, `|ts| <= mu |tn|`),
    /// residuals relative to the largest `|rho|` (`rho_n <= 0`, `rho_n = 0` where `tn < 0`,
    /// `rho_t = 0` inside the cone, on it `rho_t` opposing `ts` and parallel to it); 0 for
    /// an exact solution, unchanged under a change of units.
    fn breach(&self, t: &[f64]) -> f64 {
        let rho = self.residual(t);
        let largest = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        let relative = |v: f64, scale: f64| if scale > 0.0 { v / scale } else { 0.0 };
        let (t_max, rho_max) = (largest(&t[..rho.len()]), largest(&rho));
        let mut worst = 0.0f64;
        for node in &self.nodes {
            let i = node.normal;
            worst = worst
                .max(relative(t[i], t_max))
                .max(relative(rho[i], rho_max));
            if t[i] < 0.0 {
                worst = worst.max(relative(rho[i].abs(), rho_max));
            }
            if node.tangents == 0 {
                continue;
            }
            let (ts, rho_t) = (node.tangential(t), node.tangential(&rho));
            let limit = node.law.stick_limit(t[i]);
            worst = worst.max(relative(ts.norm() - limit, t_max));
            let off = if ts.norm() < (1.0 - LINEARIZED_CONE) * limit || ts.norm() == 0.0 {
                rho_t.norm()
            } else {
                // on the cone: `rho_t = -a ts / |ts|` with `a >= 0`
                let q = ts.scaled(1.0 / ts.norm());
                let a = -q.dot(&rho_t);
                (rho_t - q.scaled(-a)).norm() + (-a).max(0.0)
            };
            worst = worst.max(relative(off, rho_max));
        }
        worst
    }

    /// With a plate border: the contact tractions `t` and the plate's translations `U`
    /// together, by the semi-smooth Newton method from the solution with every candidate
    /// closed and sticking; where that does not settle, the condensed conditions'
    /// ([`PlateBorder::condensed`]) solution, or for a floating body that start.
    fn bordered_solution(&self, border: &PlateBorder) -> Vec<f64> {
        let m = self.r.len();
        let mut all = vec![Condition::Row; m];
        all.resize(m + border.len(), Condition::Balance);
        let Some(start) = self.step(&all) else {
            return vec![0.0; m + border.len()];
        };
        if let Some(x) = self.active_set(start.clone(), false) {
            return x;
        }
        let condensed = border.condensed(&self.s, &self.r).map(|(s, r)| Linearized {
            s,
            r,
            nodes: self.nodes.clone(),
            border: None,
        });
        condensed
            .and_then(|c| {
                let t = c.solution();
                let u = border.motion(&t)?;
                Some(t.into_iter().chain(u.iter().copied()).collect())
            })
            .unwrap_or(start)
    }

    /// `rho = S t - r` over the contact unknowns (`S t + G U - r` with a plate border, `x`
    /// then `t` followed by `U`).
    pub(super) fn residual(&self, x: &[f64]) -> Vec<f64> {
        let m = self.r.len();
        (0..m)
            .map(|i| {
                let rho = dot_dense(column(&self.s, i), x) - self.r[i];
                match &self.border {
                    None => rho,
                    Some(b) => rho + dot_dense(b.g.row(i).transpose().as_slice(), &x[m..]),
                }
            })
            .collect()
    }

    /// Projected block Gauss-Seidel from `t`: per node, the normal traction
    /// `tn <- min(0, tn - rho_n / S_nn)`, then the tangential ones
    /// `ts <- P(ts - rho_t / sigma)`, `P` the law's closest point of the cone
    /// ([`Candidate::tangent_scale`]: in the plane `sigma = S_tt`;
    /// [`FrictionLaw::project`]: in the plane the clamp to `[-mu |tn|, mu |tn|]`), until no traction changes by more
    /// than [`FALLBACK_TOLERANCE`] of the largest, within `sweeps`, or until a window of
    /// [`FALLBACK_WINDOW`] sweeps brings the change no lower. `S` is symmetric positive
    /// definite here (every column is its row).
    /// Returns the tractions, the sweeps taken and whether they settled (no traction
    /// changing by more than [`FALLBACK_TOLERANCE`] of the largest).
    fn projected(&self, mut t: Vec<f64>, sweeps: usize) -> (Vec<f64>, usize, bool) {
        let s = &self.s;
        let mut taken = 0;
        let mut rho = self.residual(&t);
        let update = |t: &mut [f64], rho: &mut [f64], i: usize, value: f64| {
            let change = value - t[i];
            if change != 0.0 {
                for (x, &c) in rho.iter_mut().zip(column(s, i)) {
                    *x += c * change;
                }
                t[i] = value;
            }
            change.abs()
        };
        // the relative change at the last window's end
        let mut last_window = f64::INFINITY;
        for sweep in 1..=sweeps {
            taken = sweep;
            let mut largest_change = 0.0f64;
            for node in &self.nodes {
                let i = node.normal;
                let tn = (t[i] - rho[i] / s[(i, i)]).min(0.0);
                largest_change = largest_change.max(update(&mut t, &mut rho, i, tn));
                if node.tangents > 0 {
                    let sigma = node.tangent_scale(s);
                    let trial = node.trial(|j| t[j] - rho[j] / sigma);
                    let ts = node.law.project(t[i], trial);
                    for (j, c) in node.tangent_unknowns() {
                        let v = ts.components()[c];
                        largest_change = largest_change.max(update(&mut t, &mut rho, j, v));
                    }
                }
            }
            let largest = t.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let relative = largest_change / largest;
            if largest_change <= FALLBACK_TOLERANCE * largest {
                return (t, sweep, true);
            }
            if sweep % FALLBACK_WINDOW == 0 {
                if relative >= last_window {
                    break;
                }
                last_window = relative;
            }
        }
        (t, taken, false)
    }

    /// The semi-smooth Newton method (the primal-dual active set method of Hüeber, Stadler
    /// and Wohlmuth, 2008) from `t`: per node, with `an = tn - rho_n / S_nn` and
    /// `at = ts - rho_t / sigma` ([`Candidate::tangent_scale`]), the node is closed where
    /// `an < 0` (then `rho_n = 0`, else `tn = 0` and `ts = 0`), and a closed node sticks
    /// where `|at| < mu |an|` (then `rho_t = 0`) and slips otherwise (`ts = c tn`, `c` the
    /// law's slip coefficients for the slip `at` opposes: [`FrictionLaw::trial_slip`]; in
    /// the plane `ts = mu |tn|` with the sign of `at`). Each step
    /// solves those linear conditions; the method stops when a step's solution makes the
    /// same choice again, which it then satisfies exactly. With `turning`, a face node's slip
    /// condition is linearized in its direction too ([`TurningCone`]), and the method stops
    /// when the directions agree to [`TURNING_DIRECTION`]. `None` when it does not settle
    /// within [`ACTIVE_SET_STEPS`] or a step's matrix is singular.
    fn active_set(&self, t: Vec<f64>, turning: bool) -> Option<Vec<f64>> {
        self.counted_active_set(t, ACTIVE_SET_STEPS, turning).0
    }

    /// [`active_set`](Self::active_set) within `max_steps`, with the steps it took (the
    /// linear solves).
    fn counted_active_set(
        &self,
        mut t: Vec<f64>,
        max_steps: usize,
        turning: bool,
    ) -> (Option<Vec<f64>>, usize) {
        let (s, m) = (&self.s, self.r.len());
        let k = self.border.as_ref().map_or(0, PlateBorder::len);
        let mut last: Vec<Condition> = Vec::new();
        for steps in 0..max_steps {
            let rho = self.residual(&t);
            let mut conditions = vec![Condition::Zero; m];
            conditions.resize(m + k, Condition::Balance);
            for node in &self.nodes {
                let i = node.normal;
                let an = t[i] - rho[i] / s[(i, i)];
                if an >= 0.0 {
                    continue;
                }
                conditions[i] = Condition::Row;
                if node.tangents == 0 {
                    continue;
                }
                let sigma = node.tangent_scale(s);
                let at = node.trial(|j| t[j] - rho[j] / sigma);
                match node.law.trial_slip(an, at) {
                    None => node
                        .tangent_unknowns()
                        .for_each(|(j, _)| conditions[j] = Condition::Row),
                    Some(slip) => {
                        let c = node.law.slip_coefficients(slip);
                        // no direction to turn without friction (the local problem's
                        // frictionless contacts keep their tangential rows) or trial
                        if turning && node.tangents == MAX_TANGENTS && c.norm() > 0.0 {
                            node.turning(t[i], at, c, sigma, &mut conditions);
                        } else {
                            for (j, ci) in node.tangent_unknowns() {
                                conditions[j] = Condition::Cone(i, c.components()[ci]);
                            }
                        }
                    }
                }
            }
            if same_conditions(&conditions, &last) {
                return (Some(t), steps);
            }
            match self.step(&conditions) {
                Some(next) => t = next,
                None => return (None, steps + 1),
            }
            last = conditions;
        }
        (None, max_steps)
    }

    /// One semi-smooth Newton step: the solution of the linear `conditions`, one per unknown
    /// (with a plate border, the plate's balance rows after the contact unknowns). `None`
    /// when they are singular.
    pub(super) fn step(&self, conditions: &[Condition]) -> Option<Vec<f64>> {
        let (s, m, n) = (&self.s, self.r.len(), conditions.len());
        let mut a = DMatrix::zeros(n, n);
        let mut g = DVector::zeros(n);
        for (j, condition) in conditions.iter().enumerate() {
            match *condition {
                Condition::Row => {
                    // S is symmetric: row j is column j
                    a.view_mut((j, 0), (1, m))
                        .copy_from(&s.column(j).transpose());
                    if let Some(b) = &self.border {
                        a.view_mut((j, m), (1, b.len())).copy_from(&b.g.row(j));
                    }
                    g[j] = self.r[j];
                }
                Condition::Balance => {
                    // the plate's balance `D U - H^T t = F - F0`
                    let (b, row) = (self.border.as_ref()?, j - m);
                    a.view_mut((j, 0), (1, m))
                        .copy_from(&(-b.h.column(row)).transpose());
                    a.view_mut((j, m), (1, b.len())).copy_from(&b.d.row(row));
                    g[j] = b.rhs[row];
                }
                Condition::Zero => a[(j, j)] = 1.0,
                Condition::Cone(normal, c) => {
                    a[(j, j)] = 1.0;
                    a[(j, normal)] = -c;
                }
                Condition::TurningCone(cone) => {
                    a[(j, j)] = 1.0;
                    a[(j, cone.normal)] = -cone.c;
                    for (k, w) in cone.w.iter().enumerate() {
                        let tk = cone.first + k;
                        a[(j, tk)] += w;
                        for (l, &x) in s.column(tk).iter().enumerate() {
                            a[(j, l)] -= w * x / cone.sigma;
                        }
                        if let Some(b) = &self.border {
                            for (l, &x) in b.g.row(tk).iter().enumerate() {
                                a[(j, m + l)] -= w * x / cone.sigma;
                            }
                        }
                        g[j] -= w * self.r[tk] / cone.sigma;
                    }
                }
            }
        }
        // faer's blocked LU (the product's small system is factored by it too, boundary.rs)
        let a = faer::MatRef::from_column_major_slice(a.as_slice(), n, n);
        let mut x = faer::Mat::from_fn(n, 1, |i, _| g[i]);
        a.partial_piv_lu().solve_in_place(x.as_mut());
        let x: Vec<f64> = (0..n).map(|i| x[(i, 0)]).collect();
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::friction::Coulomb;

    /// The unknowns, `S` and `r` of a test problem.
    type Problem = (Vec<(usize, usize, Row)>, DMatrix<f64>, Vec<f64>);

    /// Conditions over `nodes` nodes (every third frictionless), `S = B^T B + I / 10` from a
    /// seeded `B`, `r` of either sign: closed, open, stick and slip nodes all occur.
    fn problem(nodes: usize, seed: u64, tangents: usize) -> Problem {
        let mut x = seed;
        let mut draw = || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let unknowns: Vec<(usize, usize, Row)> = (0..nodes)
            .flat_map(|k| {
                let rows = if k % 3 == 2 { 0 } else { tangents };
                std::iter::once(Row::Normal)
                    .chain((0..rows).map(Row::Tangent))
                    .map(move |row| (0, k, row))
            })
            .collect();
        let m = unknowns.len();
        let b = DMatrix::from_fn(m, m, |_, _| draw());
        let s = b.transpose() * b + DMatrix::identity(m, m) * 0.1;
        let r = (0..m).map(|_| draw()).collect();
        (unknowns, s, r)
    }

    /// The largest violation of the conditions at `t`, relative to the largest traction and
    /// residual: `tn <= 0`, `rho_n <= 0`, `tn rho_n = 0`, `|ts| <= mu |tn|`, `rho_t = 0`
    /// inside the cone and `ts` opposing `rho_t` on it.
    fn violation(c: &Linearized<'_>, t: &[f64]) -> f64 {
        let rho = c.residual(t);
        let scale = t.iter().chain(&rho).fold(0.0f64, |a, v| a.max(v.abs()));
        let mut worst = 0.0f64;
        for node in &c.nodes {
            let i = node.normal;
            worst = worst
                .max(t[i])
                .max(rho[i])
                .max((t[i] * rho[i]).abs() / scale);
            if node.tangents > 0 {
                let (ts, rho_t) = (node.tangential(t), node.tangential(&rho));
                let limit = node.law.stick_limit(t[i]);
                worst = worst.max(ts.norm() - limit);
                if ts.norm() < limit * (1.0 - 1e-9) {
                    worst = worst.max(rho_t.norm());
                } else {
                    // on the cone: ts opposes rho_t, parallel to it
                    let parallel = ts.norm() * rho_t.norm() + ts.dot(&rho_t);
                    worst = worst.max(ts.dot(&rho_t) / scale).max(parallel / scale);
                }
            }
        }
        worst / scale
    }

    #[test]
    fn the_semismooth_newton_method_solves_the_conditions_exactly() {
        let law = Coulomb::new(0.3).unwrap();
        for seed in 1..=20 {
            let (unknowns, s, r) = problem(8, seed, 1);
            let laws: Vec<&dyn FrictionLaw> = vec![&law; unknowns.len()];
            let c = Linearized::new(&unknowns, &laws, |_, _| 1, s, r);
            let m = c.r.len();
            let exact = c.active_set(vec![0.0; m], false).expect("settles");
            assert!(violation(&c, &exact) < 1e-13, "seed {seed}");
            // the same solution as projected Gauss-Seidel's to convergence (unique here)
            let projected = c.projected(vec![0.0; m], 1_000_000).0;
            let largest = exact.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            for (a, b) in exact.iter().zip(&projected) {
                assert!(
                    (a - b).abs() < 1e-9 * largest,
                    "seed {seed}: {a} against {b}"
                );
            }
            let states =
                |t: &[f64]| (c.nodes.iter().map(|n| t[n.normal] < 0.0)).collect::<Vec<bool>>();
            assert!(states(&exact).contains(&true) && states(&exact).contains(&false));
        }
    }

    /// A border of two plate directions on `unknowns` from `seed`, as a plate that presses
    /// (its first direction moves every node into contact: `G_ia > 0` on normal rows) and
    /// shears (its second moves the nodes along their first tangent) with `rhs = (1, 0.1)`,
    /// less than `mu = 0.3` times the press: `G = H` drawn so, `D` zero (a floating body)
    /// or `G^T G + I` (held by the plate's stiffness too).
    fn plate_border(unknowns: &[(usize, usize, Row)], seed: u64, floating: bool) -> PlateBorder {
        let mut x = seed ^ 0x9e37_79b9_7f4a_7c15;
        let mut draw = move || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let g = DMatrix::from_fn(unknowns.len(), 2, |i, a| {
            let along = matches!((unknowns[i].2, a), (Row::Normal, 0) | (Row::Tangent(0), 1));
            let v = draw();
            if along { 0.5 + v.abs() } else { 0.1 * v }
        });
        let d = if floating {
            DMatrix::zeros(2, 2)
        } else {
            g.transpose() * &g + DMatrix::identity(2, 2)
        };
        PlateBorder {
            h: g.clone(),
            g,
            d,
            rhs: vec![1.0, 0.1],
            stiffness_scale: 1.0,
        }
    }

    /// The plate's balance residual `D U - H^T t - rhs` at `x = (t, U)`, largest.
    fn imbalance(b: &PlateBorder, x: &[f64]) -> f64 {
        let m = x.len() - b.len();
        let (t, u) = (
            DVector::from_column_slice(&x[..m]),
            DVector::from_column_slice(&x[m..]),
        );
        let r = &b.d * u - b.h.transpose() * t - DVector::from_column_slice(&b.rhs);
        r.amax()
    }

    /// The conditions bordered by two plate directions, floating (`D = 0`: the balance a
    /// constraint on the tractions) and held (`D` positive definite), over a flexibility whose
    /// diagonal dominates (with `S` of the other tests, for a floating body, the method cycles
    /// between slip directions for some seeds: it is not globally convergent; the bodies'
    /// flexibilities of `contact_plate3d` and `contact3d_plate` settle): the semi-smooth Newton
    /// method over `t` and `U` satisfies the contact conditions and the balance to round-off,
    /// and where `D` is positive definite its tractions are those of the condensed conditions
    /// ([`PlateBorder::condensed`]) solved by projected Gauss-Seidel, and its `U` the one the
    /// balance gives them ([`PlateBorder::motion`]). A solution made to be
    /// one (every node closed and sticking, `rho = 0`: `r = S^T t + G U`,
    /// `rhs = D U - H^T t`) is found again exactly. A wrong sign of `G`, `H` or `D` in
    /// the step, or a condensation that takes `D^-1` the wrong way, breaks them.
    #[test]
    fn the_bordered_conditions_balance_the_plate() {
        const OWN: f64 = 10.0;
        let law = Coulomb::new(0.3).unwrap();
        let (mut slipping, mut open) = (0, 0);
        for seed in 1..=10 {
            for floating in [true, false] {
                let (unknowns, s, r) = problem(8, seed, 2);
                let laws: Vec<&dyn FrictionLaw> = vec![&law; unknowns.len()];
                // a flexibility whose diagonal (each node's own) dominates, as a body's does
                let s = &s + DMatrix::identity(s.nrows(), s.nrows()) * OWN;
                let mut c = Linearized::new(&unknowns, &laws, |_, _| 2, s, r);
                let m = c.r.len();
                c.border = Some(plate_border(&unknowns, seed, floating));
                let b = c.border.as_ref().unwrap();
                let x = c
                    .active_set(c.bordered_solution(b), false)
                    .expect("settles");
                assert!(
                    violation(&c, &x) < 1e-12,
                    "seed {seed}: {}",
                    violation(&c, &x)
                );
                assert!(
                    imbalance(b, &x) < 1e-12,
                    "seed {seed}: {}",
                    imbalance(b, &x)
                );
                for n in c.nodes.iter().filter(|n| n.tangents == 2) {
                    let on_cone = x[n.normal] < 0.0
                        && n.tangential(&x).norm() >= (1.0 - 1e-9) * law.stick_limit(x[n.normal]);
                    slipping += usize::from(on_cone);
                    open += usize::from(x[n.normal] == 0.0);
                }
                match b.condensed(&c.s, &c.r) {
                    None => assert!(floating),
                    Some((s, r)) => {
                        let condensed = Linearized {
                            s,
                            r,
                            nodes: c.nodes.clone(),
                            border: None,
                        };
                        let t = condensed.projected(vec![0.0; m], 1_000_000).0;
                        // U recovered from the balance
                        let u = b.motion(&t).unwrap();
                        let t: Vec<f64> = t.into_iter().chain(u.iter().copied()).collect();
                        let largest = t.iter().fold(0.0f64, |a, v| a.max(v.abs()));
                        for (a, b) in x.iter().zip(&t) {
                            assert!((a - b).abs() < 1e-8 * largest, "seed {seed}: {a} {b}");
                        }
                    }
                }
                // a made solution: every node closed and sticking well inside the cone
                let b = c.border.take().unwrap();
                let made: Vec<f64> = (0..m + 2)
                    .map(|j| match unknowns.get(j) {
                        Some((_, _, Row::Normal)) => -1.0 - 0.1 * j as f64,
                        Some(_) => 0.01 * (j as f64 - 3.0),
                        None => 0.5 - j as f64,
                    })
                    .collect();
                let (t, u) = (
                    DVector::from_column_slice(&made[..m]),
                    DVector::from_column_slice(&made[m..]),
                );
                c.r = (c.s.transpose() * &t + &b.g * &u).iter().copied().collect();
                let rhs = &b.d * &u - b.h.transpose() * &t;
                c.border = Some(PlateBorder {
                    rhs: rhs.iter().copied().collect(),
                    ..b
                });
                let x = c.solution();
                for (a, b) in x.iter().zip(&made) {
                    assert!((a - b).abs() < 1e-10, "seed {seed}: {a} against {b}");
                }
            }
        }
        assert!(slipping > 0 && open > 0, "{slipping} slip, {open} open");
    }

    /// A face node whose first tangent is dropped by symmetry has one tangential unknown,
    /// its traction's second component; with `S = I` the solution is `t = r` where closed
    /// and sticking, 0 where open.
    #[test]
    fn a_dropped_tangent_has_no_unknown() {
        let law = Coulomb::new(0.3).unwrap();
        let unknowns = [
            (0, 0, Row::Normal),
            (0, 0, Row::Tangent(1)),
            (0, 1, Row::Normal),
        ];
        let laws: Vec<&dyn FrictionLaw> = vec![&law; 3];
        let (s, r) = (DMatrix::identity(3, 3), vec![-1.0, 0.2, 0.5]);
        let c = Linearized::new(&unknowns, &laws, |_, _| 2, s, r);
        assert_eq!((c.nodes.len(), c.nodes[0].tangents), (2, 1));
        assert_eq!(
            c.nodes[0].tangential(&[-1.0, 0.25, 0.0]),
            Tangential::on_face(0.0, 0.25)
        );
        assert_eq!(c.active_set(vec![0.0; 3], false).unwrap(), [-1.0, 0.2, 0.0]);
    }

    /// On a face (two tangents per node, the cone a disc): the semi-smooth Newton method, its
    /// slip coefficients from the law's `trial_slip`, settles where the slip directions agree
    /// to round-off, and its solution satisfies the conditions; projected Gauss-Seidel, with
    /// the law's radial projection, reaches the same solution.
    #[test]
    fn the_fallback_solves_the_conditions_over_a_disc() {
        let law = Coulomb::new(0.3).unwrap();
        let (mut slipping, mut sticking) = (0, 0);
        for seed in 1..=10 {
            let (unknowns, s, r) = problem(6, seed, 2);
            let laws: Vec<&dyn FrictionLaw> = vec![&law; unknowns.len()];
            let c = Linearized::new(&unknowns, &laws, |_, _| 2, s, r);
            assert!(c.nodes.iter().any(|n| n.tangents == 2));
            let m = c.r.len();
            let exact = c.active_set(vec![0.0; m], false).expect("settles");
            assert!(
                violation(&c, &exact) < 1e-12,
                "seed {seed}: {}",
                violation(&c, &exact)
            );
            let projected = c.projected(vec![0.0; m], 1_000_000).0;
            let largest = exact.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            for (a, b) in exact.iter().zip(&projected) {
                assert!(
                    (a - b).abs() < 1e-8 * largest,
                    "seed {seed}: {a} against {b}"
                );
            }
            for n in c
                .nodes
                .iter()
                .filter(|n| n.tangents == 2 && exact[n.normal] < 0.0)
            {
                let on_cone =
                    n.tangential(&exact).norm() >= (1.0 - 1e-9) * law.stick_limit(exact[n.normal]);
                if on_cone {
                    slipping += 1;
                } else {
                    sticking += 1;
                }
            }
        }
        assert!(
            slipping > 0 && sticking > 0,
            "{slipping} slip, {sticking} stick"
        );
    }
}
