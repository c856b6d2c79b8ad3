//! Element kernels: pure, allocation-free functions from node coordinates and a material to
//! element matrices (fixed-size nalgebra storage).
//!
//! # Node and dof order
//! An element is the counter-clockwise polygon of its boundary nodes. Q4 and Pian-Sumihara take
//! exactly the 4 corners. The hybrid element takes 4 to 6 nodes: the 4 corners plus 0, 1 or 2
//! mid-side nodes on straight edges (the paper's 5- and 6-node *transition* elements), listed in
//! boundary order (a mid-side node sits between the two corners of its edge). Element dofs are
//! `[u0, v0, u1, v1, ...]` in that node order; matrices are `MAX_DOF x MAX_DOF` with the leading
//! `2 n` block used.
//!
//! # Formulations
//! * [`Formulation::Hybrid`]: assumed-stress hybrid element of Kubomura and Pian. Displacement
//!   lives only on the boundary, linear between consecutive nodes; the stress inside is an
//!   equilibrated field `sigma = P beta` from an Airy function, in centred, scaled coordinates.
//!   7 beta (complete linear stress) for 4 and 5 nodes; 12 beta (complete quadratic) for 6 nodes,
//!   where 7 beta would leave two spurious zero-energy modes. `K = G^T H^-1 G`.
//! * [`Formulation::PianSumihara`]: the 5-beta hybrid quad, for comparison.
//! * [`Formulation::Q4`]: the bilinear displacement quad with 2x2 Gauss, the baseline.

pub mod geometry;
pub mod hybrid;
pub mod pian_sumihara;
pub mod q4;

use crate::error::ShapeError;
use crate::material::Material;
use nalgebra::{SMatrix, SVector};

/// Largest number of nodes of one element.
pub const MAX_NODES: usize = 6;
/// Largest number of dofs of one element.
pub const MAX_DOF: usize = 2 * MAX_NODES;
/// Largest number of stress parameters of one element.
pub const MAX_BETA: usize = 12;

/// Element stiffness storage (leading `2 n x 2 n` block used).
pub type ElementMatrix = SMatrix<f64, MAX_DOF, MAX_DOF>;
/// Element dof vector storage (leading `2 n` entries used).
pub type ElementVector = SVector<f64, MAX_DOF>;

/// Which element formulation to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Formulation {
    /// Assumed-stress hybrid (7 beta; 12 beta on 6-node transition elements). 4 to 6 nodes.
    Hybrid,
    /// Pian-Sumihara 5-beta hybrid quad. 4 nodes.
    PianSumihara,
    /// Bilinear displacement quad, 2x2 Gauss. 4 nodes.
    Q4,
}

impl Formulation {
    /// All formulations, in the order tables list them.
    pub const ALL: [Formulation; 3] = [
        Formulation::Hybrid,
        Formulation::PianSumihara,
        Formulation::Q4,
    ];

    /// Short name used in tables and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Formulation::Hybrid => "hybrid",
            Formulation::PianSumihara => "pian-sumihara",
            Formulation::Q4 => "q4",
        }
    }

    /// Whether this formulation accepts an element with `n` nodes.
    pub fn accepts(self, n: usize) -> bool {
        match self {
            Formulation::Hybrid => (4..=MAX_NODES).contains(&n),
            Formulation::PianSumihara | Formulation::Q4 => n == 4,
        }
    }
}

/// Check an element's shape for `formulation`: node count, finite coordinates, positive area,
/// counter-clockwise order, convexity (tolerances relative to the element size).
pub fn check_shape(formulation: Formulation, coords: &[[f64; 2]]) -> Result<(), ShapeError> {
    let _ = (formulation, coords);
    unimplemented!("element kernels are being written")
}

/// Element stiffness `K` into `out` (leading `2n x 2n` block; the rest is zeroed). Returns the
/// number of element dofs `2n`. Never allocates.
pub fn stiffness_into(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
    out: &mut ElementMatrix,
) -> Result<usize, ShapeError> {
    let _ = (formulation, coords, material, out);
    unimplemented!("element kernels are being written")
}

/// The stress field recovered in one element from its nodal displacements (`beta = H^-1 G q`
/// for the hybrid elements, `D B q` for Q4). Plain data: copy it freely.
#[derive(Debug, Clone, Copy)]
pub struct StressField {
    formulation: Formulation,
    n_nodes: usize,
    coords: [[f64; 2]; MAX_NODES],
    q: ElementVector,
    beta: SVector<f64, MAX_BETA>,
    n_beta: usize,
}

impl StressField {
    /// Stress `[sx, sy, txy]` at a physical point `p` of the element.
    pub fn at(&self, p: [f64; 2]) -> [f64; 3] {
        let _ = (
            p,
            self.formulation,
            self.n_nodes,
            self.coords,
            self.q,
            self.n_beta,
        );
        unimplemented!("element kernels are being written")
    }

    /// Stress at the element centroid.
    pub fn at_centroid(&self) -> [f64; 3] {
        unimplemented!("element kernels are being written")
    }

    /// Traction `Nn sigma` (outward normal) at parameter `s` in `[0, 1]` along boundary edge
    /// `edge` (from local node `edge` to `edge + 1`, cyclically).
    pub fn edge_traction(&self, edge: usize, s: f64) -> [f64; 2] {
        let _ = (edge, s);
        unimplemented!("element kernels are being written")
    }

    /// The stress parameters `beta` (empty for Q4).
    pub fn beta(&self) -> &[f64] {
        &self.beta.as_slice()[..self.n_beta]
    }
}

/// Recover the stress field of an element from its dofs `q` (`2n` values, element dof order).
pub fn recover_stress(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
    q: &[f64],
) -> Result<StressField, ShapeError> {
    let _ = (formulation, coords, material, q);
    unimplemented!("element kernels are being written")
}
