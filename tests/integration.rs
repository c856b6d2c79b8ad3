//! The product's integration tests, one module per file, built as one test binary: `cargo test
//! --test integration [filter]`, e.g. `contact_patch::` for one file's tests. `no_alloc` and
//! `solver_memory` are binaries of their own: each changes the whole process (a counting
//! allocator, an address-space limit).

mod common;

mod axisymmetric;
mod c_api;
mod contact3d_geometry;
mod contact3d_plate;
mod contact3d_slip_directions;
mod contact3d_validation;
mod contact_cutback;
mod contact_geometry;
mod contact_patch;
mod contact_properties;
mod elements;
mod header_fresh;
mod layout;
mod loads;
mod local_problem;
mod mesh;
mod readme;
mod solid;
mod solid_c_api;
mod solid_contact_c_api;
mod solid_host;
mod solid_validation;
