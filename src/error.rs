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
    /// An interior angle above 180 degrees (beyond a small tolerance).
    #[error("non-convex element (interior angle above 180 degrees at local node {node})")]
    NonConvex {
        /// Local node index (0-based) of the reflex corner.
        node: usize,
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
    /// A contact increment failed (no convergence, cycling contact set, contact reaching the
    /// end of a surface); the last converged state is kept.
    #[error("contact: {0}")]
    Contact(String),
    /// A caller-supplied callback (a host's solver, an iteration monitor) failed or asked to
    /// stop; the last converged state is kept.
    #[error("callback: {0}")]
    Callback(String),
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
