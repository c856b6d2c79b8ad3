//! The tangent space of a contact node, as the contact core sees it, for any dimension.
//!
//! A node of a contact surface carries a frame: its normal `n` and `D - 1` tangents
//! `s_1 .. s_{D-1}` (one in the plane and in axisymmetry, where `s = (n_y, -n_x)`; two on a 3D
//! face). A traction on A at the node is `t = tn n + sum_i ts_i s_i` ([`Traction`], `tn < 0`
//! compression), a slip is a unit vector of the tangent space ([`SlipDirection`]: in the plane
//! `+s` or `-s`, the sign of earlier versions). The friction law
//! ([`FrictionLaw`](super::friction::FrictionLaw)), the rules and the active set's cycle check
//! handle these types only, so that a surface with two tangents plugs in without editing them.

/// The most tangential components a node has (`D - 1` for a 3D face).
pub(crate) const MAX_TANGENTS: usize = 2;

/// Two slip directions are the same (for the active set's cycle check) when the cosine of
/// their angle is at least `1 - SAME_DIRECTION`. In the plane a direction is `+s` or `-s` and
/// the cosine is exactly 1 or -1.
pub(crate) const SAME_DIRECTION: f64 = 1e-12;

/// Components of a vector of the tangent space along the node's tangents `s_1 .. s_{D-1}`
/// (one in the plane and in axisymmetry, two on a 3D face).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tangential {
    len: u8,
    c: [f64; MAX_TANGENTS],
}

impl Tangential {
    /// Zero with `len` components (1 or 2).
    ///
    /// # Panics
    /// When `len` is 0 or above `MAX_TANGENTS` (a programming error: the geometry fixes it).
    pub fn zero(len: usize) -> Self {
        assert!((1..=MAX_TANGENTS).contains(&len), "{len} tangents");
        Tangential {
            len: len as u8,
            c: [0.0; MAX_TANGENTS],
        }
    }

    /// The component along the one tangent `s` of a plane or axisymmetric node.
    pub const fn along(s: f64) -> Self {
        Tangential {
            len: 1,
            c: [s, 0.0],
        }
    }

    /// The components along the two tangents of a 3D face node.
    pub const fn on_face(s1: f64, s2: f64) -> Self {
        Tangential {
            len: 2,
            c: [s1, s2],
        }
    }

    /// The components, one per tangent.
    pub fn components(&self) -> &[f64] {
        &self.c[..usize::from(self.len)]
    }

    /// The components, mutably.
    pub fn components_mut(&mut self) -> &mut [f64] {
        &mut self.c[..usize::from(self.len)]
    }

    /// `a v`, component by component.
    pub fn scaled(self, a: f64) -> Self {
        let mut v = self;
        for c in v.components_mut() {
            *c *= a;
        }
        v
    }

    /// `v . w` (the tangents orthonormal).
    pub fn dot(&self, w: &Tangential) -> f64 {
        self.components()
            .iter()
            .zip(w.components())
            .map(|(a, b)| a * b)
            .sum()
    }

    /// `|v|` (exactly `|v_1|` with one component).
    pub fn norm(&self) -> f64 {
        match self.components() {
            [s] => s.abs(),
            c => c.iter().fold(0.0, |h: f64, &x| h.hypot(x)),
        }
    }
}

impl std::ops::Sub for Tangential {
    type Output = Tangential;
    /// `v - w`, component by component (the same number of components).
    fn sub(self, w: Tangential) -> Tangential {
        let mut out = self;
        for (o, x) in out.components_mut().iter_mut().zip(w.components()) {
            *o -= x;
        }
        out
    }
}

/// A traction on A at a contact node: `t = normal n + sum_i tangential_i s_i` (`normal < 0`
/// compression, pressure `p = -normal`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Traction {
    /// `tn`, the normal part.
    pub normal: f64,
    /// `ts`, the tangential part, along the node's tangents.
    pub tangential: Tangential,
}

impl Traction {
    /// No traction, with `tangents` tangential components (an open node's).
    pub fn zero(tangents: usize) -> Self {
        Traction {
            normal: 0.0,
            tangential: Tangential::zero(tangents),
        }
    }
}

/// The direction of A's slip relative to B at a node: a unit vector of the tangent space. In
/// the plane `+s` or `-s` ([`SlipDirection::PLUS`], [`SlipDirection::MINUS`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipDirection(Tangential);

impl SlipDirection {
    /// Along `+s` (plane and axisymmetry).
    pub const PLUS: SlipDirection = SlipDirection(Tangential::along(1.0));
    /// Along `-s` (plane and axisymmetry).
    pub const MINUS: SlipDirection = SlipDirection(Tangential::along(-1.0));

    /// The direction of a motion `v` (`v / |v|`), `None` for no motion. With one component it
    /// is exactly `+s` or `-s`.
    pub fn of(v: Tangential) -> Option<Self> {
        match v.components() {
            [s] if *s > 0.0 => Some(Self::PLUS),
            [s] if *s < 0.0 => Some(Self::MINUS),
            [_] => None,
            _ => {
                let norm = v.norm();
                (norm > 0.0 && norm.is_finite()).then(|| SlipDirection(v.scaled(1.0 / norm)))
            }
        }
    }

    /// The direction of a slip that the traction `ts` on A opposes (friction on A points
    /// against A's slip): `-ts / |ts|`. A zero traction opposes no direction; it is given
    /// `+s_1` (in the plane: `+s`, as for every traction that is not positive before 0.9).
    pub fn opposing(ts: Tangential) -> Self {
        Self::of(ts.scaled(-1.0)).unwrap_or_else(|| {
            let mut first = Tangential::zero(ts.components().len());
            first.components_mut()[0] = 1.0;
            SlipDirection(first)
        })
    }

    /// The unit vector.
    pub fn vector(&self) -> Tangential {
        self.0
    }

    /// The component of `v` along the direction (`d . v`).
    pub fn along(&self, v: &Tangential) -> f64 {
        self.0.dot(v)
    }

    /// Whether `other` is the same direction to `SAME_DIRECTION` (in the plane: equal).
    pub fn same_as(&self, other: &SlipDirection) -> bool {
        self.0.dot(&other.0) >= 1.0 - SAME_DIRECTION
    }

    /// In the plane, `+1` for `+s` and `-1` for `-s` (the C API's slip sign); `None` on a face
    /// with two tangents.
    pub fn sign(&self) -> Option<i8> {
        match self.0.components() {
            [s] => Some(if *s > 0.0 { 1 } else { -1 }),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// In the plane a direction is a sign: exactly `+s` or `-s`, opposing a traction as the
    /// sign rule did, comparing equal only to itself.
    #[test]
    fn plane_directions_are_signs() {
        assert_eq!(
            SlipDirection::of(Tangential::along(3e-300)),
            Some(SlipDirection::PLUS)
        );
        assert_eq!(
            SlipDirection::of(Tangential::along(-2.0)),
            Some(SlipDirection::MINUS)
        );
        assert_eq!(SlipDirection::of(Tangential::along(0.0)), None);
        assert_eq!(
            SlipDirection::opposing(Tangential::along(0.5)),
            SlipDirection::MINUS
        );
        assert_eq!(
            SlipDirection::opposing(Tangential::along(-0.5)),
            SlipDirection::PLUS
        );
        assert_eq!(
            SlipDirection::opposing(Tangential::along(0.0)),
            SlipDirection::PLUS
        );
        assert!(SlipDirection::PLUS.same_as(&SlipDirection::PLUS));
        assert!(!SlipDirection::PLUS.same_as(&SlipDirection::MINUS));
        assert_eq!(SlipDirection::MINUS.sign(), Some(-1));
        assert_eq!(SlipDirection::MINUS.along(&Tangential::along(2.0)), -2.0);
        assert_eq!(Tangential::along(-1e-200).norm(), 1e-200);
    }

    /// On a face a direction is a unit 2-vector; directions a round-off apart are the same,
    /// a turned one is not.
    #[test]
    fn face_directions_are_unit_vectors() {
        let d = SlipDirection::of(Tangential::on_face(3.0, 4.0)).unwrap();
        let v = d.vector();
        assert!((v.components()[0] - 0.6).abs() < 1e-15 && (v.components()[1] - 0.8).abs() < 1e-15);
        let nearly = SlipDirection::of(Tangential::on_face(3.0, 4.0 + 1e-14)).unwrap();
        assert!(d.same_as(&nearly));
        let turned = SlipDirection::of(Tangential::on_face(4.0, -3.0)).unwrap();
        assert!(!d.same_as(&turned));
        let opposed = SlipDirection::opposing(Tangential::on_face(-3.0, -4.0));
        assert!(opposed.same_as(&d));
        assert_eq!(d.sign(), None);
        assert_eq!(SlipDirection::of(Tangential::zero(2)), None);
        assert_eq!(Tangential::on_face(3.0, 4.0).norm(), 5.0);
    }
}
