//! The contact states of one increment and their one owner: every decision about a node's
//! state is made here, on plain data that the iteration gathers.
//!
//! | decision | where |
//! |---|---|
//! | the paper's rules proposing the next states (activate on penetration, drop tensile, stick -> slip past the cone, slip -> stick on reversal) | [`ActiveSet::propose`] (`rules.rs`) |
//! | which penetrating nodes close (runs, halves, new regions) | [`ActiveSet::closing`] (`rules.rs`) |
//! | which closed state a closing node takes (stick, slip with the surfaces, frictionless) | [`closed_state`](rules::closed_state), [`closed_at_rest`] (`rules.rs`) |
//! | how B nodes over open A elements are judged (pointwise, or only at convergence); a penetrating one closes the A node the geometry finds nearest to it ([`BNodeHit`]) | [`BNodes`], [`ActiveSet::judging`], [`ActiveSet::b_node_judges`], [`ActiveSet::propose`] |
//! | what each state adds to the small system | [`rows_of`] (`rules.rs`) |
//! | the states of the fallback's solution | [`linearized_state`] (`rules.rs`) |
//! | the plate's first support | [`close_nearest`] (`rules.rs`) |
//! | a returning set: benign (locked) or a cycle | [`ActiveSet::commit`] (here) |
//! | the locks and what a locked node must satisfy at convergence | [`Locks`], [`ActiveSet::edge_penetration`], [`ActiveSet::slip_reversal`] (`locks.rs`) |
//! | whether an iterate has converged | [`Convergence`] (`convergence.rs`) |
//!
//! The rules read per node a [`NodeFacts`] (traction, weighted gap, slip since the increment
//! began, friction law) and per pair the [`Tolerances`]; the iteration (`iteration/checks.rs`)
//! gathers them from the geometry and the solve, so that a 3D geometry feeds the same
//! decisions. The friction cone is the law's ([`FrictionLaw`](super::FrictionLaw)): the
//! rules read slip directions and tangential tractions as vectors of the tangent space.
//!
//! The [`ActiveSet`] holds the current states, the locks the rules respect and the history of
//! the increment, and decides what happens when a state set comes back. Two alternations are
//! benign and resolved by a lock (at most `lock_rounds` times per increment, `locks.rs`): a
//! node alternating between stick and slip is locked in slip, one alternating between open and
//! closed is locked open. Any other returning set is a cycle, reported with a node that flips.
//! Sets are compared node by node with [`NodeState::same_as`]: slip directions by their angle
//! (in the plane `+s` and `-s`, equal or not; on a 3D face, the same to round-off).

use super::NodeState;

mod convergence;
mod locks;
mod rules;
pub(super) use convergence::{Convergence, Iterate};
pub(super) use locks::{EDGE_PENETRATION, Locks};
use locks::{open_closed_flips, stick_slip_flips};
pub(super) use rules::{
    BNodeHit, LINEARIZED_CONE, NodeFacts, Rows, Tolerances, close_nearest, closed_at_rest,
    closed_next, linearized_state, rows_of,
};

/// A node of the iteration: (pair, index of the A node in the pair).
pub(super) type NodeKey = (usize, usize);

/// What [`ActiveSet::commit`] did with a proposal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Commit {
    /// The proposal is the new state set (possibly after locking the nodes of a benign
    /// alternation).
    Accepted,
    /// The proposal returns to the set of an earlier iteration of this history (1-based), and
    /// no lock resolves it; `node` is one that flips.
    Cycle {
        /// The earlier iteration whose set it is.
        returns_to: usize,
        /// A node whose state differs between that set and the current one.
        node: NodeKey,
    },
}

/// How the rules judge a B node that penetrates an A segment whose two nodes are open.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum BNodes {
    /// In every iteration: the rules close the nearer A node (the paper's rules, the default).
    Pointwise,
    /// Only at convergence, by the condition check (the fallback's last attempt, and the
    /// same totals again after it): the rules leave such B nodes alone.
    AtConvergence,
}

/// The states of every A node during one increment, with the locks, the way B nodes are
/// judged, and the history.
#[derive(Debug, Clone)]
pub(super) struct ActiveSet {
    states: Vec<Vec<NodeState>>,
    locks: Locks,
    b_nodes: BNodes,
    /// The state sets since the increment began, or since the last lock.
    history: Vec<Vec<Vec<NodeState>>>,
    /// Lock rounds used and allowed.
    rounds: usize,
    max_rounds: usize,
}

impl ActiveSet {
    /// Start an increment from `states` (the last converged ones) and `locks` (none, or those
    /// of the last increment when it is repeated with the same totals: it then settles at
    /// once on the same state) with at most `max_rounds` lock rounds.
    pub(super) fn new(states: Vec<Vec<NodeState>>, locks: Locks, max_rounds: usize) -> Self {
        ActiveSet {
            history: vec![states.clone()],
            states,
            locks,
            b_nodes: BNodes::Pointwise,
            rounds: 0,
            max_rounds,
        }
    }

    /// The set with B nodes judged as `b_nodes` (the default: [`BNodes::Pointwise`]).
    pub(super) fn judging(mut self, b_nodes: BNodes) -> Self {
        self.b_nodes = b_nodes;
        self
    }

    /// How the rules judge B nodes over open A segments.
    pub(super) fn b_nodes(&self) -> BNodes {
        self.b_nodes
    }

    /// The locks so far.
    pub(super) fn locks(&self) -> &Locks {
        &self.locks
    }

    /// The current states, per pair, per A node.
    pub(super) fn states(&self) -> &[Vec<NodeState>] {
        &self.states
    }

    /// Whether the rules may turn slip node `node` back into stick (not locked in slip).
    pub(super) fn may_stick(&self, node: NodeKey) -> bool {
        !self.locks.slip.contains(&node)
    }

    /// Whether the rules may close open node `node` (not locked open).
    pub(super) fn may_close(&self, node: NodeKey) -> bool {
        !self.locks.open.contains(&node)
    }

    /// How many nodes `proposed` changes.
    pub(super) fn changes(&self, proposed: &[Vec<NodeState>]) -> usize {
        proposed
            .iter()
            .flatten()
            .zip(self.states.iter().flatten())
            .filter(|(a, b)| !a.same_as(b))
            .count()
    }

    /// `(active, stick, slip)` counts of the current states.
    pub(super) fn count(&self) -> (usize, usize, usize) {
        count(&self.states)
    }

    /// Take the rules' proposal as the next states. A set seen before in the history is a
    /// cycle: if the nodes that differ between it and the current set include stick/slip or
    /// open/closed alternations and lock rounds are left, those nodes are locked (in slip or
    /// open), the history restarts, and the locked proposal is accepted; otherwise the cycle is
    /// returned and the states stay as they were.
    pub(super) fn commit(&mut self, mut proposed: Vec<Vec<NodeState>>) -> Commit {
        if same_set(&proposed, &self.states) {
            return Commit::Accepted;
        }
        let Some(j) = self.history.iter().position(|h| same_set(h, &proposed)) else {
            self.history.push(proposed.clone());
            self.states = proposed;
            return Commit::Accepted;
        };
        let earlier = &self.history[j];
        let flips = stick_slip_flips(earlier, &self.states);
        let edges = open_closed_flips(earlier, &self.states);
        if (flips.is_empty() && edges.is_empty()) || self.rounds >= self.max_rounds {
            let node = first_difference(earlier, &self.states).unwrap_or((0, 0));
            return Commit::Cycle {
                returns_to: j + 1,
                node,
            };
        }
        self.rounds += 1;
        for (node, slip) in flips {
            self.locks.slip.push(node);
            proposed[node.0][node.1] = slip;
        }
        for node in edges {
            self.locks.open.push(node);
            proposed[node.0][node.1] = NodeState::Open;
        }
        self.history = vec![proposed.clone()];
        self.states = proposed;
        Commit::Accepted
    }
}

/// Whether two state sets are the same node by node ([`NodeState::same_as`]).
fn same_set(a: &[Vec<NodeState>], b: &[Vec<NodeState>]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(sa, sb)| sa.len() == sb.len() && sa.iter().zip(sb).all(|(x, y)| x.same_as(y)))
}

/// `(active, stick, slip)` counts (active: every state but open, frictionless included).
pub(super) fn count(states: &[Vec<NodeState>]) -> (usize, usize, usize) {
    let all = states.iter().flatten();
    let active = all.clone().filter(|s| **s != NodeState::Open).count();
    let stick = all.clone().filter(|s| **s == NodeState::Stick).count();
    let slip = all
        .clone()
        .filter(|s| matches!(s, NodeState::Slip { .. }))
        .count();
    (active, stick, slip)
}

/// The first node whose state differs between two state sets.
fn first_difference(a: &[Vec<NodeState>], b: &[Vec<NodeState>]) -> Option<NodeKey> {
    a.iter().zip(b).enumerate().find_map(|(p, (sa, sb))| {
        (sa.iter().zip(sb))
            .position(|(x, y)| !x.same_as(y))
            .map(|k| (p, k))
    })
}

#[cfg(test)]
mod tests {
    use super::super::{SlipDirection, Tangential};
    use super::*;

    const SLIP: NodeState = NodeState::Slip {
        direction: SlipDirection::PLUS,
    };

    /// A stick/slip alternation is locked in slip, an open/closed one locked open; a cycle of
    /// another kind, or one past the lock rounds, is reported with a flipping node.
    #[test]
    fn locks_resolve_benign_cycles_and_report_the_rest() {
        use NodeState::{Open, Stick};
        let mut set = ActiveSet::new(vec![vec![Stick, Open]], Locks::default(), 1);
        assert_eq!(set.commit(vec![vec![SLIP, Open]]), Commit::Accepted);
        // back to the first set: node (0, 0) alternates stick/slip -> locked in slip
        assert_eq!(set.commit(vec![vec![Stick, Open]]), Commit::Accepted);
        assert_eq!(set.states(), &[vec![SLIP, Open]]);
        assert!(!set.may_stick((0, 0)) && set.may_close((0, 1)));
        // a second benign cycle, but the one lock round is used up
        assert_eq!(set.commit(vec![vec![SLIP, Stick]]), Commit::Accepted);
        assert_eq!(
            set.commit(vec![vec![SLIP, Open]]),
            Commit::Cycle {
                returns_to: 1,
                node: (0, 1)
            }
        );
        assert_eq!(
            set.states(),
            &[vec![SLIP, Stick]],
            "a cycle keeps the states"
        );

        let mut edge = ActiveSet::new(vec![vec![Open]], Locks::default(), 3);
        assert_eq!(edge.commit(vec![vec![SLIP]]), Commit::Accepted);
        assert_eq!(edge.commit(vec![vec![Open]]), Commit::Accepted);
        assert_eq!(edge.states(), &[vec![Open]]);
        assert!(!edge.may_close((0, 0)));
        assert_eq!(edge.locks().open, [(0, 0)]);
        assert_eq!(edge.changes(&[vec![SLIP]]), 1);
        assert_eq!(edge.count(), (0, 0, 0));
    }

    /// The cycle check compares slip directions, not signs: on a face (two tangents) a slip
    /// whose direction comes back to round-off closes a cycle (locked as a benign stick/slip
    /// alternation), while a turned direction is a new set; in the plane `-s` is not `+s`.
    #[test]
    fn cycles_compare_slip_directions() {
        use NodeState::Stick;
        let slip = |s1: f64, s2: f64| NodeState::Slip {
            direction: SlipDirection::of(Tangential::on_face(s1, s2)).unwrap(),
        };
        let mut set = ActiveSet::new(vec![vec![slip(1.0, 1.0)]], Locks::default(), 0);
        assert_eq!(set.commit(vec![vec![slip(1.0, -1.0)]]), Commit::Accepted);
        assert_eq!(set.commit(vec![vec![Stick]]), Commit::Accepted);
        // back to the first direction, up to round-off: a cycle (no lock rounds)
        assert_eq!(
            set.commit(vec![vec![slip(1.0, 1.0 + 1e-15)]]),
            Commit::Cycle {
                returns_to: 1,
                node: (0, 0)
            }
        );
        // the same proposal as the current set is no change
        assert_eq!(set.changes(&[vec![Stick]]), 0);
        // turned by a quarter: a set not seen before
        assert_eq!(set.commit(vec![vec![slip(-1.0, 1.0)]]), Commit::Accepted);
        // a stick/slip alternation with a direction is locked in that slip
        let mut locking = ActiveSet::new(vec![vec![Stick]], Locks::default(), 1);
        assert_eq!(locking.commit(vec![vec![slip(0.0, 2.0)]]), Commit::Accepted);
        assert_eq!(locking.commit(vec![vec![Stick]]), Commit::Accepted);
        assert!(locking.states()[0][0].same_as(&slip(0.0, 1.0)));
        assert!(!locking.may_stick((0, 0)));
        // in the plane the two directions differ
        let plus = NodeState::Slip {
            direction: SlipDirection::PLUS,
        };
        let minus = NodeState::Slip {
            direction: SlipDirection::MINUS,
        };
        assert!(!plus.same_as(&minus) && plus.same_as(&plus));
    }
}
