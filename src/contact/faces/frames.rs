//! Nodal frames of a contact surface of brick faces: averaged normals, tangents from one
//! reference direction per surface, and symmetry planes (design document
//! `docs/design/3d-contact.md`, "Tangent frames from one reference direction").
//!
//! # Normals
//! The normal of A node `k` is the direction of `integral N_k n dA` over its faces,
//! `sum_faces integral N_k (x_s x x_t) ds dt`: the measure-weighted average of the face normals
//! around the node, the 3D form of the plane code's rule. With it a constant gap `g` between A
//! and a B surface parallel to A's flat faces gives the weighted mismatch
//! `R_k = -g integral N_k n dA` along the nodal normal. `x_s x x_t` is bilinear in `(s, t)`, so
//! 2x2 Gauss integrates `N_k (x_s x x_t)` exactly, warped faces included.
//!
//! # Tangents
//! One reference direction `r` per surface, and at every node
//!
//! ```text
//! s1 = normalise(r - (r . n) n),    s2 = n x s1      (n, s1, s2) right-handed
//! ```
//!
//! continuous wherever no normal is parallel to `r`: the frames do not jump between
//! neighbouring nodes, nor when a normal crosses a coordinate plane. A basis computed from the
//! normal alone cannot do this: Duff et al.'s branchless basis ("Building an orthonormal basis,
//! revisited", JCGT 6 (2017)) flips both tangents when `n_z` changes sign, which happens on any
//! curved surface crossing the `n_z = 0` orientation, so it is not used. A reference within
//! [`MIN_REFERENCE_SINE`] of parallel to a nodal normal is an error naming the node; the
//! default reference is the coordinate axis whose smallest angle to the nodal normals is
//! largest. It is chosen once per surface (in the reference configuration) and then kept:
//! [`SurfaceFrames::reference`] is what to pass again when the frames are rebuilt.
//!
//! # Symmetry planes
//! On a symmetry plane of the model (unit normal `m`) the traction component along `m`
//! vanishes by symmetry, the 3D twin of the axis nodes in axisymmetry. A node on one
//! ([`SymmetryPlane::contains`]) gets the normal of the full, mirrored model, `n` projected into
//! the plane, `n' = normalise(n - (n . m) m)` (the mirrored faces add the mirrored normal, whose
//! component along `m` cancels), and its reference frame from `n'` rotated about `n'` by the
//! smallest angle that puts one tangent along `+-m`; that tangent is flagged
//! [`NodeFrame::dropped`]: its multiplier is zero and it gets no stick constraint. A node on two
//! planes (the corner of a quarter model) keeps only the normal, along the planes' common line,
//! both tangents dropped (the first along the first plane's normal).

use super::clip::{check_face, tangents, v3};
use super::shapes;
use super::surface::SurfaceFaces;
use crate::error::{Error, Result};
use crate::solid::geometry::GAUSS2;
use nalgebra::Vector3;
use std::collections::BTreeMap;

/// Smallest sine of the angle between the reference direction and a nodal normal: below it
/// the tangent `s1` turns faster than `1 / MIN_REFERENCE_SINE` times the normal (100 times),
/// and is undefined at zero.
pub const MIN_REFERENCE_SINE: f64 = 1e-2;

/// Distance from a symmetry plane, relative to the shortest edge of a node's faces, within
/// which the node lies on it.
pub const ON_PLANE: f64 = 1e-6;

/// Relative length below which a normal (of the summed `integral N_k n dA`, relative to the
/// node's weight; of a normal projected into a symmetry plane) or a plane's normal counts as
/// zero.
const VANISHING: f64 = 1e-8;

/// A symmetry plane of the model: the points `x` with `(x - point) . normal = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SymmetryPlane {
    /// A point of the plane.
    pub point: [f64; 3],
    /// Its unit normal (either orientation; [`SymmetryPlane::new`] and [`SurfaceFrames::new`]
    /// normalise it).
    pub normal: [f64; 3],
}

impl SymmetryPlane {
    /// The plane through `point` normal to `normal` (normalised here).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-finite value or a zero normal.
    pub fn new(point: [f64; 3], normal: [f64; 3]) -> Result<Self> {
        let m = v3(normal);
        if point.iter().chain(&normal).any(|v| !v.is_finite()) || m.norm() == 0.0 {
            return Err(Error::InvalidInput(format!(
                "symmetry plane: a finite point and a non-zero normal, got {point:?} and \
                 {normal:?}"
            )));
        }
        let m = m.normalize();
        Ok(SymmetryPlane {
            point,
            normal: [m[0], m[1], m[2]],
        })
    }

    /// Whether `x` lies on the plane, within `ON_PLANE h`.
    pub fn contains(&self, x: [f64; 3], h: f64) -> bool {
        (v3(x) - v3(self.point)).dot(&v3(self.normal)).abs() <= ON_PLANE * h
    }
}

/// The frame of one A node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeFrame {
    /// Unit normal `n` (outward from A).
    pub normal: [f64; 3],
    /// Unit tangents `s1`, `s2`, `(n, s1, s2)` right-handed and orthonormal.
    pub tangents: [[f64; 3]; 2],
    /// Tangential components that vanish by symmetry (no multiplier, no stick row).
    pub dropped: [bool; 2],
}

/// The frames of a surface's nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFrames {
    /// The reference direction `r` (unit), given or chosen.
    pub reference: [f64; 3],
    /// The frame of each node of the surface's faces, by node id.
    pub frames: BTreeMap<usize, NodeFrame>,
}

/// A node's `integral N_k n dA` summed over its faces, its weight `integral N_k dA`, and the
/// shortest edge of its faces.
#[derive(Debug, Clone, Copy)]
struct NodeSums {
    normal: Vector3<f64>,
    weight: f64,
    edge: f64,
}

/// `integral N_k (x_s x x_t) ds dt` (2x2 Gauss: exact, see the module docs) and
/// `integral N_k |x_s x x_t| ds dt` for the 4 corners of every face, summed per node.
fn node_sums(surface: &SurfaceFaces) -> Result<BTreeMap<usize, NodeSums>> {
    let quads = surface.corners("A")?;
    let mut out: BTreeMap<usize, NodeSums> = BTreeMap::new();
    for (i, (quad, ids)) in quads.iter().zip(surface.faces).enumerate() {
        check_face(quad, &format!("A face {i}"))?;
        let edge = (0..4)
            .map(|k| (v3(quad[(k + 1) % 4]) - v3(quad[k])).norm())
            .fold(f64::INFINITY, f64::min);
        for (s, ws) in GAUSS2 {
            for (t, wt) in GAUSS2 {
                let (xs, xt) = tangents(quad, s, t);
                let n = xs.cross(&xt) * (ws * wt);
                for (nk, &node) in shapes(s, t).iter().zip(ids) {
                    let sums = out.entry(node).or_insert(NodeSums {
                        normal: Vector3::zeros(),
                        weight: 0.0,
                        edge,
                    });
                    sums.normal += n * *nk;
                    sums.weight += n.norm() * nk;
                    sums.edge = sums.edge.min(edge);
                }
            }
        }
    }
    Ok(out)
}

fn arr(v: Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

/// Sine of the angle between unit vectors `r` and `n` (as lines: parallel or opposite is 0).
fn sine(r: &Vector3<f64>, n: &Vector3<f64>) -> f64 {
    r.cross(n).norm()
}

/// `(s1, s2)` of unit normal `n` from reference `r`: `s1 = normalise(r - (r . n) n)`,
/// `s2 = n x s1`.
fn reference_tangents(r: &Vector3<f64>, n: &Vector3<f64>) -> [Vector3<f64>; 2] {
    let s1 = (r - n * r.dot(n)).normalize();
    [s1, n.cross(&s1)]
}

/// A node's normal and the symmetry planes it lies on, with their normals kept independent
/// (a plane parallel to one already kept is the same constraint).
struct Constrained {
    normal: Vector3<f64>,
    planes: Vec<Vector3<f64>>,
}

fn constrain(
    node: usize,
    x: [f64; 3],
    sums: &NodeSums,
    symmetry: &[SymmetryPlane],
) -> Result<Constrained> {
    let mut n = sums.normal;
    if n.norm() <= VANISHING * sums.weight {
        return Err(Error::InvalidInput(format!(
            "A node {node}: its faces' normals cancel (a surface folded onto itself there)"
        )));
    }
    n.normalize_mut();
    let mut planes: Vec<Vector3<f64>> = Vec::new();
    for plane in symmetry.iter().filter(|p| p.contains(x, sums.edge)) {
        let m = v3(plane.normal);
        if planes.iter().any(|q| sine(q, &m) <= VANISHING) {
            continue;
        }
        if planes.len() == 2 {
            return Err(Error::InvalidInput(format!(
                "A node {node} lies on three symmetry planes: no normal is left"
            )));
        }
        planes.push(m);
    }
    let projected = match planes.as_slice() {
        [] => n,
        [m] => n - m * n.dot(m),
        [m1, m2] => {
            let line = m1.cross(m2).normalize();
            line * n.dot(&line)
        }
        _ => unreachable!("at most two independent planes are kept"),
    };
    if projected.norm() <= VANISHING {
        return Err(Error::InvalidInput(format!(
            "A node {node}: its normal {:?} has no component left in its symmetry planes (a \
             face lying in a symmetry plane is no contact face)",
            arr(n)
        )));
    }
    Ok(Constrained {
        normal: projected.normalize(),
        planes,
    })
}

/// The frame of a node with constrained normal `c`, reference `r` (checked).
fn frame(node: usize, c: &Constrained, r: &Vector3<f64>) -> Result<NodeFrame> {
    let n = c.normal;
    let (tangents, dropped) = match c.planes.as_slice() {
        [m1, _] => ([*m1, n.cross(m1)], [true, true]),
        planes => {
            if sine(r, &n) < MIN_REFERENCE_SINE {
                return Err(Error::InvalidInput(format!(
                    "A node {node}: its normal {:?} is within {MIN_REFERENCE_SINE:e} (sine) of \
                     the reference direction {:?}: give another reference direction, or split \
                     the surface into patches",
                    arr(n),
                    arr(*r)
                )));
            }
            let [s1, s2] = reference_tangents(r, &n);
            match planes {
                [] => ([s1, s2], [false, false]),
                [m] if s1.dot(m).abs() >= s2.dot(m).abs() => {
                    let t1 = m * s1.dot(m).signum();
                    ([t1, n.cross(&t1)], [true, false])
                }
                [m] => {
                    let t2 = m * s2.dot(m).signum();
                    ([t2.cross(&n), t2], [false, true])
                }
                _ => unreachable!("two planes handled above"),
            }
        }
    };
    Ok(NodeFrame {
        normal: arr(n),
        tangents: tangents.map(arr),
        dropped,
    })
}

/// The coordinate axis whose smallest sine with the normals is largest (the first on a tie).
fn default_reference(normals: &[Vector3<f64>]) -> Vector3<f64> {
    let worst = |r: &Vector3<f64>| {
        normals
            .iter()
            .map(|n| sine(r, n))
            .fold(f64::INFINITY, f64::min)
    };
    let mut best = Vector3::x();
    for axis in [Vector3::y(), Vector3::z()] {
        if worst(&axis) > worst(&best) {
            best = axis;
        }
    }
    best
}

impl SurfaceFrames {
    /// The frames of the nodes of `surface`'s faces (see the [module docs](self)), with the
    /// reference direction `reference` (normalised here) or, for `None`, the coordinate axis
    /// farthest from parallel to every nodal normal; nodes on the planes of `symmetry` get
    /// their normal in those planes and the tangents along the planes' normals dropped.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a node id out of range or a failing face (naming it), a
    /// reference or a symmetry plane that is zero or not finite (the planes' normals are
    /// normalised here too), a node whose faces' normals cancel, a node on
    /// three independent symmetry planes or whose normal is along a plane's normal, and a
    /// nodal normal within [`MIN_REFERENCE_SINE`] of the reference (naming the node).
    pub fn new(
        surface: SurfaceFaces,
        reference: Option<[f64; 3]>,
        symmetry: &[SymmetryPlane],
    ) -> Result<Self> {
        let sums = node_sums(&surface)?;
        let symmetry = symmetry
            .iter()
            .map(|p| SymmetryPlane::new(p.point, p.normal))
            .collect::<Result<Vec<_>>>()?;
        let constrained = sums
            .iter()
            .map(|(&k, s)| constrain(k, surface.x[k], s, &symmetry).map(|c| (k, c)))
            .collect::<Result<Vec<_>>>()?;
        let r = match reference {
            Some(r) => {
                let v = v3(r);
                if !(r.iter().all(|c| c.is_finite()) && v.norm() > 0.0) {
                    return Err(Error::InvalidInput(format!(
                        "reference direction: finite and non-zero, got {r:?}"
                    )));
                }
                v.normalize()
            }
            None => {
                let free: Vec<Vector3<f64>> = constrained
                    .iter()
                    .filter(|(_, c)| c.planes.len() < 2)
                    .map(|(_, c)| c.normal)
                    .collect();
                default_reference(&free)
            }
        };
        let frames = constrained
            .iter()
            .map(|(k, c)| frame(*k, c, &r).map(|f| (*k, f)))
            .collect::<Result<BTreeMap<_, _>>>()?;
        Ok(SurfaceFrames {
            reference: arr(r),
            frames,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::faces::SurfaceMortar;
    use nalgebra::Rotation3;

    /// A structured surface of `nu x nv` faces over the grid `(u_i, v_j)` mapped by `f`, faces
    /// `(i, j), (i+1, j), (i+1, j+1), (i, j+1)`: outward along `f_u x f_v`. Node `(i, j)` is
    /// `i + (nu + 1) j`.
    fn grid(
        u: &[f64],
        v: &[f64],
        f: impl Fn(f64, f64) -> [f64; 3],
    ) -> (Vec<[f64; 3]>, Vec<[usize; 4]>) {
        let nu = u.len();
        let x = v
            .iter()
            .flat_map(|&b| u.iter().map(move |&a| (a, b)))
            .map(|(a, b)| f(a, b))
            .collect();
        let mut faces = Vec::new();
        for j in 0..v.len() - 1 {
            for i in 0..nu - 1 {
                let id = |i: usize, j: usize| i + nu * j;
                faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        (x, faces)
    }

    fn lin(a: f64, b: f64, n: usize) -> Vec<f64> {
        (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
    }

    /// The cylinder of radius `r` along `x` at angles `phi` (degrees) from `+z` toward `+y`:
    /// `(x, r sin phi, r cos phi)`, outward (away from the axis) over the grid `(x, phi)`.
    fn cylinder_along_x(r: f64, phi: &[f64], x: &[f64]) -> (Vec<[f64; 3]>, Vec<[usize; 4]>) {
        grid(x, phi, |x, p| {
            let (s, c) = p.to_radians().sin_cos();
            [x, r * s, r * c]
        })
    }

    fn check_orthonormal(f: &NodeFrame) {
        let [n, s1, s2] = [f.normal, f.tangents[0], f.tangents[1]].map(v3);
        for v in [n, s1, s2] {
            assert!((v.norm() - 1.0).abs() < 1e-14);
        }
        assert!(n.dot(&s1).abs() < 1e-14 && n.dot(&s2).abs() < 1e-14 && s1.dot(&s2).abs() < 1e-14);
        assert!((n.cross(&s1) - s2).norm() < 1e-14, "right-handed");
    }

    #[test]
    fn frames_do_not_jump_where_normals_cross_nz_zero() {
        // normals from 30 to 150 degrees off +z: n_z changes sign at 90
        let (x, faces) = cylinder_along_x(1.0, &lin(30.0, 150.0, 12), &[0.0, 0.2, 0.5, 1.0]);
        let s = SurfaceFaces {
            x: &x,
            faces: &faces,
        };
        let out = SurfaceFrames::new(s, None, &[]).unwrap();
        assert_eq!(out.reference, [1.0, 0.0, 0.0], "x: normal to every normal");
        let mut signs = [false; 2];
        for face in &faces {
            for k in 0..4 {
                let (i, j) = (face[k], face[(k + 1) % 4]);
                let (fi, fj) = (out.frames[&i], out.frames[&j]);
                check_orthonormal(&fi);
                let dn = (v3(fi.normal) - v3(fj.normal)).norm();
                for t in 0..2 {
                    let ds = (v3(fi.tangents[t]) - v3(fj.tangents[t])).norm();
                    assert!(
                        ds <= dn + 1e-14,
                        "nodes {i}, {j}: tangent {t} moves {ds} vs {dn}"
                    );
                }
                signs[usize::from(fi.normal[2] > 0.0)] = true;
            }
        }
        assert_eq!(signs, [true, true], "normals on both sides of n_z = 0");
        // with an oblique reference, the tangents still move continuously (Lipschitz in n)
        let r = [1.0, 0.4, -0.3];
        let out = SurfaceFrames::new(s, Some(r), &[]).unwrap();
        for face in &faces {
            for k in 0..4 {
                let (fi, fj) = (out.frames[&face[k]], out.frames[&face[(k + 1) % 4]]);
                check_orthonormal(&fi);
                let dn = (v3(fi.normal) - v3(fj.normal)).norm();
                let ds = (v3(fi.tangents[0]) - v3(fj.tangents[0])).norm();
                assert!(
                    ds <= 2.0 * dn / 0.8,
                    "tangent moves {ds} for a normal moving {dn}"
                );
                assert!(fi.dropped == [false, false]);
            }
        }
    }

    /// The prism along `x` over the polygon through `(y, z) = (sin phi, cos phi)` (`phi` in
    /// degrees), offset outward by `g` (each edge moved by `g` along its normal, the vertices
    /// to the intersections `v + g (n1 + n2) / (1 + n1 . n2)`).
    fn offset_prism(phi: &[f64], g: f64, x: &[f64]) -> (Vec<[f64; 3]>, Vec<[usize; 4]>) {
        let v: Vec<Vector3<f64>> = phi
            .iter()
            .map(|p| {
                let (s, c) = p.to_radians().sin_cos();
                Vector3::new(0.0, s, c)
            })
            .collect();
        let normal = |j: usize| Vector3::x().cross(&(v[j + 1] - v[j])).normalize();
        let last = v.len() - 1;
        let moved: Vec<Vector3<f64>> = (0..v.len())
            .map(|j| {
                let (n1, n2) = (normal(j.max(1) - 1), normal(j.min(last - 1)));
                v[j] + (n1 + n2) * (g / (1.0 + n1.dot(&n2)))
            })
            .collect();
        let u: Vec<f64> = (0..v.len()).map(|j| j as f64).collect();
        grid(x, &u, |x, u| {
            let p = moved[u as usize];
            [x, p[1], p[2]]
        })
    }

    #[test]
    fn a_constant_gap_gives_a_mismatch_along_the_nodal_normal() {
        // A: a prism along x over an irregular polygon (facets of 5 to 20 degrees), graded
        // along x; B: the polygon extended by one facet at each end, offset by 0.1 (its facets
        // parallel to A's at a constant gap), longer, facing A. Neighbouring faces of unequal
        // areas: the unweighted mean of the face normals is off the direction of R.
        let phi = [
            30.0, 38.0, 50.0, 55.0, 70.0, 90.0, 100.0, 120.0, 135.0, 150.0,
        ];
        let xs = [0.0, 0.1, 0.3, 0.6, 1.0];
        let (xa, fa) = offset_prism(&phi, 0.0, &xs);
        let wider: Vec<f64> = [10.0].iter().chain(&phi).chain(&[170.0]).copied().collect();
        let (xb, mut fb) = offset_prism(&wider, 0.1, &[-0.5, 0.5, 1.5]);
        for f in &mut fb {
            f.reverse();
        }
        let sa = SurfaceFaces { x: &xa, faces: &fa };
        let sb = SurfaceFaces { x: &xb, faces: &fb };
        let frames = SurfaceFrames::new(sa, None, &[]).unwrap();
        let mortar = SurfaceMortar::new(sa, sb, 0.2).unwrap();
        let mut unweighted_off: f64 = 0.0;
        for (k, f) in &frames.frames {
            let r = v3(mortar.mismatch[k]);
            let n = v3(f.normal);
            assert!(
                (r + n * r.norm()).norm() <= 1e-12 * r.norm(),
                "node {k}: R = {r:?}, n = {n:?}"
            );
            // |R| = 0.1 |integral N_k n dA|, between cos(10 deg) and 1 times 0.1 w_k
            let ratio = r.norm() / (0.1 * mortar.weight[k]);
            assert!(ratio > 0.98 && ratio <= 1.0 + 1e-12, "node {k}: {ratio}");
            let mean: Vector3<f64> = fa
                .iter()
                .filter(|q| q.contains(k))
                .map(|q| {
                    let c = q.map(|i| v3(xa[i]));
                    (c[1] - c[0]).cross(&(c[3] - c[0])).normalize()
                })
                .sum();
            unweighted_off = unweighted_off.max(sine(&mean.normalize(), &n));
        }
        assert!(unweighted_off > 1e-2, "{unweighted_off}");
    }

    #[test]
    fn a_reference_parallel_to_a_normal_is_an_error_naming_the_node() {
        let (x, faces) = grid(&[0.0, 1.0, 2.0], &[0.0, 1.0], |u, v| [u, v, 0.0]);
        let s = SurfaceFaces {
            x: &x,
            faces: &faces,
        };
        let out = SurfaceFrames::new(s, None, &[]).unwrap();
        assert_eq!(out.reference, [1.0, 0.0, 0.0]);
        let f = out.frames[&4];
        assert_eq!(
            (f.normal, f.tangents),
            ([0.0, 0.0, 1.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
        );
        let err = SurfaceFrames::new(s, Some([0.0, 0.005, -1.0]), &[]).unwrap_err();
        assert!(err.to_string().contains("A node 0:"), "{err}");
        assert!(SurfaceFrames::new(s, Some([0.0, 0.02, -1.0]), &[]).is_ok());
        assert!(SurfaceFrames::new(s, Some([0.0, 0.0, 0.0]), &[]).is_err());
        assert!(SurfaceFrames::new(s, Some([f64::NAN, 0.0, 1.0]), &[]).is_err());
    }

    /// A quarter cylinder along `z` (`x, y >= 0`, 9 facets of 10 degrees, 3 faces in `z`), its
    /// nodes at `phi = 0` on `y = 0` and at `phi = 90` on `x = 0`, the bottom row on `z = 0`.
    fn quarter_cylinder() -> (Vec<[f64; 3]>, Vec<[usize; 4]>) {
        grid(&lin(0.0, 90.0, 9), &[0.0, 0.3, 0.7, 1.0], |p, z| {
            let (s, c) = p.to_radians().sin_cos();
            [2.0 * c, 2.0 * s, z]
        })
    }

    fn planes() -> Vec<SymmetryPlane> {
        vec![
            SymmetryPlane::new([0.0; 3], [1.0, 0.0, 0.0]).unwrap(),
            SymmetryPlane::new([0.0; 3], [0.0, -3.0, 0.0]).unwrap(),
        ]
    }

    #[test]
    fn nodes_on_symmetry_planes_drop_the_component_normal_to_the_plane() {
        let (x, faces) = quarter_cylinder();
        let s = SurfaceFaces {
            x: &x,
            faces: &faces,
        };
        let free = SurfaceFrames::new(s, None, &[]).unwrap();
        let out = SurfaceFrames::new(s, None, &planes()).unwrap();
        assert_eq!(out.reference, [0.0, 0.0, 1.0]);
        for (&k, f) in &out.frames {
            check_orthonormal(f);
            let p = x[k];
            let radial = v3([p[0], p[1], 0.0]).normalize();
            let n = v3(f.normal);
            let [s1, s2] = f.tangents.map(v3);
            if p[1] == 0.0 || p[0].abs() < 1e-12 {
                // the full model's normal: radial, where the quarter's average tilts 5 degrees
                assert!((n - radial).norm() < 1e-14, "node {k}");
                assert!((v3(free.frames[&k].normal) - radial).norm() > 0.08);
                let m = if p[1] == 0.0 {
                    Vector3::y()
                } else {
                    Vector3::x()
                };
                // the tangent along m is dropped, the other (along z, as off the plane) kept
                assert_eq!(f.dropped, [false, true], "node {k}");
                assert!((s2.cross(&m)).norm() < 1e-14 && (s1 - Vector3::z()).norm() < 1e-14);
            } else {
                assert_eq!(f.dropped, [false, false]);
                assert_eq!(f, &free.frames[&k]);
                assert!((s1 - Vector3::z()).norm() < 1e-14);
            }
        }
    }

    #[test]
    fn a_node_on_two_planes_keeps_only_its_normal() {
        // the quarter cylinder with the plane z = 0 as well: the corners (phi = 0, z = 0) and
        // (phi = 90, z = 0) lie on two planes, the rest of the bottom row on one
        let (x, faces) = quarter_cylinder();
        let s = SurfaceFaces {
            x: &x,
            faces: &faces,
        };
        let mut three = planes();
        three.push(SymmetryPlane::new([5.0, 5.0, 0.0], [0.0, 0.0, 1.0]).unwrap());
        let out = SurfaceFrames::new(s, Some([0.0, 0.0, 1.0]), &three).unwrap();
        for (&k, f) in &out.frames {
            check_orthonormal(f);
            let p = x[k];
            let on = [p[0].abs() < 1e-12, p[1] == 0.0, p[2] == 0.0];
            let count = on.iter().filter(|&&b| b).count();
            let dropped = f.dropped.iter().filter(|&&b| b).count();
            assert_eq!(dropped, count, "node {k} at {p:?}");
            if count == 2 {
                let radial = v3([p[0], p[1], 0.0]).normalize();
                assert!((v3(f.normal) - radial).norm() < 1e-14, "node {k}");
            }
        }
        // x is parallel to the normal at phi = 0 above the bottom row (on y = 0 only)
        let err = SurfaceFrames::new(s, Some([1.0, 0.0, 0.0]), &three).unwrap_err();
        assert!(err.to_string().contains("A node "), "{err}");
    }

    #[test]
    fn faces_lying_in_a_symmetry_plane_and_bad_planes_are_errors() {
        let (x, faces) = grid(&[0.0, 1.0], &[0.0, 1.0], |u, v| [u, v, 0.0]);
        let s = SurfaceFaces {
            x: &x,
            faces: &faces,
        };
        let plane = SymmetryPlane::new([0.0; 3], [0.0, 0.0, 2.0]).unwrap();
        let err = SurfaceFrames::new(s, None, &[plane]).unwrap_err();
        assert!(err.to_string().contains("A node 0:"), "{err}");
        let zero = SymmetryPlane {
            point: [0.0; 3],
            normal: [0.0; 3],
        };
        let err = SurfaceFrames::new(s, None, &[zero]).unwrap_err();
        assert!(err.to_string().contains("symmetry plane"), "{err}");
        assert!(SymmetryPlane::new([0.0; 3], [0.0; 3]).is_err());
        assert!(SymmetryPlane::new([f64::INFINITY, 0.0, 0.0], [1.0, 0.0, 0.0]).is_err());
        let bad = [[0, 1, 2, 7]];
        let s = SurfaceFaces { x: &x, faces: &bad };
        assert!(SurfaceFrames::new(s, None, &[]).is_err());
    }

    #[test]
    fn frames_rotate_with_the_model() {
        let (x, faces) = quarter_cylinder();
        let rot = Rotation3::from_euler_angles(0.3, -1.1, 2.0);
        let turn = |p: [f64; 3]| arr(rot * v3(p));
        let xr: Vec<[f64; 3]> = x.iter().map(|&p| turn(p)).collect();
        let r = [0.2, 0.1, 1.0];
        let base = SurfaceFrames::new(
            SurfaceFaces {
                x: &x,
                faces: &faces,
            },
            Some(r),
            &planes(),
        )
        .unwrap();
        let turned_planes: Vec<SymmetryPlane> = planes()
            .iter()
            .map(|p| SymmetryPlane::new(turn(p.point), turn(p.normal)).unwrap())
            .collect();
        let turned = SurfaceFrames::new(
            SurfaceFaces {
                x: &xr,
                faces: &faces,
            },
            Some(turn(r)),
            &turned_planes,
        )
        .unwrap();
        for (k, f) in &base.frames {
            let g = turned.frames[k];
            assert_eq!(f.dropped, g.dropped);
            for (u, v) in [
                (f.normal, g.normal),
                (f.tangents[0], g.tangents[0]),
                (f.tangents[1], g.tangents[1]),
            ] {
                assert!((rot * v3(u) - v3(v)).norm() < 1e-13, "node {k}");
            }
        }
    }
}
