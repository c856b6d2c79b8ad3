//! Contact between two bodies by the method of Kubomura and Pian (docs/method.md).
//!
//! * [`plane`]: the plane and axisymmetric geometry of a pair of polylines: [`plane::mortar`], the
//!   pure contact-element kernels of one contact pair at given positions (the
//!   reference ones for small kinematics, the current ones for finite): nodal frames, weights,
//!   the mortar matrices `F^A` and `F^B`, the weighted gap `R_C`, coverage and the coupling rows.
//! * [`bodies`]: the elastic bodies as the iteration sees them: hycon's own model, or a host
//!   FE code's system (its stiffness in CSR, or its own solver through a callback).
//! * [`handover`]: a host's hand-overs checked against each other (sections, radii, elements).
//! * [`friction`]: the friction laws the iteration asks about (Coulomb).
//! * [`space`]: vectors and nodal frames for any dimension ([`space::Vector`], [`space::Frame`]):
//!   what the core handles positions, gaps, forces and frames with.
//! * [`tangent`]: a node's tangent space for any dimension: tractions, slip directions.
//! * [`iteration`]: the contact-set iteration with `K` factored once (stick, slip, open), and
//!   its results.

pub mod bodies;
pub mod faces;
pub mod friction;
pub mod geometry;
pub mod handover;
pub mod iteration;
pub mod plane;
pub mod space;
pub mod tangent;
