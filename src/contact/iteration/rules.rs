//! The contact rules in one place: which state an A node takes next, and what to do when the
//! paper's rules do not settle.
//!
//! # The rules (docs/method.md, "The rules"), per A node after each solve
//!
//! | state | condition (after the solve) | next state |
//! |---|---|---|
//! | open | weighted gap `< -gap_tol` (or a B node over its open segments penetrates), and chosen by [`ActiveSet::closing`] | closed: stick, slip (sliding since the increment began) or frictionless |
//! | stick, slip, frictionless | `tn > tension_tol tn_max` | open |
//! | stick | `|ts| > mu |tn| (1 + friction_tol)` | slip, in the direction `-ts / |ts|` |
//! | slip | slip reversed: `d . v < -slip_tol` along its direction `d` (not locked in slip) | stick |
//! | any | otherwise | unchanged |
//!
//! What each state adds to the small system ([`rows_of`], read by
//! [`ContactAnalysis::build_system`]): open, nothing; frictionless, the normal row (column
//! `n`); stick, the normal row and the tangent row `s` (no slip since the increment began);
//! slip, the normal row with the column `n + sum_i c_i s_i`, `c = mu d` the law's slip
//! coefficients for the slip direction `d`. Which penetrating nodes close in an
//! iteration is [`ActiveSet::closing`], below.
//!
//! The locks of a cycling set ([`ActiveSet::commit`]) and the checks at convergence
//! (`checks.rs`) complete the rules.
//!
//! When the rules do not settle, the increment starts again from the fallback's states
//! (`fallback.rs`).

use super::{
    ActiveSet, BNodes, ContactAnalysis, ContactError, ContactSurface, FrictionLaw, NodeState,
    Result, SlipDirection, Tangential, Traction,
};
use crate::contact::geometry::ContactNode;

/// A run of penetrating nodes away from the contact zone closes where its penetration is at
/// least this fraction of its deepest ([`ActiveSet::closing`]).
pub(super) const NEW_REGION_DEPTH: f64 = 0.9;

/// Runs of penetrating nodes up to this long close whole ([`ActiveSet::closing`]): halving a
/// run of two beside the zone made its edge node alternate open/closed where closing both
/// converged (2 of 54 finite-sliding scenes of the robustness scan, reported in
/// `docs/bench/contact_boundary.md`).
pub(super) const WHOLE_RUN: usize = 2;

/// What a state adds to the small system ([`ContactAnalysis::build_system`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Rows {
    /// Open: nothing.
    None,
    /// Frictionless: the normal row, column `n`.
    Normal,
    /// Slip: the normal row, column `n + sum_i c_i s_i` with `c` the law's slip coefficients
    /// (`ts = c tn`).
    NormalSlip(Tangential),
    /// Stick: the normal row and the tangent row (no slip since the increment began), each
    /// its own column.
    NormalTangent,
}

/// The rows of `state` under friction law `law` (the module's table).
pub(super) fn rows_of(state: NodeState, law: &dyn FrictionLaw) -> Rows {
    match state {
        NodeState::Open => Rows::None,
        NodeState::Frictionless => Rows::Normal,
        NodeState::Slip { direction } => Rows::NormalSlip(law.slip_coefficients(direction)),
        NodeState::Stick => Rows::NormalTangent,
    }
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

impl ContactAnalysis {
    /// The paper's rules, proposing the next states from the set's current ones: penetration
    /// (A nodes by weighted gap; B nodes pointwise over A segments whose two nodes are open),
    /// tension, the friction cone and slip reversal. The rules respect the set's locks: a node
    /// locked open does not close, a node locked in slip does not return to stick.
    pub(super) fn update_states(
        &self,
        set: &ActiveSet,
        tractions: &[Vec<Traction>],
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
            let tn_max = tractions[p]
                .iter()
                .fold(0.0f64, |m, t| m.max(t.normal.abs()));
            // a node closing while the surfaces slide past each other slides with them; one
            // closing without relative motion sticks
            let closed = |k: usize, node: &ContactNode| {
                let slip = self.slip_since_start(node, uc, startc);
                match SlipDirection::of(slip) {
                    _ if self.node_law(p, k).is_frictionless() => NodeState::Frictionless,
                    Some(direction) if slip.norm() > slip_tolerance => {
                        NodeState::Slip { direction }
                    }
                    _ => NodeState::Stick,
                }
            };
            // how deep each open node penetrates; which of them close is decided below
            let mut depth: Vec<Option<f64>> = vec![None; surface.nodes.len()];
            for (k, node) in surface.nodes.iter().enumerate() {
                let Traction {
                    normal: tn,
                    tangential: ts,
                } = tractions[p][k];
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
                        if ts.norm() > law.stick_limit(tn) * (1.0 + self.options.friction_tolerance)
                        {
                            new[p][k] = NodeState::Slip {
                                direction: SlipDirection::opposing(ts),
                            };
                        }
                    }
                    NodeState::Slip { direction } => {
                        if set.may_stick((p, k))
                            && direction.along(&self.slip_since_start(node, uc, startc))
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
            let inside = if set.b_nodes() == BNodes::Pointwise {
                self.geometries[p].b_node_distances(&open, &x, xg)
            } else {
                Vec::new()
            };
            for d in inside {
                let g = d.distance;
                if g >= -gap_tolerance {
                    continue;
                }
                if g <= -reach {
                    let w = [a[d.element[0]], a[d.element[1]]];
                    return Err(ContactError::BeyondSearchDistance {
                        node: self.bodies.external(d.node),
                        segment: [self.bodies.external(w[0]), self.bodies.external(w[1])],
                        depth: -g,
                        search_distance: reach,
                    }
                    .into());
                }
                let node = d.nearest;
                depth[node] = Some(depth[node].map_or(g, |d| d.min(g)));
            }
            // coverage is checked on the converged state only: an intermediate iterate may
            // move a node at the end of a surface a hair past the other's end
            for k in set.closing(p, &depth) {
                new[p][k] = closed(k, &surface.nodes[k]);
            }
        }
        Ok(new)
    }
}

impl ActiveSet {
    /// The open nodes of pair `p` that close in this iteration (docs/method.md, "The rules", step 3a,
    /// damped). `depth[k]` is `Some(d)` for an open node that penetrates (`d < 0`: the deeper of
    /// its weighted gap and any B node's distance that closes it), `None` otherwise. Per run of
    /// consecutive penetrating nodes:
    /// * between two closed nodes (a hole in the zone): all of it;
    /// * beside the zone on one side: the half nearest the zone (rounded up). The penetration
    ///   beyond a zone was computed with the contact force on that zone, which is too small, so
    ///   it overstates the band: closing all of it overshoots the edge, and the zone then
    ///   shrinks by the one or two nodes per side whose traction turns tensile in each
    ///   iteration. Halving approaches the edge from inside, where the zone grows fast
    ///   (`bench contact` at n = 256: 46 iterations before, 20 now);
    /// * away from the zone (a new contact region): the nodes within [`NEW_REGION_DEPTH`] of
    ///   the deepest one, so that conforming surfaces close at once and curved ones grow from
    ///   their deepest point.
    ///
    /// Nodes locked open are skipped; if that leaves a run's choice empty, every node of the
    /// run that may close closes, so the iteration never stops on a penetrating node it could
    /// close.
    pub(super) fn closing(&self, p: usize, depth: &[Option<f64>]) -> Vec<usize> {
        let closed = |k: usize| self.states()[p][k] != NodeState::Open;
        let mut chosen = Vec::new();
        let mut k = 0;
        while k < depth.len() {
            if depth[k].is_none() {
                k += 1;
                continue;
            }
            let start = k;
            while k < depth.len() && depth[k].is_some() {
                k += 1;
            }
            let run = start..k;
            let half = if run.len() <= WHOLE_RUN {
                run.len()
            } else {
                run.len().div_ceil(2)
            };
            let before = start > 0 && closed(start - 1);
            let after = k < depth.len() && closed(k);
            let mut pick: Vec<usize> = match (before, after) {
                (true, true) => run.clone().collect(),
                (true, false) => (start..start + half).collect(),
                (false, true) => (k - half..k).collect(),
                (false, false) => {
                    let d = |i: usize| depth[i].unwrap_or(0.0);
                    let deepest = run.clone().map(d).fold(0.0, f64::min);
                    run.clone()
                        .filter(|&i| d(i) <= NEW_REGION_DEPTH * deepest)
                        .collect()
                }
            };
            pick.retain(|&i| self.may_close((p, i)));
            if pick.is_empty() {
                pick = run.filter(|&i| self.may_close((p, i))).collect();
            }
            chosen.extend(pick);
        }
        chosen
    }
}

#[cfg(test)]
mod tests {
    use super::super::Locks;
    use super::*;

    const SLIP: NodeState = NodeState::Slip {
        direction: SlipDirection::PLUS,
    };

    /// Holes fill, bands beside the zone close by their nearer half (a band of two whole), new
    /// regions from their deepest nodes; locked nodes are skipped without stopping the growth.
    #[test]
    fn closing_grows_the_zone_by_halves() {
        use NodeState::Open;
        let depths = |entries: &[(usize, f64)]| {
            let mut depth = vec![None; 12];
            for &(k, d) in entries {
                depth[k] = Some(d);
            }
            depth
        };
        // closed: 3, 5 and 10
        let mut states = vec![Open; 12];
        for k in [3, 5, 10] {
            states[k] = SLIP;
        }
        let set = ActiveSet::new(vec![states.clone()], Locks::default(), 1);
        // a band of 3 left of node 3, a hole at 4, a band of 4 right of node 5, a band of two
        // right of node 10
        let band = [
            (0, -1.0),
            (1, -2.0),
            (2, -3.0),
            (4, -1.0),
            (6, -5.0),
            (7, -4.0),
        ];
        let rest = [(8, -3.0), (9, -2.0), (11, -1.0)];
        let depth = depths(&[&band[..], &rest[..]].concat());
        // 6..10 lies between 5 and 10: a hole, all of it
        assert_eq!(set.closing(0, &depth), vec![1, 2, 4, 6, 7, 8, 9, 11]);
        let depth = depths(&[
            (0, -1.0),
            (1, -2.0),
            (2, -3.0),
            (6, -5.0),
            (7, -4.0),
            (8, -1.0),
        ]);
        assert_eq!(set.closing(0, &depth), vec![1, 2, 6, 7]);
        let depth = depths(&[(6, -5.0), (7, -4.0)]);
        assert_eq!(
            set.closing(0, &depth),
            vec![6, 7],
            "a band of two closes whole"
        );
        // a new region: within 0.9 of its deepest node, which need not be at its middle
        let open = ActiveSet::new(vec![vec![Open; 12]], Locks::default(), 1);
        let depth = depths(&[(1, -0.5), (2, -0.95), (3, -1.0), (4, -0.91), (5, -0.2)]);
        assert_eq!(open.closing(0, &depth), vec![2, 3, 4]);
        // conforming surfaces: all at once
        assert_eq!(
            open.closing(0, &[Some(-1.0); 12]),
            (0..12).collect::<Vec<_>>()
        );
        // the chosen half locked open: the rest of the band closes instead
        let locks = Locks {
            slip: Vec::new(),
            open: vec![(0, 1), (0, 2)],
        };
        let locked = ActiveSet::new(vec![states], locks, 1);
        let depth = depths(&[(0, -1.0), (1, -2.0), (2, -3.0)]);
        assert_eq!(locked.closing(0, &depth), vec![0]);
    }
}
