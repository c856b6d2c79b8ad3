//! Isotropic linear elastic material in plane strain, plane stress or axisymmetry.
//!
//! The hybrid elements need the compliance `S` (strain = `S` stress, engineering shear strain);
//! the displacement element needs the elasticity `D = S^-1`. `S` stays finite as `nu -> 0.5` in
//! plane strain and axisymmetry, which is why the hybrid-stress elements do not lock.
//!
//! # Measure
//! Every volume and surface integral is weighted by [`Material::measure`]: the thickness `t` in
//! plane analyses, the circumference `2 pi r` in axisymmetry (the full circle: a nodal force is
//! the force summed over the whole circle, a stiffness is that of the whole ring). An
//! axisymmetric material must have `t = 1`.

use crate::error::{Error, Result};
use nalgebra::{Matrix3, Matrix4};

/// The range `E` and `t` must lie in: wide enough for any system of units, narrow enough that
/// the element matrices (`H ~ t A / E`, `G ~ t h`, `K ~ E t` for elements of area `A` and size
/// `h`) stay finite and normal in double precision for element sizes far beyond any mesh's.
pub const SCALE_RANGE: [f64; 2] = [1e-100, 1e100];

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
        if self.analysis == Analysis::Axisymmetric && t != 1.0 {
            return Err(Error::Material(format!(
                "an axisymmetric material needs thickness 1, got {t}: the measure of every \
                 integral is the circumference 2 pi r (results are for the full circle)"
            )));
        }
        Ok(())
    }

    /// The measure that weights every integral at the point `x` (`dV = measure dA`,
    /// `dS = measure ds`): the thickness `t` in plane analyses, `2 pi x[0]` (the circumference
    /// at radius `r = x[0]`) in axisymmetry.
    #[inline]
    pub fn measure(&self, x: [f64; 2]) -> f64 {
        match self.analysis {
            Analysis::Axisymmetric => std::f64::consts::TAU * x[0],
            Analysis::PlaneStrain | Analysis::PlaneStress => self.thickness,
        }
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
    /// Compliance `S` with `[ex, ey, gxy] = S [sx, sy, txy]`.
    ///
    /// Plane strain: `(1+nu)/E [[1-nu, -nu, 0], [-nu, 1-nu, 0], [0, 0, 2]]`;
    /// plane stress: `1/E [[1, -nu, 0], [-nu, 1, 0], [0, 0, 2(1+nu)]]`. Axisymmetry uses
    /// [`Material::compliance_axisymmetric`]; here it gets the plane-strain matrix (the meridian
    /// block with `eps_theta = 0`).
    pub fn compliance(&self) -> Matrix3<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        match self.analysis {
            Analysis::PlaneStrain | Analysis::Axisymmetric => {
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

    /// Elasticity `D = S^-1`, `[sx, sy, txy] = D [ex, ey, gxy]` (axisymmetry: the plane-strain
    /// matrix, see [`Material::elasticity_axisymmetric`]).
    pub fn elasticity(&self) -> Matrix3<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        let (a, b) = match self.analysis {
            Analysis::PlaneStrain | Analysis::Axisymmetric => {
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

    /// Axisymmetric compliance `S` (4 x 4), `[eps_r, eps_z, gamma_rz, eps_theta] =
    /// S [sigma_r, sigma_z, tau_rz, sigma_theta]`:
    /// `1/E [[1, -nu, 0, -nu], [-nu, 1, 0, -nu], [0, 0, 2(1+nu), 0], [-nu, -nu, 0, 1]]`.
    /// Finite as `nu -> 0.5` (singular only for the hydrostatic stress there).
    pub fn compliance_axisymmetric(&self) -> Matrix4<f64> {
        let (c, nu) = (1.0 / self.youngs, self.poisson);
        let (d, o, g) = (c, -c * nu, 2.0 * (1.0 + nu) * c);
        Matrix4::new(
            d, o, 0.0, o, //
            o, d, 0.0, o, //
            0.0, 0.0, g, 0.0, //
            o, o, 0.0, d,
        )
    }

    /// Axisymmetric elasticity `D = S^-1` (4 x 4):
    /// `E / ((1+nu)(1-2nu)) [[1-nu, nu, 0, nu], [nu, 1-nu, 0, nu], [0, 0, (1-2nu)/2, 0],
    /// [nu, nu, 0, 1-nu]]`.
    pub fn elasticity_axisymmetric(&self) -> Matrix4<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        let c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let (d, o, g) = (c * (1.0 - nu), c * nu, e / (2.0 * (1.0 + nu)));
        Matrix4::new(
            d, o, 0.0, o, //
            o, d, 0.0, o, //
            0.0, 0.0, g, 0.0, //
            o, o, 0.0, d,
        )
    }

    /// Effective modulus `E / (1 - nu^2)` in plane strain and axisymmetry, `E` in plane stress
    /// (Hertz's `E*` is built from these).
    pub fn effective_modulus(&self) -> f64 {
        match self.analysis {
            Analysis::PlaneStrain | Analysis::Axisymmetric => {
                self.youngs / (1.0 - self.poisson * self.poisson)
            }
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
