//! The 3D contact analysis of hycon's brick model: contact pairs of brick-face surfaces
//! ([`FacePair`]) on a [`SolidModel`], with the geometry of [`FaceGeometry`] and the bodies of
//! [`SolidBodies`] behind the same iteration as the plane analysis (docs/method.md, "The mixed
//! system with K factored once"; design document `docs/design/3d-contact.md`).
//!
//! Positions, loads and displacements have 3 values per node (`3 node + direction`), and every
//! node of a pair's faces has its 3 dofs among the contact dofs. A node's frame has the normal
//! and two tangents (zero where a symmetry plane drops one): a stick node has two tangent rows,
//! a slip node the column `n + mu (d_1 s_1 + d_2 s_2)`.

use super::surfaces::PairNodes;
use super::{ContactAnalysis, ContactOptions, Kinematics, contact_dofs, in_pair};
use crate::contact::bodies::SolidBodies;
use crate::contact::faces::{FaceGeometry, Pieces, SymmetryPlane, check_surface};
use crate::contact::friction::{Coulomb, FrictionLaw};
use crate::contact::geometry::ContactGeometry;
use crate::error::{Error, Result};
use crate::solid::geometry::FACES;
use crate::solid::mesh::SolidMesh;
use crate::solid::model::SolidModel;
use std::collections::{BTreeSet, HashMap};

/// Equations per node of a brick model.
const SOLID_DIM: usize = 3;

/// One 3D contact pair: the multiplier side A and the opposite side B as brick faces (4 node
/// ids each, counter-clockwise seen from outside their body: the order of
/// [`FACES`]), and the Coulomb friction coefficient between them.
#[derive(Debug, Clone, PartialEq)]
pub struct FacePair {
    /// A's faces (the multiplier side).
    pub a: Vec<[usize; 4]>,
    /// B's faces.
    pub b: Vec<[usize; 4]>,
    /// Coulomb friction coefficient `mu >= 0` (0: frictionless).
    pub friction: f64,
}

impl FacePair {
    /// Check the pair against `mesh`: friction finite and `>= 0`, each side at least one face,
    /// every face a boundary face of one brick listed outward (counter-clockwise seen from
    /// outside, from any corner), no face listed twice in the pair, finite node positions,
    /// each side one connected surface ([`check_surface`]: so on one body), the two sides on
    /// different bodies (the mesh's connected pieces, bricks joined by shared nodes). (A and
    /// B sharing a node, faces the mortar kernel cannot integrate and sides that never face
    /// each other are refused by [`FaceGeometry::new`].)
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the side, the face and what is wrong.
    pub fn check_on(&self, mesh: &SolidMesh) -> Result<()> {
        Coulomb::new(self.friction)?;
        let index = boundary_faces(mesh);
        let mut seen = BTreeSet::new();
        for (side, faces) in [("A", &self.a), ("B", &self.b)] {
            if faces.is_empty() {
                return Err(Error::InvalidInput(format!(
                    "contact side {side} has no face"
                )));
            }
            for (i, face) in faces.iter().enumerate() {
                check_face(mesh, &index, face)
                    .map_err(|m| Error::InvalidInput(format!("{side} face {i} {face:?}: {m}")))?;
                if !seen.insert(sorted(face)) {
                    return Err(Error::InvalidInput(format!(
                        "{side} face {i} {face:?} is listed twice in the pair"
                    )));
                }
            }
            check_surface(side, faces)?;
        }
        check_bodies(mesh, &self.a, &self.b)
    }
}

/// Sides `a` and `b` (checked faces of `mesh`, each one connected surface) lie on different
/// bodies: the connected pieces of the mesh, bricks joined by shared nodes.
///
/// # Errors
/// [`Error::InvalidInput`] when one body holds both sides, naming a face of each.
fn check_bodies(mesh: &SolidMesh, a: &[[usize; 4]], b: &[[usize; 4]]) -> Result<()> {
    let mut bodies = Pieces::new(mesh.n_nodes());
    for brick in &mesh.elements {
        for k in &brick[1..] {
            bodies.join(brick[0], *k);
        }
    }
    if bodies.root(a[0][0]) == bodies.root(b[0][0]) {
        return Err(Error::InvalidInput(format!(
            "both sides are on one body (its bricks join A face 0 {:?} to B face 0 {:?} \
             through shared nodes): a pair joins two bodies",
            a[0], b[0]
        )));
    }
    Ok(())
}

/// A face's node ids sorted: its key in [`boundary_faces`].
fn sorted(face: &[usize; 4]) -> [usize; 4] {
    let mut key = *face;
    key.sort_unstable();
    key
}

/// Every brick face of `mesh` by its sorted node ids: the outward node order of each brick it
/// belongs to (one for a boundary face, two for a face between bricks).
fn boundary_faces(mesh: &SolidMesh) -> HashMap<[usize; 4], Vec<[usize; 4]>> {
    let mut index: HashMap<[usize; 4], Vec<[usize; 4]>> = HashMap::new();
    for element in &mesh.elements {
        for face in FACES {
            let nodes = face.map(|k| element[k]);
            index.entry(sorted(&nodes)).or_default().push(nodes);
        }
    }
    index
}

/// `face` is a boundary face of `mesh` given outward, its nodes at finite positions; the
/// message says what it is not.
fn check_face(
    mesh: &SolidMesh,
    index: &HashMap<[usize; 4], Vec<[usize; 4]>>,
    face: &[usize; 4],
) -> std::result::Result<(), String> {
    let n = mesh.n_nodes();
    if let Some(k) = face.iter().find(|&&k| k >= n) {
        return Err(format!("node {k} is not a node of the model ({n} nodes)"));
    }
    if let Some(k) = face
        .iter()
        .find(|&&k| mesh.nodes[k].iter().any(|v| !v.is_finite()))
    {
        return Err(format!("node {k} has a non-finite position"));
    }
    match index.get(&sorted(face)).map(Vec::as_slice) {
        None => Err("not a face of any brick".into()),
        Some([outward]) => {
            let rotation = |r: usize| std::array::from_fn(|i| outward[(i + r) % 4]);
            if (0..4).any(|r| rotation(r) == *face) {
                Ok(())
            } else {
                Err("listed clockwise seen from outside: its normal points into the body".into())
            }
        }
        Some(_) => Err("an interior face, shared by two bricks".into()),
    }
}

impl ContactAnalysis {
    /// A 3D contact analysis of hycon's brick model: `pairs` of brick-face surfaces, the
    /// model's `symmetry` planes (a node of A on one has the mirrored model's normal and no
    /// tangential traction across the plane; the model must hold the nodes on it normal to
    /// it), and the options. Validates, then factors `K` once, as
    /// [`new`](Self::new) does for a plane model: in its fill-reducing order under small
    /// kinematics (the flexibility built as nodes become active), with the contact nodes' dofs
    /// eliminated last under finite kinematics. Each A face's frames take the reference
    /// direction [`FaceGeometry::new`] chooses. Loads and prescribed values of
    /// [`increment`](Self::increment) are over the model's `3 n_nodes` dofs; pair results
    /// index A's nodes in increasing id order ([`FaceGeometry::a_nodes`] of
    /// [`ContactGeometry`]) and B's likewise.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the pair for a bad option, a bad face set
    /// ([`FacePair::check_on`]), a node in both sides, a face the kernel cannot integrate,
    /// sides that never face each other or a surface without a continuous tangent frame
    /// ([`FaceGeometry::new`]), a bad symmetry plane; the errors of the factorization (a body
    /// not held: [`Error::Singular`]).
    pub fn solid(
        model: SolidModel,
        pairs: Vec<FacePair>,
        symmetry: &[SymmetryPlane],
        options: ContactOptions,
    ) -> Result<Self> {
        options.validate()?;
        for (i, pair) in pairs.iter().enumerate() {
            pair.check_on(&model.mesh).map_err(|e| in_pair(i, e))?;
        }
        let x = model.mesh.nodes.as_flattened();
        let geometries = (pairs.iter().enumerate())
            .map(|(i, p)| {
                FaceGeometry::new(p.a.clone(), p.b.clone(), x, None, symmetry)
                    .map_err(|e| in_pair(i, e))
            })
            .collect::<Result<Vec<_>>>()?;
        let node_pairs: Vec<PairNodes> = (geometries.iter())
            .map(|g| PairNodes {
                a: g.a_nodes().to_vec(),
                b: g.b_nodes().to_vec(),
            })
            .collect();
        let laws = (pairs.iter())
            .map(|p| Ok(Box::new(Coulomb::new(p.friction)?) as Box<dyn FrictionLaw>))
            .collect::<Result<_>>()?;
        let dofs = contact_dofs(&node_pairs, SOLID_DIM);
        let lazy = options.kinematics == Kinematics::Small;
        let bodies = SolidBodies::new(model, &dofs, options.backend, lazy, options.threads)?;
        let geometries = (geometries.into_iter())
            .map(|g| Box::new(g) as Box<dyn ContactGeometry>)
            .collect();
        Self::setup(
            Box::new(bodies),
            node_pairs,
            laws,
            geometries,
            dofs,
            options,
            None,
        )
    }
}
