//! The paper's rules on plain data: which state an A node takes next, which penetrating nodes
//! close, which closed state a closing node takes, what each state adds to the small system,
//! and the states of the fallback's solution.
//!
//! # The rules (docs/method.md, "The rules"), per A node after each solve
//!
//! | state | condition (after the solve) | next state |
//! |---|---|---|
//! | open | weighted gap `< -gap_tol` (or a B node over its open segments penetrates), and chosen by [`ActiveSet::closing`] | closed ([`closed_state`]): stick, slip (sliding since the increment began) or frictionless |
//! | stick, slip, frictionless | `tn > tension_tol tn_max` | open |
//! | stick | `|ts| > mu |tn| (1 + friction_tol)` | slip, in the direction `-ts / |ts|` |
//! | slip | slip reversed: `d . v < -slip_tol` along its direction `d` (not locked in slip) | stick |
//! | any | otherwise | unchanged |
//!
//! The rules read each node through [`NodeFacts`] (its traction, weighted gap, slip since the
//! increment began and friction law) and each pair through [`Tolerances`]: plain data, which
//! the iteration gathers from the geometry (`iteration/rules.rs`), so that a surface of any
//! dimension feeds the same decisions.
//!
//! What each state adds to the small system ([`rows_of`], read by `build_system`): open,
//! nothing; frictionless, the normal row (column `n`); stick, the normal row and the tangent
//! rows (no slip since the increment began); slip, the normal row with the column
//! `n + sum_i c_i s_i`, `c = mu d` the law's slip coefficients for the slip direction `d`.

use super::super::{FrictionLaw, NodeState, SlipDirection, Tangential, Traction};
use super::{ActiveSet, BNodes, NodeKey};
use crate::contact::geometry::Adjacency;

/// A run of penetrating nodes away from the contact zone closes where its penetration is at
/// least this fraction of its deepest ([`ActiveSet::closing`]).
pub(in crate::contact::iteration) const NEW_REGION_DEPTH: f64 = 0.9;

/// Runs of penetrating nodes up to this long close whole ([`ActiveSet::closing`]): halving a
/// run of two beside the zone made its edge node alternate open/closed where closing both
/// converged (2 of 54 finite-sliding scenes of the robustness scan, reported in
/// `docs/bench/contact_boundary.md`).
pub(in crate::contact::iteration) const WHOLE_RUN: usize = 2;

/// A node of the fallback's solution is in slip when `|ts| >= (1 - LINEARIZED_CONE) mu |tn|`
/// ([`linearized_state`]).
pub(in crate::contact::iteration) const LINEARIZED_CONE: f64 = 1e-9;

/// What the rules read of one A node after a solve.
#[derive(Debug, Clone, Copy)]
pub(in crate::contact::iteration) struct NodeFacts<'a> {
    /// The traction on A (zero at an open node).
    pub(in crate::contact::iteration) traction: Traction,
    /// The weighted normal gap (`< 0`: it penetrates; infinite with no B segment in reach).
    pub(in crate::contact::iteration) gap: f64,
    /// A's slip relative to B since the increment began, per unit length, in the node's
    /// tangent space.
    pub(in crate::contact::iteration) slip: Tangential,
    /// The node's friction law.
    pub(in crate::contact::iteration) law: &'a dyn FrictionLaw,
}

/// The tolerances of the rules for one pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::contact::iteration) struct Tolerances {
    /// The penetration beyond which an open node closes (a length: `gap_tolerance` times the
    /// pair's gap scale).
    pub(in crate::contact::iteration) gap: f64,
    /// The slip beyond which a closing node slides and a slip node's slip has reversed (a
    /// length: `slip_tolerance` times the pair's motion scale).
    pub(in crate::contact::iteration) slip: f64,
    /// A closed node opens when `tn > tension tn_max` (`tension_tolerance`).
    pub(in crate::contact::iteration) tension: f64,
    /// A stick node slips when `|ts| > mu |tn| (1 + friction)` (`friction_tolerance`).
    pub(in crate::contact::iteration) friction: f64,
}

/// A B node strictly inside an A element whose nodes are all open: the A node (index into A)
/// it is judged with, the element's node nearest to where it projects (the one that closes
/// when it penetrates; the geometry's
/// [`BNodeDistance::nearest`](crate::contact::geometry::BNodeDistance::nearest)), and its
/// signed distance `g` from the element (`< 0`: it penetrates).
pub(in crate::contact::iteration) type BNodeHit = (usize, f64);

/// What a state adds to the small system (`build_system`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::contact::iteration) enum Rows {
    /// Open: nothing.
    None,
    /// Frictionless: the normal row, column `n`.
    Normal,
    /// Slip: the normal row, column `n + sum_i c_i s_i` with `c` the law's slip coefficients
    /// (`ts = c tn`).
    NormalSlip(Tangential),
    /// Stick: the normal row and the tangent rows (no slip since the increment began), each
    /// its own column.
    NormalTangent,
}

/// The rows of `state` under friction law `law` (the module's table).
pub(in crate::contact::iteration) fn rows_of(state: NodeState, law: &dyn FrictionLaw) -> Rows {
    match state {
        NodeState::Open => Rows::None,
        NodeState::Frictionless => Rows::Normal,
        NodeState::Slip { direction } => Rows::NormalSlip(law.slip_coefficients(direction)),
        NodeState::Stick => Rows::NormalTangent,
    }
}

/// On a face (two tangents) a slip node's direction follows its slip since the increment
/// began (docs/design/3d-contact.md, "Friction with the circular cone"): the direction of
/// `slip` when it is longer than `tolerance` and turned from `direction` by more than
/// [`SlipDirection::same_as`] tells apart (a cosine below `1 - 1e-12`, about `1.4e-6` rad),
/// `None` otherwise. The proposal then counts as a change, so an increment converges only once
/// every slip node's direction is its slip's to that angle. In the plane a direction can only
/// flip, which the reversal rule decides.
fn followed(direction: SlipDirection, slip: Tangential, tolerance: f64) -> Option<SlipDirection> {
    if slip.components().len() < 2 || slip.norm() <= tolerance {
        return None;
    }
    SlipDirection::of(slip).filter(|d| !d.same_as(&direction))
}

/// The next state of a node in `state` from its `facts` after a solve, by the rules for a
/// closed node (the module's table, rows 2 to 4; an open node stays open here, its closing is
/// [`ActiveSet::closing`]'s): tensile (`tn > tension tn_max`) opens; stick beyond the cone
/// slips opposing `ts`; slip whose slip reversed (`d . v < -slip_tol`) sticks unless
/// `may_stick` is false (locked in slip), otherwise on a face its direction follows the slip
/// ([`followed`]). The iteration's rules ([`ActiveSet::propose`]) and the paper's rules on a
/// condensed problem (`contact::local`, `condensed.rs`) both take it.
pub(in crate::contact::iteration) fn closed_next(
    state: NodeState,
    f: &NodeFacts<'_>,
    tolerances: &Tolerances,
    tn_max: f64,
    may_stick: bool,
) -> NodeState {
    let Traction {
        normal: tn,
        tangential: ts,
    } = f.traction;
    match state {
        NodeState::Open => state,
        _ if tn > tolerances.tension * tn_max => NodeState::Open,
        NodeState::Stick if ts.norm() > f.law.stick_limit(tn) * (1.0 + tolerances.friction) => {
            NodeState::Slip {
                direction: SlipDirection::opposing(ts),
            }
        }
        NodeState::Slip { direction }
            if may_stick && direction.along(&f.slip) < -tolerances.slip =>
        {
            NodeState::Stick
        }
        NodeState::Slip { direction } => followed(direction, f.slip, tolerances.slip)
            .map_or(state, |direction| NodeState::Slip { direction }),
        NodeState::Stick | NodeState::Frictionless => state,
    }
}

/// The state of a node that closes without sliding: stick, or frictionless under a law
/// without friction.
pub(in crate::contact::iteration) fn closed_at_rest(law: &dyn FrictionLaw) -> NodeState {
    if law.is_frictionless() {
        NodeState::Frictionless
    } else {
        NodeState::Stick
    }
}

/// The state of a node that closes having slid by `slip` since the increment began: a node
/// closing while the surfaces slide past each other (`|slip| > tolerance`) slides with them,
/// one closing without relative motion is [`closed_at_rest`].
pub(in crate::contact::iteration) fn closed_state(
    law: &dyn FrictionLaw,
    slip: Tangential,
    tolerance: f64,
) -> NodeState {
    match SlipDirection::of(slip) {
        Some(direction) if !law.is_frictionless() && slip.norm() > tolerance => {
            NodeState::Slip { direction }
        }
        _ => closed_at_rest(law),
    }
}

/// The state of a node in the solution of the fallback's linearized conditions (`fallback.rs`):
/// open unless `tn < open_at` (`open_at <= 0`, the solve's resolution of zero), otherwise
/// closed: slip where the tangential traction `ts` lies on the cone
/// (`|ts| >= (1 - LINEARIZED_CONE) mu |tn|`), in the direction it opposes, at rest inside it
/// or without tangential unknowns (`ts` `None`, a law without friction).
pub(in crate::contact::iteration) fn linearized_state(
    tn: f64,
    ts: Option<Tangential>,
    law: &dyn FrictionLaw,
    open_at: f64,
) -> NodeState {
    if tn >= open_at {
        return NodeState::Open;
    }
    match ts {
        Some(ts) if ts.norm() >= (1.0 - LINEARIZED_CONE) * law.stick_limit(tn) => NodeState::Slip {
            direction: SlipDirection::opposing(ts),
        },
        _ => closed_at_rest(law),
    }
}

/// Close the covered node with the smallest gap, at rest (the first support of a
/// force-controlled body: the plate's). `nodes` are `(node, gap, covered, law)`.
pub(in crate::contact::iteration) fn close_nearest<'a>(
    states: &mut [Vec<NodeState>],
    nodes: impl IntoIterator<Item = (NodeKey, f64, bool, &'a dyn FrictionLaw)>,
) {
    let nearest = (nodes.into_iter())
        .filter(|&(_, _, covered, _)| covered)
        .min_by(|a, b| a.1.total_cmp(&b.1));
    if let Some(((p, k), _, _, law)) = nearest {
        states[p][k] = closed_at_rest(law);
    }
}

impl ActiveSet {
    /// The depth of each open node of pair `p` that penetrates by its own gap
    /// (`gap < -tolerances.gap`), `None` for the others.
    fn own_depths(
        &self,
        p: usize,
        facts: &[NodeFacts<'_>],
        tolerances: &Tolerances,
    ) -> Vec<Option<f64>> {
        (self.states()[p].iter().zip(facts))
            .map(|(state, f)| {
                (*state == NodeState::Open && f.gap < -tolerances.gap).then_some(f.gap)
            })
            .collect()
    }

    /// The A nodes of pair `p` over whose segments B nodes are judged by the rules: open and
    /// not penetrating by their own gap (a segment counts when both its nodes do). `None` when
    /// the set judges B nodes only at convergence ([`BNodes::AtConvergence`]).
    pub(in crate::contact::iteration) fn b_node_judges(
        &self,
        p: usize,
        facts: &[NodeFacts<'_>],
        tolerances: &Tolerances,
    ) -> Option<Vec<bool>> {
        (self.b_nodes() == BNodes::Pointwise).then(|| {
            let depth = self.own_depths(p, facts, tolerances);
            (self.states()[p].iter().zip(depth))
                .map(|(state, d)| *state == NodeState::Open && d.is_none())
                .collect()
        })
    }

    /// The paper's rules (the module's table) for pair `p`: the next states of its A nodes
    /// from their `facts` after a solve, and the B nodes inside segments whose two nodes are
    /// open (`b_hits`, over the segments [`b_node_judges`](Self::b_node_judges) names): a B
    /// node penetrating by more than the gap tolerance closes the nearer A node of its
    /// segment. The rules respect the locks: a node locked open does not close, a node locked
    /// in slip does not return to stick.
    pub(in crate::contact::iteration) fn propose(
        &self,
        p: usize,
        facts: &[NodeFacts<'_>],
        tolerances: &Tolerances,
        b_hits: &[BNodeHit],
        adjacency: &Adjacency,
    ) -> Vec<NodeState> {
        let states = &self.states()[p];
        let mut next = states.clone();
        let tn_max = facts
            .iter()
            .fold(0.0f64, |m, f| m.max(f.traction.normal.abs()));
        for (k, f) in facts.iter().enumerate() {
            next[k] = closed_next(states[k], f, tolerances, tn_max, self.may_stick((p, k)));
        }
        // how deep each open node penetrates; which of them close is decided by `closing`
        let mut depth = self.own_depths(p, facts, tolerances);
        for &(node, g) in b_hits {
            if g >= -tolerances.gap {
                continue;
            }
            depth[node] = Some(depth[node].map_or(g, |d| d.min(g)));
        }
        for k in self.closing(p, &depth, adjacency) {
            next[k] = closed_state(facts[k].law, facts[k].slip, tolerances.slip);
        }
        next
    }

    /// The open nodes of pair `p` that close in this iteration (docs/method.md, "The rules",
    /// step 3a, damped), in increasing order. `depth[k]` is `Some(d)` for an open node that
    /// penetrates (`d < 0`: the deeper of its weighted gap and any B node's distance that
    /// closes it), `None` otherwise. Per patch of penetrating nodes connected along A (`adjacency`; in the
    /// plane a run of consecutive nodes):
    /// * enclosed by the zone (every node around it closed, none of it on A's edge: a hole in
    ///   the zone): all of it;
    /// * beside the zone (some node around it closed): the half nearest the zone (rounded up;
    ///   by steps along A from the closed nodes, all nodes as near as the half's farthest).
    ///   The penetration beyond a zone was computed with the contact force on that zone,
    ///   which is too small, so it overstates the band: closing all of it overshoots the edge,
    ///   and the zone then shrinks by the one or two nodes per side whose traction turns
    ///   tensile in each iteration. Halving approaches the edge from inside, where the zone
    ///   grows fast (`bench contact` at n = 256: 46 iterations before, 20 now);
    /// * away from the zone (a new contact region): the nodes within [`NEW_REGION_DEPTH`] of
    ///   the deepest one, so that conforming surfaces close at once and curved ones grow from
    ///   their deepest point.
    ///
    /// Nodes locked open are skipped; if that leaves a patch's choice empty, every node of the
    /// patch that may close closes, so the iteration never stops on a penetrating node it
    /// could close.
    pub(in crate::contact::iteration) fn closing(
        &self,
        p: usize,
        depth: &[Option<f64>],
        adjacency: &Adjacency,
    ) -> Vec<usize> {
        let closed = |k: usize| self.states()[p][k] != NodeState::Open;
        let mut seen = vec![false; depth.len()];
        let mut chosen = Vec::new();
        for k in 0..depth.len() {
            if depth[k].is_none() || seen[k] {
                continue;
            }
            let patch = patch_of(k, depth, adjacency, &mut seen);
            let around: Vec<usize> = (patch.iter())
                .flat_map(|&i| adjacency.neighbours(i))
                .copied()
                .filter(|&j| depth[j].is_none())
                .collect();
            let beside = around.iter().any(|&j| closed(j));
            let enclosed = beside
                && around.iter().all(|&j| closed(j))
                && !patch.iter().any(|&i| adjacency.on_edge(i));
            let mut pick: Vec<usize> = if enclosed {
                patch.clone()
            } else if beside {
                let half = if patch.len() <= WHOLE_RUN {
                    patch.len()
                } else {
                    patch.len().div_ceil(2)
                };
                nearest(&patch, half, adjacency, |j| closed(j) && depth[j].is_none())
            } else {
                let d = |i: usize| depth[i].unwrap_or(0.0);
                let deepest = patch.iter().map(|&i| d(i)).fold(0.0, f64::min);
                (patch.iter().copied())
                    .filter(|&i| d(i) <= NEW_REGION_DEPTH * deepest)
                    .collect()
            };
            pick.retain(|&i| self.may_close((p, i)));
            if pick.is_empty() {
                pick = patch
                    .into_iter()
                    .filter(|&i| self.may_close((p, i)))
                    .collect();
            }
            chosen.extend(pick);
        }
        chosen.sort_unstable();
        chosen
    }
}

/// The patch of penetrating nodes (`depth` set) connected to node `k` along A, sorted; marks
/// them `seen`.
fn patch_of(
    k: usize,
    depth: &[Option<f64>],
    adjacency: &Adjacency,
    seen: &mut [bool],
) -> Vec<usize> {
    let mut patch = vec![k];
    seen[k] = true;
    let mut next = 0;
    while next < patch.len() {
        let i = patch[next];
        next += 1;
        for &j in adjacency.neighbours(i) {
            if depth[j].is_some() && !seen[j] {
                seen[j] = true;
                patch.push(j);
            }
        }
    }
    patch.sort_unstable();
    patch
}

/// The nodes of `patch` (sorted) at most as many steps along A from a node `source` holds as
/// its `count`-th nearest (breadth first from the patch's nodes next to a source), sorted.
fn nearest(
    patch: &[usize],
    count: usize,
    adjacency: &Adjacency,
    source: impl Fn(usize) -> bool,
) -> Vec<usize> {
    let mut steps = vec![usize::MAX; patch.len()];
    let mut order: Vec<usize> = (patch.iter().copied())
        .filter(|&i| adjacency.neighbours(i).iter().any(|&j| source(j)))
        .collect();
    for &i in &order {
        steps[patch.binary_search(&i).expect("in the patch")] = 1;
    }
    let mut next = 0;
    while next < order.len() {
        let i = order[next];
        next += 1;
        let step = steps[patch.binary_search(&i).expect("in the patch")];
        for &j in adjacency.neighbours(i) {
            if let Ok(s) = patch.binary_search(&j)
                && steps[s] == usize::MAX
            {
                steps[s] = step + 1;
                order.push(j);
            }
        }
    }
    let Some(&last) = order.get(count.saturating_sub(1)) else {
        return patch.to_vec();
    };
    let reach = steps[patch.binary_search(&last).expect("in the patch")];
    (patch.iter().zip(&steps))
        .filter(|&(_, &s)| s <= reach)
        .map(|(&i, _)| i)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::Locks;
    use super::*;
    use crate::contact::friction::Coulomb;

    const SLIP: NodeState = NodeState::Slip {
        direction: SlipDirection::PLUS,
    };

    const TOLERANCES: Tolerances = Tolerances {
        gap: 1e-6,
        slip: 1e-6,
        tension: 1e-9,
        friction: 1e-6,
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
        let chain = Adjacency::chain(12);
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
        assert_eq!(
            set.closing(0, &depth, &chain),
            vec![1, 2, 4, 6, 7, 8, 9, 11]
        );
        let depth = depths(&[
            (0, -1.0),
            (1, -2.0),
            (2, -3.0),
            (6, -5.0),
            (7, -4.0),
            (8, -1.0),
        ]);
        assert_eq!(set.closing(0, &depth, &chain), vec![1, 2, 6, 7]);
        let depth = depths(&[(6, -5.0), (7, -4.0)]);
        assert_eq!(
            set.closing(0, &depth, &chain),
            vec![6, 7],
            "a band of two closes whole"
        );
        // a new region: within 0.9 of its deepest node, which need not be at its middle
        let open = ActiveSet::new(vec![vec![Open; 12]], Locks::default(), 1);
        let depth = depths(&[(1, -0.5), (2, -0.95), (3, -1.0), (4, -0.91), (5, -0.2)]);
        assert_eq!(open.closing(0, &depth, &chain), vec![2, 3, 4]);
        // conforming surfaces: all at once
        assert_eq!(
            open.closing(0, &[Some(-1.0); 12], &chain),
            (0..12).collect::<Vec<_>>()
        );
        // the chosen half locked open: the rest of the band closes instead
        let locks = Locks {
            slip: Vec::new(),
            open: vec![(0, 1), (0, 2)],
        };
        let locked = ActiveSet::new(vec![states], locks, 1);
        let depth = depths(&[(0, -1.0), (1, -2.0), (2, -3.0)]);
        assert_eq!(locked.closing(0, &depth, &chain), vec![0]);
    }

    /// On a surface (a 5 x 5 grid of nodes, neighbours along the grid lines, the outer ring its
    /// edge) the runs become connected patches: a band around the zone closes its half
    /// nearest the zone, a hole closes whole, a new region from its deepest nodes.
    #[test]
    fn closing_grows_a_patch_on_a_surface() {
        use NodeState::Open;
        let at = |i: usize, j: usize| 5 * i + j;
        let neighbours = (0..25)
            .map(|k| {
                let (i, j) = (k / 5, k % 5);
                let mut n = Vec::new();
                if i > 0 {
                    n.push(at(i - 1, j));
                }
                if j > 0 {
                    n.push(at(i, j - 1));
                }
                if j < 4 {
                    n.push(at(i, j + 1));
                }
                if i < 4 {
                    n.push(at(i + 1, j));
                }
                n
            })
            .collect();
        let edge = (0..25).map(|k| [0, 4].contains(&(k / 5)) || [0, 4].contains(&(k % 5)));
        let grid = Adjacency::new(neighbours, edge.collect());
        let with = |entries: &[usize], d: f64| {
            let mut depth = vec![None; 25];
            for &k in entries {
                depth[k] = Some(d);
            }
            depth
        };
        // the centre closed, the ring of 8 around it penetrating: the 4 sharing an edge with
        // it close (half of 8), the corners of the ring wait
        let mut states = vec![Open; 25];
        states[12] = SLIP;
        let set = ActiveSet::new(vec![states], Locks::default(), 1);
        let ring = [6, 7, 8, 11, 13, 16, 17, 18];
        assert_eq!(
            set.closing(0, &with(&ring, -1.0), &grid),
            vec![7, 11, 13, 17]
        );
        // everything closed but a column of 3 inside: a hole, all of it; with the node below
        // it open, a band beside the zone, whose nodes are all next to it
        let column = [7, 12, 17];
        let mut states = vec![SLIP; 25];
        for k in column {
            states[k] = Open;
        }
        let hole = ActiveSet::new(vec![states.clone()], Locks::default(), 1);
        assert_eq!(hole.closing(0, &with(&column, -1.0), &grid), column);
        states[22] = Open;
        let band = ActiveSet::new(vec![states], Locks::default(), 1);
        assert_eq!(band.closing(0, &with(&column, -1.0), &grid), column);
        // a new region: within 0.9 of its deepest node
        let open = ActiveSet::new(vec![vec![Open; 25]], Locks::default(), 1);
        let mut depth = with(&ring, -0.5);
        depth[12] = Some(-1.0);
        depth[7] = Some(-0.95);
        assert_eq!(open.closing(0, &depth, &grid), vec![7, 12]);
    }

    /// The rules on plain data, in the plane and on a face (two tangents): a penetrating open
    /// node closes (sliding with the surfaces when they slid, at rest otherwise), a closed one
    /// in tension opens, a stick node outside the cone slips opposite to its traction, a slip
    /// node whose slip reversed sticks unless locked in slip; a B node penetrating an open
    /// segment closes the nearer A node.
    #[test]
    fn the_rules_on_plain_data() {
        use NodeState::{Open, Stick};
        let law = Coulomb::new(0.5).unwrap();
        let fact = |tn: f64, ts: Tangential, gap: f64, slip: Tangential| NodeFacts {
            traction: Traction {
                normal: tn,
                tangential: ts,
            },
            gap,
            slip,
            law: &law,
        };
        let zero = Tangential::along(0.0);
        let facts = [
            // open, penetrating, the surfaces slid along -s: closes in slip along -s
            fact(0.0, zero, -1e-3, Tangential::along(-1e-3)),
            // open, penetrating, no slip: closes in stick
            fact(0.0, zero, -1e-3, zero),
            // stick in tension: opens
            fact(1.0, zero, 0.0, zero),
            // stick outside the cone (|ts| = 0.6 > 0.5 |tn|): slips against ts
            fact(-1.0, Tangential::along(0.6), 0.0, zero),
            // stick inside the cone: stays
            fact(-1.0, Tangential::along(-0.4), 0.0, zero),
            // slip along +s whose slip reversed: sticks
            fact(-1.0, Tangential::along(-0.5), 0.0, Tangential::along(-1e-3)),
            // open, not penetrating
            fact(0.0, zero, 1e-3, zero),
            fact(0.0, zero, 1e-3, zero),
        ];
        let states = vec![vec![Open, Open, Stick, Stick, Stick, SLIP, Open, Open]];
        let set = ActiveSet::new(states.clone(), Locks::default(), 1);
        let next = set.propose(0, &facts, &TOLERANCES, &[], &Adjacency::chain(8));
        let minus = NodeState::Slip {
            direction: SlipDirection::MINUS,
        };
        assert_eq!(
            next,
            vec![minus, Stick, Open, minus, Stick, Stick, Open, Open]
        );
        // the B nodes are judged over the segment 6-7 only; one penetrating near node 7
        // closes it, one near node 6 within the gap tolerance closes nothing
        assert_eq!(
            set.b_node_judges(0, &facts, &TOLERANCES),
            Some(vec![false, false, false, false, false, false, true, true])
        );
        let b_hits = [(7, -1e-3), (6, -1e-9)];
        assert_eq!(
            set.propose(0, &facts, &TOLERANCES, &b_hits, &Adjacency::chain(8))[6..],
            [Open, Stick]
        );
        let at_convergence = set.clone().judging(BNodes::AtConvergence);
        assert_eq!(at_convergence.b_node_judges(0, &facts, &TOLERANCES), None);
        // a node locked in slip keeps its slip
        let locks = Locks {
            slip: vec![(0, 5)],
            open: Vec::new(),
        };
        let locked = ActiveSet::new(states, locks, 1);
        assert_eq!(
            locked.propose(0, &facts, &TOLERANCES, &[], &Adjacency::chain(8))[5],
            SLIP
        );

        // on a face: the traction (0.3, 0.4) lies outside the cone 0.5 * 0.8 = 0.4; the node
        // slips along -(0.6, 0.8), and a node closing after sliding along (0, -1) slips so
        let face = [
            fact(
                -0.8,
                Tangential::on_face(0.3, 0.4),
                0.0,
                Tangential::zero(2),
            ),
            fact(
                -0.8,
                Tangential::on_face(0.2, 0.2),
                0.0,
                Tangential::zero(2),
            ),
            fact(
                0.0,
                Tangential::zero(2),
                -1e-3,
                Tangential::on_face(0.0, -2e-3),
            ),
        ];
        let set = ActiveSet::new(vec![vec![Stick, Stick, Open]], Locks::default(), 1);
        let next = set.propose(0, &face, &TOLERANCES, &[], &Adjacency::chain(3));
        let slips_along = |state: NodeState, v: Tangential| match state {
            NodeState::Slip { direction } => direction.same_as(&SlipDirection::of(v).unwrap()),
            _ => false,
        };
        assert!(
            slips_along(next[0], Tangential::on_face(-0.6, -0.8)),
            "{next:?}"
        );
        assert_eq!(next[1], Stick, "|ts| = 0.28 < 0.4: inside the cone");
        assert!(
            slips_along(next[2], Tangential::on_face(0.0, -1.0)),
            "{next:?}"
        );
        // a slip node's direction follows its slip: turned by 90 degrees, by 1e-5 rad, and
        // not for a turn of 1e-7 rad nor for a slip within the tolerance
        let slipping = |slip| fact(-0.8, Tangential::on_face(-0.4, 0.0), 0.0, slip);
        let (sn, cs) = 1e-5f64.sin_cos();
        let face = [
            slipping(Tangential::on_face(0.0, 1e-3)),
            slipping(Tangential::on_face(1e-3 * cs, 1e-3 * sn)),
            slipping(Tangential::on_face(1e-3, 1e-10)),
            slipping(Tangential::on_face(0.0, 1e-7)),
        ];
        let along_s1 = NodeState::Slip {
            direction: SlipDirection::of(Tangential::on_face(1.0, 0.0)).unwrap(),
        };
        let set = ActiveSet::new(vec![vec![along_s1; 4]], Locks::default(), 1);
        let next = set.propose(0, &face, &TOLERANCES, &[], &Adjacency::chain(4));
        assert!(
            slips_along(next[0], Tangential::on_face(0.0, 1.0)),
            "{next:?}"
        );
        assert!(
            slips_along(next[1], Tangential::on_face(cs, sn)),
            "{next:?}"
        );
        assert!(!next[1].same_as(&along_s1), "{next:?}");
        assert_eq!(next[2..], [along_s1; 2]);
        assert_eq!(set.changes(&[next]), 2);
    }

    /// Which closed state, once: at rest a node sticks (frictionless without friction), after
    /// sliding beyond the tolerance it slips along its slip; the fallback's solution maps the
    /// same way, slip where its traction is on the cone.
    #[test]
    fn which_closed_state() {
        let law = Coulomb::new(0.5).unwrap();
        let none = Coulomb::new(0.0).unwrap();
        let slid = Tangential::on_face(3e-3, -4e-3);
        assert_eq!(closed_at_rest(&law), NodeState::Stick);
        assert_eq!(closed_at_rest(&none), NodeState::Frictionless);
        assert_eq!(closed_state(&law, slid, 6e-3), NodeState::Stick);
        assert_eq!(closed_state(&none, slid, 1e-3), NodeState::Frictionless);
        assert!(closed_state(&law, slid, 4e-3).same_as(&NodeState::Slip {
            direction: SlipDirection::of(slid).unwrap()
        }));
        // the fallback's solution
        let on_cone = Tangential::on_face(-0.3, 0.4);
        assert_eq!(
            linearized_state(-1e-13, None, &law, -1e-12),
            NodeState::Open
        );
        assert_eq!(
            linearized_state(-1.0, None, &none, -1e-12),
            NodeState::Frictionless
        );
        let slip = linearized_state(-1.0, Some(on_cone), &law, -1e-12);
        assert!(slip.same_as(&NodeState::Slip {
            direction: SlipDirection::of(Tangential::on_face(0.6, -0.8)).unwrap()
        }));
        let inside = Tangential::on_face(-0.3, 0.39);
        assert_eq!(
            linearized_state(-1.0, Some(inside), &law, -1e-12),
            NodeState::Stick
        );
        // the plate's first support: the covered node with the smallest gap
        let mut states = vec![vec![NodeState::Open; 3]];
        let nodes: [(NodeKey, f64, bool, &dyn FrictionLaw); 3] = [
            ((0, 0), -2.0, false, &law),
            ((0, 1), 0.5, true, &law),
            ((0, 2), 0.1, true, &none),
        ];
        close_nearest(&mut states, nodes);
        assert_eq!(
            states[0],
            [NodeState::Open, NodeState::Open, NodeState::Frictionless]
        );
    }
}
