//! The shared base of the plane, axisymmetric and solid layers: what both dimensions compute the
//! same way, once.
//!
//! * [`analysis`]: the two-dimensional analysis kinds and the measure `m(x)` that weights every
//!   plane or axisymmetric integral (`t`, or `2 pi r`), with its segment integral.
//! * [`isotropic`]: the isotropic elastic material (`E`, `nu`, validation) and its compliance
//!   and elasticity in every stress state (plane strain, plane stress, axisymmetric, 3D).
//! * [`quadrature`]: the Gauss rules on lines, quadrilaterals and triangles.
//! * [`hybrid`]: the hybrid element's `K = G^T H^-1 G` and `beta = H^-1 G q`, for any number of
//!   stress parameters and dofs.
//! * [`boundary`]: distributed boundary loads (pressure and traction at the nodes of an edge or
//!   a face) and the geometry of a bilinear face.
//!
//! The element, mesh and model layers of each dimension ([`crate::element`], [`crate::mesh`],
//! [`crate::model`] in the plane; [`crate::solid`] in 3D) stand side by side over this base.

pub mod analysis;
pub mod boundary;
pub mod hybrid;
pub mod isotropic;
pub mod quadrature;
pub mod quality;

pub use analysis::{Analysis, Measure};
pub use isotropic::Isotropic;
