//! When an iterate has converged (docs/method.md, "The contact iteration"): a test of parts
//! that a geometry extends rather than edits.
//!
//! In the plane and in axisymmetry an iterate has converged when the rules propose no change
//! (the states repeat) and the change ratio `R` of the contact displacements
//! (`change_ratio`, `checks.rs`) is at most the tolerance: the small system then holds every
//! active node's rows exactly and the states hold the contact conditions to the rules'
//! tolerances. A 3D geometry, whose slip directions turn continuously, adds a residual of the
//! contact conditions ([`Iterate::residual`]), held to its own tolerance.

/// What an iterate is judged by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::contact::iteration) struct Iterate {
    /// How many nodes the rules' proposal changes.
    pub(in crate::contact::iteration) changes: usize,
    /// The change ratio `R` of the iterate.
    pub(in crate::contact::iteration) r: f64,
    /// The residual of the contact conditions relative to its scale, where the geometry
    /// measures one (`None` in the plane: the states repeating decides).
    pub(in crate::contact::iteration) residual: Option<f64>,
}

/// The convergence test: the states repeat, `R <= tolerance`, and the residual, where the
/// geometry measures one, `<= residual_tolerance`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::contact::iteration) struct Convergence {
    /// The tolerance of `R` (`ContactOptions::tolerance`).
    pub(in crate::contact::iteration) tolerance: f64,
    /// The tolerance of the residual.
    pub(in crate::contact::iteration) residual_tolerance: f64,
}

impl Convergence {
    /// The plane's test: `R` and (where measured) the residual held to `tolerance`.
    pub(in crate::contact::iteration) fn new(tolerance: f64) -> Self {
        Convergence {
            tolerance,
            residual_tolerance: tolerance,
        }
    }

    /// Whether `iterate` has converged.
    pub(in crate::contact::iteration) fn reached(&self, iterate: &Iterate) -> bool {
        iterate.changes == 0
            && iterate.r <= self.tolerance
            && iterate
                .residual
                .is_none_or(|residual| residual <= self.residual_tolerance)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The states must repeat and `R` be within the tolerance; a residual, where the geometry
    /// measures one, must be within its own.
    #[test]
    fn convergence_needs_every_part() {
        let test = Convergence {
            tolerance: 1e-8,
            residual_tolerance: 1e-6,
        };
        let iterate = |changes, r, residual| Iterate {
            changes,
            r,
            residual,
        };
        assert!(test.reached(&iterate(0, 1e-8, None)));
        assert!(!test.reached(&iterate(1, 0.0, None)), "a state changes");
        assert!(!test.reached(&iterate(0, 2e-8, None)), "R too large");
        assert!(test.reached(&iterate(0, 0.0, Some(1e-6))));
        assert!(!test.reached(&iterate(0, 0.0, Some(2e-6))), "the residual");
        assert_eq!(Convergence::new(1e-7).residual_tolerance, 1e-7);
    }
}
