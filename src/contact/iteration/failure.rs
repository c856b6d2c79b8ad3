//! One classification of a failed increment with its remedy, read by the fallback
//! (`iteration.rs`, `fallback.rs`) and by the cutback (`cutback.rs`) alike.

use crate::error::{ContactError, Error};

/// What may settle an increment that failed with an error.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Failure {
    /// The rules did not settle: the iteration cap, a cycling contact set, a node locked in
    /// slip sliding against its friction, a node locked open penetrating, a converged state
    /// violating the contact conditions. The fallback's states may settle it, and a shorter
    /// step may.
    Unsettled,
    /// The step reaches beyond what the geometry resolves: a node beyond the pairing's reach,
    /// positions the geometry cannot resolve. A shorter step may settle it; the fallback's
    /// states (of the same geometry) cannot.
    TooLong,
    /// Nothing the iteration may retry: bad input, a singular system, non-finite values, a
    /// node left uncovered, small kinematics exceeded, a host's or monitor's failure.
    Final,
}

impl Failure {
    /// The class of `e`.
    pub(super) fn of(e: &Error) -> Self {
        match e {
            Error::Contact(
                ContactError::NoConvergence { .. }
                | ContactError::Cycling { .. }
                | ContactError::SlipReversal { .. }
                | ContactError::EdgePenetration { .. }
                | ContactError::ConditionViolated { .. },
            ) => Failure::Unsettled,
            Error::Contact(
                ContactError::BeyondSearchDistance { .. } | ContactError::Unresolved { .. },
            ) => Failure::TooLong,
            _ => Failure::Final,
        }
    }

    /// Whether the increment is tried again from the fallback's states.
    pub(super) fn fallback_may_settle(self) -> bool {
        self == Failure::Unsettled
    }

    /// Whether the cutback tries a shorter step.
    pub(super) fn shorter_step_may_settle(self) -> bool {
        self != Failure::Final
    }
}
