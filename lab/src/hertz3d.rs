//! Hertz's sphere in 3D, the first 3D contact scene: the quarter model of a paraboloid cap
//! `z = r^2 / (2 R)` (`R = 1`) on a block (`hycon::solid::contact_meshes::CapOnBlock`:
//! `R / a = 16`, faces of size `h = a / (a/h)` out to `1.5 a`, graded beyond, the cap `8 a`
//! high, the block `16 a` deep), the block of `E = 1`, the cap of `E = 1` or softer
//! ([`QuarterCap::with`]: `E_cap / E_block`), `nu = 0.3`, 18-beta hybrid bricks; the block's
//! bottom held, the nodes on the symmetry planes `x = 0` and `y = 0` held normal to them, the
//! cap's top moved down by Hertz's approach `delta = a^2 / R` of the target radius `a`
//! ([`crate::closed3d::hertz_approach`]); frictionless, one increment
//! (`ContactAnalysis::solid`).
//!
//! [`QuarterCap::press`] compares with [`crate::closed3d`], as the axisymmetric sphere is
//! ([`crate::axisymmetric::SphereScene::compare`]): Hertz at the computed load `P` (the sum
//! of the contact forces, times 4), the contact radius and the peak from the moments of the
//! pressure ([`HertzSphere::from_moments`]: the multipliers `p = -tn`, bilinear on A's faces,
//! integrated over their projection on the plane `z = 0`), the peak at the centre node, the
//! relative L2 error of `p` over A's faces; and `P` against Hertz's load of the prescribed
//! approach ([`crate::closed3d::hertz_load`]).
//!
//! # The load of the approach
//! It does not tend to Hertz's as the mesh is refined: the bodies are finite (the block held
//! at depth `16 a`, the cap's top moved rigidly `8 a` above the contact), which removes the
//! half-space's displacement beyond them and stiffens the contact. Boussinesq's displacement
//! on the axis at depth `z`, `P (3 - 2 nu) / (4 pi G z)`, is `0.73 a / z` of one body's Hertz
//! approach `a^2 / (2 R)` here: some 5% of the block's and 9% of the cap's, so `P`, which
//! goes with the approach to the power 3/2, lies some 10% above Hertz's (measured +5.8% at
//! `a/h = 4`, +6.5% at 8: `hycon bench hertz3d`). [`QuarterCap::load_check`] takes the
//! finite bodies as they are meshed: Hertz's pressure at the computed `P`, applied to both
//! bodies in a linear analysis of the same model, closes the gap at the centre by `D(P)`;
//! the bodies' own compliance `c = (D(P) - delta_H(P)) / P` (negative: stiffer than
//! half-spaces) then gives the reference load `P*` of the approach,
//! `delta = delta_H(P*) + c P*`, `delta_H(P) = a(P)^2 / R`. The contact's `P` meets it to the
//! difference its pressure makes at the centre against Hertz's.

use crate::axisymmetric::{GAUSS5, HertzSphere, SphereComparison, SphereOnBlock};
use crate::closed3d::{hertz_approach, hertz_load};
use crate::examples::TimeSplit;
use crate::solid_scene::{Multipliers, SolidScene};
use hycon::Result;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, NodeResult, Timings};
use hycon::solid::Isotropic;
use hycon::solid::contact_meshes::{CapModel, CapOnBlock, ContactMesh};
use hycon::solid::model::{SolidModel, SolidSystem};
use hycon::solver::{Backend, FillOrdering};
use std::time::Instant;

/// Young's modulus of the block (and of the cap with identical materials).
pub const YOUNGS: f64 = 1.0;
/// Poisson's ratio of both bodies.
pub const POISSON: f64 = 0.3;

/// `E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2)` of the two bodies, identical materials.
pub fn e_star() -> f64 {
    e_star_of(1.0)
}

/// `E*` of the cap of `E = modulus_ratio YOUNGS` on the block of `E = YOUNGS`, both of
/// `nu = POISSON`.
pub fn e_star_of(modulus_ratio: f64) -> f64 {
    let soft = 1.0 - POISSON * POISSON;
    1.0 / (soft / (modulus_ratio * YOUNGS) + soft / YOUNGS)
}

/// The quarter cap on the block, its analysis built (module docs).
#[derive(Debug)]
pub struct QuarterCap {
    /// The mesh's parameters.
    pub spec: CapOnBlock,
    /// Both bodies' mesh, contact faces and node sets.
    pub mesh: ContactMesh,
    /// The contact analysis (one pair: the cap's bottom A on the block's top B).
    pub analysis: ContactAnalysis,
    /// The model the analysis was built from (for a linear analysis of the same model).
    pub model: SolidModel,
    /// `E_cap / E_block`.
    pub modulus_ratio: f64,
}

/// One pressed cap against Hertz.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapComparison {
    /// The total load `P` of the full model (4 times the quarter's contact force).
    pub load: f64,
    /// Hertz's load of the prescribed approach, `hertz_load(a)`.
    pub hertz_load: f64,
    /// Hertz at `load`.
    pub hertz: HertzSphere,
    /// The contact radius from the pressure's moments ([`HertzSphere::from_moments`]).
    pub radius: f64,
    /// The peak pressure from the pressure's moments ([`HertzSphere::from_moments`]).
    pub peak_from_moments: f64,
    /// The peak pressure read at the centre: `-tn` of the A node on the axis.
    pub peak: f64,
    /// `||p - p_H|| / ||p_H||` in L2 over A's faces projected on `z = 0` (`p = -tn` bilinear
    /// on each face, `p_H` Hertz's at `load`).
    pub l2_error: f64,
    /// The largest `|p_k - p(r_k)| / p0` over the A nodes within `a / 2` of the centre
    /// (`p_k = -tn_k`, `p` Hertz's at `load`).
    pub interior: f64,
    /// Active A nodes at convergence.
    pub active: usize,
    /// Iterations of the increment.
    pub iterations: usize,
}

impl CapComparison {
    /// The relative errors: the radius (from the moments) and the peak at the centre node
    /// against Hertz at the load, the load against Hertz's of the approach.
    pub fn errors(&self) -> [f64; 3] {
        [
            self.radius / self.hertz.radius - 1.0,
            self.peak / self.hertz.peak - 1.0,
            self.load / self.hertz_load - 1.0,
        ]
    }

    /// The peak from the moments against Hertz's at the load.
    pub fn peak_error(&self) -> f64 {
        self.peak_from_moments / self.hertz.peak - 1.0
    }
}

/// A linear analysis of the cap's model (no contact, `hycon::solid::model::SolidSystem` in its
/// default ordering): its time, and the centre's response to Hertz's pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearRun {
    /// Seconds of the assembly (the pattern and its values).
    pub assembly: f64,
    /// Seconds of the factorization (symbolic and numeric).
    pub factorization: f64,
    /// Seconds of one solve: the cap's top moved by the approach, no contact.
    pub solve: f64,
    /// The factorization's fill-reducing ordering (the contact analysis's too).
    pub ordering: FillOrdering,
    /// Stored entries of the factor `L`.
    pub nnz_l: usize,
    /// `D(P)`: how far Hertz's pressure at the load, applied to both bodies, moves the cap's
    /// bottom and the block's top at the centre towards each other (the cap's top and the
    /// block's bottom held).
    pub centre_closure: f64,
}

impl LinearRun {
    /// Assembly, factorization and one solve.
    pub fn total(&self) -> f64 {
        self.assembly + self.factorization + self.solve
    }
}

/// The load of the approach against the finite bodies' reference (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadCheck {
    /// The prescribed approach `delta`.
    pub approach: f64,
    /// Hertz's approach at the computed load, `delta_H(P) = a(P)^2 / R`.
    pub hertz_approach: f64,
    /// `c P = D(P) - delta_H(P)`: the finite bodies' share of the approach at `P` (negative:
    /// stiffer than half-spaces).
    pub finite_share: f64,
    /// The reference load `P*`: `delta = delta_H(P*) + c P*`.
    pub reference_load: f64,
    /// The computed load `P`.
    pub load: f64,
}

impl LoadCheck {
    /// `P / P* - 1`.
    pub fn error(&self) -> f64 {
        self.load / self.reference_load - 1.0
    }
}

/// The pressure along the radius `y = 0` of the quarter cap against hycon's axisymmetric
/// sphere ([`SphereOnBlock`]: the same `R / a`, `a / h` and moduli) pressed to the same load.
#[derive(Debug, Clone, PartialEq)]
pub struct RadialComparison {
    /// `[x, p_3d, p_axi, p_H]` at each A node of the cap on `y = 0` within the contact
    /// (`p_3d > 0`), `p_axi` the axisymmetric nodal pressure at `r = x` (interpolated linearly
    /// between its nodes; they fall on the same spacing), `p_H` Hertz's at the 3D load.
    pub rows: Vec<[f64; 4]>,
    /// The axisymmetric sphere against Hertz at its load.
    pub axisymmetric: SphereComparison,
    /// The 3D load.
    pub load: f64,
    /// The largest distance from an A node of the cap on `y = 0` within the contact to the
    /// nearest axisymmetric A node, in `h` (0 on the same spacing).
    pub offset: f64,
}

impl RadialComparison {
    /// The largest `|p_3d - p_axi| / p0` over the rows (`p0` Hertz's at the 3D load).
    pub fn max_difference(&self, p0: f64) -> f64 {
        (self.rows.iter())
            .map(|r| (r[1] - r[2]).abs() / p0)
            .fold(0.0, f64::max)
    }

    /// The axisymmetric load against the 3D one, `P_axi / P_3d - 1`.
    pub fn load_mismatch(&self) -> f64 {
        self.axisymmetric.load / self.load - 1.0
    }
}

impl QuarterCap {
    /// The quarter cap at `a_over_h` with `options`, identical materials.
    ///
    /// # Errors
    /// Those of the mesh, the model and `ContactAnalysis::solid`.
    pub fn new(a_over_h: usize, options: ContactOptions) -> Result<Self> {
        Self::with(CapOnBlock::new(CapModel::Quarter, a_over_h), 1.0, options)
    }

    /// The quarter cap of mesh `spec` (a [`CapModel::Quarter`]), the cap of
    /// `E = modulus_ratio YOUNGS` on the block of `E = YOUNGS`, with `options`.
    ///
    /// # Errors
    /// Those of the mesh, the materials, the model and `ContactAnalysis::solid`.
    pub fn with(spec: CapOnBlock, modulus_ratio: f64, options: ContactOptions) -> Result<Self> {
        Self::with_mesh(spec, spec.build()?, modulus_ratio, options)
    }

    /// As [`with`](Self::with), on `mesh`, already built from `spec`.
    ///
    /// # Errors
    /// Those of the materials, the model and `ContactAnalysis::solid`.
    pub fn with_mesh(
        spec: CapOnBlock,
        mesh: ContactMesh,
        modulus_ratio: f64,
        options: ContactOptions,
    ) -> Result<Self> {
        let cap = Isotropic::new(modulus_ratio * YOUNGS, POISSON)?;
        let block = Isotropic::new(YOUNGS, POISSON)?;
        // the cap's top moved down by the increment's prescribed values (`press`)
        let scene = SolidScene::new(mesh, [cap, block], &[2], Multipliers::Upper, 0.0)?;
        let analysis = scene.analysis(options)?;
        Ok(QuarterCap {
            spec,
            mesh: scene.mesh,
            analysis,
            model: scene.model,
            modulus_ratio,
        })
    }

    /// `E*` of the two bodies.
    pub fn e_star(&self) -> f64 {
        e_star_of(self.modulus_ratio)
    }

    /// Hertz's approach `a^2 / R` of the target radius: what [`press`](Self::press) prescribes.
    pub fn approach(&self) -> f64 {
        hertz_approach(self.spec.contact_radius(), 1.0)
    }

    /// The prescribed values of the press: the cap's top moved down by the approach.
    pub fn pressed(&self) -> Vec<f64> {
        let mut qp = vec![0.0; 3 * self.mesh.mesh.n_nodes()];
        for &node in &self.mesh.a_top {
            qp[3 * node + 2] = -self.approach();
        }
        qp
    }

    /// The distance of node `node` from the axis.
    fn radial(&self, node: usize) -> f64 {
        let [x, y, _] = self.mesh.mesh.nodes[node];
        x.hypot(y)
    }

    /// Press the cap by Hertz's approach of the target radius and compare with Hertz.
    ///
    /// # Errors
    /// Those of the increment.
    pub fn press(&mut self) -> Result<CapComparison> {
        let n = 3 * self.mesh.mesh.n_nodes();
        let info = self.analysis.increment(&vec![0.0; n], &self.pressed())?;
        let nodes = self.analysis.node_results(0)?;
        let force = |r: &NodeResult| -r.frame.normal().dot(&r.force);
        let load = 4.0 * nodes.iter().map(force).sum::<f64>();
        let hertz = HertzSphere::new(load, 1.0, self.e_star());
        let peak = (nodes.iter())
            .find(|r| self.radial(r.node) == 0.0)
            .map_or(f64::NAN, |r| -r.tn);
        let interior = (nodes.iter())
            .filter(|r| self.radial(r.node) <= 0.5 * hertz.radius)
            .map(|r| (-r.tn - hertz.pressure(self.radial(r.node))).abs() / hertz.peak)
            .fold(0.0, f64::max);
        let mut pressure = vec![0.0; self.mesh.a_nodes];
        for r in &nodes {
            pressure[r.node] = -r.tn;
        }
        let integrals = self.integrals(&pressure, &hertz);
        let fit = HertzSphere::from_moments(integrals.m1, integrals.m3);
        Ok(CapComparison {
            load,
            hertz_load: hertz_load(self.spec.contact_radius(), 1.0, self.e_star()),
            hertz,
            radius: fit.radius,
            peak_from_moments: fit.peak,
            peak,
            l2_error: integrals.l2_error,
            interior,
            active: info.active,
            iterations: info.iterations,
        })
    }

    /// The moments (per radian, as [`HertzSphere::from_moments`] takes them) and the L2 error
    /// against `hertz` of the pressure bilinear on A's faces with the nodal values `pressure`
    /// (indexed by node id), over the faces projected on `z = 0`, the quarter's integrals
    /// times 4: `m1 = integral p dA / (2 pi)`, `m3 = integral p r^2 dA / (2 pi)`.
    fn integrals(&self, pressure: &[f64], hertz: &HertzSphere) -> Integrals {
        let (mut m1, mut m3, mut num, mut den) = (0.0, 0.0, 0.0, 0.0);
        for face in &self.mesh.a_faces {
            let corners = face.map(|k| self.mesh.mesh.nodes[k]);
            for (shape, x, area) in face_points(corners) {
                let p: f64 = (0..4).map(|k| shape[k] * pressure[face[k]]).sum();
                let r2 = x[0] * x[0] + x[1] * x[1];
                let da = area[2].abs();
                let exact = hertz.pressure(r2.sqrt());
                m1 += p * da;
                m3 += p * r2 * da;
                num += (p - exact).powi(2) * da;
                den += exact * exact * da;
            }
        }
        let quarter = 4.0 / (2.0 * std::f64::consts::PI);
        Integrals {
            m1: quarter * m1,
            m3: quarter * m3,
            l2_error: (num / den).sqrt(),
        }
    }

    /// The contact pressure `-tn` at the A nodes on `y = 0` (the radius along `x`), `[x, p]`
    /// sorted by `x`.
    ///
    /// # Errors
    /// Those of `ContactAnalysis::node_results` (no converged increment).
    pub fn pressure_along_x(&self) -> Result<Vec<[f64; 2]>> {
        let mut points: Vec<[f64; 2]> = (self.analysis.node_results(0)?.iter())
            .filter(|r| self.mesh.mesh.nodes[r.node][1] == 0.0)
            .map(|r| [self.mesh.mesh.nodes[r.node][0], -r.tn])
            .collect();
        points.sort_by(|u, v| u[0].total_cmp(&v[0]));
        Ok(points)
    }

    /// A linear analysis of the same model, timed: assembly and factorization of a fresh
    /// `K_ff` (the default ordering), one solve with the cap's top moved by the approach;
    /// then, untimed, the centre's closure `D(P)` under Hertz's pressure at `load` on both
    /// bodies (module docs).
    ///
    /// # Errors
    /// Those of the factorization and the solves.
    pub fn linear(&self, load: f64) -> Result<LinearRun> {
        let mut system = SolidSystem::with_trailing_on(&self.model, &[], Backend::Faer)?;
        let [assembly, factorization] = system.setup_seconds();
        let n = 3 * self.mesh.mesh.n_nodes();
        let clock = Instant::now();
        system.solve_for(&self.model, &vec![0.0; n], &self.pressed())?;
        let solve = clock.elapsed().as_secs_f64();
        let hertz = HertzSphere::new(load, 1.0, self.e_star());
        let mut f = vec![0.0; n];
        for face in self.mesh.a_faces.iter().chain(&self.mesh.b_faces) {
            let corners = face.map(|k| self.mesh.mesh.nodes[k]);
            for (shape, x, area) in face_points(corners) {
                // the traction -p n on the face's own body: area = n dA
                let p = hertz.pressure(x[0].hypot(x[1]));
                for (k, &node) in face.iter().enumerate() {
                    for d in 0..3 {
                        f[3 * node + d] -= shape[k] * p * area[d];
                    }
                }
            }
        }
        let u = system.solve_for(&self.model, &f, &vec![0.0; n])?;
        let centre = |nodes: std::ops::Range<usize>| {
            nodes
                .into_iter()
                .find(|&k| self.mesh.mesh.nodes[k] == [0.0; 3])
                .map_or(f64::NAN, |k| u[3 * k + 2])
        };
        let (a, all) = (self.mesh.a_nodes, self.mesh.mesh.n_nodes());
        Ok(LinearRun {
            assembly,
            factorization,
            solve,
            ordering: system.cholesky().ordering(),
            nnz_l: system.cholesky().nnz_l(),
            centre_closure: centre(0..a) - centre(a..all),
        })
    }

    /// The load of the approach against the finite bodies' reference `P*` (module docs) from
    /// the press `c` and the linear analysis `linear` at its load.
    pub fn load_check(&self, c: &CapComparison, linear: &LinearRun) -> LoadCheck {
        let delta_h = |p: f64| HertzSphere::new(p, 1.0, self.e_star()).radius.powi(2);
        let compliance = (linear.centre_closure - delta_h(c.load)) / c.load;
        let approach = self.approach();
        // Newton on delta_H(P) + c P = delta from P (delta_H' = 2 delta_H / (3 P))
        let mut p = c.load;
        for _ in 0..50 {
            let residual = delta_h(p) + compliance * p - approach;
            let step = residual / (2.0 * delta_h(p) / (3.0 * p) + compliance);
            p -= step;
            if step.abs() <= 1e-14 * p {
                break;
            }
        }
        LoadCheck {
            approach,
            hertz_approach: delta_h(c.load),
            finite_share: compliance * c.load,
            reference_load: p,
            load: c.load,
        }
    }

    /// The contact analysis's time so far against the linear analysis `linear` of the same
    /// model (one increment).
    pub fn time_split(&self, linear: &LinearRun) -> TimeSplit {
        time_split(self.analysis.timings(), linear)
    }

    /// The pressure along `x` of the pressed cap `c` against hycon's axisymmetric sphere of the
    /// same `R / a`, `a / h` and moduli, pressed to the same load (its approach scaled by
    /// `(P / P_axi)^(2/3)` twice: `P` goes with the approach to the power 3/2).
    ///
    /// # Errors
    /// Those of the axisymmetric scene and its increments.
    pub fn radial_comparison(&self, c: &CapComparison) -> Result<RadialComparison> {
        let sphere = SphereOnBlock {
            elements_per_radius: self.spec.a_over_h,
            radius_over_contact: self.spec.radius_over_contact,
            modulus_ratio: self.modulus_ratio,
        };
        let scene = sphere.build()?;
        let mut analysis = scene.analysis(ContactOptions::default())?;
        let f = vec![0.0; scene.model.external_forces().len()];
        let mut approach = scene.hertz_approach();
        let mut axisymmetric = None;
        for _ in 0..3 {
            analysis.increment(&f, &scene.prescribed(approach))?;
            let s = scene.compare(&analysis)?;
            approach *= (c.load / s.load).powf(2.0 / 3.0);
            axisymmetric = Some(s);
        }
        let axisymmetric = axisymmetric.expect("three presses");
        let profile = scene.pressure_profile(&analysis)?;
        let h = self.mesh.h;
        let hertz = HertzSphere::new(c.load, 1.0, self.e_star());
        let mut offset: f64 = 0.0;
        let rows = (self.pressure_along_x()?.into_iter())
            .filter(|&[_, p]| p > 0.0)
            .map(|[x, p]| {
                let nearest = (profile.iter()).fold(f64::INFINITY, |m, q| m.min((q[0] - x).abs()));
                offset = offset.max(nearest / h);
                [x, p, interpolate(&profile, x), hertz.pressure(x)]
            })
            .collect();
        Ok(RadialComparison {
            rows,
            axisymmetric,
            load: c.load,
            offset,
        })
    }
}

/// The time `phases` of a contact analysis of the cap (one increment, one factorization)
/// against the linear analysis `linear` of the same model.
pub fn time_split(phases: Timings, linear: &LinearRun) -> TimeSplit {
    TimeSplit {
        phases,
        total: phases.total(),
        increments: 1,
        factorizations: 1,
        one_solve: linear.solve,
        linear: linear.total(),
        ratio: phases.total() / linear.total(),
    }
}

/// The moments and the L2 error of [`QuarterCap::integrals`].
struct Integrals {
    m1: f64,
    m3: f64,
    l2_error: f64,
}

/// Cells per side a face is cut into for its quadrature (5 x 5 Gauss points each): Hertz's
/// square-root edge crosses some faces.
const FACE_CELLS: usize = 4;

/// The quadrature points of the bilinear face with `corners` (counter-clockwise seen from
/// outside, at `(0,0), (1,0), (1,1), (0,1)` of `(s, t)`): the shape functions, the point and
/// the weighted area vector `w x_s x x_t` (outward, its length `w dA`), cut into
/// [`FACE_CELLS`]^2 cells of [`GAUSS5`] x [`GAUSS5`] points.
fn face_points(corners: [[f64; 3]; 4]) -> impl Iterator<Item = ([f64; 4], [f64; 3], [f64; 3])> {
    let cell = 1.0 / FACE_CELLS as f64;
    let along =
        (0..FACE_CELLS).flat_map(move |i| GAUSS5.map(|(g, w)| ((i as f64 + g) * cell, w * cell)));
    let grid: Vec<(f64, f64)> = along.collect();
    let points: Vec<((f64, f64), (f64, f64))> = (grid.iter())
        .flat_map(|&s| grid.iter().map(move |&t| (s, t)))
        .collect();
    points.into_iter().map(move |((s, ws), (t, wt))| {
        let shape = [(1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t];
        let x = std::array::from_fn(|d| (0..4).map(|k| shape[k] * corners[k][d]).sum());
        let xs: [f64; 3] = std::array::from_fn(|d| {
            (1.0 - t) * (corners[1][d] - corners[0][d]) + t * (corners[2][d] - corners[3][d])
        });
        let xt: [f64; 3] = std::array::from_fn(|d| {
            (1.0 - s) * (corners[3][d] - corners[0][d]) + s * (corners[2][d] - corners[1][d])
        });
        let w = ws * wt;
        let area = [
            w * (xs[1] * xt[2] - xs[2] * xt[1]),
            w * (xs[2] * xt[0] - xs[0] * xt[2]),
            w * (xs[0] * xt[1] - xs[1] * xt[0]),
        ];
        (shape, x, area)
    })
}

/// `points` (`[r, p]`, sorted by `r`) interpolated linearly at `r` (the end values beyond).
fn interpolate(points: &[[f64; 2]], r: f64) -> f64 {
    match points.iter().position(|q| q[0] >= r) {
        None => points[points.len() - 1][1],
        Some(0) => points[0][1],
        Some(i) => {
            let ([r0, p0], [r1, p1]) = (points[i - 1], points[i]);
            p0 + (r - r0) / (r1 - r0) * (p1 - p0)
        }
    }
}
