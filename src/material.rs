//! The material of a plane or axisymmetric element: the isotropic material of the shared base
//! ([`Isotropic`]: `E`, `nu`, compliance and elasticity) plus the analysis kind and the
//! out-of-plane thickness `t`.
//!
//! # Measure
//! Every volume and surface integral is weighted by [`Material::measure`]: the thickness `t` in
//! plane analyses, the circumference `2 pi r` in axisymmetry (the full circle; see
//! [`crate::fem::analysis`]). An axisymmetric material must have `t = 1`.

use crate::error::{Error, Result};
use crate::fem::Measure;
use crate::fem::isotropic::check_scale;
use nalgebra::{Matrix3, Matrix4};

pub use crate::fem::Analysis;
pub use crate::fem::Isotropic;
pub use crate::fem::isotropic::SCALE_RANGE;

/// Isotropic material plus the analysis kind and the out-of-plane thickness `t` of the elements
/// that use it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus `E` (> 0).
    pub youngs: f64,
    /// Poisson's ratio `nu` (-1 < nu < 0.5).
    pub poisson: f64,
    /// Thickness `t` (> 0).
    pub thickness: f64,
    /// Plane strain, plane stress or axisymmetric.
    pub analysis: Analysis,
}

impl Material {
    /// A checked material: finite values, `E > 0`, `-1 < nu < 0.5`, `t > 0`, `E` and `t` within
    /// [`SCALE_RANGE`]; `t = 1` exactly in axisymmetry (the measure is `2 pi r`).
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

    /// The isotropic part, `E` and `nu`.
    #[inline]
    pub fn isotropic(&self) -> Isotropic {
        Isotropic {
            youngs: self.youngs,
            poisson: self.poisson,
        }
    }

    /// Check the invariants listed in [`Material::new`]: those of [`Isotropic::validate`], then
    /// the thickness.
    pub fn validate(&self) -> Result<()> {
        self.isotropic().validate()?;
        let t = self.thickness;
        if !t.is_finite() || t <= 0.0 {
            return Err(Error::Material(format!(
                "thickness must be finite and > 0, got {t}"
            )));
        }
        check_scale(t, "thickness")?;
        if let Some(required) = self.analysis.required_thickness()
            && t != required
        {
            return Err(Error::Material(format!(
                "an {} material needs thickness {required}, got {t}: the measure of every \
                 integral is the circumference 2 pi r (results are for the full circle)",
                self.analysis.name()
            )));
        }
        Ok(())
    }

    /// The measure of this material's elements: `t` in plane analyses, `2 pi r` in axisymmetry.
    #[inline]
    pub fn measure_kind(&self) -> Measure {
        self.analysis.measure(self.thickness)
    }

    /// The measure that weights every integral at the point `x` (`dV = measure dA`,
    /// `dS = measure ds`): the thickness `t` in plane analyses, `2 pi x[0]` (the circumference
    /// at radius `r = x[0]`) in axisymmetry.
    #[inline]
    pub fn measure(&self, x: [f64; 2]) -> f64 {
        self.measure_kind().at(x)
    }

    /// The out-of-plane normal stress that goes with the in-plane stress `s = [sx, sy, txy]`:
    /// `nu (sx + sy)` in plane strain, 0 in plane stress. Not defined by the in-plane stress in
    /// axisymmetry (the hoop stress is a field of its own): `None` there.
    pub fn out_of_plane_stress(&self, s: [f64; 3]) -> Option<f64> {
        match self.analysis {
            Analysis::PlaneStrain => Some(self.poisson * (s[0] + s[1])),
            Analysis::PlaneStress => Some(0.0),
            Analysis::Axisymmetric => None,
        }
    }

    /// Compliance `S` with `[ex, ey, gxy] = S [sx, sy, txy]` for the material's analysis kind
    /// ([`Isotropic::compliance_plane`]).
    pub fn compliance(&self) -> Matrix3<f64> {
        self.isotropic().compliance_plane(self.analysis)
    }

    /// Elasticity `D = S^-1`, `[sx, sy, txy] = D [ex, ey, gxy]`
    /// ([`Isotropic::elasticity_plane`]).
    pub fn elasticity(&self) -> Matrix3<f64> {
        self.isotropic().elasticity_plane(self.analysis)
    }

    /// Axisymmetric compliance `S` (4 x 4, [`Isotropic::compliance_axisymmetric`]).
    pub fn compliance_axisymmetric(&self) -> Matrix4<f64> {
        self.isotropic().compliance_axisymmetric()
    }

    /// Axisymmetric elasticity `D = S^-1` (4 x 4, [`Isotropic::elasticity_axisymmetric`]).
    pub fn elasticity_axisymmetric(&self) -> Matrix4<f64> {
        self.isotropic().elasticity_axisymmetric()
    }

    /// Effective modulus `E / (1 - nu^2)` in plane strain and axisymmetry, `E` in plane stress
    /// (Hertz's `E*` is built from these).
    pub fn effective_modulus(&self) -> f64 {
        self.isotropic().effective_modulus(self.analysis)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_values() {
        let a = Analysis::PlaneStrain;
        assert!(Material::new(-1.0, 0.3, 1.0, a).is_err());
        assert!(Material::new(1.0, 0.5, 1.0, a).is_err());
        assert!(Material::new(1.0, 0.3, 0.0, a).is_err());
        assert!(Material::new(f64::NAN, 0.3, 1.0, a).is_err());
        let axi = Analysis::Axisymmetric;
        let e = Material::new(1.0, 0.3, 2.0, axi).unwrap_err().to_string();
        assert!(e.contains("2 pi r"), "{e}");
        assert!(Material::new(1.0, 0.3, 1.0, axi).is_ok());
    }

    #[test]
    fn axisymmetric_compliance_inverts_elasticity_and_measures_the_circle() {
        let m = Material::new(210e3, 0.3, 1.0, Analysis::Axisymmetric).unwrap();
        let err = (m.compliance_axisymmetric() * m.elasticity_axisymmetric() - Matrix4::identity())
            .abs()
            .max();
        assert!(err < 1e-14, "|S D - I| = {err}");
        // the meridian block with eps_theta = 0 is plane strain
        let d = m.elasticity_axisymmetric();
        let plane = Material {
            analysis: Analysis::PlaneStrain,
            ..m
        };
        let d3 = plane.elasticity();
        for i in 0..3 {
            for j in 0..3 {
                assert!((d[(i, j)] - d3[(i, j)]).abs() < 1e-9 * d3.abs().max());
            }
        }
        assert_eq!(m.measure([2.0, 5.0]), 4.0 * std::f64::consts::PI);
        assert_eq!(plane.measure([2.0, 5.0]), 1.0);
        // hydrostatic stress is the only null vector of S at nu = 0.5 (limit): S (1,1,0,1) ~ 1-2nu
        let m = Material::new(1.0, 0.4999999, 1.0, Analysis::Axisymmetric).unwrap();
        let s = m.compliance_axisymmetric() * nalgebra::Vector4::new(1.0, 1.0, 0.0, 1.0);
        assert!(s.norm() < 1e-6);
    }
}
