//! Friction laws: what the contact iteration asks of the friction between the surfaces of a
//! contact pair (docs/method.md, "The rules").
//!
//! The iteration ([`super::iteration`]) reads a pair's friction only through [`FrictionLaw`]:
//! whether there is any (no tangential rows at all when not), the largest tangential traction
//! a sticking node carries (the stick -> slip rule, its cone), and the tangential traction of
//! a node slipping in a direction of the tangent space as a multiple of its normal one (the
//! slip node's column `n_k + sum_i c_i s_i` in the small system, and its `ts = c tn`). A new
//! law is a new type implementing the trait, chosen in
//! [`ContactPair::friction_law`](super::iteration::ContactPair::friction_law).
//!
//! Sign convention: `tn < 0` is compression; a [`SlipDirection`] is the direction of A's slip
//! relative to B in the node's tangent space (in the plane `+s_k` or `-s_k`), and the friction
//! traction on A opposes it.

use super::tangent::{SlipDirection, Tangential};
use crate::error::{Error, Result};

/// A friction law between the surfaces of one contact pair.
pub trait FrictionLaw: std::fmt::Debug + Send + Sync {
    /// No tangential traction at all: slipping nodes carry `ts = 0` and no tangential rows are
    /// assembled (a closing node enters in slip).
    fn is_frictionless(&self) -> bool;

    /// The largest `|ts|` a sticking node carries under the normal traction `tn` (`<= 0`):
    /// beyond it the node slips.
    fn stick_limit(&self, tn: f64) -> f64;

    /// `c` with `ts = c tn` on a node slipping in `direction` (`c` then points against the
    /// slip, since `tn < 0`): the slip column of the small system is `n + sum_i c_i s_i`.
    fn slip_coefficients(&self, direction: SlipDirection) -> Tangential;

    /// The tangential traction `ts = c tn` on a node slipping in `direction` under the normal
    /// traction `tn` (`c` of [`slip_coefficients`](Self::slip_coefficients)).
    fn slip_traction(&self, direction: SlipDirection, tn: f64) -> Tangential {
        self.slip_coefficients(direction).scaled(tn)
    }
}

/// Coulomb friction: `|ts| <= mu |tn|` while sticking, `ts = mu tn d` while slipping in the
/// direction `d` (a unit vector of the tangent space; in the plane `d = +-1`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coulomb {
    mu: f64,
}

impl Coulomb {
    /// No friction (`mu = 0`): the law of an A node on the axis in axisymmetry, where the
    /// shear traction vanishes by symmetry.
    pub(crate) const NONE: Coulomb = Coulomb { mu: 0.0 };

    /// Coulomb friction with coefficient `mu` (0: frictionless).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] unless `mu` is finite and `>= 0`.
    pub fn new(mu: f64) -> Result<Self> {
        if mu.is_finite() && mu >= 0.0 {
            Ok(Coulomb { mu })
        } else {
            Err(Error::InvalidInput(format!(
                "friction = {mu} must be finite and >= 0"
            )))
        }
    }

    /// The friction coefficient `mu`.
    pub fn mu(&self) -> f64 {
        self.mu
    }
}

impl FrictionLaw for Coulomb {
    fn is_frictionless(&self) -> bool {
        self.mu == 0.0
    }

    fn stick_limit(&self, tn: f64) -> f64 {
        self.mu * tn.abs()
    }

    fn slip_coefficients(&self, direction: SlipDirection) -> Tangential {
        direction.vector().scaled(self.mu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coulomb() {
        let law = Coulomb::new(0.3).unwrap();
        assert!(!law.is_frictionless());
        assert_eq!(law.stick_limit(-2.0), 0.6);
        // slipping in +s under compression: the traction on A points along -s
        let ts = law.slip_traction(SlipDirection::PLUS, -2.0);
        assert_eq!(ts, Tangential::along(-0.6));
        assert!(Coulomb::new(0.0).unwrap().is_frictionless());
        for bad in [-0.1, f64::NAN, f64::INFINITY] {
            assert!(Coulomb::new(bad).is_err(), "{bad}");
        }
    }

    /// A slip on a face (two tangents) through the law: the traction opposes the slip, lies on
    /// the cone `|ts| = mu |tn|`, and its direction is the slip's as the cycle check sees it.
    #[test]
    fn coulomb_on_a_face_opposes_the_slip_on_the_cone() {
        let law = Coulomb::new(0.4).unwrap();
        let slip = SlipDirection::of(Tangential::on_face(-1.0, 2.0)).unwrap();
        let tn = -3.0;
        let ts = law.slip_traction(slip, tn);
        assert!((ts.norm() - law.stick_limit(tn)).abs() <= 1e-15 * law.stick_limit(tn));
        assert!(slip.along(&ts) < 0.0, "the traction opposes the slip");
        assert!(SlipDirection::opposing(ts).same_as(&slip));
        let c = law.slip_coefficients(slip);
        assert_eq!(c.scaled(tn), ts);
    }
}
