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
//!
//! # Analysis kinds
//! The kernels read the analysis kind from the material. In plane strain and plane stress every
//! integral is weighted by the thickness `t`. In axisymmetry ([`Analysis::Axisymmetric`],
//! `x = r`, `y = z`) it is weighted by `2 pi r` and only 4-node elements are available:
//! [`Formulation::Hybrid`] becomes the 7-beta axisymmetric hybrid element and
//! [`Formulation::Q4`] the axisymmetric bilinear quad (see [`axisymmetric`]); Pian-Sumihara and
//! the 5- and 6-node transition elements are rejected ([`ShapeError::Unsupported`]).

pub mod axisymmetric;
pub mod geometry;
pub mod hybrid;
pub mod loads;
pub mod pian_sumihara;
pub mod q4;
pub mod quality;

use crate::error::{Error, ShapeError};
use crate::fem::{Analysis, hybrid as condense};
use crate::material::Material;
use geometry::{Bilinear, Frame, PolygonInfo, check_natural, is_corner};
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
/// `G` of a hybrid element with `NB` stress parameters (leading `NB x 2n` block used).
pub type CouplingMatrix<const NB: usize> = SMatrix<f64, NB, MAX_DOF>;

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

/// Check an element's shape for `formulation`: node count, finite coordinates, positive area
/// (counter-clockwise nodes), convexity; tolerances relative to the element size.
///
/// Q4 and Pian-Sumihara need 4 true corners. The hybrid element takes any convex polygon of 4 to
/// 6 nodes with at least 3 true corners; nodes on a straight edge (the mid-side nodes of the
/// transition elements) are allowed.
pub fn check_shape(formulation: Formulation, coords: &[[f64; 2]]) -> Result<(), ShapeError> {
    checked(formulation, coords).map(|_| ())
}

/// [`check_shape`] plus what the material's analysis kind needs: in axisymmetry, 4 nodes, the
/// hybrid or Q4 formulation, and every node at `r = x >= 0` (round-off of the element size
/// below zero is accepted, for nodes on the axis).
pub fn check_element(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
) -> Result<(), ShapeError> {
    checked_for(formulation, coords, material).map(|_| ())
}

fn checked_for(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
) -> Result<(PolygonInfo, StressFamily), ShapeError> {
    let family = StressFamily::of(formulation, coords.len(), material.analysis)?;
    let info = checked(formulation, coords)?;
    let size = info.area.sqrt();
    if let Some(node) = material.analysis.node_off_half_plane(coords, size) {
        return Err(ShapeError::NegativeRadius { node });
    }
    Ok((info, family))
}

fn checked(formulation: Formulation, coords: &[[f64; 2]]) -> Result<PolygonInfo, ShapeError> {
    if !formulation.accepts(coords.len()) {
        return Err(ShapeError::NodeCount {
            got: coords.len(),
            expected: match formulation {
                Formulation::Hybrid => "4 to 6",
                Formulation::PianSumihara | Formulation::Q4 => "4",
            },
        });
    }
    let min_corners = match formulation {
        Formulation::Hybrid => 3,
        Formulation::PianSumihara | Formulation::Q4 => 4,
    };
    geometry::check_polygon(coords, min_corners)
}

/// Which stress field a checked element uses: the formulation, the node count and the analysis
/// kind together.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum StressFamily {
    /// Bilinear displacement, no stress parameters.
    Q4,
    /// Pian-Sumihara's 5 beta.
    PianSumihara,
    /// Kubomura-Pian, 7 beta.
    Hybrid7,
    /// Kubomura-Pian, 12 beta (6 nodes).
    Hybrid12,
    /// Axisymmetric bilinear displacement quad.
    AxiQ4,
    /// Axisymmetric hybrid, 7 beta.
    AxiHybrid,
}

impl StressFamily {
    /// The family of `formulation` on `n_nodes` nodes in `analysis`; the analysis kind's
    /// restrictions checked (axisymmetry: 4 nodes, no Pian-Sumihara). The node count is checked
    /// against the formulation by [`check_shape`].
    fn of(
        formulation: Formulation,
        n_nodes: usize,
        analysis: Analysis,
    ) -> Result<Self, ShapeError> {
        match (analysis, formulation) {
            (Analysis::Axisymmetric, Formulation::PianSumihara) => Err(ShapeError::Unsupported(
                "the Pian-Sumihara element is not available in axisymmetric analysis (use the \
                 hybrid element or Q4)",
            )),
            (Analysis::Axisymmetric, _) if n_nodes != 4 => Err(ShapeError::Unsupported(
                "axisymmetric analysis takes 4-node elements only (the 5- and 6-node transition \
                 elements have no axisymmetric stress field): use a conforming mesh",
            )),
            (Analysis::Axisymmetric, Formulation::Q4) => Ok(StressFamily::AxiQ4),
            (Analysis::Axisymmetric, _) => Ok(StressFamily::AxiHybrid),
            (_, Formulation::Q4) => Ok(StressFamily::Q4),
            (_, Formulation::PianSumihara) => Ok(StressFamily::PianSumihara),
            (_, Formulation::Hybrid) if hybrid::n_beta(n_nodes) == 12 => Ok(StressFamily::Hybrid12),
            (_, Formulation::Hybrid) => Ok(StressFamily::Hybrid7),
        }
    }

    /// Whether the field lives in the element's physical frame (the plane hybrid element's
    /// Airy field) rather than in the natural coordinates of its bilinear map.
    fn in_physical_frame(self) -> bool {
        matches!(self, StressFamily::Hybrid7 | StressFamily::Hybrid12)
    }
}

/// `K = G^T H^-1 G` into `out` ([`condense::stiffness_into`]).
fn hybrid_stiffness<const NB: usize>(
    (h, g): (SMatrix<f64, NB, NB>, CouplingMatrix<NB>),
    out: &mut ElementMatrix,
) -> Result<(), ShapeError> {
    condense::stiffness_into(h, &g, out)
}

/// `beta = H^-1 G q` into the leading `NB` entries of `beta` ([`condense::stress_parameters`]).
fn hybrid_beta<const NB: usize>(
    (h, g): (SMatrix<f64, NB, NB>, CouplingMatrix<NB>),
    q: &ElementVector,
    beta: &mut SVector<f64, MAX_BETA>,
) -> Result<usize, ShapeError> {
    let b = condense::stress_parameters(h, &g, q)?;
    beta.fixed_rows_mut::<NB>(0).copy_from(&b);
    Ok(NB)
}

/// Element stiffness `K` into `out` (leading `2n x 2n` block; the rest is zeroed). Returns the
/// number of element dofs `2n`. Never allocates.
///
/// Hybrid elements: `K = G^T H^-1 G`, computed as `W^T W` with `W = L^-1 G`, `H = L L^T`
/// (no explicit inverse; symmetric by construction). Q4: `K = integral of B^T D B dV`. The
/// volume element is `dV = measure dA` ([`Material::measure`]: `t`, or `2 pi r`).
pub fn stiffness_into(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
    out: &mut ElementMatrix,
) -> Result<usize, ShapeError> {
    let (info, family) = checked_for(formulation, coords, material)?;
    let map = || Bilinear::new(coords);
    match family {
        StressFamily::Q4 => q4::stiffness_into(&map(), material, out),
        StressFamily::AxiQ4 => axisymmetric::q4_stiffness_into(&map(), material, out),
        StressFamily::AxiHybrid => hybrid_stiffness(
            axisymmetric::matrices(&map(), &Frame::new(&info), material),
            out,
        )?,
        StressFamily::PianSumihara => {
            hybrid_stiffness(pian_sumihara::matrices(&map(), material), out)?
        }
        StressFamily::Hybrid7 => {
            hybrid_stiffness(hybrid::matrices::<7>(coords, &info, material), out)?
        }
        StressFamily::Hybrid12 => {
            hybrid_stiffness(hybrid::matrices::<12>(coords, &info, material), out)?
        }
    }
    Ok(2 * coords.len())
}

/// The stress field recovered in one element from its nodal displacements (`beta = H^-1 G q`
/// for the hybrid elements, `D B q` for Q4). Plain data: copy it freely.
#[derive(Debug, Clone, Copy)]
pub struct StressField {
    family: StressFamily,
    material: Material,
    n_nodes: usize,
    coords: [[f64; 2]; MAX_NODES],
    frame: Frame,
    q: ElementVector,
    beta: SVector<f64, MAX_BETA>,
    n_beta: usize,
}

impl StressField {
    /// The in-plane (meridian) stress `[sx, sy, txy]` (axisymmetry: `[sigma_r, sigma_z,
    /// tau_rz]`) at a physical point `p` of the element.
    pub fn at(&self, p: [f64; 2]) -> [f64; 3] {
        let [a, b, c, _] = self.at_full(p);
        [a, b, c]
    }

    /// All four stress components at a physical point `p`: `[sx, sy, txy, sz]` in plane
    /// analyses (`sz = nu (sx + sy)` in plane strain, 0 in plane stress), `[sigma_r, sigma_z,
    /// tau_rz, sigma_theta]` in axisymmetry.
    pub fn at_full(&self, p: [f64; 2]) -> [f64; 4] {
        if self.family.in_physical_frame() {
            return self.with_out_of_plane(hybrid::stress(&self.frame, self.beta(), p));
        }
        let map = Bilinear::new(&self.coords);
        let [xi, eta] = map.inverse(p);
        self.at_natural(&map, xi, eta)
    }

    fn with_out_of_plane(&self, s: [f64; 3]) -> [f64; 4] {
        [
            s[0],
            s[1],
            s[2],
            self.material.out_of_plane_stress(s).unwrap_or(0.0),
        ]
    }

    /// The four components at natural coordinates of the bilinear map (not for the plane
    /// hybrid element, whose field lives in its frame).
    fn at_natural(&self, map: &Bilinear, xi: f64, eta: f64) -> [f64; 4] {
        let q = self.q.as_slice();
        match self.family {
            StressFamily::AxiHybrid => {
                let p = map.point(xi, eta);
                axisymmetric::stress(map, &self.frame, self.beta(), xi, eta, p)
            }
            StressFamily::AxiQ4 => axisymmetric::q4_stress(map, &self.material, q, xi, eta),
            StressFamily::PianSumihara => {
                self.with_out_of_plane(pian_sumihara::stress(map, self.beta(), xi, eta))
            }
            StressFamily::Q4 | StressFamily::Hybrid7 | StressFamily::Hybrid12 => {
                self.with_out_of_plane(q4::stress(map, &self.material, q, xi, eta))
            }
        }
    }

    /// All four stress components (as [`StressField::at_full`]) at natural coordinates
    /// `(xi, eta)` in `[-1, 1]^2` of the element's bilinear map `x(xi, eta)`: the map of its 4
    /// nodes, and for the 5- and 6-node transition elements the map of its 4 true corners in
    /// node order (the first corner at `(-1, -1)`, the next at `(1, -1)`, then `(1, 1)`,
    /// `(-1, 1)`), the mid-side nodes not taking part. The plane hybrid element's field lives
    /// in physical coordinates: there this is the stress at the mapped point `x(xi, eta)`; the
    /// other elements evaluate their field at `(xi, eta)` directly.
    ///
    /// Errors: coordinates not finite or outside `[-1, 1]`; a transition element with 3 true
    /// corners (a triangle has no bilinear map).
    pub fn at_natural_point(&self, xi: f64, eta: f64) -> crate::error::Result<[f64; 4]> {
        check_natural(&[xi, eta])?;
        let map = self.natural_map()?;
        if self.family.in_physical_frame() {
            return Ok(self.at_full(map.point(xi, eta)));
        }
        Ok(self.at_natural(&map, xi, eta))
    }

    /// The bilinear map of [`StressField::at_natural_point`].
    fn natural_map(&self) -> crate::error::Result<Bilinear> {
        let coords = &self.coords[..self.n_nodes];
        if self.n_nodes == 4 {
            return Ok(Bilinear::new(coords));
        }
        let mut corners = [[0.0; 2]; geometry::MAX_CORNERS];
        let mut count = 0;
        for i in (0..self.n_nodes).filter(|&i| is_corner(coords, i)) {
            if let Some(c) = corners.get_mut(count) {
                *c = coords[i];
            }
            count += 1;
        }
        if count != geometry::MAX_CORNERS {
            return Err(Error::InvalidInput(format!(
                "a {}-node element with {} true corners has no natural coordinates (the \
                 bilinear map needs 4 corners)",
                self.n_nodes, count
            )));
        }
        Ok(Bilinear::new(&corners))
    }

    /// Stress at the element's centre: the area centroid for the plane hybrid element, where it
    /// equals the first three `beta` (the mean stress of the linear part); `xi = eta = 0` for the
    /// quads and the axisymmetric elements.
    pub fn at_centre(&self) -> [f64; 3] {
        let [a, b, c, _] = self.at_centre_full();
        [a, b, c]
    }

    /// All four components at the centre (see [`StressField::at_full`], [`StressField::at_centre`]).
    pub fn at_centre_full(&self) -> [f64; 4] {
        if self.family.in_physical_frame() {
            self.at_full(self.frame.centre)
        } else {
            self.at_natural(&Bilinear::new(&self.coords), 0.0, 0.0)
        }
    }

    /// Traction `Nn sigma` (outward normal `n`: `[nx sx + ny txy, nx txy + ny sy]`) at parameter
    /// `s` in `[0, 1]` along boundary edge `edge` (from local node `edge` to `edge + 1`,
    /// cyclically). Panics if `edge` is not below the node count.
    pub fn edge_traction(&self, edge: usize, s: f64) -> [f64; 2] {
        assert!(
            edge < self.n_nodes,
            "edge {edge} of a {}-node element",
            self.n_nodes
        );
        let (a, b) = (self.coords[edge], self.coords[(edge + 1) % self.n_nodes]);
        let ([nx, ny], _) = geometry::edge_normal(a, b);
        let p = [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
        let [sx, sy, txy] = self.at(p);
        [nx * sx + ny * txy, nx * txy + ny * sy]
    }

    /// The stress parameters `beta` (empty for Q4).
    pub fn beta(&self) -> &[f64] {
        &self.beta.as_slice()[..self.n_beta]
    }

    /// Number of nodes of the element.
    pub fn n_nodes(&self) -> usize {
        self.n_nodes
    }
}

/// Recover the stress field of an element from its dofs `q` (`2n` values, element dof order).
/// Panics if `q` is shorter than `2n`.
pub fn recover_stress(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
    q: &[f64],
) -> Result<StressField, ShapeError> {
    let (info, family) = checked_for(formulation, coords, material)?;
    let n = coords.len();
    let mut field = StressField {
        family,
        material: *material,
        n_nodes: n,
        coords: [[0.0; 2]; MAX_NODES],
        frame: Frame::new(&info),
        q: ElementVector::zeros(),
        beta: SVector::zeros(),
        n_beta: 0,
    };
    field.coords[..n].copy_from_slice(coords);
    field.q.as_mut_slice()[..2 * n].copy_from_slice(&q[..2 * n]);
    let (q, beta) = (&field.q, &mut field.beta);
    let map = || Bilinear::new(coords);
    field.n_beta = match family {
        StressFamily::Q4 | StressFamily::AxiQ4 => 0,
        StressFamily::AxiHybrid => hybrid_beta(
            axisymmetric::matrices(&map(), &field.frame, material),
            q,
            beta,
        )?,
        StressFamily::PianSumihara => {
            hybrid_beta(pian_sumihara::matrices(&map(), material), q, beta)?
        }
        StressFamily::Hybrid7 => {
            hybrid_beta(hybrid::matrices::<7>(coords, &info, material), q, beta)?
        }
        StressFamily::Hybrid12 => {
            hybrid_beta(hybrid::matrices::<12>(coords, &info, material), q, beta)?
        }
    };
    Ok(field)
}
