//! Mortar integrals of brick faces by projection and clipping (Puso and Laursen 2004): the 3D
//! contact kernel of design document `docs/design/3d-contact.md`, section "Segment-to-segment
//! integration: projection and clipping". Pure geometry: it knows nothing of the rest of
//! `contact/`, only 4-node faces given by their corner coordinates.
//!
//! # Conventions
//! * A **face** ([`Quad`]) is a brick face's 4 corners in the order of
//!   [`crate::solid::geometry::FACES`]: counter-clockwise seen from outside the body, so that
//!   `x_s x x_t` is the outward normal. Its bilinear map is
//!   `x(s, t) = sum_k N_k(s, t) x_k`, `N_k = (1 + s s_k)(1 + t t_k) / 4` with the corners at
//!   `(s_k, t_k) = (-1,-1), (1,-1), (1,1), (-1,1)` ([`shapes`]).
//! * Side **A** carries the multipliers (bilinear over each A face, `N_a`); side **B** is the
//!   opposite surface (bilinear shapes `M_b`). A B face *faces* an A face when their centre
//!   normals point against each other, `n_B . n_0 < 0`; other B faces are ignored, as B
//!   segments that do not face A are in the plane code.
//! * **Auxiliary plane** of an A face ([`AuxPlane`]): through its centre `x_0 = x(0, 0)`,
//!   normal `n_0 = x_s x x_t / |x_s x x_t|` at the centre (for a face with an edge on a
//!   symmetry plane of the model, [`FaceGeometry`] turns `n_0` into the plane:
//!   [`AuxPlane::along`]). Both faces are projected onto it **along `n_0`** (one constant
//!   direction per A face, the 3D twin of the plane code's
//!   projection along a segment's constant normal). A point `y` of the plane has a point
//!   `x^A(y)` on A and a point `x^B(y)` on B that both project to `y`; they differ by a multiple
//!   of `n_0`, the **gap** `g(y) = (x^B - x^A) . n_0`, positive open, negative penetrating.
//! * The overlap polygon of the two projected faces ([`clip::overlap`]) is counter-clockwise
//!   about `n_0`, found by Sutherland-Hodgman clipping with tolerances relative to the faces'
//!   size (vertices within `1e-10 h` of a corner of either face are snapped to it, coincident
//!   vertices merged, overlaps below `1e-12` of the A face's area dropped).
//!
//! # What is integrated ([`mortar::FacePair`])
//! Over the part `Omega` of the A face whose projection lies in the overlap, with the area
//! measure `dA` **of the A face** (not of the plane: on a warped face
//! `dA = |x_s x x_t| / |(x_s x x_t) . n_0| dy`):
//! * `D_ab = integral_Omega N_a N_b dA` (A x A), summed over the B faces:
//!   the covered part of the plane code's `F^A`;
//! * `M_ab = integral_Omega N_a(x^A) M_b(x^B) dA` (A x B): the plane code's `F^B`;
//! * the weighted mismatch `R_a = integral_Omega N_a (x^A - x^B) dA` (a 3-vector, the plane
//!   code's `R_C`; equal to `sum_b D_ab x^A_b - sum_b M_ab x^B_b` to round-off, the rule being
//!   the same for all three) and
//!   the weighted gap `g~_a = integral_Omega N_a g dA = -n_0 . R_a` (`R_a = -g~_a n_0`);
//! * `w_a = integral_Omega N_a dA`, the covered part of the A node's weight (`sum_b M_ab = w_a`
//!   up to round-off since the `M_b` sum to one: the discrete patch-test condition).
//!
//! The whole A face's `D` and weights (over the face, covered or not) are [`mortar::face_mass`];
//! a node's coverage is the ratio of its faces' covered projected area (their overlap
//! polygons') to their projected area, each face's on its own auxiliary plane
//! ([`surface::SurfaceMortar::coverage`]): exact whatever the faces' shapes, where the covered
//! weight (the triangle rule through the inverse bilinear map) and the whole weight (Gauss's
//! rule in `(s, t)`) differ by the rule's error on non-parallelogram faces.
//!
//! # Modules
//! * [`clip`]: checks of a face, the auxiliary plane, projection, convex clipping.
//! * [`geometry`]: [`FaceGeometry`], the pair's geometry behind the contact core's
//!   [`ContactGeometry`](crate::contact::geometry::ContactGeometry) seam.
//! * [`frames`]: nodal normals and tangent frames from one reference direction per surface,
//!   symmetry planes.
//! * [`mortar`]: triangulation, the triangle rule, inverse bilinear maps, the integrals of one
//!   face pair and of one face.
//! * [`pairing`]: the candidate (A face, B face) pairs by a bounding-box grid.
//! * [`surface`]: the integrals assembled over two surfaces (per node), with coverage.
//! * [`topology`]: one side's faces form one connected surface; connected pieces.
//!
//! # Reference
//! M. A. Puso and T. A. Laursen, "A mortar segment-to-segment contact method for large
//! deformation solid mechanics", CMAME 193 (2004) 601-629.

pub mod clip;
pub mod frames;
pub mod geometry;
pub mod mortar;
pub mod pairing;
pub mod surface;
pub mod topology;

pub use clip::{AuxPlane, Overlap, overlap};
pub use frames::{NodeFrame, SurfaceFrames, SymmetryPlane};
pub use geometry::FaceGeometry;
pub use mortar::{FaceMass, FacePair, face_mass, face_pair};
pub use pairing::pair_faces;
pub use surface::{SurfaceFaces, SurfaceMortar};
pub use topology::{Pieces, check_surface};

/// A brick face: 4 corners, counter-clockwise seen from outside (see the module docs).
pub type Quad = [[f64; 3]; 4];

/// Corner parameters `(s_k, t_k)` of a face.
pub const CORNERS: [[f64; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];

/// Bilinear shapes `N_k(s, t) = (1 + s s_k)(1 + t t_k) / 4`.
pub fn shapes(s: f64, t: f64) -> [f64; 4] {
    CORNERS.map(|[sk, tk]| 0.25 * (1.0 + s * sk) * (1.0 + t * tk))
}

/// Derivatives `(dN_k/ds, dN_k/dt)`.
pub fn shape_derivatives(s: f64, t: f64) -> [[f64; 2]; 4] {
    CORNERS.map(|[sk, tk]| [0.25 * sk * (1.0 + t * tk), 0.25 * tk * (1.0 + s * sk)])
}
