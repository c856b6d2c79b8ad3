//! The plane and axisymmetric contact geometry: a pair is two polylines (node chains of the
//! bodies' boundaries, each with its body on the left).
//!
//! * [`mortar`]: the contact-element kernels of one pair at given positions: nodal frames,
//!   weights, the mortar matrices `F^A` and `F^B`, the weighted gap `R_C`, coverage and the
//!   coupling rows.
//! * [`facing`]: the orientation check of a pair (do A and B face each other) and the sides
//!   of points.

pub mod facing;
pub mod mortar;
