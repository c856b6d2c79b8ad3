//! The rigid plate in 3D (issue #43): the cap-on-block scenes of [`crate::hertz3d`] (the quarter
//! cap, frictionless) and [`crate::mindlin3d`] (the half cap on its mirror block, Coulomb
//! friction) with the cap's top tied to a rigid plate (`ContactAnalysis::solid_with_plate`)
//! whose translations are force- or displacement-controlled per direction: Hertz at a given
//! `P`, Mindlin at a given `Q`.
//!
//! [`tied_cap`] builds the analysis on a scene's mesh: the block's bottom held, the nodes on
//! each symmetry plane held normal to it, the cap's top prescribed in x, y and z and tied to
//! the plate, 18-beta hybrid bricks of `E = 1`, small kinematics. The plate's translations
//! normal to a symmetry plane stay zero (displacement-controlled), the others are driven by
//! [`press`]. [`HertzPress`] reads the quarter's results as [`crate::hertz3d`] does, the
//! contact radius from the moments of the normal contact forces
//! (`sum f r^2 / sum f = 2 a^2 / 5` for Hertz's pressure) and the peak at the centre node,
//! and the load from the contact forces' `z` components (the plate's balance: the normal
//! forces of the curved cap are tilted by `r / R` and sum to some 0.07% more).

use crate::closed3d::HertzSphere;
use crate::hertz3d::{POISSON, YOUNGS, e_star};
use crate::solid_scene::{Multipliers, SolidScene};
use hycon::Result;
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, FacePair, IncrementInfo, NodeResult, PlateControl,
};
use hycon::contact::space::Vector;
use hycon::solid::Isotropic;
use hycon::solid::contact_meshes::{CapModel, CapOnBlock, ContactMesh};

/// The analysis of `mesh` (a cap on a block) with the cap's top tied to a rigid plate (module
/// docs): both bodies of `E = 1` and `poisson`, the contact pair `pair`.
///
/// # Errors
/// Those of the material, the model and `ContactAnalysis::solid_with_plate`.
pub fn tied_cap(mesh: &ContactMesh, poisson: f64, pair: FacePair) -> Result<ContactAnalysis> {
    let material = Isotropic::new(YOUNGS, poisson)?;
    // the scene's bodies, supports and planes; its pair is `pair`
    let scene = SolidScene::new(
        mesh.clone(),
        [material; 2],
        &[0, 1, 2],
        Multipliers::Upper,
        pair.friction,
    )?;
    ContactAnalysis::solid_with_plate(
        scene.model,
        vec![pair],
        &scene.planes,
        ContactOptions::default(),
        scene.mesh.a_top,
    )
}

/// One increment of `analysis` (no load) with the plate driven by `control` (x, y, z).
///
/// # Errors
/// Those of the increment.
pub fn press(analysis: &mut ContactAnalysis, control: [PlateControl; 3]) -> Result<IncrementInfo> {
    let n = analysis.field_len();
    let zero = vec![0.0; n];
    analysis.increment_with_plate(&zero, &zero, &control)
}

/// The quarter cap of [`crate::hertz3d`] (`R / a = 16`, frictionless, the multipliers on the
/// cap) at `a_over_h`, tied to the plate.
#[derive(Debug)]
pub struct PlateCap {
    /// Both bodies' mesh, contact faces and node sets.
    pub mesh: ContactMesh,
    /// The analysis with the plate.
    pub analysis: ContactAnalysis,
}

/// The quarter cap's press against Hertz.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzPress {
    /// The full model's load `P` from the contact forces on the cap (4 times the sum of their
    /// `z` components on the quarter).
    pub load: f64,
    /// The full model's load from the plate's force (4 times its `-z` component).
    pub plate_load: f64,
    /// The plate's approach (minus its `z` displacement).
    pub approach: f64,
    /// Hertz at `load`.
    pub hertz: HertzSphere,
    /// The contact radius from the moments of the contact forces.
    pub radius: f64,
    /// The peak pressure: `-tn` at the centre node.
    pub peak: f64,
    /// The increment's summary.
    pub info: IncrementInfo,
}

impl PlateCap {
    /// The quarter cap at `a_over_h`.
    ///
    /// # Errors
    /// Those of the mesh and [`tied_cap`].
    pub fn quarter(a_over_h: usize) -> Result<Self> {
        let mesh = CapOnBlock::new(CapModel::Quarter, a_over_h).build()?;
        let pair = FacePair {
            a: mesh.a_faces.clone(),
            b: mesh.b_faces.clone(),
            friction: 0.0,
        };
        let analysis = tied_cap(&mesh, POISSON, pair)?;
        Ok(PlateCap { mesh, analysis })
    }

    /// Press the plate along `z` by `control` (the full model's: a force `-P` is `-P / 4` on
    /// the quarter's plate; an approach is the same), x and y held, and read the results.
    ///
    /// # Errors
    /// Those of the increment.
    pub fn press(&mut self, control: PlateControl) -> Result<HertzPress> {
        let z = match control {
            PlateControl::Force(f) => PlateControl::Force(f / 4.0),
            displacement => displacement,
        };
        let held = PlateControl::Displacement(0.0);
        let info = press(&mut self.analysis, [held, held, z])?;
        let (u, force): (Vector, Vector) = self.analysis.plate().expect("a plate");
        let nodes = self.analysis.node_results(0)?;
        let radial = |r: &NodeResult| {
            let [x, y, _] = self.mesh.mesh.nodes[r.node];
            x.hypot(y)
        };
        let normal = |r: &NodeResult| -r.frame.normal().dot(&r.force);
        let quarter: f64 = nodes.iter().map(normal).sum();
        let moment: f64 = nodes.iter().map(|r| normal(r) * radial(r).powi(2)).sum();
        let load = 4.0 * nodes.iter().map(|r| r.force.components()[2]).sum::<f64>();
        Ok(HertzPress {
            load,
            plate_load: -4.0 * force.components()[2],
            approach: -u.components()[2],
            hertz: HertzSphere::new(load, 1.0, e_star()),
            radius: (2.5 * moment / quarter).sqrt(),
            peak: (nodes.iter())
                .find(|r| radial(r) == 0.0)
                .map_or(f64::NAN, |r| -r.tn),
            info,
        })
    }
}
