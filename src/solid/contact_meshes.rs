//! Brick meshes of two bodies for validating 3D contact: a paraboloid cap on a block (the
//! quarter model for Hertz, the half model for Cattaneo-Mindlin) and a block on a flat turned
//! about the normal (sliding at an angle to the mesh lines). Each is one [`SolidMesh`] of both
//! bodies, body 0 (the multiplier side A) then body 1 (B), `element_material` the body index,
//! with the contact faces of both bodies (4 node ids in [`FACES`] order, outward), the nodes on
//! each symmetry plane, the nodes to load and to hold.
//!
//! # The cap
//! The cap is the paraboloid `z = (x^2 + y^2) / (2 R)`, Hertz's profile itself: his solution is
//! exact for that quadratic gap, where a sphere's gap differs by `r^4 / (8 R^3)`. It is meshed
//! as a graph over the block's `(x, y)` grid: the cap body is a structured block
//! `(x, y, zeta)`, `0 <= zeta <= H`, whose node `(x, y, zeta)` sits at
//! `z = f + zeta (H - f) / H`, `f` the paraboloid's height. Every brick is a piece of a vertical
//! column: no pole, where a latitude-longitude map of a sphere would collapse bricks onto the
//! axis, and the cap's contact nodes lie straight above the block's.
//!
//! The `(x, y)` lines and both bodies' `z` lines are uniform of size `h = a / (a/h)` out to
//! `zone a` (`a` the target contact radius) and then grow geometrically to the bodies' extents
//! (graded bricks finer near the contact centre). The cap touches the block at the origin with
//! no gap; A is the cap's bottom within `r <= zone a`, B the block's top within the square of
//! half-width `2 zone a` around the centre (so that B covers A).

use super::geometry::FACES;
use super::mesh::SolidMesh;
use crate::contact::faces::SymmetryPlane;
use crate::error::{Error, Result};

/// Two bodies meshed together, with their contact faces and node sets.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactMesh {
    /// Both bodies: body 0 (side A) then body 1 (side B); `element_material` is the body.
    pub mesh: SolidMesh,
    /// The number of nodes of body 0 (body 1's node ids follow).
    pub a_nodes: usize,
    /// A's contact faces (body 0), node ids of `mesh`, [`FACES`] order (outward).
    pub a_faces: Vec<[usize; 4]>,
    /// B's contact faces (body 1), likewise.
    pub b_faces: Vec<[usize; 4]>,
    /// Each symmetry plane of the model with the nodes (of both bodies) on it.
    pub symmetry: Vec<(SymmetryPlane, Vec<usize>)>,
    /// Body 0's face opposite the contact (its top): the nodes to move or load.
    pub a_top: Vec<usize>,
    /// Body 1's face opposite the contact (its bottom): the nodes to hold.
    pub b_bottom: Vec<usize>,
    /// The face size at the contact centre.
    pub h: f64,
}

/// Which part of the cap-on-block model to mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CapModel {
    /// `x >= 0`, `y >= 0`: symmetry planes `x = 0` and `y = 0` (normal loading: Hertz).
    Quarter,
    /// `y >= 0`: the symmetry plane `y = 0`, the plane of a tangential load along `x` and the
    /// normal (Cattaneo-Mindlin).
    Half,
}

/// A paraboloid cap of radius `R = 1` on a block (see the [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapOnBlock {
    /// Quarter or half model.
    pub model: CapModel,
    /// Target contact radius over the face size at the centre, `a / h`.
    pub a_over_h: usize,
    /// `R / a`.
    pub radius_over_contact: f64,
    /// Uniform spacing out to `zone a`; A is the cap's bottom there.
    pub zone: f64,
    /// The cap's half-width and height `H`, in `a`.
    pub cap_extent: f64,
    /// The block's half-width and depth, in `a`.
    pub block_extent: f64,
    /// Ratio of consecutive cell sizes beyond the zone.
    pub growth: f64,
}

/// `uniform` cells of size `h` from 0, then cells growing by `growth` each, ending exactly at
/// `length` (the last cell between half and one and a half times its predecessor grown).
fn lines(h: f64, uniform: usize, length: f64, growth: f64) -> Vec<f64> {
    let mut out: Vec<f64> = (0..=uniform).map(|i| i as f64 * h).collect();
    let mut cell = h;
    loop {
        cell *= growth;
        let last = out[out.len() - 1];
        if last + 1.5 * cell >= length {
            out.push(length);
            return out;
        }
        out.push(last + cell);
    }
}

/// `lines` mirrored about 0: `-l_n, ..., -l_1, 0, l_1, ..., l_n`.
fn mirrored(lines: &[f64]) -> Vec<f64> {
    lines[1..]
        .iter()
        .rev()
        .map(|v| -v)
        .chain(lines.iter().copied())
        .collect()
}

/// Node ids of `mesh` whose position satisfies `pred`, offset by `offset`.
fn nodes_of(mesh: &SolidMesh, offset: usize, pred: impl Fn([f64; 3]) -> bool) -> Vec<usize> {
    mesh.nodes_where(pred)
        .into_iter()
        .map(|n| n + offset)
        .collect()
}

/// The faces of `mesh` whose 4 nodes satisfy `pred`, as node ids offset by `offset`.
fn faces_of(mesh: &SolidMesh, offset: usize, pred: impl Fn([f64; 3]) -> bool) -> Vec<[usize; 4]> {
    mesh.faces_where(pred)
        .into_iter()
        .map(|(e, f)| FACES[f].map(|k| mesh.elements[e][k] + offset))
        .collect()
}

/// Body 0 then body 1 in one mesh, `element_material` the body index.
fn merge(a: &SolidMesh, b: &SolidMesh) -> SolidMesh {
    let offset = a.n_nodes();
    let mut out = a.clone();
    out.nodes.extend(&b.nodes);
    out.elements
        .extend(b.elements.iter().map(|el| el.map(|n| n + offset)));
    out.element_material = [(0, a.n_elements()), (1, b.n_elements())]
        .iter()
        .flat_map(|&(body, n)| std::iter::repeat_n(body, n))
        .collect();
    out
}

fn invalid(msg: String) -> Error {
    Error::InvalidInput(msg)
}

impl CapOnBlock {
    /// The model with the defaults used by the validation: `R / a = 16`, uniform to `1.5 a`,
    /// cap `8 a` wide and high, block `16 a` wide and deep, growth 1.3.
    pub fn new(model: CapModel, a_over_h: usize) -> Self {
        CapOnBlock {
            model,
            a_over_h,
            radius_over_contact: 16.0,
            zone: 1.5,
            cap_extent: 8.0,
            block_extent: 16.0,
            growth: 1.3,
        }
    }

    /// The target contact radius `a = R / (R/a)`, `R = 1`.
    pub fn contact_radius(&self) -> f64 {
        1.0 / self.radius_over_contact
    }

    /// The paraboloid's height `(x^2 + y^2) / (2 R)` above the contact centre.
    pub fn height(&self, x: f64, y: f64) -> f64 {
        0.5 * (x * x + y * y)
    }

    fn check(&self) -> Result<()> {
        let finite = [
            self.radius_over_contact,
            self.zone,
            self.cap_extent,
            self.block_extent,
            self.growth,
        ]
        .iter()
        .all(|v| v.is_finite());
        if !finite || self.a_over_h == 0 || self.radius_over_contact < 2.0 || self.zone <= 0.0 {
            return Err(invalid(format!(
                "cap on block: a/h >= 1, R/a >= 2 and zone > 0, all finite: {self:?}"
            )));
        }
        if !(self.growth >= 1.0
            && self.cap_extent > self.zone
            && self.block_extent > 2.0 * self.zone)
        {
            return Err(invalid(format!(
                "cap on block: growth >= 1, cap extent above the zone, block extent above twice \
                 the zone: {self:?}"
            )));
        }
        // the cap's bottom at its corner (r = sqrt 2 W) must stay well below its top H = W
        let w = self.cap_extent * self.contact_radius();
        if self.height(w, w) > 0.75 * w {
            return Err(invalid(format!(
                "cap on block: the paraboloid at the cap's corner, {:.3e}, is above three \
                 quarters of its height {w:.3e}: make the cap narrower or R/a larger",
                self.height(w, w)
            )));
        }
        Ok(())
    }

    /// Build the two meshes (cap: body 0, side A; block: body 1, side B).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for parameters out of range (named in the message).
    pub fn build(&self) -> Result<ContactMesh> {
        self.check()?;
        let a = self.contact_radius();
        let h = a / self.a_over_h as f64;
        let uniform = (self.zone * self.a_over_h as f64).ceil() as usize;
        let cap_half = lines(h, uniform, self.cap_extent * a, self.growth);
        let block_half = lines(h, uniform, self.block_extent * a, self.growth);
        let plane = |x: &[f64]| match self.model {
            CapModel::Quarter => x.to_vec(),
            CapModel::Half => mirrored(x),
        };
        let top = cap_half[cap_half.len() - 1];
        let cap = SolidMesh::block(&plane(&cap_half), &cap_half, &cap_half).map(|[x, y, zeta]| {
            let f = self.height(x, y);
            let z = if zeta == top {
                top
            } else {
                f + zeta * (top - f) / top
            };
            [x, y, z]
        });
        let depth: Vec<f64> = block_half.iter().rev().map(|z| -z).collect();
        let block = SolidMesh::block(&plane(&block_half), &block_half, &depth);
        let offset = cap.n_nodes();
        let zone = self.zone * a * (1.0 + 1e-12);
        let a_faces = faces_of(&cap, 0, |p| {
            p[2] == self.height(p[0], p[1]) && p[0].hypot(p[1]) <= zone
        });
        let b_faces = faces_of(&block, offset, |p| {
            p[2] == 0.0 && p[0].abs().max(p[1].abs()) <= 2.0 * zone
        });
        let planes: &[[f64; 3]] = match self.model {
            CapModel::Quarter => &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            CapModel::Half => &[[0.0, 1.0, 0.0]],
        };
        let symmetry = planes
            .iter()
            .map(|&m| {
                let on = |p: [f64; 3]| p[0] * m[0] + p[1] * m[1] + p[2] * m[2] == 0.0;
                let mut nodes = nodes_of(&cap, 0, on);
                nodes.extend(nodes_of(&block, offset, on));
                SymmetryPlane::new([0.0; 3], m).map(|plane| (plane, nodes))
            })
            .collect::<Result<Vec<_>>>()?;
        let a_top = nodes_of(&cap, 0, |p| p[2] == top);
        let bottom = depth[0];
        let b_bottom = nodes_of(&block, offset, |p| p[2] == bottom);
        Ok(ContactMesh {
            mesh: merge(&cap, &block),
            a_nodes: offset,
            a_faces,
            b_faces,
            symmetry,
            a_top,
            b_bottom,
            h,
        })
    }
}

/// A block (body 0, side A) on a flat (body 1, side B), the block turned by `angle` about the
/// normal `z` relative to the flat's mesh lines: sliding along `x` then runs at `angle` to the
/// block's mesh lines, and no face edge of A is parallel to one of B unless the angle is a
/// multiple of 90 degrees. The block is `size` wide (`x`, `y` before turning) and high, centred
/// on the `z` axis with its bottom on `z = 0`; the flat is `flat` wide and deep, centred, its
/// top on `z = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockOnFlat {
    /// The block's size `[lx, ly, lz]`.
    pub size: [f64; 3],
    /// The block's bricks per direction.
    pub cells: [usize; 3],
    /// The flat's size `[lx, ly, lz]`.
    pub flat: [f64; 3],
    /// The flat's bricks per direction.
    pub flat_cells: [usize; 3],
    /// The block's turn about `z`, in degrees.
    pub angle: f64,
}

impl BlockOnFlat {
    /// Build the two meshes (block: body 0, side A = its bottom; flat: body 1, side B = its top).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a size that is not finite and positive, a zero cell count,
    /// a non-finite angle, or a turned block reaching beyond the flat.
    pub fn build(&self) -> Result<ContactMesh> {
        let sizes = self.size.iter().chain(&self.flat);
        if !(sizes.clone().all(|v| v.is_finite() && *v > 0.0)
            && self.cells.iter().chain(&self.flat_cells).all(|&n| n > 0)
            && self.angle.is_finite())
        {
            return Err(invalid(format!(
                "block on flat: sizes finite and positive, cell counts positive, a finite \
                 angle: {self:?}"
            )));
        }
        let (sn, cs) = self.angle.to_radians().sin_cos();
        let [lx, ly, _] = self.size;
        let block = SolidMesh::uniform(self.size, self.cells).map(|[x, y, z]| {
            let (u, v) = (x - 0.5 * lx, y - 0.5 * ly);
            [cs * u - sn * v, sn * u + cs * v, z]
        });
        let [fx, fy, fz] = self.flat;
        let flat = SolidMesh::uniform(self.flat, self.flat_cells)
            .map(|[x, y, z]| [x - 0.5 * fx, y - 0.5 * fy, z - fz]);
        if block
            .nodes
            .iter()
            .any(|p| p[0].abs() > 0.5 * fx || p[1].abs() > 0.5 * fy)
        {
            return Err(invalid(format!(
                "block on flat: the turned block reaches beyond the flat: {self:?}"
            )));
        }
        let offset = block.n_nodes();
        let h = (lx / self.cells[0] as f64).min(ly / self.cells[1] as f64);
        Ok(ContactMesh {
            a_faces: faces_of(&block, 0, |p| p[2] == 0.0),
            b_faces: faces_of(&flat, offset, |p| p[2] == 0.0),
            symmetry: Vec::new(),
            a_top: nodes_of(&block, 0, |p| p[2] == self.size[2]),
            b_bottom: nodes_of(&flat, offset, |p| p[2] == -fz),
            mesh: merge(&block, &flat),
            a_nodes: offset,
            h,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solid::ShapePolicy;

    fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
        [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
    }

    fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
        [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ]
    }

    /// A face's normal at its centre (not normalised): `x_s x x_t`.
    fn normal(m: &SolidMesh, f: &[usize; 4]) -> [f64; 3] {
        let x = f.map(|k| m.nodes[k]);
        let xs = sub(sub(x[1], x[0]), sub(x[3], x[2]));
        let xt = sub(sub(x[3], x[0]), sub(x[1], x[2]));
        cross(xs, xt)
    }

    /// Every brick valid under the strict policy (no warnings, positive Jacobians at the
    /// corners); both bodies' node and brick counts and materials.
    fn check_bodies(c: &ContactMesh, counts: [[usize; 3]; 2]) {
        assert!(c.mesh.check(ShapePolicy::Strict).unwrap().is_empty());
        let nodes: Vec<usize> = counts
            .iter()
            .map(|n| n.iter().map(|k| k + 1).product())
            .collect();
        let bricks: Vec<usize> = counts.iter().map(|n| n.iter().product()).collect();
        assert_eq!(c.a_nodes, nodes[0]);
        assert_eq!(c.mesh.n_nodes(), nodes[0] + nodes[1]);
        assert_eq!(c.mesh.n_elements(), bricks[0] + bricks[1]);
        for (e, &m) in c.mesh.element_material.iter().enumerate() {
            assert_eq!(m, usize::from(e >= bricks[0]), "brick {e}");
        }
    }

    #[test]
    fn lines_are_uniform_then_graded_to_the_end() {
        let l = lines(0.1, 3, 2.0, 1.3);
        assert_eq!(&l[..4], &[0.0, 0.1, 0.2, 0.30000000000000004]);
        assert_eq!(l[l.len() - 1], 2.0);
        for w in l.windows(3).skip(3) {
            let ratio = (w[2] - w[1]) / (w[1] - w[0]);
            assert!((0.5..=1.5 * 1.3).contains(&ratio), "{ratio}");
        }
        assert_eq!(mirrored(&[0.0, 1.0, 3.0]), vec![-3.0, -1.0, 0.0, 1.0, 3.0]);
    }

    #[test]
    fn the_quarter_cap_on_a_block_reaches_the_requested_a_over_h() {
        for a_over_h in [4, 8, 16] {
            let spec = CapOnBlock::new(CapModel::Quarter, a_over_h);
            let c = spec.build().unwrap();
            let a = spec.contact_radius();
            assert_eq!(a / c.h, a_over_h as f64);
            // the cap's and the block's line counts, read off the mesh
            let cap_lines = lines(c.h, (1.5 * a_over_h as f64).ceil() as usize, 8.0 * a, 1.3);
            let block_lines = lines(c.h, (1.5 * a_over_h as f64).ceil() as usize, 16.0 * a, 1.3);
            let (nc, nb) = (cap_lines.len() - 1, block_lines.len() - 1);
            check_bodies(&c, [[nc, nc, nc], [nb, nb, nb]]);
            eprintln!(
                "a/h = {a_over_h}: cap {nc}^3 bricks, block {nb}^3, {} nodes, {} A faces, {} B \
                 faces",
                c.mesh.n_nodes(),
                c.a_faces.len(),
                c.b_faces.len()
            );
            // the faces at the centre are h x h (both sides); A within 1.5 a, outward down;
            // B on z = 0, outward up; A's corner faces are its smallest
            let m = &c.mesh;
            for f in &c.a_faces {
                let n = normal(m, f);
                assert!(n[2] < 0.0 && f.iter().all(|&k| k < c.a_nodes));
                for &k in f {
                    let p = m.nodes[k];
                    assert_eq!(p[2], spec.height(p[0], p[1]));
                    assert!(p[0].hypot(p[1]) <= 1.5 * a * (1.0 + 1e-12));
                }
            }
            for f in &c.b_faces {
                assert!(normal(m, f)[2] > 0.0 && f.iter().all(|&k| k >= c.a_nodes));
                assert!(f.iter().all(|&k| m.nodes[k][2] == 0.0));
            }
            let at_origin = |faces: &[[usize; 4]]| {
                faces
                    .iter()
                    .find(|f| {
                        f.iter()
                            .any(|&k| m.nodes[k][0] == 0.0 && m.nodes[k][1] == 0.0)
                    })
                    .map(|f| {
                        let x = f.map(|k| m.nodes[k]);
                        (0..4)
                            .map(|i| {
                                let d = sub(x[(i + 1) % 4], x[i]);
                                d[0].hypot(d[1])
                            })
                            .fold(0.0, f64::max)
                    })
                    .unwrap()
            };
            assert!((at_origin(&c.a_faces) / c.h - 1.0).abs() < 1e-12);
            assert!((at_origin(&c.b_faces) / c.h - 1.0).abs() < 1e-12);
            // A: the faces inside the quarter circle of radius 1.5 a, at least the area
            // pi (1.5 a - sqrt 2 h)^2 / 4 of the circle less a diagonal
            let area = c.a_faces.len() as f64 * c.h * c.h;
            let inner = 1.5 * a - 2f64.sqrt() * c.h;
            assert!(area >= 0.25 * std::f64::consts::PI * inner * inner);
            assert!(area <= 0.25 * std::f64::consts::PI * (1.5 * a).powi(2));
            // B: every face within the square of half-width 3 a, its outer edge the last line
            // there
            let b_max = c
                .b_faces
                .iter()
                .flatten()
                .map(|&k| m.nodes[k][0].max(m.nodes[k][1]))
                .fold(0.0, f64::max);
            let last = block_lines
                .iter()
                .copied()
                .filter(|&x| x <= 3.0 * a)
                .fold(0.0, f64::max);
            assert_eq!(b_max, last);
            assert_eq!(
                c.b_faces.len(),
                block_lines
                    .iter()
                    .filter(|&&x| x > 0.0 && x <= last)
                    .count()
                    .pow(2)
            );
            // the symmetry planes: every node on x = 0 or y = 0, of both bodies
            assert_eq!(c.symmetry.len(), 2);
            for (i, (plane, nodes)) in c.symmetry.iter().enumerate() {
                assert_eq!(plane.normal[i], 1.0);
                let expect: Vec<usize> = m.nodes_where(|p| p[i] == 0.0);
                assert_eq!(nodes, &expect);
                assert_eq!(nodes.len(), (nc + 1) * (nc + 1) + (nb + 1) * (nb + 1));
            }
            assert_eq!(c.a_top.len(), (nc + 1) * (nc + 1));
            assert_eq!(c.b_bottom.len(), (nb + 1) * (nb + 1));
            assert!(c.a_top.iter().all(|&k| m.nodes[k][2] == 8.0 * a));
            assert!(c.b_bottom.iter().all(|&k| m.nodes[k][2] == -16.0 * a));
        }
    }

    #[test]
    fn the_half_cap_on_a_block_is_the_quarter_mirrored() {
        let quarter = CapOnBlock::new(CapModel::Quarter, 4).build().unwrap();
        let c = CapOnBlock::new(CapModel::Half, 4).build().unwrap();
        assert!(c.mesh.check(ShapePolicy::Strict).unwrap().is_empty());
        assert_eq!(c.a_faces.len(), 2 * quarter.a_faces.len());
        assert_eq!(c.b_faces.len(), 2 * quarter.b_faces.len());
        assert_eq!(c.mesh.n_elements(), 2 * quarter.mesh.n_elements());
        assert_eq!(c.symmetry.len(), 1);
        assert_eq!(c.symmetry[0].0.normal, [0.0, 1.0, 0.0]);
        assert_eq!(c.symmetry[0].1, c.mesh.nodes_where(|p| p[1] == 0.0));
        for f in &c.a_faces {
            assert!(normal(&c.mesh, f)[2] < 0.0);
        }
        let xs: Vec<f64> = c
            .a_faces
            .iter()
            .flatten()
            .map(|&k| c.mesh.nodes[k][0])
            .collect();
        let (lo, hi) = xs
            .iter()
            .fold((0.0f64, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
        assert_eq!(lo, -hi);
    }

    #[test]
    fn the_block_on_a_flat_is_turned_about_the_normal() {
        let spec = BlockOnFlat {
            size: [1.0, 0.8, 0.5],
            cells: [5, 4, 2],
            flat: [3.0, 3.0, 1.0],
            flat_cells: [6, 6, 2],
            angle: 30.0,
        };
        let c = spec.build().unwrap();
        check_bodies(&c, [[5, 4, 2], [6, 6, 2]]);
        assert_eq!(c.a_faces.len(), 20);
        assert_eq!(c.b_faces.len(), 36);
        assert!((c.h - 0.2).abs() < 1e-15);
        let m = &c.mesh;
        let (sn, cs) = 30f64.to_radians().sin_cos();
        for f in &c.a_faces {
            assert!(normal(m, f)[2] < 0.0);
            // the edges along the block's x run at 30 degrees to the flat's x
            let d = sub(m.nodes[f[3]], m.nodes[f[0]]);
            let along = (d[0] * cs + d[1] * sn).abs() / d[0].hypot(d[1]);
            let across = (d[0] * -sn + d[1] * cs).abs() / d[0].hypot(d[1]);
            assert!(
                along.max(across) > 1.0 - 1e-12,
                "an edge along the turned axes"
            );
        }
        for f in &c.b_faces {
            assert!(normal(m, f)[2] > 0.0);
        }
        assert_eq!(c.a_top.len(), 30);
        assert_eq!(c.b_bottom.len(), 49);
        assert!(c.symmetry.is_empty());
        let too_far = BlockOnFlat {
            flat: [1.2, 1.2, 1.0],
            ..spec
        };
        assert!(too_far.build().is_err());
        assert!(
            BlockOnFlat {
                angle: f64::NAN,
                ..spec
            }
            .build()
            .is_err()
        );
        assert!(
            CapOnBlock {
                a_over_h: 0,
                ..CapOnBlock::new(CapModel::Quarter, 4)
            }
            .build()
            .is_err()
        );
        // a cap too wide for R: the paraboloid would reach its top
        assert!(
            CapOnBlock {
                radius_over_contact: 4.0,
                ..CapOnBlock::new(CapModel::Quarter, 4)
            }
            .build()
            .is_err()
        );
    }
}
