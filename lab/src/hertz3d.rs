//! Hertz's sphere in 3D, the first 3D contact scene: the quarter model of a paraboloid cap
//! `z = r^2 / (2 R)` (`R = 1`) on a block (`hycon::solid::contact_meshes::CapOnBlock`:
//! `R / a = 16`, faces of size `h = a / (a/h)` out to `1.5 a`, graded beyond, the cap `8 a`
//! high, the block `16 a` deep), both of `E = 1`, `nu = 0.3`, 18-beta hybrid bricks; the
//! block's bottom held, the nodes on the symmetry planes `x = 0` and `y = 0` held normal to
//! them, the cap's top moved down by Hertz's approach `delta = a^2 / R` of the target radius
//! `a` ([`crate::closed3d::hertz_approach`]); frictionless, one increment
//! (`ContactAnalysis::solid`).
//!
//! [`QuarterCap::press`] compares with [`crate::closed3d`]: the contact radius and the peak
//! pressure against Hertz at the computed load `P` (as the axisymmetric sphere is,
//! [`crate::axisymmetric`]), and `P` against Hertz's load of the prescribed approach
//! ([`crate::closed3d::hertz_load`]). The radius comes from the moments of the contact
//! forces, `sum f_k r_k^2 / sum f_k = 2 a^2 / 5` for Hertz's pressure; the peak is the
//! multiplier at the centre node.
//!
//! The load of the approach does not tend to Hertz's as the mesh is refined: the bodies are
//! finite (the block held at depth `16 a`, the cap's top moved rigidly `8 a` above the
//! contact), which removes the half-space's displacement beyond them and stiffens the contact.
//! Boussinesq's displacement on the axis at depth `z`, `P (3 - 2 nu) / (4 pi G z)`, is
//! `0.73 a / z` of one body's Hertz approach `a^2 / (2 R)` here: some 5% of the block's and 9%
//! of the cap's, so `P`, which goes with the approach to the power 3/2, lies some 10% above
//! Hertz's (measured +5.8% at `a/h = 4`, +6.5% at 8: `hycon bench hertz3d`).

use crate::closed3d::{HertzSphere, hertz_approach, hertz_load};
use hycon::Result;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeResult};
use hycon::solid::contact_meshes::{CapModel, CapOnBlock, ContactMesh};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};

/// Young's modulus of both bodies.
pub const YOUNGS: f64 = 1.0;
/// Poisson's ratio of both bodies.
pub const POISSON: f64 = 0.3;

/// `E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2)` of the two bodies.
pub fn e_star() -> f64 {
    YOUNGS / (2.0 * (1.0 - POISSON * POISSON))
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
    /// The contact radius from the moments of the contact forces.
    pub radius: f64,
    /// The peak pressure: `-tn` at the centre node.
    pub peak: f64,
    /// The largest `|p_k - p(r_k)| / p0` over the A nodes within `a / 2` of the centre
    /// (`p_k = -tn_k`, `p` Hertz's at `load`).
    pub interior: f64,
    /// Active A nodes at convergence.
    pub active: usize,
    /// Iterations of the increment.
    pub iterations: usize,
}

impl CapComparison {
    /// The relative errors: the radius and the peak against Hertz at the load, the load
    /// against Hertz's of the approach.
    pub fn errors(&self) -> [f64; 3] {
        [
            self.radius / self.hertz.radius - 1.0,
            self.peak / self.hertz.peak - 1.0,
            self.load / self.hertz_load - 1.0,
        ]
    }
}

impl QuarterCap {
    /// The quarter cap at `a_over_h` with `options`.
    ///
    /// # Errors
    /// Those of the mesh, the model and `ContactAnalysis::solid`.
    pub fn new(a_over_h: usize, options: ContactOptions) -> Result<Self> {
        let spec = CapOnBlock::new(CapModel::Quarter, a_over_h);
        let mesh = spec.build()?;
        let material = Isotropic::new(YOUNGS, POISSON)?;
        let mut model = SolidModel::new(
            mesh.mesh.clone(),
            vec![material, material],
            BrickFormulation::Hybrid18,
        )?;
        for &n in &mesh.b_bottom {
            for d in 0..3 {
                model.fix(n, d, 0.0);
            }
        }
        for (plane, nodes) in &mesh.symmetry {
            // the quarter's planes are x = 0 and y = 0
            let d = (plane.normal.iter()).position(|&v| v != 0.0).unwrap_or(0);
            for &n in nodes {
                model.fix(n, d, 0.0);
            }
        }
        // moved by the increment's prescribed values (`press`)
        for &n in &mesh.a_top {
            model.fix(n, 2, 0.0);
        }
        let pair = FacePair {
            a: mesh.a_faces.clone(),
            b: mesh.b_faces.clone(),
            friction: 0.0,
        };
        let planes: Vec<_> = mesh.symmetry.iter().map(|(p, _)| *p).collect();
        let analysis = ContactAnalysis::solid(model, vec![pair], &planes, options)?;
        Ok(QuarterCap {
            spec,
            mesh,
            analysis,
        })
    }

    /// The distance of A node result `r` from the axis.
    fn radial(&self, r: &NodeResult) -> f64 {
        let [x, y, _] = self.mesh.mesh.nodes[r.node];
        x.hypot(y)
    }

    /// Press the cap by Hertz's approach of the target radius and compare with Hertz.
    ///
    /// # Errors
    /// Those of the increment.
    pub fn press(&mut self) -> Result<CapComparison> {
        let n = 3 * self.mesh.mesh.n_nodes();
        let mut qp = vec![0.0; n];
        for &node in &self.mesh.a_top {
            qp[3 * node + 2] = -hertz_approach(self.spec.contact_radius(), 1.0);
        }
        let info = self.analysis.increment(&vec![0.0; n], &qp)?;
        let nodes = self.analysis.node_results(0)?;
        let force = |r: &NodeResult| -r.frame.normal().dot(&r.force);
        let quarter_load: f64 = nodes.iter().map(force).sum();
        let moment: f64 = (nodes.iter())
            .map(|r| force(r) * self.radial(r).powi(2))
            .sum();
        let load = 4.0 * quarter_load;
        let hertz = HertzSphere::new(load, 1.0, e_star());
        let peak = (nodes.iter())
            .find(|r| self.radial(r) == 0.0)
            .map_or(f64::NAN, |r| -r.tn);
        let interior = (nodes.iter())
            .filter(|r| self.radial(r) <= 0.5 * hertz.radius)
            .map(|r| (-r.tn - hertz.pressure(self.radial(r))).abs() / hertz.peak)
            .fold(0.0, f64::max);
        Ok(CapComparison {
            load,
            hertz_load: hertz_load(self.spec.contact_radius(), 1.0, e_star()),
            hertz,
            radius: (2.5 * moment / quarter_load).sqrt(),
            peak,
            interior,
            active: info.active,
            iterations: info.iterations,
        })
    }
}
