//! The contact rules in one place: which state an A node takes next, and what to do when the
//! paper's rules do not settle.
//!
//! # The rules (METHOD.md section 4), per A node after each solve
//!
//! | state | condition (after the solve) | next state |
//! |---|---|---|
//! | open | weighted gap `< -gap_tol` (or a B node over its open segments penetrates), and chosen by [`ActiveSet::closing`] | closed: stick, slip (sliding since the increment began) or frictionless |
//! | stick, slip, frictionless | `tn > tension_tol tn_max` | open |
//! | stick | `|ts| > mu |tn| (1 + friction_tol)` | slip, `sign = -sign(ts)` |
//! | slip | slip reversed: `sign v < -slip_tol` (not locked in slip) | stick |
//! | any | otherwise | unchanged |
//!
//! What each state adds to the small system ([`ContactAnalysis::build_system`]): open, nothing;
//! frictionless, the normal row (column `n`); stick, the normal row and the tangent row `s`
//! (no slip since the increment began); slip, the normal row with the column `n + mu sign s`.
//!
//! The locks of a cycling set ([`ActiveSet::commit`]) and the checks at convergence
//! (`checks.rs`) complete the rules.
//!
//! # When the rules do not settle: the projected fallback
//!
//! The rules move one way only from a slip node that slides with its friction: it stays in
//! slip. At the first all-stick iterate the stick shear of the linear multipliers alternates
//! in sign from node to node (the oscillation that shows at the Hertz edge), many nodes
//! exceed the cone at once and all of them turn to slip; a node whose violation was only that
//! oscillation then slides consistently and never returns, while its neighbour alternates
//! between stick (outside the cone) and slip (sliding against its friction). The cycle guard
//! locks the neighbour in slip and the increment fails with a slip reversal (434 of the 513
//! failures of `hycon bench presses` in 0.6.2); the same happens to the normal states at the
//! edge of a zone (a node locked open that penetrates). In the traced press 247 of seed 1
//! (`hycon bench presses --count 2000`) the state {stick, slip(-1)} satisfies every condition,
//! but the rules go {stick, stick} -> {slip(+1), slip(-1)} and then cycle between
//! {slip(+1), stick} and {slip(+1), slip(-1)}.
//!
//! When the rules fail for such a reason ([`settles_by_fallback`]), the increment starts
//! again from the states of the solution of the same conditions, linearized at the start of
//! the increment, over the candidate nodes (closed at the start, or penetrating under the
//! load alone, and their neighbours): with every candidate's normal and tangent rows,
//! `S t - r = rho` (`rho_n = n . R_C` the weighted gap with its sign reversed, `rho_t` the
//! weighted slip), solve `tn <= 0`, `rho_n <= 0`, `tn rho_n = 0`, `|ts| <= mu |tn|`, `ts`
//! opposing `rho_t` where it is on the cone and `rho_t = 0` inside, by projected block
//! Gauss-Seidel over the nodes (for a fixed `|tn|` the problem is the minimum of a convex
//! quadratic over boxes, so each sweep lowers it; the friction bound follows `tn`). Its
//! states (closed where `tn < 0`, slip where `|ts|` is on the cone, with the sign of
//! `-ts`) start the paper's iteration again, which then settles in a few iterations and
//! checks every condition as usual. The paper's rules keep their results wherever they
//! settle: the fallback runs only after they failed.

use super::*;

/// Whether an increment that failed with `e` is tried again from the fallback's states: a
/// failure of the rules (a cycle, the iteration cap, a node locked in slip that slides
/// against its friction, a node locked open that penetrates). Geometry, coverage, a singular
/// system and a host's or monitor's failure are not the rules' to fix.
pub(super) fn settles_by_fallback(e: &Error) -> bool {
    matches!(
        e,
        Error::Contact(
            ContactError::Cycling { .. }
                | ContactError::NoConvergence { .. }
                | ContactError::SlipReversal { .. }
                | ContactError::EdgePenetration { .. }
                | ContactError::ConditionViolated { .. }
        )
    )
}

/// The state of a node that closes without sliding: stick, or frictionless under a pair
/// without friction.
pub(super) fn closed_at_rest(law: &dyn FrictionLaw) -> NodeState {
    if law.is_frictionless() {
        NodeState::Frictionless
    } else {
        NodeState::Stick
    }
}

/// Projected Gauss-Seidel sweeps of the fallback, at most.
const FALLBACK_SWEEPS: usize = 20_000;

/// The sweeps stop when no traction changes by more than this, relative to the largest.
const FALLBACK_TOLERANCE: f64 = 1e-12;

/// A node is in slip in the fallback's states when `|ts| >= (1 - FALLBACK_CONE) mu |tn|`.
const FALLBACK_CONE: f64 = 1e-9;

impl ContactAnalysis {
    /// The paper's rules, proposing the next states from the set's current ones: penetration
    /// (A nodes by weighted gap; B nodes pointwise over A segments whose two nodes are open),
    /// tension, the friction cone and slip reversal. The rules respect the set's locks: a node
    /// locked open does not close, a node locked in slip does not return to stick.
    pub(super) fn update_states(
        &self,
        set: &ActiveSet,
        tractions: &[Vec<(f64, f64)>],
        surfaces: &[ContactSurface],
        uc: &[f64],
        startc: &[f64],
    ) -> Result<Vec<Vec<NodeState>>> {
        let states = set.states();
        let mut new = states.to_vec();
        let x = self.positions(uc);
        let xg = self.geometry_positions(&x);
        for (p, surface) in surfaces.iter().enumerate() {
            let law = &*self.laws[p];
            let slip_tolerance = self.options.slip_tolerance * self.motion_scale(p, xg, uc, startc);
            let reach = self.search_reach(p, xg, uc, startc);
            // penetration is judged against the increment's own displacement scale
            let gap_tolerance = self.options.gap_tolerance * self.gap_scale(p, xg, uc, startc);
            let tn_max = tractions[p].iter().fold(0.0f64, |m, t| m.max(t.0.abs()));
            // a node closing while the surfaces slide past each other slides with them; one
            // closing without relative motion sticks
            let closed = |node: &geometry::ContactNode| {
                let slip = self.slip_since_start(node, uc, startc);
                if law.is_frictionless() {
                    NodeState::Frictionless
                } else if slip.abs() > slip_tolerance {
                    NodeState::Slip {
                        sign: if slip > 0.0 { 1 } else { -1 },
                    }
                } else {
                    NodeState::Stick
                }
            };
            // how deep each open node penetrates; which of them close is decided below
            let mut depth: Vec<Option<f64>> = vec![None; surface.nodes.len()];
            for (k, node) in surface.nodes.iter().enumerate() {
                let (tn, ts) = tractions[p][k];
                match states[p][k] {
                    NodeState::Open => {
                        if node.normal_gap < -gap_tolerance {
                            depth[k] = Some(node.normal_gap);
                        }
                    }
                    _ if tn > self.options.tension_tolerance * tn_max => {
                        new[p][k] = NodeState::Open;
                    }
                    NodeState::Stick => {
                        if ts.abs() > law.stick_limit(tn) * (1.0 + self.options.friction_tolerance)
                        {
                            new[p][k] = NodeState::Slip {
                                sign: if ts > 0.0 { -1 } else { 1 },
                            };
                        }
                    }
                    NodeState::Slip { sign } => {
                        if set.may_stick((p, k))
                            && f64::from(sign) * self.slip_since_start(node, uc, startc)
                                < -slip_tolerance
                        {
                            new[p][k] = NodeState::Stick;
                        }
                    }
                    NodeState::Frictionless => {}
                }
            }
            // B nodes over A segments whose two nodes are open (not in the fallback's attempt,
            // see the module docs)
            let a = &self.pairs[p].a;
            let open: Vec<bool> = (0..a.len())
                .map(|k| states[p][k] == NodeState::Open && depth[k].is_none())
                .collect();
            let inside = if self.pointwise_b {
                self.b_node_distances(p, &open, &x, xg)
            } else {
                Vec::new()
            };
            for (k, j, xi, g) in inside {
                if g >= -gap_tolerance {
                    continue;
                }
                if g <= -reach {
                    let w = [a[k], a[k + 1]];
                    return Err(ContactError::BeyondSearchDistance {
                        node: self.bodies.external(j),
                        segment: [self.bodies.external(w[0]), self.bodies.external(w[1])],
                        depth: -g,
                        search_distance: reach,
                    }
                    .into());
                }
                let node = if xi < 0.5 { k } else { k + 1 };
                depth[node] = Some(depth[node].map_or(g, |d| d.min(g)));
            }
            // coverage is checked on the converged state only: an intermediate iterate may
            // move a node at the end of a surface a hair past the other's end
            for k in set.closing(p, &depth) {
                new[p][k] = closed(&surface.nodes[k]);
            }
        }
        Ok(new)
    }

    /// The B nodes strictly inside the A segments of pair `p` whose two nodes are `open`:
    /// `(segment k, B node j, xi, g)` with `g` the signed distance of the B node from the
    /// segment along its normal (`< 0`: it penetrates), the segment's point `xi`, normal and
    /// the B node's projection taken in the geometry's configuration `xg` (frozen under small
    /// kinematics: the distance is then linear in the displacements), `x` the current
    /// positions.
    pub(super) fn b_node_distances(
        &self,
        p: usize,
        open: &[bool],
        x: &[[f64; 2]],
        xg: &[[f64; 2]],
    ) -> Vec<(usize, usize, f64, f64)> {
        let mut out = Vec::new();
        for (k, w) in self.pairs[p].a.windows(2).enumerate() {
            if !(open[k] && open[k + 1]) {
                continue;
            }
            let (s0, s1) = (xg[w[0]], xg[w[1]]);
            let d = [s1[0] - s0[0], s1[1] - s0[1]];
            let len = (d[0] * d[0] + d[1] * d[1]).sqrt();
            let n = [d[1] / len, -d[0] / len];
            // current segment end points (equal to s0, s1 under finite kinematics)
            let (c0, c1) = (x[w[0]], x[w[1]]);
            // under small kinematics the B nodes inside each segment were found once, in the
            // reference configuration
            let candidates = match &self.interiors {
                Some(interiors) => interiors[p].segment(k),
                None => &self.pairs[p].b[..],
            };
            for &j in candidates {
                let (xi, inside) = geometry::interior_parameter(s0, s1, xg[j]);
                if !inside {
                    continue;
                }
                let hit = [c0[0] + xi * (c1[0] - c0[0]), c0[1] + xi * (c1[1] - c0[1])];
                let g = (x[j][0] - hit[0]) * n[0] + (x[j][1] - hit[1]) * n[1];
                out.push((k, j, xi, g));
            }
        }
        out
    }

    /// The fallback's start states for `attempt` (module docs): the candidates' conditions
    /// linearized at the start of the increment, solved by projected block Gauss-Seidel.
    pub(super) fn fallback_states(&mut self, attempt: &Attempt<'_>) -> Result<Vec<Vec<NodeState>>> {
        let startc = &attempt.startc;
        let surfaces = self.surfaces.clone();
        let closed_state = |p: usize| closed_at_rest(&*self.laws[p]);
        // the candidates: closed at the start, or penetrating under the load alone, and
        // their covered neighbours
        let mut states: Vec<Vec<NodeState>> = Vec::with_capacity(surfaces.len());
        for (p, surface) in surfaces.iter().enumerate() {
            let nodes = &surface.nodes;
            let penetrates: Vec<bool> = nodes
                .iter()
                .enumerate()
                .map(|(k, node)| {
                    if self.nodes[p][k].state != NodeState::Open {
                        return true;
                    }
                    if !node.is_covered() {
                        return false;
                    }
                    let row = self.directed(&node.coupling, node.normal);
                    let rg = node.gap[0] * node.normal[0] + node.gap[1] * node.normal[1];
                    rg + dot(&row, attempt.u0c) - dot(&row, startc) > 0.0
                })
                .collect();
            let candidate = |k: usize| {
                nodes[k].is_covered()
                    && (penetrates[k]
                        || (k > 0 && penetrates[k - 1])
                        || (k + 1 < nodes.len() && penetrates[k + 1]))
            };
            states.push(
                (0..nodes.len())
                    .map(|k| {
                        if candidate(k) {
                            closed_state(p)
                        } else {
                            NodeState::Open
                        }
                    })
                    .collect(),
            );
        }
        let system = self.build_system(&surfaces, &states, startc, startc)?;
        let s = self.dense_matrix(&system)?;
        let r: Vec<f64> = system
            .rows
            .iter()
            .zip(&system.b)
            .map(|(row, b)| b - dot(row, attempt.u0c))
            .collect();
        let t = self.projected_solution(&system, &s, &r);
        let tn_max = system
            .unknowns
            .iter()
            .zip(&t)
            .filter(|(u, _)| u.2 == small_system::Row::Normal)
            .fold(0.0f64, |m, (_, v)| m.max(v.abs()));
        let mut out: Vec<Vec<NodeState>> = states
            .iter()
            .map(|s| vec![NodeState::Open; s.len()])
            .collect();
        for (i, &(p, k, row)) in system.unknowns.iter().enumerate() {
            if row != small_system::Row::Normal || t[i] >= -FALLBACK_TOLERANCE * tn_max {
                continue;
            }
            let tangent = system
                .unknowns
                .get(i + 1)
                .filter(|u| (u.0, u.1) == (p, k))
                .map(|_| t[i + 1]);
            out[p][k] = match tangent {
                None => NodeState::Frictionless,
                Some(ts) => {
                    let limit = self.laws[p].stick_limit(t[i]);
                    if ts.abs() >= (1.0 - FALLBACK_CONE) * limit {
                        NodeState::Slip {
                            sign: if ts > 0.0 { -1 } else { 1 },
                        }
                    } else {
                        NodeState::Stick
                    }
                }
            };
        }
        Ok(out)
    }

    /// Projected block Gauss-Seidel on `S t - r = rho` (module docs): per node, the normal
    /// traction `tn <- min(0, tn - rho_n / S_nn)`, then the tangential one
    /// `ts <- clamp(ts - rho_t / S_tt, -mu |tn|, mu |tn|)`, until no traction changes by more
    /// than [`FALLBACK_TOLERANCE`] of the largest. `S` is symmetric positive definite here
    /// (every column is its row).
    fn projected_solution(&self, system: &SmallSystem, s: &DMatrix<f64>, r: &[f64]) -> Vec<f64> {
        let m = r.len();
        let mut t = vec![0.0; m];
        let mut rho: Vec<f64> = r.iter().map(|v| -v).collect();
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
        for _ in 0..FALLBACK_SWEEPS {
            let mut largest_change = 0.0f64;
            let mut i = 0;
            while i < m {
                let (p, k, _) = system.unknowns[i];
                let tn = (t[i] - rho[i] / s[(i, i)]).min(0.0);
                largest_change = largest_change.max(update(&mut t, &mut rho, i, tn));
                let frictional = system
                    .unknowns
                    .get(i + 1)
                    .is_some_and(|u| (u.0, u.1) == (p, k) && u.2 == small_system::Row::Tangent);
                if frictional {
                    let j = i + 1;
                    let limit = self.laws[p].stick_limit(t[i]);
                    let ts = (t[j] - rho[j] / s[(j, j)]).clamp(-limit, limit);
                    largest_change = largest_change.max(update(&mut t, &mut rho, j, ts));
                    i += 2;
                } else {
                    i += 1;
                }
            }
            let largest = t.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            if largest_change <= FALLBACK_TOLERANCE * largest {
                break;
            }
        }
        t
    }
}
