//! The locks of an increment: which alternations of a cycling set are benign, and what a
//! locked node must satisfy at convergence.
//!
//! * A node on the edge of the friction cone alternating between stick (violating the cone)
//!   and slip (whose slip reverses) sits on the cone with a vanishing slip: it is **locked in
//!   slip** and may not return to stick. At convergence it may slide against its friction by
//!   at most [`SLIP_REVERSAL`] of the motion scale ([`ActiveSet::slip_reversal`]).
//! * A node on the edge of the contact zone alternating between closed (in tension by a hair)
//!   and open (penetrating by a hair) has zero traction and zero gap to round-off: it is
//!   **locked open** and may not close. At convergence it may penetrate by at most
//!   [`EDGE_PENETRATION`] of the gap scale ([`ActiveSet::edge_penetration`]).

use super::super::{NodeState, Tangential};
use super::{ActiveSet, NodeKey};

/// How far a node locked open after an open/closed cycle may penetrate at convergence,
/// relative to the increment's displacement scale (the gap scale, `gap_scale`).
pub(in crate::contact::iteration) const EDGE_PENETRATION: f64 = 1e-4;

/// How far a node locked in slip after a stick/slip cycle may slide against its friction at
/// convergence, relative to the increment's motion (the motion scale, `motion_scale`): the
/// same hair as [`EDGE_PENETRATION`].
pub(in crate::contact::iteration) const SLIP_REVERSAL: f64 = EDGE_PENETRATION;

/// The locks of an increment.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(in crate::contact::iteration) struct Locks {
    /// Nodes locked in slip (they may not return to stick).
    pub(in crate::contact::iteration) slip: Vec<NodeKey>,
    /// Nodes locked open (they may not close).
    pub(in crate::contact::iteration) open: Vec<NodeKey>,
}

/// A locked node that breaks its lock's condition at convergence: the node, the amount (a
/// depth or a slip against the friction) and the amount relative to its scale.
pub(in crate::contact::iteration) type Breach = (NodeKey, f64, f64);

impl ActiveSet {
    /// The first node locked open that penetrates at convergence by more than
    /// [`EDGE_PENETRATION`] of its scale: the cycle was not an edge effect. `gap(node)` is the
    /// node's weighted normal gap and the pair's gap scale.
    pub(in crate::contact::iteration) fn edge_penetration(
        &self,
        gap: impl Fn(NodeKey) -> (f64, f64),
    ) -> Option<Breach> {
        self.locks().open.iter().find_map(|&node| {
            let (gap, scale) = gap(node);
            (gap < -EDGE_PENETRATION * scale).then_some((node, -gap, -gap / scale))
        })
    }

    /// The first node locked in slip that slides against its friction (`-d . v` along its
    /// slip direction `d`) at convergence by more than [`SLIP_REVERSAL`] of its scale: it was
    /// not on the cone's edge. `slip(node)` is the node's slip since the increment began and
    /// the pair's motion scale.
    pub(in crate::contact::iteration) fn slip_reversal(
        &self,
        slip: impl Fn(NodeKey) -> (Tangential, f64),
    ) -> Option<Breach> {
        self.locks().slip.iter().find_map(|&(p, k)| {
            let NodeState::Slip { direction } = self.states()[p][k] else {
                return None;
            };
            let (v, scale) = slip((p, k));
            let against = -direction.along(&v);
            (against > SLIP_REVERSAL * scale).then_some(((p, k), against, against / scale))
        })
    }
}

/// The nodes that are stick in one state set and slip in the other, with the slip state.
pub(super) fn stick_slip_flips(
    a: &[Vec<NodeState>],
    b: &[Vec<NodeState>],
) -> Vec<(NodeKey, NodeState)> {
    let mut flips = Vec::new();
    for (p, (sa, sb)) in a.iter().zip(b).enumerate() {
        for (k, (&x, &y)) in sa.iter().zip(sb).enumerate() {
            match (x, y) {
                (NodeState::Stick, slip @ NodeState::Slip { .. })
                | (slip @ NodeState::Slip { .. }, NodeState::Stick) => flips.push(((p, k), slip)),
                _ => {}
            }
        }
    }
    flips
}

/// The nodes that are open in one state set and closed in the other.
pub(super) fn open_closed_flips(a: &[Vec<NodeState>], b: &[Vec<NodeState>]) -> Vec<NodeKey> {
    let mut flips = Vec::new();
    for (p, (sa, sb)) in a.iter().zip(b).enumerate() {
        for (k, (&x, &y)) in sa.iter().zip(sb).enumerate() {
            if (x == NodeState::Open) != (y == NodeState::Open) {
                flips.push((p, k));
            }
        }
    }
    flips
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::tangent::SlipDirection;

    /// A locked node breaks its lock only beyond its hair: a node locked open penetrating by
    /// more than `1e-4` of the gap scale, a node locked in slip sliding against its friction
    /// (here on a face, a slip along `(0.6, 0.8)` sliding back along `-(0.6, 0.8)`) by more
    /// than `1e-4` of the motion scale.
    #[test]
    fn locked_nodes_are_held_to_their_hair() {
        let d = SlipDirection::of(Tangential::on_face(0.6, 0.8)).unwrap();
        let slip = NodeState::Slip { direction: d };
        let locks = Locks {
            slip: vec![(0, 0)],
            open: vec![(0, 1)],
        };
        let set = ActiveSet::new(vec![vec![slip, NodeState::Open]], locks, 1);
        assert_eq!(set.edge_penetration(|_| (-0.9e-4, 1.0)), None);
        assert_eq!(
            set.edge_penetration(|_| (-3e-4, 2.0)),
            Some(((0, 1), 3e-4, 1.5e-4))
        );
        let back = |s: f64| move |_| (Tangential::on_face(-0.6 * s, -0.8 * s), 1.0);
        assert_eq!(set.slip_reversal(back(0.9e-4)), None);
        let (node, against, _) = set.slip_reversal(back(2e-4)).unwrap();
        assert_eq!(node, (0, 0));
        assert!((against - 2e-4).abs() < 1e-18);
        // sliding with its friction is no breach however far
        assert_eq!(set.slip_reversal(back(-1.0)), None);
    }
}
