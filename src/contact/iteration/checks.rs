//! The measures of an iterate: the facts the active set's rules judge, the convergence
//! measure, the breach of the discrete contact conditions, and what a converged increment must
//! also satisfy (active nodes fully covered, the locks held (gathered here, judged by the
//! active set: `active_set/locks.rs`), small kinematics within their range).
//!
//! # The facts the rules judge
//!
//! After each solve the iteration reads, per A node, its traction, weighted normal gap and
//! slip since the increment began ([`NodeFacts`]), per pair the rules' tolerances as lengths
//! ([`Tolerances`]: the gap and slip tolerances times the pair's gap and motion scales, below),
//! and the B nodes inside A elements whose nodes are all open with the A node each would close
//! (the geometry's
//! [`b_node_distances`](crate::contact::geometry::ContactGeometry::b_node_distances)); the
//! decisions on them are the active set's ([`ActiveSet::propose`], `active_set/rules.rs`, with
//! the rules' table).
//!
//! When the rules do not settle, the increment starts again from the fallback's states
//! (`fallback.rs`).

use super::small_system::kept_tangents;
use super::{
    ActiveSet, BNodeHit, BNodes, ContactAnalysis, ContactError, ContactSurface, EDGE_PENETRATION,
    Kinematics, Locks, NodeFacts, NodeKey, NodeState, Result, Tangential, Tolerances, Traction,
    dot,
};
use crate::contact::geometry::ContactNode;
use crate::contact::space::Vector;

/// Under small kinematics, the largest change of an active node's gap caused by sliding with
/// the pairing frozen (slip times the angle between the surfaces), relative to the contact's
/// normal approach (the largest change of a normal gap over the active nodes); beyond it the
/// increment fails and names the node.
pub const SMALL_SLIDING_LIMIT: f64 = 0.1;

/// Round-off level of a displacement, relative to its size: iterates that differ by less than
/// this times `|u|` are the same to the precision the geometry can be evaluated at.
pub(super) const ROUND_OFF: f64 = 1e4 * f64::EPSILON;

/// Round-off level of the positions, relative to their size: the contact geometry works on
/// positions `X + u`, so where the coordinates are large (a model far from its origin) it
/// cannot resolve displacement changes below this times `|X|`.
pub(super) const POSITION_ROUND_OFF: f64 = 64.0 * f64::EPSILON;

/// The largest length of a contact node's displacement from `before` to `after` (both over
/// the contact dofs, a node's `dim` components side by side).
pub(super) fn largest_node_motion(after: &[f64], before: &[f64], dim: usize) -> f64 {
    let length = |a: &[f64], b: &[f64]| match (a, b) {
        ([a0, a1], [b0, b1]) => (a0 - b0).hypot(a1 - b1),
        _ => (a.iter().zip(b)).fold(0.0, |h: f64, (x, y)| h.hypot(x - y)),
    };
    (after.chunks_exact(dim).zip(before.chunks_exact(dim)))
        .map(|(a, b)| length(a, b))
        .fold(0.0, f64::max)
}

/// The convergence measure over the contact dofs,
/// `R = |u_new - u_old| / max(|u_new - u_start|, ROUND_OFF |u_new| / tolerance, floor)`: the
/// change of the last iteration relative to the increment's motion, so that `R <= tolerance`
/// once the iterate changes by less than `tolerance` times the increment's motion, by less than
/// round-off of the displacement, or by less than `tolerance` times `floor` (a scale the caller
/// knows the iterate cannot resolve below: see `ContactAnalysis::resolution`). The lower
/// bounds keep a zero or tiny increment (a host repeating its totals) from measuring round-off
/// against round-off. 0 when nothing moved.
pub(super) fn change_ratio(
    new: &[f64],
    old: &[f64],
    start: &[f64],
    floor: f64,
    tolerance: f64,
) -> f64 {
    let difference =
        |a: &[f64], b: &[f64]| -> Vec<f64> { a.iter().zip(b).map(|(x, y)| x - y).collect() };
    let change = norm2(&difference(new, old));
    let motion = norm2(&difference(new, start));
    let scale = motion.max(ROUND_OFF * norm2(new) / tolerance).max(floor);
    if scale == 0.0 { change } else { change / scale }
}

/// The Euclidean norm `|v|`, scaled by `max |v_i|` so that it overflows only when the result
/// does (a vector of entries near 1e300 has a finite norm, not `inf`).
pub(super) fn norm2(v: &[f64]) -> f64 {
    let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return scale;
    }
    scale * v.iter().map(|x| (x / scale).powi(2)).sum::<f64>().sqrt()
}

/// The tangential vector of `node` whose component along each kept frame tangent `s_i` is
/// `along(s_i)` (0 along a dropped tangent: [`kept_tangents`]), one component per tangent.
fn tangential_parts(node: &ContactNode, along: impl Fn(&Vector) -> f64) -> Tangential {
    let mut v = Tangential::zero(node.frame.tangents().len());
    for (i, s) in kept_tangents(&node.frame) {
        v.components_mut()[i] = along(&s);
    }
    v
}

impl ContactAnalysis {
    /// The length against which gaps of pair `p` are judged: the
    /// [`motion_scale`](Self::motion_scale) bounded above by the mean A segment length `h`, so
    /// that tiny loads still close the contact, the judgement does not depend on units, and a
    /// repeated increment accepts the gaps its predecessors accepted (judged against its own
    /// vanishing motion, a node left open a hair inside the tolerance would close and reopen).
    pub(super) fn gap_scale(&self, p: usize, xg: &[f64], uc: &[f64], startc: &[f64]) -> f64 {
        let h = self.surfaces.geometries[p].mean_size(xg);
        self.motion_scale(p, xg, uc, startc).min(h)
    }

    /// The length against which slips of pair `p` are judged: the largest motion of a contact
    /// node (the length of its displacement change) in this increment or in any converged
    /// one, bounded below by `1e-12 h`. Unbounded above, so that a slip is told from round-off
    /// however far the bodies move, and scaling every load by `s` scales the slips and their
    /// threshold alike; a length, not a component, so that rotating the model changes no
    /// threshold (by components, a rotation by 0.6 rad changed the tractions of round 83973 of
    /// `contact_randomized 1000 1` by 1.8e-4 of their peak).
    pub(super) fn motion_scale(&self, p: usize, xg: &[f64], uc: &[f64], startc: &[f64]) -> f64 {
        let h = self.surfaces.geometries[p].mean_size(xg);
        let motion = largest_node_motion(uc, startc, self.dim());
        motion.max(self.driver.largest_node_motion).max(1e-12 * h)
    }

    /// The checks of the locks at convergence ([`ActiveSet::edge_penetration`],
    /// [`ActiveSet::slip_reversal`]): a node locked open must not penetrate by more than its
    /// hair of the gap scale, a node locked in slip must not slide against its friction by more
    /// than its hair of the motion scale; otherwise the cycle was not an edge effect and the
    /// increment fails naming the node.
    pub(super) fn locks_hold(
        &self,
        number: usize,
        surfaces: &[ContactSurface],
        set: &ActiveSet,
        uc: &[f64],
        startc: &[f64],
    ) -> Result<()> {
        if set.locks() == &Locks::default() {
            return Ok(());
        }
        let x = self.positions(uc);
        let xg = self.geometry_positions(&x);
        let gap = |(p, k): NodeKey| {
            (
                surfaces[p].nodes[k].normal_gap,
                self.gap_scale(p, xg, uc, startc),
            )
        };
        if let Some((node, depth, relative)) = set.edge_penetration(gap) {
            return Err(ContactError::EdgePenetration {
                increment: number,
                node: self.external_a(node),
                depth,
                relative,
            }
            .into());
        }
        let slip = |(p, k): NodeKey| {
            let slip = self.slip_since_start(&surfaces[p].nodes[k], uc, startc);
            (slip, self.motion_scale(p, xg, uc, startc))
        };
        if let Some((node, slip, relative)) = set.slip_reversal(slip) {
            return Err(ContactError::SlipReversal {
                increment: number,
                node: self.external_a(node),
                slip,
                relative,
            }
            .into());
        }
        Ok(())
    }

    /// The tangential slip of A relative to B at `node` since the increment began, per unit
    /// length, in the node's tangent space: `s_ki = (r_ki . (u - u_start)) / w_k` along each
    /// frame tangent `s_i`, `r_ki` the node's row along it (its coupling along `s_i`) and
    /// `w_k` its weight; 0 along a dropped tangent.
    pub(super) fn slip_since_start(
        &self,
        node: &ContactNode,
        uc: &[f64],
        startc: &[f64],
    ) -> Tangential {
        tangential_parts(node, |s| {
            let row = self.boundary.directed(&node.coupling, s);
            (dot(&row, uc) - dot(&row, startc)) / node.weight
        })
    }

    /// Under small kinematics the pairing of A with B is frozen in the reference configuration.
    /// When the surfaces slide along each other by `slip_ki = s_ki . sum_j c_kj u_j / covered
    /// weight` along each kept tangent `s_ki` at node `k` (the mean tangential displacement of
    /// A relative to B over the node's support), the frozen pairing misplaces B by `slip_k`,
    /// which changes the gap by about `|slip_k| |dg0/ds|_k`, `|dg0/ds|` the slope of the
    /// reference gap along A (the angle between the surfaces). That is the linearization that
    /// Hertz theory makes too, harmless while it is small against the contact's normal
    /// approach `delta` (the largest change of a normal gap over the active nodes); an active
    /// node whose error exceeds [`SMALL_SLIDING_LIMIT`] `delta` fails the increment, naming
    /// the node and pointing to finite kinematics.
    pub(super) fn small_sliding(
        &self,
        number: usize,
        states: &[Vec<NodeState>],
        uc: &[f64],
    ) -> Result<()> {
        if self.options.kinematics != Kinematics::Small {
            return Ok(());
        }
        let active = || {
            self.surfaces
                .reference
                .iter()
                .zip(states)
                .enumerate()
                .flat_map(|(p, (surface, states))| {
                    surface
                        .nodes
                        .iter()
                        .enumerate()
                        .zip(states)
                        .filter(|(_, s)| **s != NodeState::Open)
                        .map(move |((k, node), _)| (p, surface, k, node))
                })
        };
        let along = |node: &ContactNode, d: Vector| {
            let change = self.boundary.coupled((&node.coupling, self.dim()), uc);
            d.dot(&change) / node.covered_weight
        };
        let delta = active()
            .map(|(_, _, _, node)| along(node, node.frame.normal()).abs())
            .fold(0.0, f64::max);
        let x = self.bodies.positions();
        for (p, surface, k, node) in active() {
            let slope = self.surfaces.geometries[p].gap_slope(surface, k, x);
            let slip = tangential_parts(node, |s| along(node, *s));
            // |slip| |dg0/ds| (in the plane |slip_k| is the component's magnitude: the
            // product's magnitude to the bit)
            let error = slip.norm() * slope;
            if error > SMALL_SLIDING_LIMIT * delta {
                return Err(ContactError::SmallSlidingExceeded {
                    increment: number,
                    node: self.bodies.external(node.node),
                    slip: match slip.components() {
                        [s] => *s,
                        _ => slip.norm(),
                    },
                    relative: error / delta,
                }
                .into());
            }
        }
        Ok(())
    }

    /// Every active node of a converged state must have its support fully covered by the
    /// opposite surface (never integrate over a hole silently).
    pub(super) fn uncovered(
        &self,
        surfaces: &[ContactSurface],
        states: &[Vec<NodeState>],
    ) -> Result<()> {
        for (surface, states) in surfaces.iter().zip(states) {
            for (node, state) in surface.nodes.iter().zip(states) {
                if *state != NodeState::Open && node.coverage < 1.0 - 1e-9 {
                    return Err(ContactError::Uncovered {
                        node: self.bodies.external(node.node),
                        coverage: node.coverage,
                    }
                    .into());
                }
            }
        }
        Ok(())
    }

    /// No node that the pairing does not see may have passed through the opposite surface. An
    /// open A node with no B segment within the search distance (an infinite gap) is tested at
    /// the current positions against every B segment, without a search window
    /// ([`ContactGeometry::behind`](crate::contact::geometry::ContactGeometry::behind)): penetrating B by more than the gap tolerance fails the increment,
    /// naming the node. This catches a surface pushed through the other in one increment
    /// (any depth, any coordinate magnitude) and, under small kinematics, a node that was out
    /// of reach in the reference configuration and penetrates now. (B nodes over open A
    /// segments are tested the same way by the iteration's rules.)
    pub(super) fn passed_through(
        &self,
        surfaces: &[ContactSurface],
        states: &[Vec<NodeState>],
        uc: &[f64],
        startc: &[f64],
    ) -> Result<()> {
        let x = self.positions(uc);
        let xg = self.geometry_positions(&x);
        for (p, (surface, states)) in surfaces.iter().zip(states).enumerate() {
            let pair = &self.surfaces.pairs[p];
            let limit = self.options.gap_tolerance * self.gap_scale(p, xg, uc, startc);
            let lost = surface
                .nodes
                .iter()
                .zip(states)
                .enumerate()
                .filter(|(_, (node, state))| {
                    **state == NodeState::Open && !node.normal_gap.is_finite()
                });
            for (k, _) in lost {
                if let Some((element, depth)) = self.surfaces.geometries[p].behind(k, &x, limit) {
                    return Err(ContactError::BeyondSearchDistance {
                        node: self.bodies.external(pair.a[k]),
                        element: element.iter().map(|&n| self.bodies.external(n)).collect(),
                        depth,
                        search_distance: self.search_reach(p, xg, uc, startc),
                    }
                    .into());
                }
            }
        }
        Ok(())
    }
}

/// A converged state may violate the discrete contact conditions by at most this, relative to
/// the problem's scale (see [`IterationRecord::violation`](super::IterationRecord::violation)):
/// the hair that a node locked open or in slip is allowed (`1e-4` of the gap or motion scale,
/// the limits the cycle locks are held to); the rules themselves hold the other nodes to their
/// tolerances (`1e-9` and `1e-6` by default).
pub const CONDITION_LIMIT: f64 = EDGE_PENETRATION;

/// The violated condition when a B node penetrates between two open A nodes, with what the
/// user can do. Of the 127 such failures of `hycon bench presses --count 20000 --seed 1`
/// (wide ranges), 126 have a stiffer body A (modulus ratio 11 to 1e4) and 126 B segments
/// longer than A's: B's nodes poke between A's, closing the nearer A node puts it in
/// tension, and no state satisfies the conditions. With B's segments halved or quartered 123
/// of the 127 settle (making the softer body A instead leaves A's nodes beyond the narrower
/// B uncovered).
pub(super) const B_NODE_PENETRATES: &str = "a B node penetrates between two open A nodes \
     (refine the B surface: its nodes fall between A's)";

/// The worst violation of the discrete contact conditions in a state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Violation {
    /// The violation relative to its scale (0: every condition holds).
    pub(super) relative: f64,
    /// The A node where it is worst.
    pub(super) node: NodeKey,
    /// Which condition, in words.
    pub(super) condition: &'static str,
}

impl ContactAnalysis {
    /// The worst violation of the discrete contact conditions, node by node, in the state
    /// `states` with tractions `tractions` at displacement `uc` (docs/method.md, "The checks at convergence"), each
    /// relative to its scale: gaps to the gap scale `g_s` of the pair
    /// ([`gap_scale`](Self::gap_scale)), tractions to the pair's largest `|tn|`, slips
    /// (weighted, since the increment began) to the motion scale `v_s`
    /// ([`motion_scale`](Self::motion_scale)):
    ///
    /// ```text
    /// open:           gap >= 0                       max(0, -gap) / g_s
    /// closed:         p = -tn >= 0                   max(0, tn) / tn_max
    ///                 gap = 0 (complementarity)      |gap| / g_s
    /// stick:          |ts| <= mu p                   max(0, |ts| - mu p) / tn_max
    ///                 no slip                        |v| / v_s
    /// slip:           slip opposes ts (d . v >= 0)    max(0, -d . v) / v_s
    ///                 slip along d (on a face)       |v - (d . v) d| / v_s
    /// B node over an A segment whose two nodes are open (pointwise):
    ///                 distance >= 0                  max(0, -distance) / g_s
    /// ```
    ///
    /// The last line is measured only when the rules do not check B nodes themselves
    /// (`b_nodes` is [`BNodes::AtConvergence`]: the fallback's last attempt, see `fallback.rs`): otherwise the rules close the nearer A node
    /// of a B node that penetrates by more than the gap tolerance (a node locked open
    /// excepted, as 0.6.2 did: beside one, a B node may end up through A's segment by about
    /// `1e-3` of the gap scale, as in the axisymmetric sphere of
    /// `lab/tests/contact_axisymmetric.rs`, whose results are validated against Hertz).
    ///
    /// (`d` is a slip node's direction; it carries `ts = mu tn d` by construction, a frictionless
    /// node `ts = 0`).
    pub(super) fn violation(
        &self,
        surfaces: &[ContactSurface],
        states: &[Vec<NodeState>],
        tractions: &[Vec<Traction>],
        b_nodes: BNodes,
        uc: &[f64],
        startc: &[f64],
    ) -> Violation {
        let x = self.positions(uc);
        let xg = self.geometry_positions(&x);
        let mut worst = Violation {
            relative: 0.0,
            node: (0, 0),
            condition: "none",
        };
        for (p, surface) in surfaces.iter().enumerate() {
            let gap_scale = self.gap_scale(p, xg, uc, startc);
            // a closed node's gap and a stick node's slip are solved for: what is left of them
            // is round-off of the motion, however far the bodies move
            let motion_scale = self.motion_scale(p, xg, uc, startc);
            let tn_max = tractions[p]
                .iter()
                .fold(0.0f64, |m, t| m.max(t.normal.abs()));
            let per_traction = |v: f64| if tn_max > 0.0 { v / tn_max } else { 0.0 };
            let law = &*self.surfaces.laws[p];
            for (k, node) in surface.nodes.iter().enumerate() {
                let Traction {
                    normal: tn,
                    tangential: ts,
                } = tractions[p][k];
                let gap = node.normal_gap;
                let slip = || self.slip_since_start(node, uc, startc);
                let mut found = |relative: f64, condition: &'static str| {
                    if relative > worst.relative {
                        worst = Violation {
                            relative,
                            node: (p, k),
                            condition,
                        };
                    }
                };
                if states[p][k] == NodeState::Open {
                    if gap.is_finite() {
                        found(-gap / gap_scale, "an open node penetrates");
                    }
                    continue;
                }
                found(per_traction(tn), "a closed node is in tension");
                found(
                    gap.abs() / motion_scale,
                    "a closed node's gap is not closed",
                );
                match states[p][k] {
                    NodeState::Stick => {
                        found(
                            per_traction(ts.norm() - law.stick_limit(tn)),
                            "a stick node is outside the friction cone",
                        );
                        found(slip().norm() / motion_scale, "a stick node slides");
                    }
                    NodeState::Slip { direction } if !law.is_frictionless() => {
                        let slip = slip();
                        let along = direction.along(&slip);
                        found(
                            -along / motion_scale,
                            "a slip node slides against its friction",
                        );
                        // on a face the slip must be parallel to the direction too: its part
                        // across it (exactly 0 in the plane, where `d = +-1`)
                        found(
                            (slip - direction.vector().scaled(along)).norm() / motion_scale,
                            "a slip node slides across the direction of its friction",
                        );
                    }
                    _ => {}
                }
            }
            if b_nodes == BNodes::Pointwise {
                // the rules hold these: they close the nearer A node
                continue;
            }
            let open: Vec<bool> = states[p].iter().map(|s| *s == NodeState::Open).collect();
            for d in self.surfaces.geometries[p].b_node_distances(&open, &x, xg) {
                let (node, g) = ((p, d.nearest), d.distance);
                if -g / gap_scale > worst.relative {
                    worst = Violation {
                        relative: -g / gap_scale,
                        node,
                        condition: B_NODE_PENETRATES,
                    };
                }
            }
        }
        worst
    }
}

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
                    return Err(ContactError::BeyondSearchDistance {
                        node: self.bodies.external(d.node),
                        element: (d.element.iter())
                            .map(|&k| self.bodies.external(a[k]))
                            .collect(),
                        depth: -g,
                        search_distance: reach,
                    }
                    .into());
                }
                hits.push((d.nearest, g));
            }
            // coverage is checked on the converged state only: an intermediate iterate may
            // move a node at the end of a surface a hair past the other's end
            let adjacency = self.surfaces.geometries[p].adjacency();
            new.push(set.propose(p, &facts, &tolerances, &hits, adjacency));
        }
        Ok(new)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::space::Frame;

    /// A slip has one component per frame tangent: two on a 3D face (0 along a dropped
    /// tangent), one in the plane.
    #[test]
    fn tangential_parts_follow_the_frame() {
        let motion = Vector::solid(3.0, 4.0, 12.0);
        let along = |s: &Vector| s.dot(&motion);
        let mut node = ContactNode::empty(3);
        node.frame = Frame::face([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(
            tangential_parts(&node, along),
            Tangential::on_face(3.0, 4.0)
        );
        node.frame = Frame::face([0.0, 0.0, 1.0], [0.0; 3], [0.0, 1.0, 0.0]);
        assert_eq!(
            tangential_parts(&node, along),
            Tangential::on_face(0.0, 4.0)
        );
        let mut plane = ContactNode::empty(2);
        plane.frame = Frame::plane(Vector::plane(0.0, 1.0));
        let planar = Vector::plane(3.0, 4.0);
        assert_eq!(
            tangential_parts(&plane, |s| s.dot(&planar)),
            Tangential::along(3.0)
        );
    }
}
