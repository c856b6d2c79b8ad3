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
use super::{
    ContactAnalysis, ContactOptions, Kinematics, check_host_dimension, check_inside_count,
    contact_dofs, host_bodies, in_pair,
};
use crate::contact::bodies::{Bodies, HostBodies, HostSystem, SolidBodies};
use crate::contact::faces::{FaceGeometry, Pieces, SymmetryPlane, check_surface};
use crate::contact::friction::{Coulomb, FrictionLaw};
use crate::contact::geometry::ContactGeometry;
use crate::contact::space::Vector;
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
        let index = boundary_faces(mesh);
        self.check_faces(|face| check_face(mesh, &index, face))?;
        check_bodies(mesh, &self.a, &self.b)
    }

    /// Check the pair without a mesh, as a host's faces are (node ids of its numbering):
    /// friction finite and `>= 0`, each side at least one face, every face of 4 distinct
    /// nodes, no face listed twice in the pair, each side one connected surface
    /// ([`check_surface`]), no node on both sides. (Whether the nodes are
    /// the host's, at finite positions, and faces the mortar kernel cannot integrate are
    /// refused by [`ContactAnalysis::solid_host`] and [`FaceGeometry::new`].)
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the side, the face and what is wrong, or the shared node.
    pub fn check(&self) -> Result<()> {
        self.check_faces(distinct_corners)?;
        let b: BTreeSet<usize> = self.b.iter().flatten().copied().collect();
        for (i, face) in self.a.iter().enumerate() {
            if let Some(k) = face.iter().find(|k| b.contains(k)) {
                return Err(Error::InvalidInput(format!(
                    "node {k} of A face {i} {face:?} is also on side B: A and B must be \
                     surfaces of different bodies"
                )));
            }
        }
        Ok(())
    }

    /// The checks shared by [`check_on`](Self::check_on) and [`check`](Self::check), with
    /// `face_check` saying what is wrong with one face.
    fn check_faces(
        &self,
        face_check: impl Fn(&[usize; 4]) -> std::result::Result<(), String>,
    ) -> Result<()> {
        Coulomb::new(self.friction)?;
        let mut seen = BTreeSet::new();
        for (side, faces) in [("A", &self.a), ("B", &self.b)] {
            if faces.is_empty() {
                return Err(Error::InvalidInput(format!(
                    "contact side {side} has no face"
                )));
            }
            for (i, face) in faces.iter().enumerate() {
                face_check(face)
                    .map_err(|m| Error::InvalidInput(format!("{side} face {i} {face:?}: {m}")))?;
                if !seen.insert(sorted(face)) {
                    return Err(Error::InvalidInput(format!(
                        "{side} face {i} {face:?} is listed twice in the pair"
                    )));
                }
            }
            check_surface(side, faces)?;
        }
        Ok(())
    }
}

/// A face of 4 distinct node ids; the message names the repeated one.
fn distinct_corners(face: &[usize; 4]) -> std::result::Result<(), String> {
    match (1..4).find(|&i| face[..i].contains(&face[i])) {
        Some(i) => Err(format!("node {} appears twice", face[i])),
        None => Ok(()),
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
        let parts = FaceParts::new(&pairs, model.mesh.nodes.as_flattened(), symmetry)?;
        let dofs = contact_dofs(&parts.nodes, SOLID_DIM);
        let lazy = options.kinematics == Kinematics::Small;
        let bodies = SolidBodies::new(model, &dofs, options.backend, lazy, options.threads)?;
        parts.setup(Box::new(bodies), dofs, options, None)
    }

    /// A 3D contact analysis of a host's system: its contact nodes with 3 equations each
    /// ([`HostSystem::nodes`], positions of 3 components), its stiffness as a CSR matrix
    /// factored here, a solve callback or its condensed operator (as for
    /// [`host`](Self::host)), `pairs` of faces given as 4 node ids of the host's numbering
    /// (counter-clockwise seen from outside their body), the `symmetry` planes (the host holds
    /// the nodes on them normal to them) and the options. The host has no brick mesh, so the
    /// faces are checked as far as that allows ([`FacePair::check`], every node one of the
    /// contact nodes, [`FaceGeometry::new`]: no flat, warped or inverted face, a continuous
    /// frame); which side body A is on comes from its faces' order, confirmed by a point
    /// inside body A ([`HostSystem::a_inside`], 3 components) where given, and needed where
    /// A and B touch wherever they are near each other. Loads are the host's right-hand sides
    /// ([`increment`](Self::increment) with empty `qp`), or the load image of its condensed
    /// operator; displacements its equations. A pair's A nodes are reported in the order of
    /// the host's node list, B's likewise.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a bad option or node (those of [`HostBodies::new`]), a bad
    /// pair (naming it), host sections or elements (plane concepts: a 3D host gives none), a
    /// point inside A on A's outward side; those of the factorization (a body not held:
    /// [`Error::Singular`]) or of the callback ([`Error::Callback`]).
    pub fn solid_host(
        mut system: HostSystem,
        pairs: Vec<FacePair>,
        symmetry: &[SymmetryPlane],
        options: ContactOptions,
    ) -> Result<Self> {
        options.validate()?;
        for (i, pair) in pairs.iter().enumerate() {
            pair.check().map_err(|e| in_pair(i, e))?;
        }
        check_inside_count(&system.a_inside, pairs.len())?;
        if !system.sections.is_empty() || system.elements.is_some() {
            return Err(Error::InvalidInput(
                "a 3D host gives no sections and no elements (plane and axisymmetric concepts: \
                 its contact integrals are over the faces' areas, its tractions the multipliers)"
                    .into(),
            ));
        }
        let mut a_inside = std::mem::take(&mut system.a_inside);
        a_inside.resize(pairs.len(), None);
        let (bodies, seconds) = host_bodies(system, &options)?;
        check_host_dimension(&bodies, &a_inside, SOLID_DIM)?;
        let pairs = (pairs.iter().enumerate())
            .map(|(i, p)| local_pair(p, &bodies).map_err(|e| in_pair(i, e)))
            .collect::<Result<Vec<_>>>()?;
        let parts = FaceParts::new(&pairs, bodies.positions(), symmetry)?;
        let dofs = (0..bodies.positions().len()).collect();
        let mut analysis = parts.setup(Box::new(bodies), dofs, options, Some(a_inside))?;
        analysis.driver.timings.factorization = seconds;
        Ok(analysis)
    }
}

/// What the 3D constructors build from their face pairs alike: each pair's geometry, nodes
/// and friction law.
struct FaceParts {
    geometries: Vec<FaceGeometry>,
    nodes: Vec<PairNodes>,
    laws: Vec<Box<dyn FrictionLaw>>,
}

impl FaceParts {
    /// The parts of `pairs` (checked) at the positions `x` (3 per node, indexed by the pairs'
    /// node ids) with the `symmetry` planes.
    ///
    /// # Errors
    /// Those of [`FaceGeometry::new`], naming the pair.
    fn new(pairs: &[FacePair], x: &[f64], symmetry: &[SymmetryPlane]) -> Result<Self> {
        let geometries = (pairs.iter().enumerate())
            .map(|(i, p)| {
                FaceGeometry::new(p.a.clone(), p.b.clone(), x, None, symmetry)
                    .map_err(|e| in_pair(i, e))
            })
            .collect::<Result<Vec<_>>>()?;
        let nodes = (geometries.iter())
            .map(|g| PairNodes {
                a: g.a_nodes().to_vec(),
                b: g.b_nodes().to_vec(),
            })
            .collect();
        let laws = (pairs.iter())
            .map(|p| Ok(Box::new(Coulomb::new(p.friction)?) as Box<dyn FrictionLaw>))
            .collect::<Result<_>>()?;
        Ok(FaceParts {
            geometries,
            nodes,
            laws,
        })
    }

    /// The analysis of these parts on `bodies` ([`ContactAnalysis::setup`]).
    fn setup(
        self,
        bodies: Box<dyn Bodies>,
        dofs: Vec<usize>,
        options: ContactOptions,
        a_inside: Option<Vec<Option<Vector>>>,
    ) -> Result<ContactAnalysis> {
        let geometries = (self.geometries.into_iter())
            .map(|g| Box::new(g) as Box<dyn ContactGeometry>)
            .collect();
        ContactAnalysis::setup(
            bodies, self.nodes, self.laws, geometries, dofs, options, a_inside,
        )
    }
}

/// A host's face pair with its node ids translated into the bodies' local numbering.
///
/// # Errors
/// [`Error::InvalidInput`] naming the side, the face and a node that is not one of the host's
/// contact nodes.
fn local_pair(pair: &FacePair, bodies: &HostBodies) -> Result<FacePair> {
    let side = |faces: &[[usize; 4]], name: &str| {
        (faces.iter().enumerate())
            .map(|(i, face)| {
                let mut local = [0; 4];
                for (l, &k) in local.iter_mut().zip(face) {
                    *l = bodies.local(k).ok_or_else(|| {
                        Error::InvalidInput(format!(
                            "{name} face {i} {face:?}: node {k} is not one of the host's \
                             contact nodes"
                        ))
                    })?;
                }
                Ok(local)
            })
            .collect::<Result<Vec<_>>>()
    };
    Ok(FacePair {
        a: side(&pair.a, "A")?,
        b: side(&pair.b, "B")?,
        friction: pair.friction,
    })
}
