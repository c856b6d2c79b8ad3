//! The assumed-stress hybrid element of Kubomura and Pian: 4 corners plus 0, 1 or 2 mid-side
//! nodes (any convex polygon of 4 to 6 boundary nodes), displacement linear between consecutive
//! boundary nodes, an equilibrated stress field `sigma = P beta` inside.
//!
//! With local coordinates `xh = (x - xc) / s`, `yh = (y - yc) / s` (see [`Frame`]) the stress
//! basis comes from an Airy function `phi` (`sx = phi_yy`, `sy = phi_xx`, `txy = -phi_xy`):
//! * 7 beta, all cubic `phi` (complete linear stress):
//!   `sx = b1 + b4 yh + b6 xh`, `sy = b2 + b5 xh + b7 yh`, `txy = b3 - b6 yh - b7 xh`;
//! * 12 beta, adding the quartic `phi` terms `x^4, y^4, x^3 y, x y^3, x^2 y^2` (complete
//!   quadratic stress), used for 6 nodes, where 7 beta leaves two spurious zero-energy modes.
//!
//! `H = integral of P^T S P t dA` over the polygon (a fan of triangles from the centroid,
//! Dunavant's degree-4 rule: exact); `G = sum over boundary edges of integral (Nn P)^T L t ds`
//! (two Gauss points per edge: exact), `Nn = [[nx, 0, ny], [0, ny, nx]]` with the outward normal,
//! `L` the linear interpolation between the edge's two nodes.

use super::MAX_DOF;
use super::geometry::{DUNAVANT4, Frame, GAUSS2_UNIT, PolygonInfo, STRANG_FIX2, edge_normal};
use crate::material::Material;
use nalgebra::SMatrix;

/// Number of stress parameters for an `n`-node element: 7, or 12 for 6 nodes.
pub fn n_beta(n_nodes: usize) -> usize {
    if n_nodes >= 6 { 12 } else { 7 }
}

/// The stress basis `P(xh, yh)`: 3 rows (`sx, sy, txy`), `NB` columns (7 or 12), in local
/// coordinates.
pub fn stress_basis<const NB: usize>(local: [f64; 2]) -> SMatrix<f64, 3, NB> {
    let [x, y] = local;
    let mut p = SMatrix::<f64, 3, NB>::zeros();
    let linear: [[f64; 3]; 7] = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [y, 0.0, 0.0],
        [0.0, x, 0.0],
        [x, 0.0, -y],
        [0.0, y, -x],
    ];
    let quadratic: [[f64; 3]; 5] = [
        [0.0, x * x, 0.0],            // phi = x^4 / 12
        [y * y, 0.0, 0.0],            // phi = y^4 / 12
        [0.0, 2.0 * x * y, -x * x],   // phi = x^3 y / 3
        [2.0 * x * y, 0.0, -y * y],   // phi = x y^3 / 3
        [x * x, y * y, -2.0 * x * y], // phi = x^2 y^2 / 2
    ];
    for (j, col) in linear.iter().chain(quadratic.iter()).take(NB).enumerate() {
        for r in 0..3 {
            p[(r, j)] = col[r];
        }
    }
    p
}

/// `H` (`NB x NB`) and `G` (`NB x 2n`, zero-padded to `MAX_DOF` columns) of the hybrid element.
/// `H` uses a degree-2 triangle rule for 7 beta (its integrand is quadratic) and a degree-4 rule
/// for 12 beta: exact in both cases.
pub fn matrices<const NB: usize>(
    coords: &[[f64; 2]],
    info: &PolygonInfo,
    material: &Material,
) -> (SMatrix<f64, NB, NB>, SMatrix<f64, NB, MAX_DOF>) {
    let n = coords.len();
    let frame = Frame::new(info);
    let t = material.thickness;
    let s = material.compliance();
    let rule: &[([f64; 3], f64)] = if NB > 7 { &DUNAVANT4 } else { &STRANG_FIX2 };
    let mut h = SMatrix::<f64, NB, NB>::zeros();
    // fan of triangles (centroid, node i, node i + 1), in local coordinates (area ~ 1)
    for i in 0..n {
        let (a, b) = (frame.local(coords[i]), frame.local(coords[(i + 1) % n]));
        let area = 0.5 * (a[0] * b[1] - b[0] * a[1]);
        for (l, w) in rule {
            let p = [l[1] * a[0] + l[2] * b[0], l[1] * a[1] + l[2] * b[1]];
            let pb = stress_basis::<NB>(p);
            h += pb.transpose() * (s * pb) * (area * w);
        }
    }
    h *= t * frame.scale * frame.scale;
    let mut g = SMatrix::<f64, NB, MAX_DOF>::zeros();
    for i in 0..n {
        let j = (i + 1) % n;
        let (a, b) = (coords[i], coords[j]);
        let ([nx, ny], len) = edge_normal(a, b);
        for (r, w) in GAUSS2_UNIT {
            let p = [a[0] + r * (b[0] - a[0]), a[1] + r * (b[1] - a[1])];
            let pb = stress_basis::<NB>(frame.local(p));
            let weight = w * len * t;
            for k in 0..NB {
                // traction of basis column k: Nn P_k
                let tx = nx * pb[(0, k)] + ny * pb[(2, k)];
                let ty = nx * pb[(2, k)] + ny * pb[(1, k)];
                for (node, shape) in [(i, 1.0 - r), (j, r)] {
                    g[(k, 2 * node)] += weight * shape * tx;
                    g[(k, 2 * node + 1)] += weight * shape * ty;
                }
            }
        }
    }
    (h, g)
}

/// Stress at a physical point from `beta` (7 or 12 values): `P(xh, yh) beta`.
pub fn stress(frame: &Frame, beta: &[f64], p: [f64; 2]) -> [f64; 3] {
    fn apply<const NB: usize>(local: [f64; 2], beta: &[f64]) -> [f64; 3] {
        let s = stress_basis::<NB>(local) * nalgebra::SVector::<f64, NB>::from_column_slice(beta);
        [s[0], s[1], s[2]]
    }
    let local = frame.local(p);
    if beta.len() > 7 {
        apply::<12>(local, beta)
    } else {
        apply::<7>(local, beta)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every basis column satisfies equilibrium without body force:
    /// `dsx/dx + dtxy/dy = 0`, `dtxy/dx + dsy/dy = 0` (central differences are exact for
    /// quadratics up to round-off).
    #[test]
    fn basis_is_equilibrated() {
        let h = 1e-3;
        let at = |x: f64, y: f64| stress_basis::<12>([x, y]);
        for &(x, y) in &[(0.3, -0.2), (-0.7, 0.9)] {
            let dx = (at(x + h, y) - at(x - h, y)) / (2.0 * h);
            let dy = (at(x, y + h) - at(x, y - h)) / (2.0 * h);
            for k in 0..12 {
                let r1 = dx[(0, k)] + dy[(2, k)];
                let r2 = dx[(2, k)] + dy[(1, k)];
                assert!(r1.abs() < 1e-9 && r2.abs() < 1e-9, "column {k}: {r1} {r2}");
            }
        }
    }
}
