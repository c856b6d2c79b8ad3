//! The mortar integrals assembled over two surfaces of brick faces, per node.

use super::{Quad, face_mass, face_pair, pair_faces};
use crate::error::{Error, Result};
use std::collections::BTreeMap;

/// Relative shortfall of a node's coverage below which it counts as fully covered.
pub const COVERED: f64 = 1e-10;

/// One side's contact surface: node positions and faces (4 node ids indexing `x`, in
/// [`crate::solid::geometry::FACES`] order, outward by the right-hand rule).
#[derive(Debug, Clone, Copy)]
pub struct SurfaceFaces<'a> {
    /// Positions of the nodes the faces use.
    pub x: &'a [[f64; 3]],
    /// The faces.
    pub faces: &'a [[usize; 4]],
}

impl SurfaceFaces<'_> {
    fn corners(&self, side: &str) -> Result<Vec<Quad>> {
        let n = self.x.len();
        self.faces
            .iter()
            .enumerate()
            .map(|(i, f)| match f.iter().find(|&&k| k >= n) {
                Some(k) => Err(Error::InvalidInput(format!(
                    "{side} face {i} uses node {k} but there are {n} nodes"
                ))),
                None => Ok(f.map(|k| self.x[k])),
            })
            .collect()
    }
}

/// The mortar integrals of surface A (the multiplier side) against surface B, by node ids:
/// sums over the overlapping face pairs of [`face_pair`] and over A's faces of [`face_mass`].
///
/// `d` is summed over the **covered** parts (Puso and Laursen's segment-wise `D`), so that for
/// a fully covered A node `sum_j d[k, j] = covered[k] = sum_b m[k, b]` to round-off whatever
/// the faces' shapes: a uniform pressure `p` gives the same resultant on A (`sum_j d_kj p`) as
/// B transmits (`sum_b m_kb p`), the discrete patch-test condition. For a fully covered node
/// it equals the whole-support `F^A` of the plane code up to the triangle rule's error (none on
/// flat parallelograms).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SurfaceMortar {
    /// `D_kj` (A node, A node) over the covered parts.
    pub d: BTreeMap<(usize, usize), f64>,
    /// `M_kb` (A node, B node).
    pub m: BTreeMap<(usize, usize), f64>,
    /// `R_k = integral N_k (x^A - x^B) dA` per A node (covered parts).
    pub mismatch: BTreeMap<usize, [f64; 3]>,
    /// `integral N_k dA` over the whole support of A node `k`.
    pub weight: BTreeMap<usize, f64>,
    /// `integral N_k dA` over the covered part of its support.
    pub covered: BTreeMap<usize, f64>,
    /// The number of overlapping face pairs.
    pub pairs: usize,
}

impl SurfaceMortar {
    /// Assemble over the face pairs [`pair_faces`] finds within `search`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a node id out of range, or a failing face or face pair
    /// (the message names the faces by their index in `a.faces`, `b.faces`).
    pub fn new(a: SurfaceFaces, b: SurfaceFaces, search: f64) -> Result<Self> {
        let (qa, qb) = (a.corners("A")?, b.corners("B")?);
        let mut out = SurfaceMortar::default();
        let at = |i: usize, e: Error| match e {
            Error::InvalidInput(msg) => Error::InvalidInput(format!("A face {i}: {msg}")),
            other => other,
        };
        for (i, (quad, ids)) in qa.iter().zip(a.faces).enumerate() {
            let mass = face_mass(quad).map_err(|e| at(i, e))?;
            for (k, &node) in ids.iter().enumerate() {
                *out.weight.entry(node).or_default() += mass.weight[k];
                out.covered.entry(node).or_default();
            }
        }
        for (i, j) in pair_faces(&qa, &qb, search)? {
            let pair = face_pair(&qa[i], &qb[j]).map_err(|e| at(i, e))?;
            let Some(pair) = pair else { continue };
            out.pairs += 1;
            let (ia, ib) = (a.faces[i], b.faces[j]);
            for (k, &row) in ia.iter().enumerate() {
                *out.covered.entry(row).or_default() += pair.weight[k];
                let r = out.mismatch.entry(row).or_default();
                for c in 0..3 {
                    r[c] += pair.mismatch[k][c];
                }
                for l in 0..4 {
                    *out.d.entry((row, ia[l])).or_default() += pair.d[k][l];
                    *out.m.entry((row, ib[l])).or_default() += pair.m[k][l];
                }
            }
        }
        Ok(out)
    }

    /// Coverage of A node `k`: its covered weight over its whole weight, in `[0, 1]` to
    /// round-off (0 for a node of no A face).
    pub fn coverage(&self, k: usize) -> f64 {
        match (self.covered.get(&k), self.weight.get(&k)) {
            (Some(c), Some(w)) if *w > 0.0 => c / w,
            _ => 0.0,
        }
    }

    /// Check that every node of `nodes` (active A nodes) is fully covered, to [`COVERED`]: an
    /// active node only partly over B would transmit its pressure over part of its support
    /// (a silent hole in the contact zone).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first node that is not.
    pub fn require_covered(&self, nodes: &[usize]) -> Result<()> {
        match nodes.iter().find(|&&k| self.coverage(k) < 1.0 - COVERED) {
            Some(&k) => Err(Error::InvalidInput(format!(
                "A node {k} is active but only {:.6} of its support is over B",
                self.coverage(k)
            ))),
            None => Ok(()),
        }
    }
}
