//! Writing an element routine's results (plane, axisymmetric and brick alike): every value is
//! checked finite before anything is written, and a non-finite one is reported with the likely
//! cause (see the [parent module](super) for the conventions).

use super::{Fail, write_doubles};

/// The likely cause of a non-finite stress, traction or matrix of a plane element.
pub(super) const OUTSIDE_ELEMENT: &str = "is the point inside the element?";
/// The likely cause of a non-finite stress, traction or matrix of a brick.
pub(super) const OUTSIDE_BRICK: &str = "is the point inside the brick?";
/// The likely cause of a non-finite load, volume or quality.
pub(super) const OVERFLOW: &str = "values beyond the range of doubles";

/// Check that every one of `values` is finite: else `HYCON_ERROR_INVALID_ARGUMENT` saying
/// "`what` is not finite (`cause`)".
pub(super) fn check_results(values: &[f64], what: &str, cause: &str) -> Result<(), Fail> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(Fail::invalid(format!("{what} is not finite ({cause})")))
    }
}

/// [`check_results`], then copy `values` to `out`.
///
/// # Safety
/// `out` must have been checked with `check_output` or `check_pointer` and be writable for
/// `values.len()` doubles.
pub(super) unsafe fn write_results(
    out: *mut f64,
    values: &[f64],
    what: &str,
    cause: &str,
) -> Result<(), Fail> {
    check_results(values, what, cause)?;
    // SAFETY: the caller's contract.
    unsafe { write_doubles(out, values) };
    Ok(())
}
