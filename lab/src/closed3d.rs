//! The closed forms of the 3D contact validation, in one place (their sources in
//! docs/validation.md, "3D contact: closed forms"):
//!
//! * Hertz's sphere (or paraboloid `z = r^2 / (2 R)`) on a half-space: [`HertzSphere`] (contact
//!   radius `a^3 = 3 P R / (4 E*)`, peak `p0 = 3 P / (2 pi a^2)`,
//!   `p(r) = p0 sqrt(1 - r^2 / a^2)`; shared with the axisymmetric scenes), its approach
//!   `delta = a^2 / R` ([`hertz_approach`]) and the load of a contact radius ([`hertz_load`]).
//! * Cattaneo-Mindlin's partial slip of a sphere under a tangential load `Q < mu P` applied
//!   after `P`, elastically identical bodies: [`Mindlin`] (stick radius
//!   `c/a = (1 - Q/(mu P))^(1/3)`, the tangential traction, the tangential compliance).

pub use crate::axisymmetric::HertzSphere;
use hycon::{Error, Result};

/// Hertz's approach of the remote points of the two bodies, `delta = a^2 / R`.
pub fn hertz_approach(a: f64, r: f64) -> f64 {
    a * a / r
}

/// The load that gives contact radius `a`: `P = 4 E* a^3 / (3 R)`.
pub fn hertz_load(a: f64, r: f64, e_star: f64) -> f64 {
    4.0 * e_star * a.powi(3) / (3.0 * r)
}

/// Cattaneo-Mindlin: a Hertz contact (`P`, `a`, `p0`) then a tangential load `Q < mu P` along a
/// fixed direction, elastically identical bodies (normal and tangential tractions uncoupled).
/// A central disk of radius `c` sticks, the annulus `c < r < a` slips:
///
/// ```text
/// c / a = (1 - Q / (mu P))^(1/3)
/// q(r)  = mu p0 sqrt(1 - r^2/a^2) - (c/a) mu p0 sqrt(1 - r^2/c^2)    r < c
/// q(r)  = mu p0 sqrt(1 - r^2/a^2)                                    c <= r <= a
/// delta_t = 3 mu P / (16 a) ((2 - nu1)/G1 + (2 - nu2)/G2) (1 - (1 - Q/(mu P))^(2/3))
/// ```
///
/// `delta_t` the tangential displacement of one body's remote points relative to the other's;
/// its slope at `Q = 0` is Mindlin's full-stick compliance `1 / (8 G* a)`,
/// `1/G* = (2 - nu1)/G1 + (2 - nu2)/G2`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mindlin {
    /// The normal contact.
    pub hertz: HertzSphere,
    /// Normal load `P`.
    pub load: f64,
    /// Friction coefficient `mu`.
    pub friction: f64,
    /// Tangential load `Q`.
    pub tangential: f64,
    /// Stick radius `c`.
    pub stick: f64,
}

impl Mindlin {
    /// The closed form for normal load `p`, sphere radius `r`, effective modulus `e_star`,
    /// friction `mu` and tangential load `q`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] unless `p, r, e_star, mu > 0` and `0 <= q < mu p`.
    pub fn new(p: f64, r: f64, e_star: f64, mu: f64, q: f64) -> Result<Self> {
        let positive = [p, r, e_star, mu].iter().all(|v| v.is_finite() && *v > 0.0);
        if !(positive && q >= 0.0 && q < mu * p) {
            return Err(Error::InvalidInput(format!(
                "Mindlin: P, R, E*, mu positive and 0 <= Q < mu P, got P = {p}, R = {r}, E* = \
                 {e_star}, mu = {mu}, Q = {q}"
            )));
        }
        let hertz = HertzSphere::new(p, r, e_star);
        Ok(Mindlin {
            hertz,
            load: p,
            friction: mu,
            tangential: q,
            stick: hertz.radius * (1.0 - q / (mu * p)).cbrt(),
        })
    }

    /// The tangential traction `q(r)` (along `Q`; 0 outside the contact).
    pub fn traction(&self, r: f64) -> f64 {
        let slip = self.friction * self.hertz.pressure(r);
        let (a, c) = (self.hertz.radius, self.stick);
        if r < c {
            slip - (c / a) * self.friction * self.hertz.peak * (1.0 - (r / c).powi(2)).sqrt()
        } else {
            slip
        }
    }

    /// The tangential displacement `delta_t` of the bodies' remote points, with shear moduli
    /// `g` and Poisson's ratios `nu` of the two bodies.
    pub fn compliance_displacement(&self, g: [f64; 2], nu: [f64; 2]) -> f64 {
        let soft = (2.0 - nu[0]) / g[0] + (2.0 - nu[1]) / g[1];
        let x = self.tangential / (self.friction * self.load);
        3.0 * self.friction * self.load / (16.0 * self.hertz.radius)
            * soft
            * (1.0 - (1.0 - x).powf(2.0 / 3.0))
    }
}
