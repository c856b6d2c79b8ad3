//! Friction laws: what the contact iteration asks of the friction between the surfaces of a
//! contact pair (METHOD.md section 4).
//!
//! The iteration ([`super::iteration`]) reads a pair's friction only through [`FrictionLaw`]:
//! whether there is any (no tangential rows at all when not), the largest tangential traction
//! a sticking node carries (the stick -> slip rule), and the tangential traction of a slipping
//! node as a multiple of its normal one (the slip node's column `n_k + c s_k` in the small
//! system, and its `ts = c tn`). A new law is a new type implementing the trait, chosen in
//! [`ContactPair::friction_law`](super::iteration::ContactPair::friction_law).
//!
//! Sign convention: `tn < 0` is compression; `sign` is the direction of A's slip relative to
//! B along the nodal tangent `s_k` (`+1` or `-1`), and the friction traction on A opposes it.

use crate::error::{Error, Result};

/// A friction law between the surfaces of one contact pair.
pub trait FrictionLaw: std::fmt::Debug + Send + Sync {
    /// No tangential traction at all: slipping nodes carry `ts = 0` and no tangential rows are
    /// assembled (a closing node enters in slip).
    fn is_frictionless(&self) -> bool;

    /// The largest `|ts|` a sticking node carries under the normal traction `tn` (`<= 0`):
    /// beyond it the node slips.
    fn stick_limit(&self, tn: f64) -> f64;

    /// `c` with `ts = c tn` on a node slipping in direction `sign` (`c` is then opposite in
    /// sign to the slip, since `tn < 0`).
    fn slip_coefficient(&self, sign: i8) -> f64;
}

/// Coulomb friction: `|ts| <= mu |tn|` while sticking, `ts = mu sign tn` while slipping.
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

    fn slip_coefficient(&self, sign: i8) -> f64 {
        self.mu * f64::from(sign)
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
        assert!(law.slip_coefficient(1) * -2.0 < 0.0);
        assert!(Coulomb::new(0.0).unwrap().is_frictionless());
        for bad in [-0.1, f64::NAN, f64::INFINITY] {
            assert!(Coulomb::new(bad).is_err(), "{bad}");
        }
    }
}
