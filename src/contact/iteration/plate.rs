//! The rigid loading plate: a face tied to the plate's translations (one per direction: two
//! in the plane, three in 3D), each displacement- or force-controlled per increment; force
//! control borders the small system with the plate's force balance (docs/method.md, "Floating
//! bodies and the rigid plate"). One body for the plane and the brick models: what the plate
//! needs of them (solves, element forces, a stiffness scale) comes through [`Bodies`].

use super::{
    ContactAnalysis, ContactOptions, ContactPair, ContactSurface, DMatrix, Error, FacePair,
    IncrementInfo, Model, NodeState, PlateControl, Result, Sparse, close_nearest, dot,
};
use crate::contact::bodies::Bodies;
use crate::contact::faces::SymmetryPlane;
use crate::contact::space::{MAX_DIM, Vector};
use crate::solid::model::SolidModel;

/// A symmetry plane's normal component beyond which the plate's translation in that direction
/// crosses the plane (normals are unit vectors).
const ACROSS: f64 = 1e-9;

/// The names of the directions, for messages.
const AXES: [&str; MAX_DIM] = ["x", "y", "z"];

/// The plate's control of each of its `dim` translations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Controls {
    len: u8,
    c: [PlateControl; MAX_DIM],
}

impl Controls {
    /// The controls `c`, one per direction (at most [`MAX_DIM`]).
    pub(super) fn new(c: &[PlateControl]) -> Self {
        let mut out = Controls {
            len: c.len() as u8,
            c: [PlateControl::Displacement(0.0); MAX_DIM],
        };
        out.c[..c.len()].copy_from_slice(c);
        out
    }

    /// One per direction.
    pub(super) fn as_slice(&self) -> &[PlateControl] {
        &self.c[..usize::from(self.len)]
    }

    /// `f(d, control)` per direction `d`.
    pub(super) fn map(self, f: impl Fn(usize, PlateControl) -> PlateControl) -> Self {
        let mut out = self;
        for (d, c) in out.c[..usize::from(self.len)].iter_mut().enumerate() {
            *c = f(d, *c);
        }
        out
    }

    /// The vector of `f(d, control)` per direction `d`.
    pub(super) fn values(&self, f: impl Fn(usize, PlateControl) -> f64) -> Vector {
        let mut v = Vector::zero(self.as_slice().len());
        for (d, (out, &c)) in v
            .components_mut()
            .iter_mut()
            .zip(self.as_slice())
            .enumerate()
        {
            *out = f(d, c);
        }
        v
    }
}

/// A rigid loading plate: nodes of one body's face tied to the plate's translations, one per
/// direction. Each direction is displacement- or force-controlled per increment.
#[derive(Debug, Clone)]
pub(super) struct Plate {
    /// Tied nodes (prescribed in every direction in the model).
    pub(super) nodes: Vec<usize>,
    /// Contact-dof response to a unit plate translation, per direction (no load, no contact).
    pub(super) response: Vec<Vec<f64>>,
    /// Plate stiffness `D`: the force the plate exerts on the body per unit translation.
    pub(super) stiffness: DMatrix<f64>,
    /// Converged plate displacement and force.
    pub(super) displacement: Vector,
    pub(super) force: Vector,
    /// The model's symmetry planes: the plate may not move across them.
    pub(super) symmetry: Vec<SymmetryPlane>,
}

impl Plate {
    /// Record the converged plate state: its motion (prescribed, or `motion[k]` for the
    /// force-controlled directions `directions[k]`) written into `prescribed` at the tied nodes, and the force
    /// it exerts on the body, `force0 + D U_force - W^T f_c` (load, force-controlled motion and
    /// contact parts).
    pub(super) fn settle(
        &mut self,
        control: Controls,
        (directions, solved): (&[usize], &[f64]),
        force0: Vector,
        contact_forces: &[f64],
        prescribed: &mut [f64],
    ) {
        let mut motion = control.values(|_, c| match c {
            PlateControl::Displacement(u) => u,
            PlateControl::Force(_) => 0.0,
        });
        for (&d, &m) in directions.iter().zip(solved) {
            motion[d] = m;
        }
        let dim = motion.dim();
        for &node in &self.nodes {
            for (d, &m) in motion.components().iter().enumerate() {
                prescribed[dim * node + d] = m;
            }
        }
        let force_controlled = |e: usize| matches!(control.as_slice()[e], PlateControl::Force(_));
        let mut force = force0;
        for (d, out) in force.components_mut().iter_mut().enumerate() {
            for (e, &m) in motion.components().iter().enumerate() {
                if force_controlled(e) {
                    *out += self.stiffness[(d, e)] * m;
                }
            }
            *out -= dot_dense(&self.response[d], contact_forces);
        }
        self.displacement = motion;
        self.force = force;
    }
}

pub(super) fn dot_dense(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The force the tied nodes `plate` exert on the bodies in the field `q` under loads `f`: the
/// sum of the reactions `K q - f` at their dofs, one per direction.
pub(super) fn plate_force(
    bodies: &dyn Bodies,
    plate: &[usize],
    q: &[f64],
    f: &[f64],
) -> Result<Vector> {
    let dim = bodies.dim();
    let r = bodies.internal_forces(q)?;
    let mut force = Vector::zero(dim);
    for &node in plate {
        for (d, out) in force.components_mut().iter_mut().enumerate() {
            *out += r[dim * node + d] - f[dim * node + d];
        }
    }
    Ok(force)
}

/// The plate's force-controlled translations as extra unknowns of the small system.
#[derive(Debug, Clone)]
pub(super) struct Border {
    /// Force-controlled directions (0 = x, 1 = y, 2 = z).
    pub(super) directions: Vec<usize>,
    /// Contact-dof response to a unit plate translation, per direction.
    pub(super) response: Vec<Vec<f64>>,
    /// Plate stiffness.
    pub(super) stiffness: DMatrix<f64>,
    /// `F_d - force0_d` per force-controlled direction.
    pub(super) rhs: Vec<f64>,
    /// Stiffness scale of the bodies (largest `E t`), against which `D` counts as zero.
    pub(super) stiffness_scale: f64,
}

impl Border {
    /// The border of the small system for the force-controlled plate directions `a` (plate
    /// direction `d`), after the `m` contact unknowns with `rows` and `cols`:
    /// `S[i, m+a] = row_i . w_d`, `S[m+a, j] = -col_j . w_d`, `S[m+a, m+c] = D[d, e]` (the
    /// plate's stiffness) and `rhs[m+a] = F_d - F0_d`, with `w_d` the contact dofs' response to
    /// a unit plate translation. Written through `set(i, j, v)` and `set_rhs(i, v)`, so that
    /// either matrix type takes it.
    ///
    /// # Errors
    /// [`Error::Singular`] when no constraint of the contact set acts along a force-controlled
    /// direction (see [`unheld`](Self::unheld)).
    pub(super) fn fill(
        &self,
        rows: &[Sparse],
        cols: &[Sparse],
        m: usize,
        set: &mut dyn FnMut(usize, usize, f64),
        set_rhs: &mut dyn FnMut(usize, f64),
    ) -> Result<()> {
        if let Some(d) = self.unheld(rows) {
            return Err(Error::Singular(format!(
                "the plate's {} translation is force-controlled but no constraint of the \
                 contact set acts along it (open nodes resist nothing; frictionless and \
                 slipping nodes do not resist tangential motion): control it by \
                 displacement",
                AXES[d]
            )));
        }
        for (a, &d) in self.directions.iter().enumerate() {
            for (i, row) in rows.iter().enumerate() {
                set(i, m + a, dot(row, &self.response[d]));
            }
            for (j, col) in cols.iter().enumerate() {
                set(m + a, j, -dot(col, &self.response[d]));
            }
            for (c, &e) in self.directions.iter().enumerate() {
                set(m + a, m + c, self.stiffness[(d, e)]);
            }
            set_rhs(m + a, self.rhs[a]);
        }
        Ok(())
    }

    /// A force-controlled direction is held only if the plate's own stiffness holds it or an
    /// active constraint row sees the plate's motion in it (relative to the sizes of the row
    /// and of the motion); otherwise the bordered system is singular whatever its round-off.
    pub(super) fn unheld(&self, rows: &[Sparse]) -> Option<usize> {
        self.directions.iter().copied().find(|&d| {
            let w = &self.response[d];
            let w_norm = dot_dense(w, w).sqrt();
            let seen = rows.iter().any(|row| {
                let row_norm = row.iter().map(|(_, v)| v * v).sum::<f64>().sqrt();
                dot(row, w).abs() > 1e-9 * row_norm * w_norm
            });
            !seen && self.stiffness[(d, d)].abs() <= 1e-10 * self.stiffness_scale
        })
    }
}

impl ContactAnalysis {
    /// As [`ContactAnalysis::new`], with the nodes `plate` (prescribed in every direction in
    /// the model, none of them a contact node) tied to a rigid plate whose translations are
    /// displacement- or force-controlled in each increment
    /// ([`increment_with_plate`](Self::increment_with_plate)). Under force control the plate
    /// translation joins the small contact system as extra unknowns with the plate's force
    /// balance as extra equations (a bordered system): a body held only by the plate and by
    /// contact, like a pressed disk, then takes a prescribed load. Costs two solves.
    ///
    /// # Errors
    /// Those of [`new`](Self::new); [`Error::InvalidInput`] for a plate node that does not
    /// exist, is not prescribed in x and y, or is a contact node.
    pub fn with_plate(
        model: Model,
        pairs: Vec<ContactPair>,
        options: ContactOptions,
        plate: Vec<usize>,
    ) -> Result<Self> {
        Self::new(model, pairs, options)?.tied_to_plate(plate, Vec::new())
    }

    /// As [`ContactAnalysis::solid`], with the nodes `plate` (prescribed in x, y and z in the
    /// model, none of them a contact node) tied to a rigid plate whose three translations are
    /// displacement- or force-controlled in each increment
    /// ([`increment_with_plate`](Self::increment_with_plate)), as
    /// [`with_plate`](Self::with_plate) does for a plane model: Hertz at a given force `P`,
    /// Mindlin at a given shear `Q`. The plate of a model cut by `symmetry` planes does not
    /// move across them: a translation with a component along a plane's normal must be
    /// displacement-controlled to zero (a quarter model's plate moves along the axis only).
    ///
    /// # Errors
    /// Those of [`solid`](Self::solid); [`Error::InvalidInput`] for a plate node that does not
    /// exist, is not prescribed in x, y and z, or is a contact node.
    pub fn solid_with_plate(
        model: SolidModel,
        pairs: Vec<FacePair>,
        symmetry: &[SymmetryPlane],
        options: ContactOptions,
        plate: Vec<usize>,
    ) -> Result<Self> {
        Self::solid(model, pairs, symmetry, options)?.tied_to_plate(plate, symmetry.to_vec())
    }

    /// Tie the nodes `plate` to a rigid plate (the common part of
    /// [`with_plate`](Self::with_plate) and [`solid_with_plate`](Self::solid_with_plate)):
    /// check them, then solve once per direction for the contact dofs' response `w_d` to a
    /// unit plate translation (contact open, no load) and the plate stiffness `D[e, d]`, the
    /// force the plate exerts in direction `e` in that field.
    fn tied_to_plate(mut self, plate: Vec<usize>, symmetry: Vec<SymmetryPlane>) -> Result<Self> {
        let n = self.bodies.field_len();
        let dim = self.dim();
        for &node in &plate {
            let held = node < n / dim && (0..dim).all(|d| !self.bodies.is_free(dim * node + d));
            if !held || self.boundary.slot[dim * node].is_some() {
                return Err(Error::InvalidInput(format!(
                    "plate node {node} must exist, be prescribed in {}, and not be a contact \
                     node",
                    if dim == 2 { "x and y" } else { "x, y and z" }
                )));
            }
        }
        let zero = vec![0.0; n];
        let mut response = vec![Vec::new(); dim];
        let mut stiffness = DMatrix::zeros(dim, dim);
        for d in 0..dim {
            let mut qp = zero.clone();
            for &node in &plate {
                qp[dim * node + d] = 1.0;
            }
            let q = self.bodies.solve(&zero, &qp)?;
            response[d] = self.boundary.dofs.iter().map(|&i| q[i]).collect();
            let force = plate_force(&*self.bodies, &plate, &q, &zero)?;
            for (e, &v) in force.components().iter().enumerate() {
                stiffness[(e, d)] = v;
            }
        }
        self.plate = Some(Plate {
            nodes: plate,
            response,
            stiffness,
            displacement: Vector::zero(dim),
            force: Vector::zero(dim),
            symmetry,
        });
        Ok(self)
    }

    /// The border of the small system for the force-controlled plate directions, if any.
    pub(super) fn border(&self, control: Controls, force0: Vector) -> Option<Border> {
        let plate = self.plate.as_ref()?;
        let mut directions = Vec::new();
        let mut rhs = Vec::new();
        for (d, c) in control.as_slice().iter().enumerate() {
            if let PlateControl::Force(f) = c {
                directions.push(d);
                rhs.push(f - force0[d]);
            }
        }
        let stiffness_scale = self.bodies.stiffness_scale()?;
        (!directions.is_empty()).then(|| Border {
            directions,
            response: plate.response.clone(),
            stiffness: plate.stiffness.clone(),
            rhs,
            stiffness_scale,
        })
    }

    /// Close the covered A node with the smallest normal gap (the first support of a
    /// force-controlled body; the decision is the active set's [`close_nearest`]).
    pub(super) fn close_nearest(&self, surfaces: &[ContactSurface], states: &mut [Vec<NodeState>]) {
        let nodes = surfaces.iter().enumerate().flat_map(|(p, s)| {
            (s.nodes.iter().enumerate())
                .map(move |(k, n)| ((p, k), n.normal_gap, n.is_covered(), self.node_law(p, k)))
        });
        close_nearest(states, nodes);
    }

    /// The converged plate displacement and the force it exerts on the body (`None` without a
    /// plate).
    pub fn plate(&self) -> Option<(Vector, Vector)> {
        self.plate.as_ref().map(|p| (p.displacement, p.force))
    }

    /// One load increment of an analysis built [`with_plate`](Self::with_plate) or
    /// [`solid_with_plate`](Self::solid_with_plate): as [`increment`](Self::increment), with
    /// the plate's translations driven by `control`, one per direction (x and y in the plane,
    /// x, y and z in 3D; the values `qp` holds at the plate nodes are ignored).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] without a plate, for the wrong number of controls, a non-finite
    /// value, a translation across a symmetry plane that is not `Displacement(0.0)`, or a
    /// prescribed vector of the wrong length; the errors of [`increment`](Self::increment).
    pub fn increment_with_plate(
        &mut self,
        f: &[f64],
        qp: &[f64],
        control: &[PlateControl],
    ) -> Result<IncrementInfo> {
        if self.plate.is_none() {
            return Err(Error::InvalidInput(
                "increment_with_plate needs an analysis built with_plate".into(),
            ));
        }
        if control.len() != self.dim() {
            return Err(Error::InvalidInput(format!(
                "the plate needs {} controls (one per direction), got {}",
                self.dim(),
                control.len()
            )));
        }
        if control.iter().any(|c| match c {
            PlateControl::Displacement(v) | PlateControl::Force(v) => !v.is_finite(),
        }) {
            return Err(Error::InvalidInput(format!(
                "non-finite plate control {control:?}"
            )));
        }
        self.check_symmetry(control)?;
        let n = self.bodies.field_len();
        if qp.len() != n {
            return Err(Error::InvalidInput(format!(
                "the prescribed vector needs {n} entries, got {}",
                qp.len()
            )));
        }
        let control = Controls::new(control);
        let mut qp = qp.to_vec();
        self.drive_plate(&mut qp, control);
        self.cut_increment(f, &qp, Some(control))
    }

    /// Write the plate's drive into the prescribed values `qp` at its nodes: the displacement
    /// of a displacement-controlled direction, 0 in a force-controlled one (whose motion is an
    /// unknown of the contact system). Nothing without a plate.
    pub(super) fn drive_plate(&self, qp: &mut [f64], control: Controls) {
        let Some(plate) = &self.plate else {
            return;
        };
        let dim = self.dim();
        for &node in &plate.nodes {
            for (d, c) in control.as_slice().iter().enumerate() {
                qp[dim * node + d] = match c {
                    PlateControl::Displacement(u) => *u,
                    PlateControl::Force(_) => 0.0,
                };
            }
        }
    }

    /// The plate does not move across a symmetry plane of the model: every direction `d` in
    /// which a plane's normal has a component (beyond [`ACROSS`]) must be
    /// `Displacement(0.0)`.
    fn check_symmetry(&self, control: &[PlateControl]) -> Result<()> {
        let Some(plate) = &self.plate else {
            return Ok(());
        };
        for plane in &plate.symmetry {
            for (d, c) in control.iter().enumerate() {
                if plane.normal[d].abs() > ACROSS && *c != PlateControl::Displacement(0.0) {
                    return Err(Error::InvalidInput(format!(
                        "the plate's {} translation ({c:?}) would cross the symmetry plane \
                         through {:?} with normal {:?}: a symmetric plate does not move \
                         across it, so control {} by Displacement(0.0)",
                        AXES[d], plane.point, plane.normal, AXES[d]
                    )));
                }
            }
        }
        Ok(())
    }
}
