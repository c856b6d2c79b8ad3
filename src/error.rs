//! Errors of the safe Rust core.
//!
//! Every error says *where* it happened (element index, node, dof, body) so that a host code can
//! point its user at the offending input. The C ABI maps each variant to a status code
//! (see [`crate::ffi`]).

use thiserror::Error;

/// What is wrong with one element's geometry or definition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
pub enum ShapeError {
    /// A coordinate is NaN or infinite.
    #[error("non-finite node coordinate")]
    NonFinite,
    /// The node count does not fit the formulation (4 for Q4 and Pian-Sumihara, 4 to 6 for the
    /// hybrid element).
    #[error("{got} nodes, this formulation takes {expected}")]
    NodeCount {
        /// Node count received.
        got: usize,
        /// What the formulation accepts, in words.
        expected: &'static str,
    },
    /// Zero (or round-off) area, or two coincident nodes.
    #[error("degenerate element (zero area or coincident nodes)")]
    Degenerate,
    /// Nodes given clockwise, or a bilinear map whose Jacobian changes sign.
    #[error("inverted element (nodes must be counter-clockwise)")]
    Inverted,
    /// More than 4 true corners: a 5- or 6-node element is a quadrilateral with mid-side
    /// nodes on straight edges, not a general polygon.
    #[error(
        "{corners} corners: an element has at most 4, its other nodes lie mid-side on straight \
         edges"
    )]
    Corners {
        /// The number of true corners found.
        corners: usize,
    },
    /// An interior angle above 180 degrees (beyond a small tolerance).
    #[error("non-convex element (interior angle above 180 degrees at local node {node})")]
    NonConvex {
        /// Local node index (0-based) of the reflex corner.
        node: usize,
    },
    /// A brick (8-node solid) whose Jacobian is not positive at a corner: a re-entrant,
    /// collapsed or self-crossing hexahedron, or one with its bottom and top faces swapped.
    #[error(
        "Jacobian not positive at local node {node} (nodes 0-3 counter-clockwise seen from \
         nodes 4-7, node 4 + i above node i)"
    )]
    InvertedCorner {
        /// Local node index (0-based) where `det J <= 0`.
        node: usize,
    },
    /// A brick face whose two triangle halves (split along either diagonal) differ in normal
    /// by more than [`crate::solid::WARP_LIMIT_DEGREES`] (the strict shape policy only).
    #[error("face {face} is warped beyond the limit (see the face numbering of the brick)")]
    WarpedFace {
        /// Local face index (0-based).
        face: usize,
    },
    /// A brick whose Jacobian is not positive (relative to the longest edge cubed) at a point
    /// of its 2x2x2 integration rule: the element cannot be computed (every shape policy).
    #[error(
        "Jacobian not positive at the integration point nearest local node {node} (nodes 0-3 \
         counter-clockwise seen from nodes 4-7, node 4 + i above node i)"
    )]
    InvertedIntegrationPoint {
        /// The local node (0-based) nearest that integration point.
        node: usize,
    },
    /// In axisymmetry, a node with a negative radius `x < 0` (beyond round-off of the element
    /// size): the section must lie on the side `r >= 0` of the axis.
    #[error("node at local index {node} has a negative radius (axisymmetric: x = r >= 0)")]
    NegativeRadius {
        /// Local node index (0-based).
        node: usize,
    },
    /// The formulation or node count is not available for the material's analysis kind.
    #[error("{0}")]
    Unsupported(&'static str),
}

/// A distortion of a brick that the default shape policy accepts and the strict one rejects
/// (see [`crate::solid::ShapePolicy`]): the results are computed and exact for linear fields, but
/// the mesh deserves a look.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum ShapeWarning {
    /// The Jacobian is not positive at a corner although it is at every integration point.
    #[error(
        "Jacobian not positive at local node {node} (det J = {relative:.2e} h^3, h the longest \
         edge; positive at every integration point)"
    )]
    CornerJacobian {
        /// The local node (0-based) with the smallest corner Jacobian.
        node: usize,
        /// Its `det J / h^3`.
        relative: f64,
    },
    /// A face warped beyond [`crate::solid::WARP_LIMIT_DEGREES`] (the measure:
    /// [`crate::solid::ShapeReport::warp_degrees`]).
    #[error(
        "face {face} is warped by {degrees:.1} degrees (angle between the normals of its \
         triangle halves; the limit is {limit} degrees)",
        limit = crate::solid::WARP_LIMIT_DEGREES
    )]
    WarpedFace {
        /// The local face (0-based) with the largest warp.
        face: usize,
        /// Its warp in degrees.
        degrees: f64,
    },
}

/// The crate-wide error type.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A bad element, with its index in the mesh (`None` for a single-element call).
    #[error("element {}: {kind}", fmt_index(*.element))]
    Element {
        /// Index of the element in the mesh, if known.
        element: Option<usize>,
        /// What is wrong with it.
        kind: ShapeError,
    },
    /// An invalid material (E <= 0, nu outside (-1, 0.5), thickness <= 0, non-finite values).
    #[error("invalid material: {0}")]
    Material(String),
    /// Any other invalid argument: lengths, indices, non-finite loads, unknown node ids.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// The stiffness is singular: a body is not held against rigid motion.
    #[error("singular system: {0}")]
    Singular(String),
    /// The sparse factorization failed for a numerical reason.
    #[error("linear solver failed: {0}")]
    Solver(String),
    /// A contact increment failed; the last converged state is kept.
    #[error("contact: {0}")]
    Contact(ContactError),
    /// A caller-supplied callback (a host's solver, an iteration monitor) failed or asked to
    /// stop; the last converged state is kept.
    #[error("callback: {0}")]
    Callback(String),
}

/// Why a contact increment failed. Every variant leaves the analysis at its last converged
/// state; node ids are the caller's. Later versions may add variants.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ContactError {
    /// The iteration cap was reached before the contact set settled and `R` fell below the
    /// tolerance.
    #[error(
        "increment {increment}: no convergence in {iterations} iterations (last R = {last_r:.3e})"
    )]
    NoConvergence {
        /// Increment number (1-based).
        increment: usize,
        /// The iteration cap.
        iterations: usize,
        /// The convergence measure of the last iteration.
        last_r: f64,
    },
    /// A contact-state set returned that was seen before in the increment, and it was not a
    /// benign alternation the locks resolve (or they were used up).
    #[error(
        "increment {increment}: the contact set cycles (iteration {iteration} returns to the set \
         of iteration {returns_to}; node {node} flips)"
    )]
    Cycling {
        /// Increment number (1-based).
        increment: usize,
        /// The iteration at which the set returned.
        iteration: usize,
        /// The earlier iteration whose set it is.
        returns_to: usize,
        /// A node whose state differs between the two.
        node: usize,
    },
    /// A node locked open after alternating between open and closed penetrates at convergence
    /// by more than a hair: the alternation was not an edge effect.
    #[error(
        "increment {increment}: the contact set cycles: node {node} alternates between open and \
         closed, and open it penetrates by {depth:.3e} ({relative:.1e} of the increment's \
         motion): reduce the load step"
    )]
    EdgePenetration {
        /// Increment number (1-based).
        increment: usize,
        /// The A node.
        node: usize,
        /// Its penetration (a length, positive).
        depth: f64,
        /// The penetration over the increment's motion.
        relative: f64,
    },
    /// A node locked in slip after alternating between stick and slip slides against its
    /// friction at convergence by more than a hair: it did not sit on the edge of the friction
    /// cone, and the state would break the friction law (the traction pushing along the slip).
    #[error(
        "increment {increment}: the contact set cycles: node {node} alternates between stick \
         and slip, and in slip it slides against its friction by {slip:.3e} ({relative:.1e} of \
         the increment's motion)"
    )]
    SlipReversal {
        /// Increment number (1-based).
        increment: usize,
        /// The A node.
        node: usize,
        /// How far it slides against its friction since the increment began (a length,
        /// positive).
        slip: f64,
        /// That slide over the increment's motion.
        relative: f64,
    },
    /// A converged state violates the discrete contact conditions by more than
    /// `CONDITION_LIMIT` (1e-4) of the problem's scale (gaps against the gap scale, tractions
    /// against the largest, slips against the increment's motion): the rules settled on a
    /// state that is not a solution.
    #[error(
        "increment {increment}: the converged state violates the contact conditions at node \
         {node}: {condition} ({relative:.1e} of the problem's scale)"
    )]
    ConditionViolated {
        /// Increment number (1-based).
        increment: usize,
        /// The A node.
        node: usize,
        /// Which condition, in words.
        condition: &'static str,
        /// The violation relative to its scale.
        relative: f64,
    },
    /// A node penetrates the opposite surface where the pairing does not see it: a B node
    /// deeper than the search distance below an open A element, or an A node with no B
    /// element within the search distance (one surface pushed through the other).
    #[error(
        "node {node} penetrates the opposite surface's {} by {depth:.3e}, beyond what the \
         pairing sees (search distance {search_distance:.3e}): reduce the load step or widen \
         search_distance",
        element_name(element)
    )]
    BeyondSearchDistance {
        /// The penetrating node (of A or of B).
        node: usize,
        /// The nodes of the opposite surface's element it penetrates: a segment's 2 (plane
        /// and axisymmetric), a face's 4 (3D).
        element: Vec<usize>,
        /// The penetration (a length, positive).
        depth: f64,
        /// The search distance it exceeds.
        search_distance: f64,
    },
    /// Under finite kinematics an iterate moves the contact nodes so far that double precision
    /// no longer resolves the surfaces at their current positions: an element's size, or a
    /// node's distance to the opposite surface, is below the round-off of the coordinates
    /// (a press of `1e16` body sizes in one increment, say). The geometry cannot be evaluated
    /// there, so no contact state can be judged: the surfaces are beyond what the pairing
    /// sees.
    #[error(
        "increment {increment}: node {node} moves {motion:.3e}, beyond what the pairing sees: \
         at that distance double precision does not resolve the contact surfaces (an element \
         {length:.3e} in size): reduce the load step"
    )]
    Unresolved {
        /// Increment number (1-based).
        increment: usize,
        /// The element's node that moved most (the caller's id).
        node: usize,
        /// The node's displacement in the increment (a length).
        motion: f64,
        /// The element's size in the reference configuration (a segment's length).
        length: f64,
    },
    /// An active A node's support is not fully covered by the opposite surface (an integral
    /// over a hole would be wrong).
    #[error(
        "contact node {node} is active but {:.1e} of its support is not covered by the opposite \
         surface: extend the B surface",
        1.0 - coverage
    )]
    Uncovered {
        /// The A node.
        node: usize,
        /// The covered fraction of its support, below 1.
        coverage: f64,
    },
    /// The displacements of an iterate are not finite: the loads or prescribed values, finite
    /// themselves, overflow double precision on the way (a load of 1e300, say).
    #[error(
        "increment {increment}: the displacements are not finite at iteration {iteration} (the \
         loads or prescribed values overflow double precision: rescale the units)"
    )]
    NonFinite {
        /// Increment number (1-based).
        increment: usize,
        /// The iteration (0: the solve for the loads, before any contact force).
        iteration: usize,
    },
    /// Under small kinematics an active node slid so far that the frozen pairing misplaces
    /// the opposite surface by a noticeable part of the normal approach.
    #[error(
        "increment {increment}: node {node} slid {slip:.3e} along the opposite surface, which \
         moves its gap by about {percent:.1}% of the normal approach: beyond small kinematics \
         (the pairing frozen in the reference configuration): use finite kinematics",
        percent = 100.0 * relative
    )]
    SmallSlidingExceeded {
        /// Increment number (1-based).
        increment: usize,
        /// The A node.
        node: usize,
        /// Its tangential slip relative to B since the reference configuration (in the plane
        /// and in axisymmetry its component along `s`, on a 3D face its length).
        slip: f64,
        /// The gap change it causes over the normal approach.
        relative: f64,
    },
}

impl From<ContactError> for Error {
    fn from(e: ContactError) -> Self {
        Error::Contact(e)
    }
}

/// A contact element named by its nodes: a segment `a -> b` (2 nodes), a face `(a, b, c, d)`.
fn element_name(nodes: &[usize]) -> String {
    match nodes {
        [a, b] => format!("segment {a} -> {b}"),
        _ => {
            let ids: Vec<String> = nodes.iter().map(usize::to_string).collect();
            format!("face ({})", ids.join(", "))
        }
    }
}

fn fmt_index(e: Option<usize>) -> String {
    e.map_or_else(|| "(single)".to_string(), |i| i.to_string())
}

impl Error {
    /// Attach the element index to an element error.
    pub fn at_element(kind: ShapeError, element: usize) -> Self {
        Error::Element {
            element: Some(element),
            kind,
        }
    }
}

impl From<ShapeError> for Error {
    fn from(kind: ShapeError) -> Self {
        Error::Element {
            element: None,
            kind,
        }
    }
}

/// Result alias used throughout the crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;
