//! Named sets of FCLIB local problems (`hycon::contact::local`, docs/method.md "The local
//! problem"): increments of hycon's 3D and plane scenes exported with their converged
//! reactions (`ContactAnalysis::local_problem`), and random well-posed problems of growing
//! size. The FCLIB commands (`hycon fclib`) and the Siconos bench take their problems here.
//!
//! * `hertz3d`: the quarter cap pressed on its block (`hertz3d::QuarterCap`, frictionless, two
//!   symmetry planes: decoupled rows for the dropped tangents).
//! * `mindlin3d`: the half cap pressed and pulled to `Q / (mu P) = 0.5` (`mindlin3d::HalfCap`,
//!   `mu = 0.3`: stick inside, slip around it, one symmetry plane).
//! * `slide3d`: the block pressed on the flat and dragged at 30 degrees to its mesh lines
//!   (`slide3d::Slide`, small and finite kinematics: every node slipping).
//! * `plane`: the disk pressed on the block and then slid (`scene::DiskOnBlock`, `mu = 0.3`).
//! * `random`: `W = s (B^T B / m + I)` from a seeded `B`, `q` pressing most contacts and
//!   shearing some beyond their cone ([`random`]).

use crate::hertz3d::QuarterCap;
use crate::mindlin3d::HalfCap;
use crate::scene::DiskOnBlock;
use crate::slide3d::Slide;
use hycon::Result;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions};
use hycon::contact::local::LocalProblem;
use nalgebra::DMatrix;

/// One problem of a set: its class, a name unique in the class, the problem and, where it
/// comes from a converged increment, hycon's reactions (FCLIB's signs).
#[derive(Debug, Clone, PartialEq)]
pub struct NamedProblem {
    /// The class (module docs): `hertz3d`, `mindlin3d`, `slide3d`, `plane`, `random`.
    pub class: String,
    /// The problem's name within its class.
    pub name: String,
    /// The problem.
    pub problem: LocalProblem,
    /// The analysis' converged reactions (`None` for a random problem).
    pub solution: Option<Vec<f64>>,
}

/// The problem of `analysis`' last converged increment, named.
fn exported(class: &str, name: String, analysis: &mut ContactAnalysis) -> Result<NamedProblem> {
    let export = analysis.local_problem()?;
    Ok(NamedProblem {
        class: class.into(),
        name,
        problem: export.problem,
        solution: Some(export.solution),
    })
}

/// The quarter cap at `a_over_h` pressed by Hertz's approach: one problem (`a_over_h = 2` is
/// quick, 8 a bench size).
///
/// # Errors
/// Those of the scene and its increment.
pub fn hertz3d(a_over_h: usize) -> Result<Vec<NamedProblem>> {
    let mut cap = QuarterCap::new(a_over_h, ContactOptions::default())?;
    cap.press()?;
    let name = format!("quarter-cap-a{a_over_h}");
    Ok(vec![exported("hertz3d", name, &mut cap.analysis)?])
}

/// The half cap at `a_over_h` (`nu = 0.3`, `mu = 0.3`) pressed, then pulled to
/// `Q / (mu P) = 0.5`: two problems.
///
/// # Errors
/// Those of the scene and its increments.
pub fn mindlin3d(a_over_h: usize) -> Result<Vec<NamedProblem>> {
    let mut cap = HalfCap::new(a_over_h, 0.3, 0.3)?;
    let pressed = cap.press()?;
    let mut out = vec![exported(
        "mindlin3d",
        format!("half-cap-a{a_over_h}-press"),
        &mut cap.analysis,
    )?];
    cap.pull_to(&pressed, 0.5, 0.05, 6)?;
    out.push(exported(
        "mindlin3d",
        format!("half-cap-a{a_over_h}-pull"),
        &mut cap.analysis,
    )?);
    Ok(out)
}

/// The block dragged at 30 degrees over the flat, under small and finite kinematics: the
/// press and the first two drags of each.
///
/// # Errors
/// Those of the scene and its increments.
pub fn slide3d() -> Result<Vec<NamedProblem>> {
    let mut out = Vec::new();
    for (kind, slide) in [
        ("small", Slide::small(30.0)),
        ("finite", Slide::finite(30.0)),
    ] {
        let (mesh, mut analysis) = slide.analysis()?;
        let f = vec![0.0; 3 * mesh.mesh.n_nodes()];
        for step in 0..=2 {
            analysis.increment(&f, &slide.prescribed(&mesh, step))?;
            let name = format!("block-{kind}-step{step}");
            out.push(exported("slide3d", name, &mut analysis)?);
        }
    }
    Ok(out)
}

/// The plane disk on the block (`mu = 0.3`, 8 elements per half-width) pressed to Hertz's
/// load, then slid by a tenth of the approach: two problems of `dim = 2`.
///
/// # Errors
/// Those of the scene and its increments.
pub fn plane() -> Result<Vec<NamedProblem>> {
    let scene = DiskOnBlock {
        friction: 0.3,
        elements_per_half_width: 8,
        ..DiskOnBlock::default()
    }
    .build()?;
    let (mut analysis, approach) = scene.pressed(ContactOptions::default())?;
    let mut out = vec![exported("plane", "disk-press".into(), &mut analysis)?];
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    analysis.increment(&f, &scene.prescribed(approach, 0.1 * approach))?;
    out.push(exported("plane", "disk-slide".into(), &mut analysis)?);
    Ok(out)
}

/// A random well-posed problem of `contacts` contacts of `dim` components (seeded):
/// `W = s (B^T B / m + I)` with `B` of uniform entries in `(-0.5, 0.5)` (`m = dim contacts`,
/// `s = 1e-3`, a flexibility's size: `W` symmetric positive definite, its condition number a
/// few units); per contact `mu` from `{0, 0.1, .., 0.5}` (one in six frictionless), `q_N`
/// pressing (`-1` to `-0.5`) at two contacts in three and opening (`0.1` to `0.6`) at the
/// third, `q_T` up to twice `mu |q_N|` (some beyond the cone: slip), in units of `s`.
pub fn random(contacts: usize, dim: usize, seed: u64) -> NamedProblem {
    const SCALE: f64 = 1e-3;
    let mut x = seed ^ 0x2545_f491_4f6c_dd1d;
    let mut draw = move || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let m = dim * contacts;
    let b = DMatrix::from_fn(m, m, |_, _| draw() - 0.5);
    let w = (b.transpose() * &b / m as f64 + DMatrix::identity(m, m)) * SCALE;
    // exactly symmetric
    let w = (&w + w.transpose()) * 0.5;
    let mut q = vec![0.0; m];
    let mut mu = vec![0.0; contacts];
    for i in 0..contacts {
        mu[i] = if i % 6 == 5 {
            0.0
        } else {
            0.1 * (draw() * 5.0).floor() + 0.1
        };
        let normal = if i % 3 == 2 {
            0.1 + 0.5 * draw()
        } else {
            -0.5 - 0.5 * draw()
        };
        q[i * dim] = SCALE * normal;
        for j in 1..dim {
            q[i * dim + j] = SCALE * 2.0 * mu[i] * normal.abs() * (draw() - 0.5);
        }
    }
    NamedProblem {
        class: "random".into(),
        name: format!("random-d{dim}-n{contacts}-s{seed}"),
        problem: LocalProblem::new(dim, w, q, mu).expect("well formed"),
        solution: None,
    }
}

/// Random problems (`dim = 3`) of each size in `sizes`, seed `seed`.
pub fn randoms(sizes: &[usize], seed: u64) -> Vec<NamedProblem> {
    sizes.iter().map(|&n| random(n, 3, seed)).collect()
}
