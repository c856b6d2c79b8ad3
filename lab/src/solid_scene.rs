//! The lab's two-body 3D scene: a [`ContactMesh`] (a cap on a block, a block on a flat) made
//! into the [`SolidModel`] of its two bodies, one contact pair and its symmetry planes, the
//! supports every 3D scene of the lab takes:
//!
//! * each body of its [`Isotropic`] material (the upper body first), 18-beta hybrid bricks;
//! * the lower body's bottom (`b_bottom`) held in all three directions;
//! * the upper body's top (`a_top`) prescribed in the directions the scene moves it (the values
//!   come with each increment);
//! * the nodes on each symmetry plane held normal to it (the quarter's `x = 0` and `y = 0`, the
//!   half's `y = 0`), the planes passed to `ContactAnalysis::solid`;
//! * one pair between the upper body's bottom faces (`a_faces`) and the lower body's top
//!   (`b_faces`), the multipliers on the side [`Multipliers`] names, Coulomb's `mu`.

use hycon::contact::faces::SymmetryPlane;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair};
use hycon::solid::contact_meshes::ContactMesh;
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use hycon::{Error, Result};

/// Which body's contact faces carry the multipliers (side A of the pair).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Multipliers {
    /// The upper body's bottom (body 0: the cap, the dragged block).
    Upper,
    /// The lower body's top (body 1: the block under the cap, the flat).
    Lower,
}

/// The two bodies, their supports, the pair and the symmetry planes (module docs).
#[derive(Debug, Clone)]
pub struct SolidScene {
    /// Both bodies' mesh, contact faces and node sets.
    pub mesh: ContactMesh,
    /// The model: both bodies, the supports (the top's prescribed values zero until an
    /// increment gives them).
    pub model: SolidModel,
    /// The contact pair.
    pub pair: FacePair,
    /// The symmetry planes of the mesh.
    pub planes: Vec<SymmetryPlane>,
}

impl SolidScene {
    /// The scene of `mesh`: the bodies of `materials` (upper, lower), the upper body's top prescribed in
    /// `top` (0, 1, 2 = x, y, z), the multipliers on `multipliers`, friction `mu`.
    ///
    /// # Errors
    /// Those of [`SolidModel::new`] and [`SolidModel::prescribe`];
    /// [`Error::InvalidInput`] for a symmetry plane not normal to `x`, `y` or `z`.
    pub fn new(
        mesh: ContactMesh,
        materials: [Isotropic; 2],
        top: &[usize],
        multipliers: Multipliers,
        mu: f64,
    ) -> Result<Self> {
        let mut model = SolidModel::new(
            mesh.mesh.clone(),
            materials.to_vec(),
            BrickFormulation::Hybrid18,
        )?;
        model.prescribe(&mesh.b_bottom, &[0, 1, 2])?;
        model.prescribe(&mesh.a_top, top)?;
        for (plane, nodes) in &mesh.symmetry {
            let d = axis(plane)?;
            // a node on the plane may already be held (bottom, top): `fix` keeps it held
            for &n in nodes {
                model.fix(n, d, 0.0);
            }
        }
        let (a, b) = match multipliers {
            Multipliers::Upper => (mesh.a_faces.clone(), mesh.b_faces.clone()),
            Multipliers::Lower => (mesh.b_faces.clone(), mesh.a_faces.clone()),
        };
        let planes = mesh.symmetry.iter().map(|(p, _)| *p).collect();
        Ok(SolidScene {
            mesh,
            model,
            pair: FacePair { a, b, friction: mu },
            planes,
        })
    }

    /// The contact analysis of the scene with `options` (`ContactAnalysis::solid` on a copy of
    /// the model).
    ///
    /// # Errors
    /// Those of `ContactAnalysis::solid`.
    pub fn analysis(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        ContactAnalysis::solid(
            self.model.clone(),
            vec![self.pair.clone()],
            &self.planes,
            options,
        )
    }

    /// The prescribed values over the model's `3 n_nodes` dofs: the upper body's top moved by
    /// `motion` (x, y, z), everything else held at zero.
    pub fn prescribed(&self, motion: [f64; 3]) -> Vec<f64> {
        let mut qp = vec![0.0; 3 * self.mesh.mesh.n_nodes()];
        for &k in &self.mesh.a_top {
            qp[3 * k..3 * k + 3].copy_from_slice(&motion);
        }
        qp
    }
}

/// The direction (0, 1, 2) a symmetry plane is normal to.
fn axis(plane: &SymmetryPlane) -> Result<usize> {
    let n = plane.normal;
    let on = |d: usize| n[d] != 0.0 && (0..3).all(|e| e == d || n[e] == 0.0);
    (0..3).find(|&d| on(d)).ok_or_else(|| {
        Error::InvalidInput(format!(
            "symmetry plane with normal {n:?}: the scene holds planes normal to x, y or z"
        ))
    })
}
