//! The facts the active set's rules judge, gathered from the geometry and the solve.
//!
//! After each solve the iteration reads, per A node, its traction, weighted normal gap and
//! slip since the increment began ([`NodeFacts`]), per pair the rules' tolerances as lengths
//! ([`Tolerances`]: the gap and slip tolerances times the pair's gap and motion scales,
//! `checks.rs`), and the B nodes inside A elements whose nodes are all open with the A node
//! each would close (the geometry's
//! [`b_node_distances`](crate::contact::geometry::ContactGeometry::b_node_distances)); the
//! decisions on them are the
//! active set's ([`ActiveSet::propose`], `active_set/rules.rs`, with the rules' table).
//!
//! When the rules do not settle, the increment starts again from the fallback's states
//! (`fallback.rs`).

use super::{
    ActiveSet, BNodeHit, ContactAnalysis, ContactError, ContactSurface, NodeFacts, NodeState,
    Result, Tolerances, Traction,
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
                Some(open) => self.surfaces.geometries[p].b_node_distances(&open, &x, xg),
                None => Vec::new(),
            };
            let a = &self.surfaces.pairs[p].a;
            let mut hits: Vec<BNodeHit> = Vec::with_capacity(inside.len());
            for d in inside {
                let g = d.distance;
                if g < -tolerances.gap && g <= -reach {
                    let w = [a[d.element[0]], a[d.element[1]]];
                    return Err(ContactError::BeyondSearchDistance {
                        node: self.bodies.external(d.node),
                        segment: [self.bodies.external(w[0]), self.bodies.external(w[1])],
                        depth: -g,
                        search_distance: reach,
                    }
                    .into());
                }
                hits.push((d.nearest, g));
            }
            // coverage is checked on the converged state only: an intermediate iterate may
            // move a node at the end of a surface a hair past the other's end
            new.push(set.propose(p, &facts, &tolerances, &hits));
        }
        Ok(new)
    }
}
