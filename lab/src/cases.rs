//! Reference problems with published or closed-form answers, shared by the CLI, the tests and
//! the benchmarks.
//!
//! * Cook's membrane (plane stress, `E = 1`, `nu = 1/3`, `t = 1`): vertical displacement at the
//!   mid-point of the loaded edge, published values for Q4 and Pian-Sumihara, converged value
//!   about 23.96.
//! * The Pian-Sumihara cantilever (`L = 10`, `h = 2`, `E = 1500`, `nu = 0.25`, plane stress):
//!   tip deflection 100.0 under end moment `M = 2000`, 102.6 under end shear `P = 300`; in plane
//!   strain under end moment the exact deflection is `M L^2 / (2 E' I)`, `E' = E / (1 - nu^2)`,
//!   which is the locking test for nearly incompressible material.

use hycon::element::Formulation;
use hycon::error::{Error, Result};
use hycon::material::{Analysis, Material};
use hycon::mesh::generate;
use hycon::model::Model;

/// Converged vertical tip displacement of Cook's membrane.
pub const COOK_CONVERGED: f64 = 23.96;

/// Published Cook's membrane values: `(n, Q4, Pian-Sumihara)` for `n x n` meshes.
pub const COOK_PUBLISHED: [(usize, f64, f64); 4] = [
    (2, 11.845, 21.129),
    (4, 18.299, 23.022),
    (8, 22.079, 23.689),
    (16, 23.430, 23.883),
];

/// Cook's membrane in consistent units scaled by `length` (coordinates times `length`) and
/// `force` (load times `force`, moduli times `force / length^2`): returns the tip vertical
/// displacement divided by `length`, which is independent of both scales.
pub fn cook_membrane_scaled(
    formulation: Formulation,
    n: usize,
    length: f64,
    force: f64,
) -> Result<f64> {
    let mut mesh = generate::cooks_membrane(n);
    for p in &mut mesh.nodes {
        p[0] *= length;
        p[1] *= length;
    }
    let material = Material::new(
        force / (length * length),
        1.0 / 3.0,
        length,
        Analysis::PlaneStress,
    )?;
    let clamped = mesh.node_sets["clamped"].clone();
    let loaded = mesh.edge_sets["loaded"].clone();
    let tip = *mesh.node_sets["tip"]
        .first()
        .ok_or_else(|| Error::InvalidInput(format!("Cook's membrane needs an even n, got {n}")))?;
    let mut model = Model::new(mesh, vec![material], formulation);
    model.fix(&clamped, [0.0, 0.0])?;
    // total shear `force` over the loaded face, 16 `length` long and `t = length` thick: the
    // traction (force per area) `force / (16 length^2)`
    model.load_edges(&loaded, [0.0, force / (16.0 * length * length)]);
    let solution = model.solve()?;
    Ok(solution.displacement(tip)[1] / length)
}

/// Cook's membrane in its usual units: vertical displacement at (48, 52).
pub fn cook_membrane(formulation: Formulation, n: usize) -> Result<f64> {
    cook_membrane_scaled(formulation, n, 1.0, 1.0)
}

/// End load of the cantilever.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BeamLoad {
    /// End moment `M = 2000` (linear bending stress on the loaded end).
    Moment,
    /// End shear `P = 300` (parabolic shear stress on the loaded end).
    Shear,
}

/// Pian-Sumihara cantilever: `L = 10`, `h = 2`, `E = 1500`, unit thickness, clamped at `x = 0`
/// (`u = 0` on the whole end, `v = 0` at its centre node), loaded at `x = L` by consistent nodal
/// forces of the exact end stress. `nx x ny` elements (`ny` even), interior vertical lines
/// shifted by `distortion` (see [`generate::beam`]). Returns the vertical displacement of the
/// centre node of the loaded end.
pub fn cantilever(
    formulation: Formulation,
    load: BeamLoad,
    material: Material,
    nx: usize,
    ny: usize,
    distortion: f64,
) -> Result<f64> {
    const L: f64 = 10.0;
    const H: f64 = 2.0;
    if !ny.is_multiple_of(2) {
        return Err(Error::InvalidInput(format!(
            "the cantilever needs an even ny, got {ny}"
        )));
    }
    let mesh = generate::beam(L, H, nx, ny, distortion);
    let at = |set: &str, y: f64| -> usize {
        mesh.node_sets[set]
            .iter()
            .copied()
            .find(|&i| (mesh.nodes[i][1] - y).abs() < 1e-9)
            .expect("beam mesh has a centre node on each end")
    };
    let (root, tip) = (at("left", 0.0), at("right", 0.0));
    let left = mesh.node_sets["left"].clone();
    let right = mesh.edge_sets["right"].clone();
    let inertia = material.thickness * H.powi(3) / 12.0;
    let stress = |y: f64| -> [f64; 2] {
        match load {
            // sigma_x = -M y / I on the end face (outward normal +x): traction (sx, 0)
            BeamLoad::Moment => [-2000.0 * y / inertia, 0.0],
            // tau_xy = P/(2I) (h^2/4 - y^2), downward shear resultant -P... acts as +P upward
            BeamLoad::Shear => [0.0, 300.0 / (2.0 * inertia) * (H * H / 4.0 - y * y)],
        }
    };
    let t = material.thickness;
    let mut model = Model::new(mesh, vec![material], formulation);
    model.fix_dir(&left, 0, 0.0)?;
    model.fix_dir(&[root], 1, 0.0)?;
    // consistent forces of the (at most quadratic) end traction: Simpson's rule per edge
    let mut forces = vec![[0.0; 2]; model.mesh.n_nodes()];
    for &[a, b] in &right {
        let (ya, yb) = (model.mesh.nodes[a][1], model.mesh.nodes[b][1]);
        let len = (yb - ya).abs();
        let (sa, sm, sb) = (stress(ya), stress(0.5 * (ya + yb)), stress(yb));
        for d in 0..2 {
            forces[a][d] += t * len * (sa[d] + 2.0 * sm[d]) / 6.0;
            forces[b][d] += t * len * (sb[d] + 2.0 * sm[d]) / 6.0;
        }
    }
    model.nodal_forces = forces
        .into_iter()
        .enumerate()
        .filter(|(_, f)| *f != [0.0; 2])
        .collect();
    let solution = model.solve()?;
    Ok(solution.displacement(tip)[1])
}

/// The cantilever's material in the usual test: `E = 1500`, `nu = 0.25`, plane stress, `t = 1`.
pub fn cantilever_material() -> Material {
    Material {
        youngs: 1500.0,
        poisson: 0.25,
        thickness: 1.0,
        analysis: Analysis::PlaneStress,
    }
}

/// Hertz's closed form for a cylinder on a half-plane (plane strain), per unit thickness:
/// `1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`, `a = sqrt(4 P R / (pi E*))`, `p0 = 2 P / (pi a)`,
/// `p(x) = p0 sqrt(1 - x^2/a^2)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    /// Contact half-width `a`.
    pub half_width: f64,
    /// Peak pressure `p0`.
    pub peak: f64,
}

impl Hertz {
    /// The closed form for load `p` per unit thickness, disk radius `r`, effective modulus `e_star`.
    pub fn new(p: f64, r: f64, e_star: f64) -> Self {
        let a = (4.0 * p * r / (std::f64::consts::PI * e_star)).sqrt();
        Hertz {
            half_width: a,
            peak: 2.0 * p / (std::f64::consts::PI * a),
        }
    }

    /// Pressure at distance `x` from the centre of contact (0 outside).
    pub fn pressure(&self, x: f64) -> f64 {
        let r = 1.0 - (x / self.half_width).powi(2);
        if r > 0.0 { self.peak * r.sqrt() } else { 0.0 }
    }

    /// `1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2` (plane strain moduli of the two bodies).
    pub fn effective_modulus(a: &Material, b: &Material) -> f64 {
        1.0 / (1.0 / a.effective_modulus() + 1.0 / b.effective_modulus())
    }
}
