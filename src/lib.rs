//! # hycon
//!
//! The assumed-stress hybrid contact method of Kubomura and Pian for plane elasticity, as a
//! library for C and C++ finite-element codes (through [`ffi`]) and for Rust.
//!
//! Modules, each owning one concept:
//! * [`fem`]: the shared base of the plane and solid layers: the isotropic material in every
//!   stress state, the analysis kind and its measure, Gauss rules, the hybrid condensation
//!   `K = G^T H^-1 G`, boundary loads and face geometry.
//! * [`material`]: the plane or axisymmetric material (the isotropic one, the analysis kind, the
//!   thickness).
//! * [`element`]: pure element kernels (hybrid 4/5/6-node, Pian-Sumihara, Q4): stiffness, stress
//!   recovery, edge tractions; edge loads, volume and quality for hosts.
//! * [`mesh`]: mesh storage, graded 2:1 mesh generators with transition elements, quality report.
//! * [`assembly`]: dof numbering and sparse assembly (pattern built once, values refilled), the
//!   element loops of the plane and the solid models written once ([`assembly::elements`]).
//! * [`solver`]: sparse Cholesky with the symbolic analysis kept and reused.
//! * [`model`]: a linear static problem: prescribed displacements, loads, solve, reactions,
//!   stresses.
//! * [`solid`]: 3D bricks (18-beta hybrid, H8), hexahedral meshes, a 3D linear static model.
//! * [`contact`]: contact-element kernels (mortar projection, weighted gaps, coupling rows), the
//!   bodies (hycon's model or a host's system) and the contact-set iteration with its results.
//! * [`ffi`]: the C ABI, a thin checked layer over the above.
//!
//! The reference scenes and cases, the paper's examples, the benchmarks, the report writers and
//! the `hycon` program live beside the library in the workspace crate `hycon-lab` (`lab/`).
#![deny(unsafe_op_in_unsafe_fn)]
#![warn(missing_docs)]

pub mod assembly;
pub mod contact;
pub mod element;
pub mod error;
pub mod fem;
pub mod ffi;
pub mod material;
pub mod mesh;
pub mod model;
pub mod solid;
pub mod solver;

pub use error::{ContactError, Error, Result, ShapeError, ShapeWarning};
pub use material::{Analysis, Material};
