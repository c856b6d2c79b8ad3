//! The two-dimensional analysis kinds and their measure, the one place where plane and
//! axisymmetric analysis differ in what an integral is weighted by.
//!
//! # Measure
//! Every volume and surface integral of a plane or axisymmetric body is weighted by the measure
//! `m(x)` ([`Measure::at`]): the thickness `t` in plane analyses, the circumference `2 pi r` in
//! axisymmetry (the full circle: a nodal force is the force summed over the whole circle, a
//! stiffness is that of the whole ring; the thickness must then be 1). See docs/method.md,
//! "Axisymmetric elements".

use super::isotropic::SCALE_RANGE;
use super::quadrature::GAUSS2_UNIT;
use crate::error::{Error, Result};

/// Which two-dimensional idealisation is used. One model uses one kind
/// ([`crate::model::Model::validate`] rejects a mix).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Analysis {
    /// `eps_z = 0`; `t` is the thickness the results are reported per (usually 1).
    PlaneStrain,
    /// `sigma_z = 0`.
    PlaneStress,
    /// A solid of revolution about the `y` axis: `x = r >= 0` (radial), `y = z` (axial), no
    /// torsion. Strains `(eps_r, eps_z, gamma_rz, eps_theta = u_r / r)`, stresses
    /// `(sigma_r, sigma_z, tau_rz, sigma_theta)`; integrals weighted by `2 pi r` (the full
    /// circle); the thickness must be 1.
    Axisymmetric,
}

impl Analysis {
    /// A short name for messages and tables.
    pub fn name(self) -> &'static str {
        match self {
            Analysis::PlaneStrain => "plane strain",
            Analysis::PlaneStress => "plane stress",
            Analysis::Axisymmetric => "axisymmetric",
        }
    }

    /// The measure of a body of this kind with thickness `thickness` (unchecked; an
    /// axisymmetric body ignores it, see [`Analysis::required_thickness`]).
    #[inline]
    pub fn measure(self, thickness: f64) -> Measure {
        match self {
            Analysis::PlaneStrain | Analysis::PlaneStress => Measure::Plane { thickness },
            Analysis::Axisymmetric => Measure::Axisymmetric,
        }
    }

    /// The thickness this kind requires: 1 in axisymmetry (the measure is `2 pi r`), none in
    /// plane analyses.
    pub fn required_thickness(self) -> Option<f64> {
        match self {
            Analysis::Axisymmetric => Some(1.0),
            Analysis::PlaneStrain | Analysis::PlaneStress => None,
        }
    }

    /// Number of stress components of an element of this kind: 3 in plane analyses
    /// (`sx, sy, txy`), 4 in axisymmetry (`sigma_r, sigma_z, tau_rz, sigma_theta`).
    pub fn stress_components(self) -> usize {
        match self {
            Analysis::Axisymmetric => 4,
            Analysis::PlaneStrain | Analysis::PlaneStress => 3,
        }
    }

    /// The first node of `coords` at a negative radius beyond round-off of the element size
    /// `size` (`x < -1e-10 size`) in axisymmetry, where `x = r >= 0`; `None` in plane analyses.
    pub fn node_off_half_plane(self, coords: &[[f64; 2]], size: f64) -> Option<usize> {
        match self {
            Analysis::Axisymmetric => coords.iter().position(|p| p[0] < -1e-10 * size),
            Analysis::PlaneStrain | Analysis::PlaneStress => None,
        }
    }
}

/// The measure `m(x)` that weights every integral of a plane or axisymmetric body (see the
/// [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Measure {
    /// Plane strain or plane stress: `m = t`.
    Plane {
        /// The thickness `t > 0`.
        thickness: f64,
    },
    /// Axisymmetric, the full circle: `m = 2 pi r`, `r = x[0] >= 0` at the point.
    Axisymmetric,
}

impl Measure {
    /// The measure of a surface or body of analysis kind `analysis` and thickness
    /// `thickness`: `t` in plane analysis, `2 pi r` in axisymmetry (where the thickness must be
    /// exactly 1, as for an axisymmetric [`crate::material::Material`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a plane thickness that is not finite, positive and within
    /// [`SCALE_RANGE`], or an axisymmetric one other than 1.
    pub fn new(analysis: Analysis, thickness: f64) -> Result<Self> {
        let m = match analysis {
            Analysis::PlaneStrain | Analysis::PlaneStress => Measure::Plane { thickness },
            Analysis::Axisymmetric if thickness == 1.0 => Measure::Axisymmetric,
            Analysis::Axisymmetric => {
                return Err(Error::InvalidInput(format!(
                    "axisymmetric thickness must be 1, got {thickness} (the measure is 2 pi r, \
                     the full circle)"
                )));
            }
        };
        m.validate()?;
        Ok(m)
    }

    /// Check a plane thickness: finite, positive, within [`SCALE_RANGE`].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] saying what is wrong.
    pub fn validate(&self) -> Result<()> {
        match *self {
            Measure::Plane { thickness: t } => {
                if t.is_finite() && (SCALE_RANGE[0]..=SCALE_RANGE[1]).contains(&t) {
                    Ok(())
                } else {
                    Err(Error::InvalidInput(format!(
                        "contact surface thickness must be finite and in [{:e}, {:e}], got {t}",
                        SCALE_RANGE[0], SCALE_RANGE[1]
                    )))
                }
            }
            Measure::Axisymmetric => Ok(()),
        }
    }

    /// `m(x)`: `t`, or `2 pi x[0]`.
    #[inline]
    pub fn at(&self, x: [f64; 2]) -> f64 {
        match *self {
            Measure::Plane { thickness } => thickness,
            Measure::Axisymmetric => std::f64::consts::TAU * x[0],
        }
    }

    /// Whether two measures are of the same analysis kind (plane or axisymmetric).
    pub fn same_kind(&self, other: &Measure) -> bool {
        std::mem::discriminant(self) == std::mem::discriminant(other)
    }

    /// Consistent nodal forces `f_a = integral of N_a q m ds` (`a` = start, end) of a force per
    /// area `q` given at the ends `a` and `b` of a straight segment and linear between them,
    /// `N_a` the segment's linear shape functions. In plane analyses the closed form
    /// `f_a = t L (2 q_a + q_b) / 6`, `f_b = t L (q_a + 2 q_b) / 6`; in axisymmetry `r` is
    /// linear too, the integrand cubic, and two-point Gauss integrates it exactly.
    pub fn segment_forces(&self, a: [f64; 2], b: [f64; 2], q: [[f64; 2]; 2]) -> [[f64; 2]; 2] {
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        let mut f = [[0.0; 2]; 2];
        for dir in 0..2 {
            let (qa, qb) = (q[0][dir], q[1][dir]);
            match *self {
                Measure::Axisymmetric => {
                    for (s, w) in GAUSS2_UNIT {
                        let x = [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
                        let qs = (qa + s * (qb - qa)) * self.at(x) * w * len;
                        f[0][dir] += (1.0 - s) * qs;
                        f[1][dir] += s * qs;
                    }
                }
                Measure::Plane { thickness: t } => {
                    f[0][dir] += t * len * (2.0 * qa + qb) / 6.0;
                    f[1][dir] += t * len * (qa + 2.0 * qb) / 6.0;
                }
            }
        }
        f
    }
}

impl Default for Measure {
    /// Plane, unit thickness.
    fn default() -> Self {
        Measure::Plane { thickness: 1.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_and_segment_forces() {
        let axi = Analysis::Axisymmetric.measure(1.0);
        let plane = Analysis::PlaneStrain.measure(2.0);
        assert_eq!(axi.at([2.0, 5.0]), 4.0 * std::f64::consts::PI);
        assert_eq!(plane.at([2.0, 5.0]), 2.0);
        assert!(!axi.same_kind(&plane) && plane.same_kind(&Measure::Plane { thickness: 1.0 }));
        // a uniform radial load on the axial segment r = 2, z in [0, 3]: 2 pi 2 3 in total,
        // half to each end
        let f = axi.segment_forces([2.0, 0.0], [2.0, 3.0], [[1.0, 0.0]; 2]);
        let half = 6.0 * std::f64::consts::PI;
        for fa in f {
            assert!(
                (fa[0] - half).abs() < 1e-14 * half && fa[1] == 0.0,
                "{fa:?}"
            );
        }
        // a linear load on a plane segment of length 3, thickness 2: t L (2 qa + qb) / 6
        let f = plane.segment_forces([0.0, 0.0], [3.0, 0.0], [[0.0, 1.0], [0.0, 4.0]]);
        assert_eq!(f, [[0.0, 6.0], [0.0, 9.0]]);
        assert_eq!(Analysis::Axisymmetric.stress_components(), 4);
        assert_eq!(
            Analysis::Axisymmetric.node_off_half_plane(&[[0.0, 0.0], [-1e-3, 1.0]], 1.0),
            Some(1)
        );
        assert_eq!(
            Analysis::PlaneStress.node_off_half_plane(&[[-1.0, 0.0]], 1.0),
            None
        );
    }
}
