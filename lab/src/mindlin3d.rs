//! Cattaneo-Mindlin in 3D: the half model (`y >= 0`, cut by the plane of `Q` and the normal) of
//! the paraboloid cap on the block (`hycon::solid::contact_meshes::CapOnBlock`, `R / a = 256`,
//! faces of size `h = a / (a/h)` out to `1.5 a`), the two bodies elastically identical (the same
//! `E = 1` and `nu`) and of the same shape: the block's extent set to the cap's, `8 a` wide and
//! deep, so that the block is the cap's mirror image in `z = 0` (meshes included) but for the
//! cap's curved bottom. The block's bottom is held, the cap's top moved rigidly (all three
//! directions prescribed, as the block's bottom's are), the nodes on `y = 0` held along `y`;
//! 18-beta hybrid bricks, small kinematics, Coulomb friction `mu` from the start; the
//! multipliers on the block's flat top (side A), the cap's bottom side B.
//!
//! [`HalfCap::press`] moves the cap's top down by Hertz's approach `a^2 / R` of the target
//! radius ([`crate::closed3d::hertz_approach`]); [`HalfCap::pull_to`] then moves it along `x`
//! until `Q / (mu P)` reaches a target, forward only (friction remembers the path): a secant
//! on `y = 1 - (1 - Q / (mu P))^(2/3)`, which Mindlin's compliance makes proportional to the
//! displacement ([`crate::closed3d::Mindlin::compliance_displacement`]), each step one
//! increment from the last. [`Pull`] reports `P`, `Q`, the contact radius (from the moments of
//! the normal forces, `sum f r^2 / sum f = 2 a^2 / 5` for Hertz's pressure) and the stick
//! radius read off the node states along and across `Q` ([`Ray`]), against Mindlin's
//! `c = a (1 - Q / (mu P))^(1/3)`.
//!
//! Why this model (measured at `nu = 0`, `mu = 0.3`): Mindlin's solution needs the press to
//! leave no tangential traction, i.e. the two surfaces to move alike radially under the
//! pressure, as identical half-spaces do (at any `nu`: each surface's radial displacement,
//! `(1 - 2 nu) / (4 pi G r)` per unit load, is the other's).
//! * The unlike bodies of `CapOnBlock::new` (the cap `8 a`, the block `16 a`, `R / a = 16`):
//!   the press slips at 4 of the 26 active nodes at `a/h = 4` (`contact_friction3d`).
//! * Mirror bodies, `R / a = 16`, multipliers on the cap: the press still slips at the same 4
//!   nodes (`r = 0.87 a`), the cap's surface moving inward relative to the block's.
//!   Frictionless, the cap's surface moves along `x` by `-1.757e-4` at `x = h` and the block's
//!   by `-1.398e-4`: the cap's bottom is curved, its normal tilted by `r / R`, so the pressure
//!   pushes the cap inward and the block outward by `p r / R`, and the relative approach has
//!   a component along the tilted tangent; both are of relative order `a / R`, outside
//!   Hertz's and Mindlin's linearised theory, and they slip where the pressure is small. With
//!   the multipliers on the block the press slips nowhere at `a/h = 4` but at 3 nodes at the
//!   edge at `a/h = 8`, and at `Q / (mu P) = 0.5` and `a/h = 4` the stick radius on the
//!   trailing side is a node spacing smaller than on the leading side.
//! * Multipliers on the curved cap, even at `R / a = 256`: the tangential tractions of the
//!   stick nodes come out unlike on the two sides of the centre (at `a/h = 4`,
//!   `Q / (mu P) = 0.088`, all stick: `|tx| / |tn|` 0.060 at `x = -3 h` and 0.036 at `+3 h`,
//!   against 0.049 and 0.046 with them on the flat block), and at `Q / (mu P) = 0.5` the node
//!   at `-3 h` slips while its twin at `+3 h` sticks; the stick nodes' tractions alternate
//!   from node to node on either side (0.024, 0.080, 0.018, 0.26 at `x = 0, h, 2 h, 3 h` at
//!   0.5, Mindlin's ratio 0.062, 0.066, 0.084, 0.155) and follow small changes of the
//!   geometry strongly.
//! * Multipliers on the block and `R / a =` [`RADIUS_OVER_CONTACT`] `= 256` (64 measures the
//!   same): the press slips nowhere at `a/h = 4` and 8, and the leading and trailing sides
//!   agree node for node.
//!
//! The numbers against Mindlin are `lab/tests/contact_mindlin3d.rs`'s.

use crate::closed3d::{Mindlin, hertz_approach};
use crate::solid_scene::{Multipliers, SolidScene};
use hycon::Result;
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, IncrementInfo, NodeResult, NodeState,
};
use hycon::solid::Isotropic;
use hycon::solid::contact_meshes::{CapModel, CapOnBlock};

/// Young's modulus of both bodies.
pub const YOUNGS: f64 = 1.0;

/// `R / a` of [`HalfCap::new`]: flat enough that the press slips nowhere at `a/h = 4` and 8
/// (module docs).
pub const RADIUS_OVER_CONTACT: f64 = 256.0;

/// The half cap on its mirror block, its analysis built (module docs).
#[derive(Debug)]
pub struct HalfCap {
    /// The mesh's parameters.
    pub spec: CapOnBlock,
    /// Both bodies' mesh and model, the pair and the symmetry plane.
    pub scene: SolidScene,
    /// The contact analysis (one pair: the block's top A under the cap's bottom B).
    pub analysis: ContactAnalysis,
    /// Poisson's ratio of both bodies.
    pub poisson: f64,
    /// The friction coefficient `mu`.
    pub friction: f64,
    /// The prescribed motion of the cap's top so far, `[x, z]`.
    motion: [f64; 2],
}

/// The stick-slip transition along one ray from the contact's centre (reference positions):
/// the largest radius of a stick node on it, and the smallest radius of a node on it that does
/// not stick (slips, or is open: the end of the contact where nothing slips).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// Largest radius of a stick node (`NaN` if none sticks).
    pub stick: f64,
    /// Smallest radius of a node that does not stick (infinite if there is none).
    pub beyond: f64,
}

impl Ray {
    /// The stick radius measured on the ray: midway between the last stick node and the first
    /// node that does not stick.
    pub fn radius(&self) -> f64 {
        0.5 * (self.stick + self.beyond)
    }

    /// Whether the stick nodes form one disk on the ray: the first node that does not stick
    /// lies beyond the last one that does.
    pub fn is_stick_disk(&self) -> bool {
        self.beyond > self.stick
    }
}

/// The state of the contact after an increment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pull {
    /// The full model's normal load `P` (twice the half's).
    pub load: f64,
    /// The full model's tangential load `Q` along `x`.
    pub tangential: f64,
    /// The contact radius from the moments of the normal forces.
    pub radius: f64,
    /// The cap's top's prescribed motion along `x`.
    pub displacement: f64,
    /// Along `+x`, the leading side (the cap moves towards `+x`).
    pub leading: Ray,
    /// Along `-x`, the trailing side.
    pub trailing: Ray,
    /// Along `+y`, across `Q`.
    pub across: Ray,
    /// The largest angle, in degrees, of a slip node's slip direction to Mindlin's: the cap's
    /// along `Q` (`+x`) relative to the block (0 without slip nodes).
    pub spread: f64,
    /// The increment's summary.
    pub info: IncrementInfo,
}

impl Pull {
    /// `Q / (mu P)`.
    pub fn ratio(&self, mu: f64) -> f64 {
        self.tangential / (mu * self.load)
    }

    /// Mindlin's stick radius `c = a (1 - Q / (mu P))^(1/3)` at this pull's `Q / (mu P)`, with
    /// the measured contact radius `a`.
    pub fn mindlin_stick(&self, mu: f64) -> f64 {
        self.radius * (1.0 - self.ratio(mu)).cbrt()
    }
}

/// Mindlin's `y = 1 - (1 - x)^(2/3)`, proportional to the tangential displacement.
fn compliance_fraction(x: f64) -> f64 {
    1.0 - (1.0 - x).powf(2.0 / 3.0)
}

impl HalfCap {
    /// The half cap at `a_over_h`, both bodies of `E = 1` and `poisson`, friction `mu`.
    ///
    /// # Errors
    /// Those of the mesh, the material, the model and `ContactAnalysis::solid`.
    pub fn new(a_over_h: usize, poisson: f64, mu: f64) -> Result<Self> {
        let base = CapOnBlock::new(CapModel::Half, a_over_h);
        let spec = CapOnBlock {
            block_extent: base.cap_extent,
            radius_over_contact: RADIUS_OVER_CONTACT,
            ..base
        };
        Self::with_spec(spec, poisson, mu)
    }

    /// The half model of `spec` (its `model` should be [`CapModel::Half`]), both bodies of
    /// `E = 1` and `poisson`, friction `mu`.
    ///
    /// # Errors
    /// Those of the mesh, the material, the model and `ContactAnalysis::solid`.
    pub fn with_spec(spec: CapOnBlock, poisson: f64, mu: f64) -> Result<Self> {
        // the block's bottom held, the cap's top moved by the increments' prescribed values in
        // all three directions, the multipliers on the flat block's top (module docs)
        let scene = SolidScene::new(
            spec.build()?,
            [Isotropic::new(YOUNGS, poisson)?; 2],
            &[0, 1, 2],
            Multipliers::Lower,
            mu,
        )?;
        let analysis = scene.analysis(ContactOptions::default())?;
        Ok(HalfCap {
            spec,
            scene,
            analysis,
            poisson,
            friction: mu,
            motion: [0.0; 2],
        })
    }

    /// One increment to the cap's top's total motion `[x, z]`, and its results.
    fn step(&mut self, motion: [f64; 2]) -> Result<Pull> {
        let qp = self.scene.prescribed([motion[0], 0.0, motion[1]]);
        let info = self.analysis.increment(&vec![0.0; qp.len()], &qp)?;
        self.motion = motion;
        self.results(info)
    }

    /// Press by Hertz's approach of the target radius (the first increment).
    ///
    /// # Errors
    /// Those of the increment.
    pub fn press(&mut self) -> Result<Pull> {
        let approach = hertz_approach(self.spec.contact_radius(), 1.0);
        self.step([0.0, -approach])
    }

    /// Move the cap's top along `x` to `displacement` (total) in one increment.
    ///
    /// # Errors
    /// Those of the increment.
    pub fn pull(&mut self, displacement: f64) -> Result<Pull> {
        self.step([displacement, self.motion[1]])
    }

    /// Pull forward from `from` (the last increment's results) until `Q / (mu P)` is within
    /// `tolerance` of `target` or above it (the path cannot go back), at most `steps`
    /// increments. The first displacement is Mindlin's for the target at `from`'s load if
    /// `from` is the press, else `from`'s scaled by Mindlin's compliance fraction
    /// `y = 1 - (1 - Q / (mu P))^(2/3)` (proportional to the displacement in Mindlin's
    /// solution); the next ones a secant on `y` through the last two increments.
    ///
    /// # Errors
    /// Those of the increments.
    pub fn pull_to(
        &mut self,
        from: &Pull,
        target: f64,
        tolerance: f64,
        steps: usize,
    ) -> Result<Pull> {
        let mu = self.friction;
        let goal = compliance_fraction(target);
        let y = |p: &Pull| compliance_fraction(p.ratio(mu));
        let first = if from.displacement == 0.0 {
            let g = YOUNGS / (2.0 * (1.0 + self.poisson));
            let e_star = YOUNGS / (2.0 * (1.0 - self.poisson * self.poisson));
            let mindlin = Mindlin::new(from.load, 1.0, e_star, mu, target * mu * from.load)?;
            mindlin.compliance_displacement([g, g], [self.poisson; 2])
        } else {
            from.displacement * goal / y(from)
        };
        let mut previous = *from;
        let mut current = self.pull(first)?;
        for _ in 1..steps {
            if current.ratio(mu) >= target - tolerance {
                break;
            }
            let slope =
                (y(&current) - y(&previous)) / (current.displacement - previous.displacement);
            let next = current.displacement + (goal - y(&current)) / slope;
            previous = current;
            current = self.pull(next)?;
        }
        Ok(current)
    }

    /// The reference position of A node `r`.
    fn at(&self, r: &NodeResult) -> [f64; 3] {
        self.scene.mesh.mesh.nodes[r.node]
    }

    /// The stick-slip transition along the ray of the unit direction `along` (in `x, y`).
    fn ray(&self, nodes: &[NodeResult], along: [f64; 2]) -> Ray {
        let mut ray = Ray {
            stick: f64::NAN,
            beyond: f64::INFINITY,
        };
        for r in nodes {
            let [x, y, _] = self.at(r);
            let radius = x * along[0] + y * along[1];
            let off = (x * along[1] - y * along[0]).abs();
            if off > 1e-9 * self.scene.mesh.h || radius < 0.0 {
                continue;
            }
            if r.state == NodeState::Stick {
                ray.stick = ray.stick.max(radius);
            } else {
                ray.beyond = ray.beyond.min(radius);
            }
        }
        ray
    }

    /// The state after the increment `info` of [`analysis`](Self::analysis) (which may be
    /// another analysis of this mesh, e.g. `hycon_lab::plate3d`'s with the cap's top tied to a
    /// rigid plate; `displacement` is then this cap's prescribed motion, 0).
    ///
    /// # Errors
    /// Those of the node results.
    pub fn results(&self, info: IncrementInfo) -> Result<Pull> {
        let nodes = self.analysis.node_results(0)?;
        // the contact force on the cap: minus that on the block (A)
        let total = |c: usize| -2.0 * nodes.iter().map(|r| r.force.components()[c]).sum::<f64>();
        let normal = |r: &NodeResult| -r.frame.normal().dot(&r.force);
        let moment: f64 = (nodes.iter())
            .map(|r| {
                let [x, y, _] = self.at(r);
                normal(r) * (x * x + y * y)
            })
            .sum();
        let half: f64 = nodes.iter().map(normal).sum();
        let spread = (nodes.iter())
            .filter_map(|r| match r.state {
                NodeState::Slip { direction } => {
                    let slip = r.frame.vector(0.0, direction.vector());
                    let [x, y, _] = [0, 1, 2].map(|i| slip.components()[i]);
                    // A (the block) slips along -x relative to the cap
                    Some(y.atan2(-x).abs().to_degrees())
                }
                _ => None,
            })
            .fold(0.0, f64::max);
        Ok(Pull {
            load: total(2),
            tangential: -total(0),
            radius: (2.5 * moment / half).sqrt(),
            displacement: self.motion[0],
            leading: self.ray(&nodes, [1.0, 0.0]),
            trailing: self.ray(&nodes, [-1.0, 0.0]),
            across: self.ray(&nodes, [0.0, 1.0]),
            spread,
            info,
        })
    }
}
