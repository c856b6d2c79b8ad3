//! The isotropic linear elastic material shared by every element: Young's modulus `E`, Poisson's
//! ratio `nu`, their validation, and the compliance `S` (strain = `S` stress, engineering shear
//! strain) and elasticity `D = S^-1` in each stress state.
//!
//! The hybrid elements need `S`, the displacement elements `D`. `S` stays finite as
//! `nu -> 0.5` in plane strain, axisymmetry and 3D, which is why the hybrid-stress elements do
//! not lock. The plane [`crate::material::Material`] adds the analysis kind and the thickness;
//! the bricks use this material as it is.

use super::analysis::Analysis;
use crate::error::{Error, Result};
use nalgebra::{Matrix3, Matrix4, SMatrix};

/// The range `E` and the thickness `t` must lie in: wide enough for any system of units, narrow
/// enough that the element matrices (`H ~ t A / E`, `G ~ t h`, `K ~ E t` for elements of area
/// `A` and size `h`; in 3D `H ~ V / E`, `K ~ E h`) stay finite and normal in double precision for
/// element sizes far beyond any mesh's.
pub const SCALE_RANGE: [f64; 2] = [1e-100, 1e100];

/// An isotropic linear elastic material: `E` and `nu`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Isotropic {
    /// Young's modulus `E` (> 0, within [`SCALE_RANGE`]).
    pub youngs: f64,
    /// Poisson's ratio `nu` (-1 < nu < 0.5).
    pub poisson: f64,
}

impl Isotropic {
    /// A checked material: finite values, `E > 0` within [`SCALE_RANGE`], `-1 < nu < 0.5`.
    pub fn new(youngs: f64, poisson: f64) -> Result<Self> {
        let m = Isotropic { youngs, poisson };
        m.validate()?;
        Ok(m)
    }

    /// Check the invariants listed in [`Isotropic::new`].
    pub fn validate(&self) -> Result<()> {
        let (e, nu) = (self.youngs, self.poisson);
        if !(e.is_finite() && nu.is_finite()) {
            return Err(Error::Material(format!(
                "non-finite value (E = {e}, nu = {nu})"
            )));
        }
        if e <= 0.0 {
            return Err(Error::Material(format!(
                "Young's modulus must be > 0, got {e}"
            )));
        }
        check_scale(e, "Young's modulus")?;
        if !(nu > -1.0 && nu < 0.5) {
            return Err(Error::Material(format!(
                "Poisson's ratio must lie in (-1, 0.5), got {nu}"
            )));
        }
        Ok(())
    }

    /// Plane compliance `S` with `[ex, ey, gxy] = S [sx, sy, txy]`.
    ///
    /// Plane strain: `(1+nu)/E [[1-nu, -nu, 0], [-nu, 1-nu, 0], [0, 0, 2]]`;
    /// plane stress: `1/E [[1, -nu, 0], [-nu, 1, 0], [0, 0, 2(1+nu)]]`. Axisymmetry uses
    /// [`Isotropic::compliance_axisymmetric`]; here it gets the plane-strain matrix (the meridian
    /// block with `eps_theta = 0`).
    pub fn compliance_plane(&self, analysis: Analysis) -> Matrix3<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        match analysis {
            Analysis::PlaneStrain | Analysis::Axisymmetric => {
                let c = (1.0 + nu) / e;
                plane_pattern(c * (1.0 - nu), -c * nu, 2.0 * c)
            }
            Analysis::PlaneStress => {
                let c = 1.0 / e;
                plane_pattern(c, -c * nu, 2.0 * (1.0 + nu) * c)
            }
        }
    }

    /// Plane elasticity `D = S^-1`, `[sx, sy, txy] = D [ex, ey, gxy]` (axisymmetry: the
    /// plane-strain matrix, see [`Isotropic::elasticity_axisymmetric`]).
    pub fn elasticity_plane(&self, analysis: Analysis) -> Matrix3<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        let (a, b) = match analysis {
            Analysis::PlaneStrain | Analysis::Axisymmetric => {
                let c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
                (c * (1.0 - nu), c * nu)
            }
            Analysis::PlaneStress => {
                let c = e / (1.0 - nu * nu);
                (c, c * nu)
            }
        };
        plane_pattern(a, b, e / (2.0 * (1.0 + nu)))
    }

    /// Axisymmetric compliance `S` (4 x 4), `[eps_r, eps_z, gamma_rz, eps_theta] =
    /// S [sigma_r, sigma_z, tau_rz, sigma_theta]`:
    /// `1/E [[1, -nu, 0, -nu], [-nu, 1, 0, -nu], [0, 0, 2(1+nu), 0], [-nu, -nu, 0, 1]]`.
    /// Finite as `nu -> 0.5` (singular only for the hydrostatic stress there).
    pub fn compliance_axisymmetric(&self) -> Matrix4<f64> {
        let (c, nu) = (1.0 / self.youngs, self.poisson);
        axisymmetric_pattern(c, -c * nu, 2.0 * (1.0 + nu) * c)
    }

    /// Axisymmetric elasticity `D = S^-1` (4 x 4):
    /// `E / ((1+nu)(1-2nu)) [[1-nu, nu, 0, nu], [nu, 1-nu, 0, nu], [0, 0, (1-2nu)/2, 0],
    /// [nu, nu, 0, 1-nu]]`.
    pub fn elasticity_axisymmetric(&self) -> Matrix4<f64> {
        let (e, nu) = (self.youngs, self.poisson);
        let c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
        axisymmetric_pattern(c * (1.0 - nu), c * nu, e / (2.0 * (1.0 + nu)))
    }

    /// 3D compliance `S` (6 x 6, Voigt order `[xx, yy, zz, xy, yz, zx]`): `1/E` times `1` on the
    /// normal diagonal, `-nu` off it, `2 (1 + nu)` on the shear diagonal. Finite as `nu -> 0.5`.
    pub fn compliance(&self) -> SMatrix<f64, 6, 6> {
        let (e, nu) = (self.youngs, self.poisson);
        let mut s = SMatrix::<f64, 6, 6>::zeros();
        for i in 0..3 {
            for j in 0..3 {
                s[(i, j)] = if i == j { 1.0 / e } else { -nu / e };
            }
            s[(3 + i, 3 + i)] = 2.0 * (1.0 + nu) / e;
        }
        s
    }

    /// 3D elasticity `D = S^-1`: `lambda + 2 mu` / `lambda` on the normal block, `mu` on the
    /// shear diagonal, `lambda = E nu / ((1 + nu)(1 - 2 nu))`, `mu = E / (2 (1 + nu))`.
    pub fn elasticity(&self) -> SMatrix<f64, 6, 6> {
        let (e, nu) = (self.youngs, self.poisson);
        let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let mu = e / (2.0 * (1.0 + nu));
        let mut d = SMatrix::<f64, 6, 6>::zeros();
        for i in 0..3 {
            for j in 0..3 {
                d[(i, j)] = lambda + if i == j { 2.0 * mu } else { 0.0 };
            }
            d[(3 + i, 3 + i)] = mu;
        }
        d
    }

    /// Effective modulus `E / (1 - nu^2)` in plane strain and axisymmetry, `E` in plane stress
    /// (Hertz's `E*` is built from these).
    pub fn effective_modulus(&self, analysis: Analysis) -> f64 {
        match analysis {
            Analysis::PlaneStrain | Analysis::Axisymmetric => {
                self.youngs / (1.0 - self.poisson * self.poisson)
            }
            Analysis::PlaneStress => self.youngs,
        }
    }
}

/// The isotropic plane pattern `[[d, o, 0], [o, d, 0], [0, 0, g]]` (`d` the normal diagonal,
/// `o` the normal coupling, `g` the shear term).
fn plane_pattern(d: f64, o: f64, g: f64) -> Matrix3<f64> {
    Matrix3::new(d, o, 0.0, o, d, 0.0, 0.0, 0.0, g)
}

/// The isotropic axisymmetric pattern in the order `[r, z, rz, theta]`: `d` on the normal
/// diagonal, `o` coupling the three normal components, `g` the shear term.
fn axisymmetric_pattern(d: f64, o: f64, g: f64) -> Matrix4<f64> {
    Matrix4::new(
        d, o, 0.0, o, //
        o, d, 0.0, o, //
        0.0, 0.0, g, 0.0, //
        o, o, 0.0, d,
    )
}

/// Check that a positive scale (`E`, a thickness) named `name` lies within [`SCALE_RANGE`].
pub fn check_scale(value: f64, name: &str) -> Result<()> {
    if (SCALE_RANGE[0]..=SCALE_RANGE[1]).contains(&value) {
        Ok(())
    } else {
        Err(Error::Material(format!(
            "{name} {value:e} lies outside [{:e}, {:e}], where the element matrices stay finite \
             and normal in double precision: choose other units",
            SCALE_RANGE[0], SCALE_RANGE[1]
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compliances_invert_elasticities() {
        let m = Isotropic::new(210e3, 0.3).unwrap();
        for analysis in [Analysis::PlaneStrain, Analysis::PlaneStress] {
            let err = (m.compliance_plane(analysis) * m.elasticity_plane(analysis)
                - Matrix3::identity())
            .abs()
            .max();
            assert!(err < 1e-14, "{analysis:?}: |S D - I| = {err}");
        }
        let err = (m.compliance() * m.elasticity() - SMatrix::<f64, 6, 6>::identity())
            .abs()
            .max();
        assert!(err < 1e-14, "3D: |S D - I| = {err}");
    }

    #[test]
    fn rejects_bad_values() {
        for (e, nu, what) in [
            (-1.0, 0.3, "must be > 0"),
            (1e101, 0.3, "choose other units"),
            (1.0, 0.5, "Poisson"),
            (f64::NAN, 0.3, "non-finite"),
        ] {
            let msg = Isotropic::new(e, nu).unwrap_err().to_string();
            assert!(msg.contains(what), "{e} {nu}: {msg}");
        }
    }
}
