//! Hexahedral meshes: storage, structured blocks and beams with graded spacing, mapped and
//! distorted variants, and consistent face loads.
//!
//! A structured block of `nx x ny x nz` bricks over the coordinate lines `xs`, `ys`, `zs`
//! numbers node `(i, j, k)` as `i + (nx + 1) (j + (ny + 1) k)` and brick `(i, j, k)` as
//! `i + nx (j + ny k)`, its nodes in the brick order of [`super::geometry`] (so a block in a
//! right-handed frame gives positive Jacobians). Any smooth map of the nodes keeps the
//! connectivity: beams that twist or curve, and distorted meshes for tests, are a block plus a
//! map.
//!
//! # Face sets
//! A mesh names sets of boundary faces (what a load or a contact surface is applied to), as a
//! plane [`crate::mesh::Mesh`] names edge sets. A face is its 4 global nodes in the order of
//! [`FACES`]: counter-clockwise seen from outside, so `(x1 - x0) x (x3 - x0)` points out of the
//! body. [`SolidMesh::block`] names the six sides of the block: `left` (`x = xs[0]`), `right`
//! (`x` the last of `xs`), `front` (`y = ys[0]`), `back`, `bottom` (`z = zs[0]`) and `top`.

use super::geometry::{FACES, Trilinear};
use super::{N_NODES, ShapePolicy, check_shape};
use crate::error::{Error, Result, ShapeWarning};
use std::collections::{BTreeMap, HashMap};

/// One face of a brick: its 4 global nodes, counter-clockwise seen from outside (the order of
/// [`FACES`]).
pub type Face = [usize; 4];

/// The names [`SolidMesh::block`] gives its six sides, with the brick face (numbering of
/// [`super::geometry`]) that lies on each: `left`/`right` at the least/greatest `x`,
/// `front`/`back` at `y`, `bottom`/`top` at `z`.
pub const BLOCK_SIDES: [(&str, usize); 6] = [
    ("left", 0),
    ("right", 1),
    ("front", 2),
    ("back", 3),
    ("bottom", 4),
    ("top", 5),
];

/// A mesh of 8-node bricks.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SolidMesh {
    /// Node coordinates.
    pub nodes: Vec<[f64; 3]>,
    /// Brick connectivity (node order of [`super::geometry`]).
    pub elements: Vec<[usize; N_NODES]>,
    /// Material index of each brick.
    pub element_material: Vec<usize>,
    /// Named face sets (see the [module docs](self)): each face a face of a brick of the mesh,
    /// its nodes counter-clockwise seen from outside.
    pub face_sets: BTreeMap<String, Vec<Face>>,
}

/// `n` intervals from `a` to `b` whose lengths grow geometrically, the last `ratio` times the
/// first (`ratio = 1`: uniform). Returns the `n + 1` coordinates, ending exactly at `b`.
pub fn graded(a: f64, b: f64, n: usize, ratio: f64) -> Vec<f64> {
    assert!(n > 0 && ratio > 0.0, "graded: n > 0 and ratio > 0");
    let q = if n > 1 {
        ratio.powf(1.0 / (n - 1) as f64)
    } else {
        1.0
    };
    let weights: Vec<f64> = (0..n).map(|i| q.powi(i as i32)).collect();
    let total: f64 = weights.iter().sum();
    let mut out = Vec::with_capacity(n + 1);
    let mut x = a;
    out.push(a);
    for w in &weights[..n - 1] {
        x += (b - a) * w / total;
        out.push(x);
    }
    out.push(b);
    out
}

impl SolidMesh {
    /// The structured block over the coordinate lines `xs`, `ys`, `zs` (each increasing, at least
    /// two values), material 0 everywhere, its six sides named ([`BLOCK_SIDES`]).
    pub fn block(xs: &[f64], ys: &[f64], zs: &[f64]) -> Self {
        let (nx, ny, nz) = (xs.len() - 1, ys.len() - 1, zs.len() - 1);
        let mut nodes = Vec::with_capacity(xs.len() * ys.len() * zs.len());
        for &z in zs {
            for &y in ys {
                for &x in xs {
                    nodes.push([x, y, z]);
                }
            }
        }
        let id = |i: usize, j: usize, k: usize| i + (nx + 1) * (j + (ny + 1) * k);
        let mut elements = Vec::with_capacity(nx * ny * nz);
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    let bottom = [
                        id(i, j, k),
                        id(i + 1, j, k),
                        id(i + 1, j + 1, k),
                        id(i, j + 1, k),
                    ];
                    let top = bottom.map(|n| n + (nx + 1) * (ny + 1));
                    elements.push([
                        bottom[0], bottom[1], bottom[2], bottom[3], top[0], top[1], top[2], top[3],
                    ]);
                }
            }
        }
        let element_material = vec![0; elements.len()];
        let on_side = |e: usize, face: usize| {
            let (i, j, k) = (e % nx, (e / nx) % ny, e / (nx * ny));
            match face {
                0 => i == 0,
                1 => i + 1 == nx,
                2 => j == 0,
                3 => j + 1 == ny,
                4 => k == 0,
                _ => k + 1 == nz,
            }
        };
        let face_sets = BLOCK_SIDES
            .iter()
            .map(|&(name, face)| {
                let faces = (0..elements.len())
                    .filter(|&e| on_side(e, face))
                    .map(|e| FACES[face].map(|k| elements[e][k]))
                    .collect();
                (name.to_string(), faces)
            })
            .collect();
        SolidMesh {
            nodes,
            elements,
            element_material,
            face_sets,
        }
    }

    /// A uniform block `[0, lx] x [0, ly] x [0, lz]` of `nx x ny x nz` bricks (a beam along `x`
    /// when `lx` is the long side).
    pub fn uniform(l: [f64; 3], n: [usize; 3]) -> Self {
        let lines = |k: usize| graded(0.0, l[k], n[k], 1.0);
        Self::block(&lines(0), &lines(1), &lines(2))
    }

    /// Move every node by `f` (connectivity unchanged).
    pub fn map(mut self, f: impl Fn([f64; 3]) -> [f64; 3]) -> Self {
        for p in &mut self.nodes {
            *p = f(*p);
        }
        self
    }

    /// Move each node for which `free` holds by a pseudo-random vector (deterministic in
    /// `seed`) of components up to `amount` times its shortest incident edge. Nodes on the
    /// boundary should be excluded by `free` (or moved only along it) to keep the outline.
    pub fn distort(mut self, amount: f64, seed: u64, free: impl Fn([f64; 3]) -> bool) -> Self {
        let mut shortest = vec![f64::INFINITY; self.nodes.len()];
        for el in &self.elements {
            for &(a, b) in &super::geometry::EDGES {
                let (p, q) = (self.nodes[el[a]], self.nodes[el[b]]);
                let d =
                    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
                for n in [el[a], el[b]] {
                    shortest[n] = shortest[n].min(d);
                }
            }
        }
        let mut state = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        let mut next = move || {
            // 64-bit LCG (Knuth's MMIX constants), top 53 bits to [-1, 1)
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        };
        for (p, h) in self.nodes.iter_mut().zip(&shortest) {
            let step = [next(), next(), next()];
            if free(*p) {
                for i in 0..3 {
                    p[i] += amount * h * step[i];
                }
            }
        }
        self
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Number of bricks.
    pub fn n_elements(&self) -> usize {
        self.elements.len()
    }

    /// Node coordinates of brick `e`.
    pub fn element_coords(&self, e: usize) -> [[f64; 3]; N_NODES] {
        self.elements[e].map(|n| self.nodes[n])
    }

    /// The nodes for which `pred` holds, in increasing order.
    pub fn nodes_where(&self, pred: impl Fn([f64; 3]) -> bool) -> Vec<usize> {
        (0..self.nodes.len())
            .filter(|&n| pred(self.nodes[n]))
            .collect()
    }

    /// The outward face `face` (0 to 5, numbering of [`super::geometry`]) of brick `brick`:
    /// its 4 global nodes in the order of [`FACES`].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a brick or a local face that does not exist.
    pub fn brick_face(&self, brick: usize, face: usize) -> Result<Face> {
        let element = self.elements.get(brick).ok_or_else(|| {
            Error::InvalidInput(format!(
                "brick {brick} does not exist ({} bricks)",
                self.elements.len()
            ))
        })?;
        let local = FACES.get(face).ok_or_else(|| {
            Error::InvalidInput(format!(
                "local face {face} of brick {brick} (faces are 0 to 5)"
            ))
        })?;
        Ok(local.map(|k| element[k]))
    }

    /// The boundary faces `(brick, local face)` whose 4 nodes all satisfy `pred`.
    pub fn faces_where(&self, pred: impl Fn([f64; 3]) -> bool) -> Vec<(usize, usize)> {
        let mut out = Vec::new();
        for (e, el) in self.elements.iter().enumerate() {
            for (f, face) in FACES.iter().enumerate() {
                if face.iter().all(|&k| pred(self.nodes[el[k]])) {
                    out.push((e, f));
                }
            }
        }
        out
    }

    /// Every brick face, keyed by its sorted nodes, with the bricks and local faces it belongs to.
    fn face_index(&self) -> HashMap<Face, Vec<(usize, usize)>> {
        let mut index: HashMap<Face, Vec<(usize, usize)>> = HashMap::new();
        for (e, el) in self.elements.iter().enumerate() {
            for (f, face) in FACES.iter().enumerate() {
                let mut key = face.map(|k| el[k]);
                key.sort_unstable();
                index.entry(key).or_default().push((e, f));
            }
        }
        index
    }

    /// The brick and local face (numbering of [`super::geometry`]) whose outward face is `face`
    /// (its 4 nodes counter-clockwise seen from outside, starting at any of them).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `face` is no face of a brick, or lists one clockwise seen
    /// from outside (its normal would point into the body).
    pub fn locate_face(&self, face: Face) -> Result<(usize, usize)> {
        locate(&self.face_index(), &self.elements, face).map_err(Error::InvalidInput)
    }

    /// The faces of set `name` as `(brick, local face)` pairs ([`SolidMesh::locate_face`]), in
    /// the set's order.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for an unknown set or a face [`SolidMesh::locate_face`] rejects.
    pub fn face_set(&self, name: &str) -> Result<Vec<(usize, usize)>> {
        self.face_set_in(&self.face_index(), name)
    }

    /// [`SolidMesh::face_set`] with the mesh's face index.
    fn face_set_in(
        &self,
        index: &HashMap<Face, Vec<(usize, usize)>>,
        name: &str,
    ) -> Result<Vec<(usize, usize)>> {
        let set = self
            .face_sets
            .get(name)
            .ok_or_else(|| Error::InvalidInput(format!("no face set {name:?} in the mesh")))?;
        set.iter()
            .map(|&face| {
                locate(index, &self.elements, face)
                    .map_err(|m| Error::InvalidInput(format!("face set {name:?}: {m}")))
            })
            .collect()
    }

    /// Check every face set: each face a face of a brick, listed outward.
    fn check_face_sets(&self) -> Result<()> {
        if self.face_sets.is_empty() {
            return Ok(());
        }
        let index = self.face_index();
        for name in self.face_sets.keys() {
            self.face_set_in(&index, name)?;
        }
        Ok(())
    }

    /// Check connectivity (node indices in range), the face sets and every brick's shape under
    /// the default [`ShapePolicy`]; errors name the brick. [`check`](Self::check) returns the
    /// warnings.
    pub fn validate(&self) -> Result<()> {
        self.check(ShapePolicy::default()).map(|_| ())
    }

    /// Check connectivity, the face sets and every brick's shape under `policy`; errors name the
    /// brick or the set. Returns the shape warnings (none under [`ShapePolicy::Strict`]) with
    /// their bricks.
    pub fn check(&self, policy: ShapePolicy) -> Result<Vec<(usize, ShapeWarning)>> {
        if self.element_material.len() != self.elements.len() {
            return Err(Error::InvalidInput(format!(
                "{} material indices for {} bricks",
                self.element_material.len(),
                self.elements.len()
            )));
        }
        let mut warnings = Vec::new();
        for (e, el) in self.elements.iter().enumerate() {
            if let Some(&n) = el.iter().find(|&&n| n >= self.nodes.len()) {
                return Err(Error::InvalidInput(format!(
                    "brick {e} uses node {n} but the mesh has {} nodes",
                    self.nodes.len()
                )));
            }
            let report = check_shape(&self.element_coords(e), policy)
                .map_err(|kind| Error::at_element(kind, e))?;
            warnings.extend(report.warnings().map(|w| (e, w)));
        }
        self.check_face_sets()?;
        Ok(warnings)
    }

    /// Consistent nodal forces of the traction field `traction(x, n)` (`x` the point, `n` the
    /// outward unit normal) on face `face` of brick `e`: `f_k = integral of N_k t dA` with 2x2
    /// Gauss on the face ([`super::loads::face_forces`]: exact for a uniform traction on a plane
    /// face). Returns the 4 face nodes (global ids, in face order) and their forces.
    pub fn face_forces(
        &self,
        e: usize,
        face: usize,
        traction: impl Fn([f64; 3], [f64; 3]) -> [f64; 3],
    ) -> [(usize, [f64; 3]); 4] {
        let map = Trilinear::new(&self.element_coords(e));
        let f = super::loads::face_forces(&map, face, |p| traction(p.x, p.normal));
        let ids = FACES[face].map(|k| self.elements[e][k]);
        std::array::from_fn(|k| (ids[k], f[k]))
    }
}

/// [`SolidMesh::locate_face`] with the mesh's face index; the error says what is wrong.
fn locate(
    index: &HashMap<Face, Vec<(usize, usize)>>,
    elements: &[[usize; N_NODES]],
    face: Face,
) -> std::result::Result<(usize, usize), String> {
    let mut key = face;
    key.sort_unstable();
    let owners = index.get(&key).map_or(&[][..], Vec::as_slice);
    let same_cycle = |a: Face, b: Face| (0..4).any(|r| (0..4).all(|k| a[k] == b[(k + r) % 4]));
    let mut reversed = face;
    reversed.reverse();
    if let Some(&(e, f)) = owners
        .iter()
        .find(|&&(e, f)| same_cycle(face, FACES[f].map(|k| elements[e][k])))
    {
        return Ok((e, f));
    }
    Err(
        match owners
            .iter()
            .find(|&&(e, f)| same_cycle(reversed, FACES[f].map(|k| elements[e][k])))
        {
            Some(&(e, f)) => format!(
                "face {face:?} is face {f} of brick {e} listed clockwise seen from outside (its \
             normal points into the body): list it as {:?}",
                FACES[f].map(|k| elements[e][k])
            ),
            None => format!("face {face:?} is no face of a brick of the mesh"),
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::boundary::FacePoint;

    /// The six sides of a block: the right number of faces, every face on its side with the
    /// outward unit normal, the areas summing to the side's.
    #[test]
    fn block_names_its_six_sides_outward() {
        let (xs, ys, zs) = (
            [0.0, 1.0, 3.0],
            [0.0, 2.0, 2.5, 4.0],
            [1.0, 1.5, 2.0, 3.0, 5.0],
        );
        let mesh = SolidMesh::block(&xs, &ys, &zs);
        mesh.validate().unwrap();
        let lo = [0.0, 0.0, 1.0];
        let hi = [3.0, 4.0, 5.0];
        for (name, face) in BLOCK_SIDES {
            let axis = face / 2;
            let (value, sign) = if face % 2 == 0 {
                (lo[axis], -1.0)
            } else {
                (hi[axis], 1.0)
            };
            let set = &mesh.face_sets[name];
            let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
            let n_cells = [xs.len() - 1, ys.len() - 1, zs.len() - 1];
            assert_eq!(set.len(), n_cells[a] * n_cells[b], "{name}");
            let mut area = 0.0;
            for f in set {
                let corners = f.map(|n| mesh.nodes[n]);
                assert!(
                    corners.iter().all(|p| p[axis] == value),
                    "{name}: {corners:?}"
                );
                let point = FacePoint::new(corners, 0.0, 0.0);
                let mut want = [0.0; 3];
                want[axis] = sign;
                assert_eq!(point.normal, want, "{name}");
                area += 4.0 * point.area;
            }
            let side = (hi[a] - lo[a]) * (hi[b] - lo[b]);
            assert!(
                (area - side).abs() <= 1e-14 * side,
                "{name}: {area} vs {side}"
            );
            let located = mesh.face_set(name).unwrap();
            assert!(located.iter().all(|&(_, f)| f == face), "{name}");
        }
    }

    #[test]
    fn face_sets_are_checked() {
        let mesh = SolidMesh::uniform([1.0, 1.0, 1.0], [2, 1, 1]);
        let top = mesh.face_sets["top"][1];
        // any starting node, counter-clockwise seen from outside
        let turned = [top[2], top[3], top[0], top[1]];
        assert_eq!(mesh.locate_face(turned).unwrap(), (1, 5));
        let mut bad = mesh.clone();
        let mut inward = top;
        inward.reverse();
        bad.face_sets.insert("inward".into(), vec![inward]);
        let e = bad.validate().unwrap_err().to_string();
        assert!(e.contains("\"inward\"") && e.contains("clockwise"), "{e}");
        let mut bad = mesh.clone();
        bad.face_sets.insert("diagonal".into(), vec![[0, 1, 10, 9]]);
        let e = bad.validate().unwrap_err().to_string();
        assert!(e.contains("no face of a brick"), "{e}");
        assert!(mesh.face_set("none").is_err());
        // moving the nodes keeps the sets
        let moved = mesh.clone().map(|p| [2.0 * p[0], p[1], p[2]]);
        assert_eq!(moved.face_sets, mesh.face_sets);
        moved.validate().unwrap();
    }
}
