//! The tests of hycon-lab (the scenes, reference cases, benchmarks' building blocks and the
//! `hycon` program), one module per file, built as one test binary: `cargo test -p hycon-lab
//! --test lab [filter]`, e.g. `contact_hertz::` for one file's tests.

mod common;

mod backends;
mod cli;
mod closed3d;
mod contact_algebra;
mod contact_axisymmetric;
mod contact_cattaneo;
mod contact_convergence;
mod contact_friction3d;
mod contact_hertz;
mod contact_hertz3d;
mod contact_host;
mod contact_mindlin3d;
mod contact_plate3d;
mod contact_robustness;
mod contact_settle;
mod contact_slide3d;
mod contact_sliding;
#[cfg(feature = "fclib")]
mod fclib;
mod guard;
mod linear;
mod local_problems;
mod scene_findings;
mod scenes;
#[cfg(feature = "siconos")]
mod siconos;
mod stress_suite;
