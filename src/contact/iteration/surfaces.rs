//! The contact geometry of the analysis: the pairs with their geometries and friction laws,
//! the surfaces in the reference and the converged configurations, and the pairing's reach.

use super::Kinematics;
use super::boundary::Boundary;
use super::checks::POSITION_ROUND_OFF;
use crate::contact::bodies::Bodies;
use crate::contact::friction::{Coulomb, FrictionLaw};
use crate::contact::geometry::{ContactGeometry, ContactSurface};
use crate::error::{ContactError, Result};

/// The nodes of one pair, as the iteration reads them: ids in the iteration's numbering (see
/// [`Bodies::local`]), A's in the order of its geometry's contact nodes
/// ([`ContactGeometry::a_nodes`]), and B's. Each constructor builds them from its own pair
/// type (a plane [`ContactPair`](super::ContactPair)'s polylines, a
/// [`FacePair`](super::FacePair)'s face nodes).
///
/// [`Bodies::local`]: crate::contact::bodies::Bodies::local
#[derive(Debug)]
pub(super) struct PairNodes {
    /// The multiplier side's nodes.
    pub(super) a: Vec<usize>,
    /// The opposite side's nodes.
    pub(super) b: Vec<usize>,
}

/// The contact geometry part of the analysis.
pub(super) struct Surfaces {
    /// The nodes of each pair.
    pub(super) pairs: Vec<PairNodes>,
    /// The geometry of each pair (its A side's surface measure with it, all of one kind).
    pub(super) geometries: Vec<Box<dyn ContactGeometry>>,
    /// The friction law of each pair: all the iteration knows of its friction.
    pub(super) laws: Vec<Box<dyn FrictionLaw>>,
    /// The contact geometry of every pair in the reference configuration (the frozen pairing
    /// of small kinematics).
    pub(super) reference: Vec<ContactSurface>,
    /// How far from A the pairing of `reference` looked for B, per pair (absolute):
    /// `search_distance` mean A segment lengths, widened under small kinematics as the bodies
    /// move (see [`Surfaces::widen`]).
    pub(super) reach: Vec<f64>,
    /// The contact geometry of every pair at the last converged state (the reference one
    /// before the first increment): the iteration starts from it and the result queries read
    /// it, so nothing is evaluated twice.
    pub(super) current: Vec<ContactSurface>,
    /// The analysis's kinematics: whether the geometry follows the iterate.
    pub(super) kinematics: Kinematics,
    /// The pairing's reach in mean A segment lengths (`ContactOptions::search_distance`).
    pub(super) search_distance: f64,
}

/// The pairing of every pair: what a failed try may change of the geometry (widened under
/// small kinematics, see [`Surfaces::widen`]).
pub(super) struct Pairing {
    reach: Vec<f64>,
    reference: Vec<ContactSurface>,
    current: Vec<ContactSurface>,
}

impl Surfaces {
    /// The pairing as it is (the cutback's snapshot).
    pub(super) fn pairing(&self) -> Pairing {
        Pairing {
            reach: self.reach.clone(),
            reference: self.reference.clone(),
            current: self.current.clone(),
        }
    }

    /// Put back a pairing taken by [`pairing`](Self::pairing); whether the present one was
    /// widened since (its directions' flexibility is then stale).
    pub(super) fn restore_pairing(&mut self, p: Pairing) -> bool {
        let widened = p.reach != self.reach;
        (self.reach, self.reference, self.current) = (p.reach, p.reference, p.current);
        widened
    }

    /// The friction law of A node `k` of pair `p`: the pair's, but none for a node on the axis
    /// in axisymmetry (in the reference configuration `x0`,
    /// [`ContactGeometry::frictionless_at`]). There `tau_rz = 0` by symmetry, and a tangential
    /// row would constrain the radial slip that `u_r = 0` on both sides already holds: with
    /// B's segment over A's axis node spanning as many of A's active nodes' radial dofs as it
    /// has rows, the field `u_r = c r` (which both sides represent with `u_r(0) = 0`) slips
    /// nowhere, so the stick rows were dependent and the small system singular. Such a node
    /// closes frictionless and keeps `ts = 0`.
    pub(super) fn node_law(&self, p: usize, k: usize, x0: &[f64]) -> &dyn FrictionLaw {
        if self.geometries[p].frictionless_at(k, x0) {
            &Coulomb::NONE
        } else {
            &*self.laws[p]
        }
    }

    /// How far the pairing of pair `p` reaches during an increment whose largest motion of a
    /// contact node so far is `motion`: `search_distance` mean A segment lengths (in the
    /// geometry's configuration `xg`), or twice `motion` when that is more. Two surfaces
    /// approach each other by at most twice that motion in an increment, so a pairing that
    /// held at its start still finds its partner, however fine the mesh (a reach tied to the
    /// element size alone breaks exactly when a user refines).
    pub(super) fn search_reach(&self, p: usize, xg: &[f64], motion: f64) -> f64 {
        (self.search_distance * self.geometries[p].mean_size(xg)).max(2.0 * motion)
    }

    /// The positions the contact geometry is evaluated at, given the reference ones `x0` and
    /// the current ones `x`: `x0` under small kinematics, `x` under finite kinematics.
    pub(super) fn geometry_positions<'a>(&self, x0: &'a [f64], x: &'a [f64]) -> &'a [f64] {
        match self.kinematics {
            Kinematics::Small => x0,
            Kinematics::Finite => x,
        }
    }

    /// Bring the contact geometry `surfaces` to the displacement `uc` of the contact dofs
    /// (`dofs` maps them to nodes), in increment `number` whose largest motion of a contact
    /// node so far is `motion`. Finite kinematics: evaluate every pair at the current
    /// positions (reusing the surfaces' buffers). Small kinematics: nothing but the gaps
    /// changes, linearly: `R_C,k = R_C,k(X) + sum_j c_kj u_j`,
    /// `normal_gap_k = -n_k . R_C,k / covered weight` (and `mean_distance` moves with
    /// `normal_gap`), with the reference pairing, frames, weights and coupling rows.
    pub(super) fn update(
        &self,
        surfaces: &mut [ContactSurface],
        bodies: &dyn Bodies,
        dofs: &Boundary,
        uc: &[f64],
        (number, motion): (usize, f64),
    ) -> Result<()> {
        match self.kinematics {
            Kinematics::Finite => {
                let x = dofs.positions(bodies.positions(), uc);
                self.resolved(&x, bodies, number)?;
                for (p, surface) in surfaces.iter_mut().enumerate() {
                    let distance = self.search_reach(p, &x, motion);
                    self.geometries[p].evaluate_into(&x, distance, surface)?;
                }
            }
            Kinematics::Small => {
                for (surface, reference) in surfaces.iter_mut().zip(&self.reference) {
                    for (node, r) in surface.nodes.iter_mut().zip(&reference.nodes) {
                        let change = dofs.coupled((&r.coupling, bodies.dim()), uc);
                        node.gap = r.gap + change;
                        if r.covered_weight > 0.0 {
                            node.normal_gap = -r.frame.normal().dot(&node.gap) / r.covered_weight;
                            node.mean_distance = r.mean_distance + (node.normal_gap - r.normal_gap);
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Small kinematics: keep the frozen pairing wide enough for displacement `uc` of the
    /// contact dofs. A point of A at reference distance `g0` from B along A's normal can touch
    /// B only if `g0 <= |u_A| + |u_B| <= 2 max |u|` (the largest nodal displacement of the
    /// pair since the reference configuration), so whenever `2 max |u|` exceeds the pair's
    /// reach the pairing is evaluated again in the reference configuration within
    /// `4 max |u|` (a growing load widens it a logarithmic number of times). Without this, a
    /// reach of a few element lengths loses the outer part of a contact zone whose initial
    /// gaps span more elements than that: exactly what refining the mesh does.
    ///
    /// Every point paired before keeps its partner (a new hit is farther than the old reach),
    /// so the nodes whose data change are those that were not fully covered. If one of them
    /// has been active its directions' flexibility is stale and the boundary algebra forgets
    /// all of it ([`Boundary::forget_directions`]), to be rebuilt as nodes close again. The
    /// working `surfaces` and the converged ones (at the boundary's converged displacement)
    /// are brought to the new pairing (the converged state itself, node states and
    /// tractions, does not change).
    pub(super) fn widen(
        &mut self,
        uc: &[f64],
        surfaces: &mut [ContactSurface],
        bodies: &dyn Bodies,
        boundary: &mut Boundary,
    ) -> Result<()> {
        if self.kinematics != Kinematics::Small {
            return Ok(());
        }
        for p in 0..self.pairs.len() {
            let pair = &self.pairs[p];
            let motion = pair
                .a
                .iter()
                .chain(&pair.b)
                .map(|&n| boundary.node_vector((n, bodies.dim()), uc).norm())
                .fold(0.0f64, f64::max);
            if 2.0 * motion <= self.reach[p] {
                continue;
            }
            let reach = 4.0 * motion;
            let x = bodies.positions();
            let wider = self.geometries[p].evaluate(x, reach)?;
            let stale = (wider.nodes.iter().zip(&self.reference[p].nodes))
                .enumerate()
                .any(|(k, (new, old))| new != old && boundary.node_flexibility.knows(p, k));
            if stale {
                boundary.forget_directions();
            }
            self.reach[p] = reach;
            self.reference[p] = wider;
            surfaces[p] = self.reference[p].clone();
            let mut converged = std::mem::take(&mut self.current);
            converged[p] = self.reference[p].clone();
            // (small kinematics: no motion, no increment number read)
            self.update(&mut converged, bodies, boundary, &boundary.qc, (0, 0.0))?;
            self.current = converged;
        }
        Ok(())
    }

    /// Under finite kinematics the geometry is evaluated at the current positions
    /// `x = X + u`, which double precision holds to about `POSITION_ROUND_OFF |x|`. When the
    /// displacement `u` of a segment's end is so large that this round-off reaches the
    /// segment's length (its reference length, the scale the mesh describes the surface at,
    /// or its current one), the positions no longer carry the surface's shape: the segment's
    /// direction, its normal and the gaps measured from it are round-off, and no contact state
    /// can be judged (a press of `1e16` body sizes in one increment moved every A node far
    /// behind B and left them all open; at `1e66` a segment collapsed to zero length; at
    /// `1e300` both bodies were stretched to `1e299` and the contact system was singular).
    /// Such an iterate fails the increment ([`ContactError::Unresolved`]), at any magnitude.
    /// (Large coordinates alone, a model far from its origin, are the caller's choice and are
    /// not judged here: only the motion is.)
    fn resolved(&self, x: &[f64], bodies: &dyn Bodies, number: usize) -> Result<()> {
        let reference = bodies.positions();
        for geometry in &self.geometries {
            if let Some(u) = geometry.unresolved(x, reference, POSITION_ROUND_OFF) {
                return Err(ContactError::Unresolved {
                    increment: number,
                    node: bodies.external(u.node),
                    motion: u.motion,
                    length: u.length,
                }
                .into());
            }
        }
        Ok(())
    }
}
