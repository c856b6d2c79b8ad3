//! Friction laws: what the contact iteration asks of the friction between the surfaces of a
//! contact pair (docs/method.md, "The rules").
//!
//! The iteration ([`super::iteration`]) reads a pair's friction only through [`FrictionLaw`]:
//! whether there is any (no tangential rows at all when not), the largest tangential traction
//! a sticking node carries (the stick -> slip rule, its cone), and the tangential traction of
//! a node slipping in a direction of the tangent space as a multiple of its normal one (the
//! slip node's column `n_k + sum_i c_i s_i` in the small system, and its `ts = c tn`), and,
//! from these, the closest point of the cone ([`FrictionLaw::project`]) and whether a trial
//! traction slips ([`FrictionLaw::trial_slip`]), which the fallback's solver reads. A new
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

    /// The closest point to `ts` of the cone's section under the normal traction `tn`, the
    /// set `|ts| <= stick_limit(tn)`: in the plane the clamp of `ts` to `[-l, l]`, on a face
    /// (two tangents) the radial projection onto the disc of radius `l`. The fallback's
    /// projected sweeps take a node's tangential traction there.
    fn project(&self, tn: f64, ts: Tangential) -> Tangential {
        let limit = self.stick_limit(tn);
        match ts.components() {
            [s] => Tangential::along(s.clamp(-limit, limit)),
            _ => {
                let norm = ts.norm();
                if norm > limit {
                    ts.scaled(limit / norm)
                } else {
                    ts
                }
            }
        }
    }

    /// Whether a trial tangential traction `ts` under the trial normal traction `tn` slips:
    /// `None` strictly inside the cone (`|ts| < stick_limit(tn)`: the node sticks), otherwise
    /// the slip direction it opposes, `-ts / |ts|` (the fallback's semi-smooth Newton step
    /// then takes `ts = c tn`, `c` the [`slip_coefficients`](Self::slip_coefficients) of that
    /// direction).
    fn trial_slip(&self, tn: f64, ts: Tangential) -> Option<SlipDirection> {
        if ts.norm() < self.stick_limit(tn) {
            None
        } else {
            Some(SlipDirection::opposing(ts))
        }
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

    /// The cone's closest point: in the plane a clamp (exactly), on a face the radial
    /// projection onto the disc `|ts| <= mu |tn|`, a point inside kept as it is; a trial
    /// traction slips on or outside the cone, opposite to its direction.
    #[test]
    fn the_cone_projects_and_judges_trial_tractions() {
        let law = Coulomb::new(0.5).unwrap();
        assert_eq!(
            law.project(-2.0, Tangential::along(1.5)),
            Tangential::along(1.0)
        );
        assert_eq!(
            law.project(-2.0, Tangential::along(-1.5)),
            Tangential::along(-1.0)
        );
        assert_eq!(
            law.project(-2.0, Tangential::along(0.3)),
            Tangential::along(0.3)
        );
        let outside = law.project(-2.0, Tangential::on_face(3.0, -4.0));
        let [a, b] = outside.components() else {
            panic!("two components")
        };
        assert!(
            (a - 0.6).abs() < 1e-15 && (b + 0.8).abs() < 1e-15,
            "{outside:?}"
        );
        let inside = Tangential::on_face(0.6, 0.7);
        assert_eq!(law.project(-2.0, inside), inside);
        assert_eq!(law.project(0.0, inside), Tangential::on_face(0.0, 0.0));
        // trial tractions
        assert_eq!(law.trial_slip(-2.0, inside), None);
        assert_eq!(law.trial_slip(-2.0, Tangential::along(0.99)), None);
        assert_eq!(
            law.trial_slip(-2.0, Tangential::along(1.0)),
            Some(SlipDirection::MINUS)
        );
        let slip = law
            .trial_slip(-2.0, Tangential::on_face(3.0, -4.0))
            .unwrap();
        assert!(slip.same_as(&SlipDirection::of(Tangential::on_face(-3.0, 4.0)).unwrap()));
        // its slip traction is the projection of the trial traction
        let ts = law.slip_traction(slip, -2.0);
        assert!((ts.components()[0] - 0.6).abs() < 1e-15);
        assert!((ts.components()[1] + 0.8).abs() < 1e-15);
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
