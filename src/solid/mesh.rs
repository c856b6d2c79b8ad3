//! Hexahedral meshes: storage, structured blocks and beams with graded spacing, mapped and
//! distorted variants, and consistent face loads.
//!
//! A structured block of `nx x ny x nz` bricks over the coordinate lines `xs`, `ys`, `zs`
//! numbers node `(i, j, k)` as `i + (nx + 1) (j + (ny + 1) k)` and brick `(i, j, k)` as
//! `i + nx (j + ny k)`, its nodes in the brick order of [`super::geometry`] (so a block in a
//! right-handed frame gives positive Jacobians). Any smooth map of the nodes keeps the
//! connectivity: beams that twist or curve, and distorted meshes for tests, are a block plus a
//! map.

use super::geometry::{FACES, Trilinear};
use super::{N_NODES, ShapePolicy, check_shape};
use crate::error::{Error, Result, ShapeWarning};

/// A mesh of 8-node bricks.
#[derive(Debug, Clone, PartialEq)]
pub struct SolidMesh {
    /// Node coordinates.
    pub nodes: Vec<[f64; 3]>,
    /// Brick connectivity (node order of [`super::geometry`]).
    pub elements: Vec<[usize; N_NODES]>,
    /// Material index of each brick.
    pub element_material: Vec<usize>,
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
    /// two values), material 0 everywhere.
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
        SolidMesh {
            nodes,
            elements,
            element_material,
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

    /// Check connectivity (node indices in range) and every brick's shape under the default
    /// [`ShapePolicy`]; errors name the brick. [`check`](Self::check) returns the warnings.
    pub fn validate(&self) -> Result<()> {
        self.check(ShapePolicy::default()).map(|_| ())
    }

    /// Check connectivity and every brick's shape under `policy`; errors name the brick. Returns
    /// the shape warnings (none under [`ShapePolicy::Strict`]) with their bricks.
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
