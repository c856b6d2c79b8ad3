//! L2 comparisons of nodal values with a closed form, shared by the contact tests.

/// `(|v_h - exact|, |exact|)` in L2 over the span of the points `v` (sorted by x), `v_h` their
/// linear interpolant: the midpoint rule on 64 sub-intervals of each segment.
pub fn distance_and_norm(v: &[(f64, f64)], exact: impl Fn(f64) -> f64) -> (f64, f64) {
    const SUB: usize = 64;
    let (mut num, mut den) = (0.0, 0.0);
    for w in v.windows(2) {
        let ((x0, p0), (x1, p1)) = (w[0], w[1]);
        let dx = (x1 - x0) / SUB as f64;
        for i in 0..SUB {
            let t = (i as f64 + 0.5) / SUB as f64;
            let (x, p) = (x0 + t * (x1 - x0), p0 + t * (p1 - p0));
            let e = exact(x);
            num += dx * (p - e).powi(2);
            den += dx * e * e;
        }
    }
    (num.sqrt(), den.sqrt())
}

/// Relative L2 distance `|v_h - exact| / |exact|` (see [`distance_and_norm`]).
pub fn relative_error(v: &[(f64, f64)], exact: impl Fn(f64) -> f64) -> f64 {
    let (distance, norm) = distance_and_norm(v, exact);
    distance / norm
}
