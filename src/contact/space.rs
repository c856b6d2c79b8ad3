//! Vectors and nodal frames of the contact core, for any dimension.
//!
//! The contact core (the active set, the iteration, the boundary algebra, the results) handles
//! positions, gaps, forces and frames through these types only, so that the plane and
//! axisymmetric geometry (2 components) and a 3D face geometry (3 components) plug in behind
//! the same code. Positions of all nodes are a flat slice with `dim` values per node (node `i`
//! at `x[dim * i..dim * i + dim]`, see [`node`]).
//!
//! Every operation reproduces, with 2 components, the floating-point operations of the
//! two-array code it replaced (same order; `hypot` for lengths), so plane results are
//! unchanged bit for bit.

use super::tangent::Tangential;
use std::ops::{Index, IndexMut};

/// The most components a vector has (3D).
pub const MAX_DIM: usize = 3;

/// A vector of the plane (2 components: `x, y`, or `r, z` in axisymmetry) or of space (3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vector {
    len: u8,
    c: [f64; MAX_DIM],
}

impl Vector {
    /// Zero with `dim` components (2 or 3).
    ///
    /// # Panics
    /// When `dim` is not 2 or 3 (a programming error: the geometry fixes it).
    pub fn zero(dim: usize) -> Self {
        assert!((2..=MAX_DIM).contains(&dim), "dimension {dim}");
        Vector {
            len: dim as u8,
            c: [0.0; MAX_DIM],
        }
    }

    /// A vector of the plane.
    pub const fn plane(x: f64, y: f64) -> Self {
        Vector {
            len: 2,
            c: [x, y, 0.0],
        }
    }

    /// A vector of space.
    pub const fn solid(x: f64, y: f64, z: f64) -> Self {
        Vector {
            len: 3,
            c: [x, y, z],
        }
    }

    /// The vector with components `c` (2 or 3 of them).
    ///
    /// # Panics
    /// When `c` has not 2 or 3 components.
    pub fn from_components(c: &[f64]) -> Self {
        let mut v = Self::zero(c.len());
        v.components_mut().copy_from_slice(c);
        v
    }

    /// The number of components (2 or 3).
    pub fn dim(&self) -> usize {
        usize::from(self.len)
    }

    /// The components.
    pub fn components(&self) -> &[f64] {
        &self.c[..usize::from(self.len)]
    }

    /// The components, mutably.
    pub fn components_mut(&mut self) -> &mut [f64] {
        &mut self.c[..usize::from(self.len)]
    }

    /// `u . v` (`u_0 v_0 + u_1 v_1 [+ u_2 v_2]`, left to right).
    pub fn dot(&self, v: &Vector) -> f64 {
        match (self.components(), v.components()) {
            ([a0, a1], [b0, b1]) => a0 * b0 + a1 * b1,
            (a, b) => a.iter().zip(b).map(|(a, b)| a * b).sum(),
        }
    }

    /// `|v|` by `hypot` (`v_0.hypot(v_1)[.hypot(v_2)]`).
    pub fn norm(&self) -> f64 {
        let c = self.components();
        c[1..].iter().fold(c[0], |h, &x| h.hypot(x))
    }

    /// `a v`, component by component.
    pub fn scaled(self, a: f64) -> Self {
        self.map(|x| a * x)
    }

    /// `u + a v`, component by component (`u_i + a * v_i`).
    pub fn add_scaled(self, a: f64, v: &Vector) -> Self {
        let mut out = self;
        for (o, w) in out.components_mut().iter_mut().zip(v.components()) {
            *o += a * w;
        }
        out
    }

    /// `f` applied to every component.
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        let mut v = self;
        for c in v.components_mut() {
            *c = f(*c);
        }
        v
    }
}

/// The vector of components `c`.
///
/// # Panics
/// When `N` is not 2 or 3.
impl<const N: usize> From<[f64; N]> for Vector {
    fn from(c: [f64; N]) -> Self {
        Vector::from_components(&c)
    }
}

impl Index<usize> for Vector {
    type Output = f64;
    fn index(&self, i: usize) -> &f64 {
        &self.components()[i]
    }
}

impl IndexMut<usize> for Vector {
    fn index_mut(&mut self, i: usize) -> &mut f64 {
        &mut self.components_mut()[i]
    }
}

impl std::ops::Add for Vector {
    type Output = Vector;
    /// `u + v`, component by component.
    fn add(self, v: Vector) -> Vector {
        let mut out = self;
        for (o, w) in out.components_mut().iter_mut().zip(v.components()) {
            *o += w;
        }
        out
    }
}

impl std::ops::Sub for Vector {
    type Output = Vector;
    /// `u - v`, component by component.
    fn sub(self, v: Vector) -> Vector {
        let mut out = self;
        for (o, w) in out.components_mut().iter_mut().zip(v.components()) {
            *o -= w;
        }
        out
    }
}

/// Node `i`'s position in the flat positions `x` with `dim` values per node.
pub fn node(x: &[f64], dim: usize, i: usize) -> Vector {
    Vector::from_components(&x[dim * i..dim * i + dim])
}

/// A contact node's frame: its unit normal `n` and `dim - 1` unit tangents (in the plane and
/// in axisymmetry the one tangent `s = (n_y, -n_x)`; on a 3D face two, orthonormal with `n`,
/// or zero where a symmetry plane drops that component: [`Frame::is_dropped`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    normal: Vector,
    tangents: [Vector; 2],
}

impl Frame {
    /// The plane frame of the unit normal `n` (2 components): `s = (n_y, -n_x)`.
    pub fn plane(n: Vector) -> Self {
        Frame {
            normal: n,
            tangents: [Vector::plane(n[1], -n[0]), Vector::zero(2)],
        }
    }

    /// A zero frame of dimension `dim` (zero normal and tangents): a node not evaluated yet.
    pub fn zero(dim: usize) -> Self {
        Frame {
            normal: Vector::zero(dim),
            tangents: [Vector::zero(dim); 2],
        }
    }

    /// The frame of a 3D face node: unit normal `n`, unit tangents `s1`, `s2` (the caller
    /// makes them orthonormal), or a zero tangent for a component dropped by symmetry
    /// ([`is_dropped`](Self::is_dropped)).
    pub fn face(n: [f64; 3], s1: [f64; 3], s2: [f64; 3]) -> Self {
        Frame {
            normal: n.into(),
            tangents: [s1.into(), s2.into()],
        }
    }

    /// The dimension (2 or 3).
    pub fn dim(&self) -> usize {
        self.normal.dim()
    }

    /// `n`.
    pub fn normal(&self) -> Vector {
        self.normal
    }

    /// The tangents `s_1 .. s_{dim-1}`.
    pub fn tangents(&self) -> &[Vector] {
        &self.tangents[..self.dim() - 1]
    }

    /// The tangent `s_i` (`i < dim - 1`).
    pub fn tangent(&self, i: usize) -> Vector {
        self.tangents()[i]
    }

    /// Whether tangent `s_i` is dropped: zero, the tangential component of a node on a
    /// symmetry plane that vanishes by symmetry (its multiplier is zero and it gets no stick
    /// row; [`tangential`](Self::tangential) gives 0 for it and [`vector`](Self::vector) adds
    /// nothing along it).
    pub fn is_dropped(&self, i: usize) -> bool {
        self.tangent(i) == Vector::zero(self.dim())
    }

    /// The tangential components `s_i . v` of `v`.
    pub fn tangential(&self, v: &Vector) -> Tangential {
        match self.tangents() {
            [s] => Tangential::along(s.dot(v)),
            [s1, s2] => Tangential::on_face(s1.dot(v), s2.dot(v)),
            _ => unreachable!("a frame has 1 or 2 tangents"),
        }
    }

    /// The vector `tn n + sum_i ts_i s_i` (component by component, in that order).
    pub fn vector(&self, tn: f64, ts: Tangential) -> Vector {
        let mut v = Vector::zero(self.dim());
        for (c, out) in v.components_mut().iter_mut().enumerate() {
            *out = self
                .tangents()
                .iter()
                .zip(ts.components())
                .fold(tn * self.normal[c], |acc, (s, t)| acc + t * s[c]);
        }
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With two components every operation is the two-array expression it replaced, bit for
    /// bit (values chosen so that a different order or a plain square root would round
    /// differently somewhere).
    #[test]
    fn plane_operations_are_the_two_component_expressions() {
        let (u, v) = ([0.1, 0.7], [1e-3 / 3.0, 2.0 / 7.0]);
        let (a, b) = (Vector::from(u), Vector::from(v));
        assert_eq!(a.dot(&b), u[0] * v[0] + u[1] * v[1]);
        assert_eq!(a.norm(), u[0].hypot(u[1]));
        assert_eq!((a - b).components(), &[u[0] - v[0], u[1] - v[1]]);
        assert_eq!((a + b).components(), &[u[0] + v[0], u[1] + v[1]]);
        assert_eq!(
            a.add_scaled(0.3, &b).components(),
            &[u[0] + 0.3 * v[0], u[1] + 0.3 * v[1]]
        );
        let n = [0.6, 0.8];
        let f = Frame::plane(n.into());
        assert_eq!(f.tangents(), &[Vector::plane(0.8, -0.6)]);
        assert_eq!(
            f.tangential(&a),
            Tangential::along(u[0] * n[1] + u[1] * -n[0])
        );
        let (tn, ts) = (-1.3, 0.45);
        assert_eq!(
            f.vector(tn, Tangential::along(ts)).components(),
            &[tn * n[0] + ts * n[1], tn * n[1] + ts * -n[0]]
        );
        assert_eq!(a[1], 0.7);
        assert_eq!(node(&[1.0, 2.0, 3.0, 4.0], 2, 1), Vector::plane(3.0, 4.0));
    }

    /// In space: the norm of a 3-4-12 vector is 13, a face frame splits a vector into its
    /// normal and tangential parts and puts it back together.
    #[test]
    fn space_vectors_and_face_frames() {
        let v = Vector::solid(3.0, 4.0, 12.0);
        assert_eq!(v.norm(), 13.0);
        assert_eq!(v.dot(&Vector::solid(1.0, 1.0, 1.0)), 19.0);
        assert_eq!(node(&[0.0, 0.0, 0.0, 3.0, 4.0, 12.0], 3, 1), v);
        let f = Frame::face([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let ts = f.tangential(&v);
        assert_eq!(ts, Tangential::on_face(3.0, 4.0));
        assert_eq!(f.vector(f.normal().dot(&v), ts), v);
        assert_eq!(f.tangents().len(), 2);
    }
}
