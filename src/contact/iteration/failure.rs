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

#[cfg(test)]
mod tests {
    use super::*;

    /// The rules' failures go to the fallback and the cutback, a step too long to the cutback
    /// only, the rest to neither.
    #[test]
    fn each_failure_has_one_remedy() {
        let unsettled: Error = ContactError::NoConvergence {
            increment: 1,
            iterations: 60,
            last_r: 1.0,
        }
        .into();
        let too_long: Error = ContactError::BeyondSearchDistance {
            node: 3,
            segment: [1, 2],
            depth: 1.0,
            search_distance: 0.5,
        }
        .into();
        let last = Error::Singular("K".into());
        assert_eq!(Failure::of(&unsettled), Failure::Unsettled);
        assert_eq!(Failure::of(&too_long), Failure::TooLong);
        assert_eq!(Failure::of(&last), Failure::Final);
        let remedies = |e: &Error| {
            let f = Failure::of(e);
            (f.fallback_may_settle(), f.shorter_step_may_settle())
        };
        assert_eq!(remedies(&unsettled), (true, true));
        assert_eq!(remedies(&too_long), (false, true));
        assert_eq!(remedies(&last), (false, false));
    }
}
