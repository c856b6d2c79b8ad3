//! Sliding at an angle in 3D (issue #43): a block dragged over a flat at an angle `theta` to
//! the flat's mesh lines (`hycon::solid::contact_meshes::BlockOnFlat`, the block turned by
//! `theta` about the normal, so that it slides along its own mesh lines), both of `E = 1`,
//! `nu = 0.3`, 18-beta hybrid bricks, Coulomb friction `mu`; the flat's bottom held, the
//! block's top prescribed: pressed down by `depth` in the first increment, then moved by
//! `step` along `(cos theta, sin theta, 0)` in each further one (`ContactAnalysis::solid`).
//!
//! Once the whole bottom of the block slides (every drag increment after the first), every
//! A node slips along the drag, so the total friction force on the block opposes the drag and
//! its magnitude is `mu P` (`P` the total normal force), whatever the angle: a pyramid cone
//! (a polygonal cone aligned with the frames' tangents) errs by tens of percent off its
//! facets, a slip direction kept from the first drag increment errs in direction.
//! [`Slide::run`] reports both per increment ([`Increment`]).

use crate::solid_scene::{Multipliers, SolidScene};
use hycon::Result;
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, Kinematics, NodeResult, NodeState,
};
use hycon::solid::Isotropic;
use hycon::solid::contact_meshes::{BlockOnFlat, ContactMesh};

/// Young's modulus of both bodies.
pub const YOUNGS: f64 = 1.0;
/// Poisson's ratio of both bodies.
pub const POISSON: f64 = 0.3;

/// The scene's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slide {
    /// The drag's angle to the flat's mesh lines (and the block's turn), in degrees.
    pub theta: f64,
    /// The block's size and bricks: `[1, 1, 0.5]`, `[4, 4, 2]` by default.
    pub size: [f64; 3],
    /// The block's bricks per direction.
    pub cells: [usize; 3],
    /// The flat's size and bricks: `[5, 5, 1]`, `[10, 10, 2]` by default (faces `0.5` wide).
    pub flat: [f64; 3],
    /// The flat's bricks per direction.
    pub flat_cells: [usize; 3],
    /// The block's start, along the drag from the flat's centre.
    pub start: f64,
    /// The press of the block's top.
    pub depth: f64,
    /// The drag per increment.
    pub step: f64,
    /// Drag increments.
    pub steps: usize,
    /// Coulomb's coefficient.
    pub mu: f64,
    /// Small or finite kinematics.
    pub kinematics: Kinematics,
}

impl Slide {
    /// Small kinematics at `theta`: pressed by `1e-3`, dragged by `0.1` four times. The drag
    /// per increment is large against the block's elastic tangential displacement (some
    /// `mu depth`): an increment's slip is the drag plus the change of that displacement as
    /// the tractions turn from the press's to the drag's, which dies out geometrically from
    /// one increment to the next, by a factor of the order of their ratio (measured: the
    /// magnitude's error in the second drag increment is `8e-8`, `8e-12`, `4e-14` for drags of
    /// `0.01`, `0.1`, `1`; on a flat the size of the drag changes nothing else).
    pub fn small(theta: f64) -> Self {
        Slide {
            theta,
            size: [1.0, 1.0, 0.5],
            cells: [4, 4, 2],
            flat: [5.0, 5.0, 1.0],
            flat_cells: [10, 10, 2],
            start: 0.0,
            depth: 1e-3,
            step: 0.1,
            steps: 4,
            mu: 0.3,
            kinematics: Kinematics::Small,
        }
    }

    /// Finite kinematics at `theta`: pressed by `1e-6`, the block starts `1` behind the centre
    /// and is dragged by `0.25` eight times, over four of the flat's faces (`0.5` wide).
    ///
    /// The press is small against the drag for the reason of [`small`](Self::small), and
    /// more: under finite kinematics the interface is the deformed one, its normals tilted by
    /// the strain (up to about `depth`, measured), and the block meets new parts of the flat
    /// in every increment, whose elastic tangential displacement turns the slip off the drag.
    /// Both change the totals in the global axes by some `depth` relative (measured: the
    /// magnitude by `3.9e-4`, `3.9e-6`, `3.9e-7` and the angle by up to `3.7e-4`, `3.7e-6`,
    /// `3.8e-7` rad at presses of `1e-3`, `1e-5`, `1e-6`); in the nodes' own frames the
    /// magnitude errs by the square of the tilt (`3.4e-7`, `3.4e-11`, `3.4e-13`).
    pub fn finite(theta: f64) -> Self {
        Slide {
            depth: 1e-6,
            start: -1.0,
            step: 0.25,
            steps: 8,
            kinematics: Kinematics::Finite,
            ..Slide::small(theta)
        }
    }

    /// The unit drag direction.
    pub fn direction(&self) -> [f64; 2] {
        let (s, c) = self.theta.to_radians().sin_cos();
        [c, s]
    }

    /// The mesh: [`BlockOnFlat`] at `theta`, the block moved by `start` along the drag.
    ///
    /// # Errors
    /// Those of [`BlockOnFlat::build`].
    pub fn mesh(&self) -> Result<ContactMesh> {
        let mut mesh = BlockOnFlat {
            size: self.size,
            cells: self.cells,
            flat: self.flat,
            flat_cells: self.flat_cells,
            angle: self.theta,
        }
        .build()?;
        let [dx, dy] = self.direction();
        for p in &mut mesh.mesh.nodes[..mesh.a_nodes] {
            p[0] += self.start * dx;
            p[1] += self.start * dy;
        }
        Ok(mesh)
    }

    /// The mesh and the analysis, the flat's bottom held, the block's top prescribed (at 0).
    ///
    /// # Errors
    /// Those of the mesh, the model and `ContactAnalysis::solid`.
    pub fn analysis(&self) -> Result<(ContactMesh, ContactAnalysis)> {
        let material = Isotropic::new(YOUNGS, POISSON)?;
        let scene = SolidScene::new(
            self.mesh()?,
            [material; 2],
            &[0, 1, 2],
            Multipliers::Upper,
            self.mu,
        )?;
        let analysis = scene.analysis(ContactOptions {
            kinematics: self.kinematics,
            ..ContactOptions::default()
        })?;
        Ok((scene.mesh, analysis))
    }

    /// The prescribed values of the block's top (the model's `3 n_nodes` dofs) after `step`
    /// drag increments.
    pub fn prescribed(&self, mesh: &ContactMesh, step: usize) -> Vec<f64> {
        let mut qp = vec![0.0; 3 * mesh.mesh.n_nodes()];
        let [dx, dy] = self.direction();
        let drag = step as f64 * self.step;
        for &k in &mesh.a_top {
            qp[3 * k] = drag * dx;
            qp[3 * k + 1] = drag * dy;
            qp[3 * k + 2] = -self.depth;
        }
        qp
    }

    /// Build, press, drag; the increments' totals.
    ///
    /// # Errors
    /// Those of [`analysis`](Self::analysis) and the increments.
    pub fn run(&self) -> Result<Vec<Increment>> {
        let (mesh, mut analysis) = self.analysis()?;
        let n = 3 * mesh.mesh.n_nodes();
        let f = vec![0.0; n];
        let mut out = Vec::with_capacity(self.steps + 1);
        for step in 0..=self.steps {
            let info = analysis.increment(&f, &self.prescribed(&mesh, step))?;
            let nodes = analysis.node_results(0)?;
            let drag = step as f64 * self.step;
            out.push(Increment::of(self, &nodes, info.iterations, drag));
        }
        Ok(out)
    }
}

/// One increment's totals over the block's bottom.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Increment {
    /// The top's drag so far.
    pub drag: f64,
    /// The total normal force `P` on the block (its `z` component).
    pub normal: f64,
    /// The total friction force on the block (`x`, `y`).
    pub friction: [f64; 2],
    /// The angle in radians between the friction force and the opposite of the drag.
    pub angle: f64,
    /// `|F_t| / (mu P) - 1`.
    pub magnitude: f64,
    /// The same in the nodes' own frames, `|sum_k w_k t_k| / (mu sum_k w_k |tn_k|) - 1` with
    /// `t_k` node `k`'s tangential traction (a vector of its tangent plane) and `w_k` its
    /// weight: under finite kinematics the frames tilt with the deformed interface.
    pub frame_magnitude: f64,
    /// The mean position (`x`, `y`) of the block's bottom nodes.
    pub centre: [f64; 2],
    /// The largest angle in radians between a slip node's slip direction and the drag (0
    /// without slip nodes).
    pub spread: f64,
    /// Active, stick and slip A nodes.
    pub states: [usize; 3],
    /// Iterations of the increment.
    pub iterations: usize,
}

impl Increment {
    fn of(slide: &Slide, nodes: &[NodeResult], iterations: usize, drag: f64) -> Self {
        let total = |c: usize| nodes.iter().map(|r| r.force.components()[c]).sum::<f64>();
        let friction = [total(0), total(1)];
        let normal = total(2);
        let [dx, dy] = slide.direction();
        // the friction force against -d: atan2 of its cross and dot products with -d
        let along = -(friction[0] * dx + friction[1] * dy);
        let across = friction[1] * dx - friction[0] * dy;
        let spread = (nodes.iter())
            .filter_map(|r| match r.state {
                NodeState::Slip { direction } => {
                    let v = r.frame.vector(0.0, direction.vector());
                    let [x, y, z] = [0, 1, 2].map(|c| v.components()[c]);
                    let along = x * dx + y * dy;
                    Some((x * dy - y * dx).hypot(z).atan2(along))
                }
                _ => None,
            })
            .fold(0.0, f64::max);
        let (mut tangential, mut pressing) = ([0.0; 3], 0.0);
        for r in nodes {
            let t = r.frame.vector(0.0, r.ts);
            for (sum, c) in tangential.iter_mut().zip(t.components()) {
                *sum += r.weight * c;
            }
            pressing -= r.weight * r.tn;
        }
        let norm = tangential.iter().map(|c| c * c).sum::<f64>().sqrt();
        let mean = |c: usize| {
            nodes
                .iter()
                .map(|r| r.position.components()[c])
                .sum::<f64>()
                / nodes.len() as f64
        };
        let count = |f: fn(&NodeState) -> bool| nodes.iter().filter(|r| f(&r.state)).count();
        Increment {
            drag,
            normal,
            friction,
            angle: across.atan2(along).abs(),
            magnitude: friction[0].hypot(friction[1]) / (slide.mu * normal) - 1.0,
            frame_magnitude: norm / (slide.mu * pressing) - 1.0,
            centre: [mean(0), mean(1)],
            spread,
            states: [
                count(|s| *s != NodeState::Open),
                count(|s| *s == NodeState::Stick),
                count(|s| matches!(s, NodeState::Slip { .. })),
            ],
            iterations,
        }
    }
}
