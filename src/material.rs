//! Isotropic linear elastic material in plane strain or plane stress.
//!
//! The hybrid elements need the compliance `S` (strain = `S` stress, engineering shear strain);
//! the displacement element needs the elasticity `D = S^-1`. `S` stays finite as `nu -> 0.5` in
//! plane strain, which is why the hybrid-stress elements do not lock.

use crate::error::{Error, Result};
use nalgebra::Matrix3;

/// The range `E` and `t` must lie in: wide enough for any system of units, narrow enough that
/// the element matrices (`H ~ t A / E`, `G ~ t h`, `K ~ E t` for elements of area `A` and size
/// `h`) stay finite and normal in double precision for element sizes far beyond any mesh's.
pub const SCALE_RANGE: [f64; 2] = [1e-100, 1e100];

/// Which two-dimensional idealisation is used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Analysis {
    /// `eps_z = 0`; `t` is the thickness the results are reported per (usually 1).
    PlaneStrain,
    /// `sigma_z = 0`.
    PlaneStress,
}

/// Isotropic material plus the out-of-plane thickness `t` of the elements that use it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus `E` (> 0).
    pub youngs: f64,
    /// Poisson's ratio `nu` (-1 < nu < 0.5).
    pub poisson: f64,
    /// Thickness `t` (> 0).
    pub thickness: f64,
    /// Plane strain or plane stress.
    pub analysis: Analysis,
}

impl Material {
    /// A checked material: finite values, `E > 0`, `-1 < nu < 0.5`, `t > 0`, `E` and `t` within
    /// [`SCALE_RANGE`].
    pub fn new(youngs: f64, poisson: f64, thickness: f64, analysis: Analysis) -> Result<Self> {
        let m = Material {
            youngs,
            poisson,
            thickness,
            analysis,
        };
        m.validate()?;
        Ok(m)
    }

    /// Check the invariants listed in [`Material::new`].
    pub fn validate(&self) -> Result<()> {
        let Material {
            youngs: e,
            poisson: nu,
            thickness: t,
            ..
        } = *self;
        if !(e.is_finite() && nu.is_finite() && t.is_finite()) {
            return Err(Error::Material(format!(
                "non-finite value (E = {e}, nu = {nu}, t = {t})"
            )));
        }
        if e <= 0.0 {
            return Err(Error::Material(format!(
                "Young's modulus must be > 0, got {e}"
            )));
        }
        for (value, name) in [(e, "Young's modulus"), (t, "thickness")] {
            if value > 0.0 && !(SCALE_RANGE[0]..=SCALE_RANGE[1]).contains(&value) {
                return Err(Error::Material(format!(
                    "{name} {value:e} lies outside [{:e}, {:e}], where the element matrices \
                     stay finite and normal in double precision: choose other units",
                    SCALE_RANGE[0], SCALE_RANGE[1]
                )));
            }
        }
        if !(nu > -1.0 && nu < 0.5) {
            return Err(Error::Material(format!(
                "Poisson's ratio must lie in (-1, 0.5), got {nu}"
            )));
        }
        if t <= 0.0 {
            return Err(Error::Material(format!("thickness must be > 0, got {t}")));
        }
        Ok(())
    }

    /// Compliance `S` with `[ex, ey, gxy] = S [sx, sy, txy]`.
    ///
    /// Plane strain: `(1+nu)/E [[1-nu, -nu, 0], [-nu, 1-nu, 0], [0, 0, 2]]`;
    /// plane stress: `1/E [[1, -nu, 0], [-nu, 1, 0], [0, 0, 2(1+nu)]]`.
    pub fn compliance(&self) -> Matrix3<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        match self.analysis {
            Analysis::PlaneStrain => {
                let c = (1.0 + nu) / e;
                Matrix3::new(
                    c * (1.0 - nu),
                    -c * nu,
                    0.0,
                    -c * nu,
                    c * (1.0 - nu),
                    0.0,
                    0.0,
                    0.0,
                    2.0 * c,
                )
            }
            Analysis::PlaneStress => {
                let c = 1.0 / e;
                Matrix3::new(
                    c,
                    -c * nu,
                    0.0,
                    -c * nu,
                    c,
                    0.0,
                    0.0,
                    0.0,
                    2.0 * (1.0 + nu) * c,
                )
            }
        }
    }

    /// Elasticity `D = S^-1`, `[sx, sy, txy] = D [ex, ey, gxy]`.
    pub fn elasticity(&self) -> Matrix3<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        let (a, b) = match self.analysis {
            Analysis::PlaneStrain => {
                let c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
                (c * (1.0 - nu), c * nu)
            }
            Analysis::PlaneStress => {
                let c = e / (1.0 - nu * nu);
                (c, c * nu)
            }
        };
        let g = e / (2.0 * (1.0 + nu));
        Matrix3::new(a, b, 0.0, b, a, 0.0, 0.0, 0.0, g)
    }

    /// Plane-strain effective modulus `E / (1 - nu^2)`, or `E` in plane stress (Hertz's `E*` is
    /// built from these).
    pub fn effective_modulus(&self) -> f64 {
        match self.analysis {
            Analysis::PlaneStrain => self.youngs / (1.0 - self.poisson * self.poisson),
            Analysis::PlaneStress => self.youngs,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compliance_inverts_elasticity() {
        for analysis in [Analysis::PlaneStrain, Analysis::PlaneStress] {
            let m = Material::new(210e3, 0.3, 1.0, analysis).unwrap();
            let err = (m.compliance() * m.elasticity() - Matrix3::identity())
                .abs()
                .max();
            assert!(err < 1e-14, "{analysis:?}: |S D - I| = {err}");
        }
    }

    #[test]
    fn rejects_bad_values() {
        let a = Analysis::PlaneStrain;
        assert!(Material::new(-1.0, 0.3, 1.0, a).is_err());
        assert!(Material::new(1.0, 0.5, 1.0, a).is_err());
        assert!(Material::new(1.0, 0.3, 0.0, a).is_err());
        assert!(Material::new(f64::NAN, 0.3, 1.0, a).is_err());
    }
}
