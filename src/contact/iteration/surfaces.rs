//! The contact geometry of the analysis: the pairs with their geometries and friction laws,
//! the surfaces in the reference and the converged configurations, and the pairing's reach.

use super::ContactPair;
use crate::contact::friction::FrictionLaw;
use crate::contact::geometry::{ContactGeometry, ContactSurface};

/// The contact geometry part of the analysis.
pub(super) struct Surfaces {
    /// The pairs, node ids in the iteration's numbering (see [`Bodies::local`]).
    ///
    /// [`Bodies::local`]: crate::contact::bodies::Bodies::local
    pub(super) pairs: Vec<ContactPair>,
    /// The geometry of each pair (its A side's surface measure with it, all of one kind).
    pub(super) geometries: Vec<Box<dyn ContactGeometry>>,
    /// The friction law of each pair: all the iteration knows of its friction.
    pub(super) laws: Vec<Box<dyn FrictionLaw>>,
    /// The contact geometry of every pair in the reference configuration (the frozen pairing
    /// of small kinematics).
    pub(super) reference: Vec<ContactSurface>,
    /// How far from A the pairing of `reference` looked for B, per pair (absolute):
    /// `search_distance` mean A segment lengths, widened under small kinematics as the bodies
    /// move (see `widen_pairing`).
    pub(super) reach: Vec<f64>,
    /// The contact geometry of every pair at the last converged state (the reference one
    /// before the first increment): the iteration starts from it and the result queries read
    /// it, so nothing is evaluated twice.
    pub(super) current: Vec<ContactSurface>,
}
