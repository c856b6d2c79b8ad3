//! Contact between two bodies by the method of Kubomura and Pian (docs/method.md).
//!
//! The core (the iteration, its active set, checks and boundary algebra, the results) is
//! dimension-free: it reaches a pair's surfaces only through [`geometry::ContactGeometry`],
//! and handles positions (flat, `dim` values per node), gaps, forces and frames as
//! [`space::Vector`] and [`space::Frame`], tractions and slips as [`tangent`]'s types. A
//! geometry of another dimension is a sibling of [`plane`], not an edit of it.
//!
//! * [`geometry`]: the seam: the [`geometry::ContactGeometry`] trait (evaluate a pair at
//!   positions, its scales and checks) and what an evaluation gives per A node
//!   ([`geometry::ContactNode`], [`geometry::ContactSurface`]).
//! * [`plane`]: the plane and axisymmetric geometry of a pair of polylines,
//!   [`plane::PlaneGeometry`]: [`plane::mortar`], the pure contact-element kernels of one pair
//!   at given positions (the reference ones for small kinematics, the current ones for
//!   finite): nodal frames, weights, the mortar matrices `F^A` and `F^B`, the weighted gap
//!   `R_C`, coverage and the coupling rows; [`plane::facing`], the orientation checks.
//! * [`faces`]: the 3D geometry of a pair of brick-face surfaces behind the seam,
//!   [`faces::FaceGeometry`], and its mortar integrals by projection and clipping.
//! * [`bodies`]: the elastic bodies as the iteration sees them: hycon's own model, or a host
//!   FE code's system (its stiffness in CSR, or its own solver through a callback).
//! * [`handover`]: a host's hand-overs checked against each other (sections, radii, elements).
//! * [`friction`]: the friction laws the iteration asks about (Coulomb).
//! * [`space`]: vectors and nodal frames for any dimension ([`space::Vector`], [`space::Frame`]):
//!   what the core handles positions, gaps, forces and frames with.
//! * [`tangent`]: a node's tangent space for any dimension: tractions, slip directions.
//! * [`iteration`]: the contact-set iteration with `K` factored once (stick, slip, open), and
//!   its results.
//! * [`local`]: the local frictional contact problem of one increment (FCLIB's), its
//!   natural-map residual and hycon's solvers of it.

pub mod bodies;
pub mod faces;
pub mod friction;
pub mod geometry;
pub mod handover;
pub mod iteration;
pub mod local;
pub mod plane;
pub mod space;
pub mod tangent;
