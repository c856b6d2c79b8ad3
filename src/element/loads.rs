//! Consistent nodal forces of a distributed load on one boundary edge of a plane or
//! axisymmetric element.
//!
//! Edge `e` of an element runs from local node `e` to local node `e + 1` (cyclically); on the 5-
//! and 6-node transition elements each segment between consecutive nodes is an edge of its own.
//! Every edge is straight, with the body on its left and the outward unit normal `n` of
//! [`edge_normal`]. On it the load is a pressure `p` (force per area, **positive pushing into the
//! body**, as the scene files' `pressure`) and a traction vector `t` (force per area; in
//! axisymmetry the meridian components `[t_r, t_z]`), each given by its values at the edge's two
//! nodes and linear between them. The surface force is `q = t - p n`, and the consistent nodal
//! forces are
//!
//! ```text
//! f_a = integral over the edge of N_a q m ds,     a = start, end node,
//! ```
//!
//! with `N_a` the linear shape functions of the edge (the element's displacement along a
//! boundary edge is linear in every formulation) and `m` the measure ([`Material::measure`]): the
//! thickness in plane analyses, `2 pi r` in axisymmetry, so forces there are for the full circle.
//! Since `n` is constant along a straight edge, `q` is linear; in plane analyses the integral is
//! the closed form `f_a = m L (2 q_a + q_b) / 6`, `f_b = m L (q_a + 2 q_b) / 6`; in axisymmetry
//! `r` is linear too, the integrand cubic, and two-point Gauss integrates it exactly.

use super::geometry::edge_normal;
use super::{ElementVector, Formulation, checked_for};
use crate::error::{Error, Result};
use crate::fem::boundary::BoundaryLoad;
use crate::material::Material;

/// A distributed load on one element edge: pressure and traction `[tx, ty]` (axisymmetry:
/// `[t_r, t_z]`) at the edge's start node (local node `e`) and end node (`e + 1`), linear
/// between them. The surface force is `t - p n` (`n` the outward unit normal).
pub type EdgeLoad = BoundaryLoad<2, 2>;

/// Consistent nodal forces `[f_a, f_b]` of the surface force `q`, given at the ends `a` and `b`
/// of a straight segment (linear between them), with the measure of `material` (see
/// [`crate::fem::Measure::segment_forces`] for the integral and why it is exact).
pub fn segment_forces(
    a: [f64; 2],
    b: [f64; 2],
    material: &Material,
    q: [[f64; 2]; 2],
) -> [[f64; 2]; 2] {
    material.measure_kind().segment_forces(a, b, q)
}

/// Consistent nodal forces of `load` on edge `edge` of an element (see the module docs), as an
/// element force vector in element dof order `[fx0, fy0, fx1, fy1, ...]`: the leading `2n`
/// entries are used, only those of the edge's two nodes are nonzero.
///
/// Checks the element for the material's analysis kind (as [`super::stiffness_into`] does: an
/// inverted element would turn the normal inward), `edge < n` and a finite load.
pub fn edge_load(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
    edge: usize,
    load: &EdgeLoad,
) -> Result<ElementVector> {
    checked_for(formulation, coords, material)?;
    let n = coords.len();
    if edge >= n {
        return Err(Error::InvalidInput(format!(
            "edge {edge} of a {n}-node element (edges are 0 to {})",
            n - 1
        )));
    }
    load.validate()?;
    let nodes = [edge, (edge + 1) % n];
    let (a, b) = (coords[nodes[0]], coords[nodes[1]]);
    let (normal, _) = edge_normal(a, b);
    let q = [0, 1].map(|k| load.surface_force(k, normal));
    let f = segment_forces(a, b, material, q);
    let mut out = ElementVector::zeros();
    for (node, force) in nodes.into_iter().zip(f) {
        out[2 * node] = force[0];
        out[2 * node + 1] = force[1];
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Analysis;

    fn close(a: f64, b: f64, scale: f64) -> bool {
        (a - b).abs() <= 1e-14 * scale
    }

    /// A uniform pressure on a straight plane edge splits 1/2-1/2, along the inward normal.
    #[test]
    fn uniform_pressure_splits_in_halves() {
        let m = Material::new(1.0, 0.3, 2.5, Analysis::PlaneStress).unwrap();
        // edge 1 of the unit square runs along x = 1 (outward normal +x)
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let f = edge_load(Formulation::Q4, &square, &m, 1, &EdgeLoad::pressure(4.0)).unwrap();
        let want = [0.0, 0.0, -5.0, 0.0, -5.0, 0.0, 0.0, 0.0];
        for (k, w) in want.iter().enumerate() {
            assert!(close(f[k], *w, 5.0), "{k}: {} vs {w}", f[k]);
        }
        assert!(f.rows(8, 4).iter().all(|&v| v == 0.0));
    }

    #[test]
    fn bad_edges_and_loads_are_rejected() {
        let m = Material::new(1.0, 0.3, 1.0, Analysis::PlaneStrain).unwrap();
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let f = Formulation::Hybrid;
        assert!(matches!(
            edge_load(f, &square, &m, 4, &EdgeLoad::pressure(1.0)),
            Err(Error::InvalidInput(s)) if s.contains("edge 4")
        ));
        assert!(matches!(
            edge_load(f, &square, &m, 0, &EdgeLoad::pressure(f64::NAN)),
            Err(Error::InvalidInput(s)) if s.contains("not finite")
        ));
        let mut cw = square;
        cw.reverse();
        assert!(matches!(
            edge_load(f, &cw, &m, 0, &EdgeLoad::pressure(1.0)),
            Err(Error::Element { .. })
        ));
    }
}
