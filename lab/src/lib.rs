//! # hycon-lab
//!
//! Everything around the hycon library that a host does not link: the reference scenes and
//! cases, the paper's examples, the benchmarks, the report writers and the `hycon` command-line
//! program (`src/main.rs`). It uses only hycon's public Rust API.
//!
//! * [`cases`]: reference problems with closed forms or published values (Hertz, Cook's
//!   membrane, the Pian-Sumihara cantilever).
//! * [`scene`]: the disk-on-block contact scene of the paper and its comparison with Hertz.
//! * [`axisymmetric`]: axisymmetric contact scenes with closed forms (shrink fit, push-out,
//!   cylinders stacked on the axis).
//! * [`closed3d`]: the closed forms of the 3D contact validation (Hertz's sphere, its approach,
//!   Cattaneo-Mindlin's partial slip of a sphere).
//! * [`mindlin3d`]: Cattaneo-Mindlin's partial slip in 3D (the half cap on its mirror block).
//! * [`plate3d`]: the rigid plate in 3D: Hertz at a given force, Mindlin at a given shear.
//! * [`examples`]: the paper's examples on that scene (Hertz, sliding, Cattaneo-Mindlin).
//! * [`examples3d`]: the main job's 3D examples (Hertz's sphere, Cattaneo-Mindlin) in the same
//!   result structs.
//! * [`solid_scene`]: the two-body 3D scene (model, supports, pair, symmetry planes) the 3D
//!   scenes share.
//! * [`bench`](mod@bench): the measurements behind the performance figures of docs/performance.md.
//! * [`presses`]: random two-block presses, counted by how the contact iteration ends.
//! * [`report`]: output writers: SVG plots, VTU files of both bodies, JSON.
//! * `fclib` (feature `fclib`): FCLIB's local problem files out and in, through libfclib.
//! * [`gmsh`]: a Gmsh MSH 4.1 ASCII reader (quadrilaterals, lines, points, physical groups).
//! * [`scenefile`]: TOML scene files over Gmsh meshes (`hycon run`).
//! * [`local_problems`]: named sets of FCLIB local problems: increments of the 3D and plane
//!   scenes exported with their converged reactions, random well-posed problems.
//! * [`slide3d`]: a block dragged over a flat at an angle to its mesh lines (3D friction).
//! * `siconos` (feature `siconos`): Siconos' `fc3d` solvers on hycon's local problems, side
//!   by side with hycon's; `siconos_bench`: the bench (`hycon bench siconos`).
#![warn(missing_docs)]

pub mod axisymmetric;
pub mod bench;
pub mod cases;
pub mod closed3d;
pub mod examples;
pub mod examples3d;
#[cfg(feature = "fclib")]
pub mod fclib;
pub mod gmsh;
pub mod hertz3d;
pub mod local_problems;
pub mod mindlin3d;
pub mod plate3d;
pub mod presses;
pub mod report;
pub mod scene;
pub mod scenefile;
#[cfg(feature = "siconos")]
pub mod siconos;
#[cfg(feature = "siconos")]
pub mod siconos_bench;
pub mod slide3d;
pub mod solid_scene;
