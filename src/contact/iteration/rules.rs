//! The facts the active set's rules judge, gathered from the geometry and the solve.
//!
//! After each solve the iteration reads, per A node, its traction, weighted normal gap and
//! slip since the increment began ([`NodeFacts`]), per pair the rules' tolerances as lengths
//! ([`Tolerances`]: the gap and slip tolerances times the pair's gap and motion scales,
//! `checks.rs`), and the B nodes inside A segments whose two nodes are open
//! ([`b_node_distances`](ContactAnalysis::b_node_distances)); the decisions on them are the
//! active set's ([`ActiveSet::propose`], `active_set/rules.rs`, with the rules' table).
//!
//! When the rules do not settle, the increment starts again from the fallback's states
//! (`fallback.rs`).

use super::{
    ActiveSet, BNodeHit, ContactAnalysis, ContactError, ContactSurface, NodeFacts, NodeState,
    Result, Tolerances, Traction, edge_normal, geometry,
};

impl ContactAnalysis {
    /// The paper's rules ([`ActiveSet::propose`]) applied to the iterate `uc` with
    /// `tractions` and the geometry `surfaces`, pair by pair: the proposed next states. A B
    /// node that penetrates an open A segment beyond the pairing's reach fails the increment
    /// ([`ContactError::BeyondSearchDistance`]).
    pub(super) fn update_states(
        &self,
        set: &ActiveSet,
        tractions: &[Vec<Traction>],
        surfaces: &[ContactSurface],
        uc: &[f64],
        startc: &[f64],
    ) -> Result<Vec<Vec<NodeState>>> {
        let x = self.positions(uc);
        let xg = self.geometry_positions(&x);
        let mut new = Vec::with_capacity(surfaces.len());
        for (p, surface) in surfaces.iter().enumerate() {
            let reach = self.search_reach(p, xg, uc, startc);
            let tolerances = Tolerances {
                // penetration is judged against the increment's own displacement scale
                gap: self.options.gap_tolerance * self.gap_scale(p, xg, uc, startc),
                slip: self.options.slip_tolerance * self.motion_scale(p, xg, uc, startc),
                tension: self.options.tension_tolerance,
                friction: self.options.friction_tolerance,
            };
            let facts: Vec<NodeFacts<'_>> = (surface.nodes.iter().enumerate())
                .map(|(k, node)| NodeFacts {
                    traction: tractions[p][k],
                    gap: node.normal_gap,
                    slip: self.slip_since_start(node, uc, startc),
                    law: self.node_law(p, k),
                })
                .collect();
            // B nodes over A segments whose two nodes are open (not in the fallback's last
            // attempt: `BNodes`)
            let inside = match set.b_node_judges(p, &facts, &tolerances) {
                Some(open) => self.b_node_distances(p, &open, &x, xg),
                None => Vec::new(),
            };
            let a = &self.pairs[p].a;
            let mut hits: Vec<BNodeHit> = Vec::with_capacity(inside.len());
            for (k, j, xi, g) in inside {
                if g < -tolerances.gap && g <= -reach {
                    let w = [a[k], a[k + 1]];
                    return Err(ContactError::BeyondSearchDistance {
                        node: self.bodies.external(j),
                        segment: [self.bodies.external(w[0]), self.bodies.external(w[1])],
                        depth: -g,
                        search_distance: reach,
                    }
                    .into());
                }
                hits.push((k, xi, g));
            }
            // coverage is checked on the converged state only: an intermediate iterate may
            // move a node at the end of a surface a hair past the other's end
            new.push(set.propose(p, &facts, &tolerances, &hits));
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
            let (n, _) = edge_normal(s0, s1);
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
}
