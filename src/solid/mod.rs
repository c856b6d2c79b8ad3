//! Three-dimensional solids: the 8-node bricks (the 18-beta assumed-stress hybrid brick and the
//! trilinear displacement brick H8), structured hexahedral meshes, and a linear static 3D model
//! assembled into the sparse Cholesky.
//!
//! * [`geometry`]: the trilinear map, node and face numbering, shape check and policy.
//! * [`hybrid18`]: the Pian-Tong 18-beta hybrid brick (why this field: see there).
//! * [`h8`]: the displacement brick, the baseline.
//! * [`mesh`]: structured hexahedral meshes of blocks and beams, graded and distorted.
//! * [`model`]: 3D dof map (3 dofs per node), sparse assembly, solve, stresses.
//! * [`loads`]: consistent nodal forces of pressures and tractions on a face.
//! * [`quality`]: volume and scaled Jacobian of a brick.
//!
//! # Kernels
//! Element kernels are pure, allocation-free functions of the 8 node coordinates (node order in
//! [`geometry`]) and an [`Isotropic`] material, on fixed-size nalgebra storage. Element dofs are
//! `[u0, v0, w0, u1, v1, w1, ...]` (24). Stress and strain are Voigt vectors
//! `[xx, yy, zz, xy, yz, zx]`, strains with engineering shear (`gamma_xy = 2 eps_xy`).
//!
//! Hybrid brick: `K = G^T H^-1 G` with `H = integral of P^T S P dV` and
//! `G = integral of P^T B dV` (2x2x2 Gauss), computed as `W^T W` with `W = L^-1 G`, `H = L L^T`
//! (Cholesky: no explicit inverse, symmetric by construction); `beta = H^-1 G q`.

pub mod contact_meshes;
pub mod geometry;
pub mod h8;
pub mod hybrid18;
pub mod loads;
pub mod mesh;
pub mod model;
pub mod quality;

use crate::error::{Error, Result, ShapeError};
use crate::material::SCALE_RANGE;
use geometry::{FACES, Trilinear, check_brick, face_natural, face_normal};
use nalgebra::{Cholesky, SMatrix, SVector};

pub use geometry::{ShapePolicy, ShapeReport, WARP_LIMIT_DEGREES};

/// Nodes of a brick.
pub const N_NODES: usize = 8;
/// Dofs of a brick.
pub const N_DOF: usize = 24;
/// Largest number of stress parameters of a brick.
pub const MAX_BETA: usize = hybrid18::N_BETA;

/// A Voigt stress or strain vector `[xx, yy, zz, xy, yz, zx]`.
pub type Voigt = SVector<f64, 6>;
/// Brick stiffness (24 x 24).
pub type BrickMatrix = SMatrix<f64, N_DOF, N_DOF>;

/// Isotropic linear elastic material of a 3D solid (no thickness, no plane idealisation).
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
        if !(SCALE_RANGE[0]..=SCALE_RANGE[1]).contains(&e) {
            return Err(Error::Material(format!(
                "Young's modulus must lie in [{:e}, {:e}], got {e}",
                SCALE_RANGE[0], SCALE_RANGE[1]
            )));
        }
        if !(nu > -1.0 && nu < 0.5) {
            return Err(Error::Material(format!(
                "Poisson's ratio must lie in (-1, 0.5), got {nu}"
            )));
        }
        Ok(())
    }

    /// Compliance `S` (strain = `S` stress): `1/E` times `1` on the normal diagonal, `-nu` off
    /// it, `2 (1 + nu)` on the shear diagonal. Finite as `nu -> 0.5`.
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

    /// Elasticity `D = S^-1`: `lambda + 2 mu` / `lambda` on the normal block, `mu` on the shear
    /// diagonal, `lambda = E nu / ((1 + nu)(1 - 2 nu))`, `mu = E / (2 (1 + nu))`.
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
}

/// Which brick formulation to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BrickFormulation {
    /// Pian-Tong 18-beta assumed-stress hybrid brick.
    Hybrid18,
    /// Trilinear displacement brick, 2x2x2 Gauss.
    H8,
}

impl BrickFormulation {
    /// Both formulations, in the order tables list them.
    pub const ALL: [BrickFormulation; 2] = [BrickFormulation::Hybrid18, BrickFormulation::H8];

    /// Short name used in tables.
    pub fn name(self) -> &'static str {
        match self {
            BrickFormulation::Hybrid18 => "hybrid18",
            BrickFormulation::H8 => "h8",
        }
    }

    /// Number of stress parameters (0 for H8).
    pub fn n_beta(self) -> usize {
        match self {
            BrickFormulation::Hybrid18 => hybrid18::N_BETA,
            BrickFormulation::H8 => 0,
        }
    }
}

/// Check a brick's shape under `policy` and measure it (see [`geometry::check_brick`]: node
/// count, finite coordinates, degenerate, inverted, `det J <= 0` at an integration point; strict
/// also at a corner, and warped faces). Both formulations accept the same shapes (both integrate
/// with the same 2x2x2 rule). The kernels below apply the default policy and return its report.
pub fn check_shape(
    coords: &[[f64; 3]],
    policy: ShapePolicy,
) -> std::result::Result<ShapeReport, ShapeError> {
    check_brick(coords, policy).map(|(_, report)| report)
}

/// `H` and `G` of the hybrid brick, `H` factored.
fn factored(
    map: &Trilinear,
    material: &Isotropic,
) -> std::result::Result<
    (
        Cholesky<f64, nalgebra::Const<{ hybrid18::N_BETA }>>,
        SMatrix<f64, { hybrid18::N_BETA }, N_DOF>,
    ),
    ShapeError,
> {
    let (h, g) = hybrid18::matrices(map, material);
    let chol = Cholesky::new(h).ok_or(ShapeError::Degenerate)?;
    Ok((chol, g))
}

/// Element stiffness `K` (24 x 24) into `out`; returns the shape report of the default policy
/// (its [`warnings`](ShapeReport::warnings) are for the caller to show). Never allocates.
///
/// Hybrid: `K = G^T H^-1 G` (as `W^T W`, `W = L^-1 G`); H8: `K = integral of B^T D B dV`.
pub fn stiffness_into(
    formulation: BrickFormulation,
    coords: &[[f64; 3]],
    material: &Isotropic,
    out: &mut BrickMatrix,
) -> std::result::Result<ShapeReport, ShapeError> {
    let (map, report) = check_brick(coords, ShapePolicy::default())?;
    match formulation {
        BrickFormulation::H8 => *out = h8::stiffness(&map, material),
        BrickFormulation::Hybrid18 => {
            let (chol, g) = factored(&map, material)?;
            let w = chol
                .l_dirty()
                .solve_lower_triangular(&g)
                .ok_or(ShapeError::Degenerate)?;
            w.tr_mul_to(&w, out);
        }
    }
    Ok(report)
}

/// The stress field recovered in one brick from its nodal displacements (`beta = H^-1 G q` for
/// the hybrid brick, `D B q` for H8). Plain data: copy it freely.
#[derive(Debug, Clone, Copy)]
pub struct BrickStress {
    formulation: BrickFormulation,
    material: Isotropic,
    map: Trilinear,
    frame: hybrid18::Frame,
    q: SVector<f64, N_DOF>,
    beta: SVector<f64, MAX_BETA>,
    shape: ShapeReport,
}

impl BrickStress {
    /// Stress at natural coordinates `xi`.
    pub fn at_natural(&self, xi: [f64; 3]) -> Voigt {
        match self.formulation {
            BrickFormulation::Hybrid18 => hybrid18::stress(&self.frame, self.beta(), xi),
            BrickFormulation::H8 => h8::stress(&self.map, &self.material, self.q.as_slice(), xi),
        }
    }

    /// [`BrickStress::at_natural`] with the natural coordinates checked: finite and in
    /// `[-1, 1]^3` (the ends included).
    pub fn at_natural_point(&self, xi: [f64; 3]) -> Result<Voigt> {
        crate::element::geometry::check_natural(&xi)?;
        Ok(self.at_natural(xi))
    }

    /// Stress at the physical point `p` (inverse trilinear map by Newton's method; a point
    /// outside the brick gives an extrapolation).
    pub fn at(&self, p: [f64; 3]) -> Voigt {
        self.at_natural(self.map.inverse(p))
    }

    /// Stress at the centre `xi = 0` (for the hybrid brick, `beta_1..6`: the mean stress).
    pub fn at_centre(&self) -> Voigt {
        self.at_natural([0.0; 3])
    }

    /// Traction `sigma n` (outward unit normal `n`) at face parameters `(s, t)` in `[-1, 1]^2`
    /// of face `face` (see [`geometry`] for the numbering). Panics if `face >= 6`.
    pub fn face_traction(&self, face: usize, s: f64, t: f64) -> [f64; 3] {
        assert!(face < FACES.len(), "face {face} of a brick (0 to 5)");
        let sigma = self.at_natural(face_natural(face, s, t));
        let n = face_normal(&self.map, face, s, t);
        traction(&sigma, n)
    }

    /// The stress parameters `beta` (empty for H8).
    pub fn beta(&self) -> &[f64] {
        &self.beta.as_slice()[..self.formulation.n_beta()]
    }

    /// The brick's shape report under the default policy (its warnings).
    pub fn shape(&self) -> &ShapeReport {
        &self.shape
    }
}

/// `sigma n` for a Voigt stress.
pub fn traction(s: &Voigt, n: [f64; 3]) -> [f64; 3] {
    [
        s[0] * n[0] + s[3] * n[1] + s[5] * n[2],
        s[3] * n[0] + s[1] * n[1] + s[4] * n[2],
        s[5] * n[0] + s[4] * n[1] + s[2] * n[2],
    ]
}

/// Recover the stress field of a brick from its 24 dofs `q` (element dof order), its shape
/// checked under the default policy. Panics if `q` is shorter than 24.
pub fn recover_stress(
    formulation: BrickFormulation,
    coords: &[[f64; 3]],
    material: &Isotropic,
    q: &[f64],
) -> std::result::Result<BrickStress, ShapeError> {
    let (map, shape) = check_brick(coords, ShapePolicy::default())?;
    let q = SVector::<f64, N_DOF>::from_column_slice(&q[..N_DOF]);
    let mut beta = SVector::<f64, MAX_BETA>::zeros();
    if formulation == BrickFormulation::Hybrid18 {
        let (chol, g) = factored(&map, material)?;
        beta = chol.solve(&(g * q));
    }
    Ok(BrickStress {
        formulation,
        material: *material,
        map,
        frame: hybrid18::Frame::new(&map),
        q,
        beta,
        shape,
    })
}
