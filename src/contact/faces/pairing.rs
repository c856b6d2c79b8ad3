//! Candidate pairs of A and B faces: those whose bounding boxes, A's widened by the search
//! distance, intersect, found with a uniform grid.

use super::Quad;
use crate::error::{Error, Result};
use std::collections::HashMap;

/// Axis-aligned bounding box `[min, max]` of a face, widened by `pad` on every side.
fn bounding_box(x: &Quad, pad: f64) -> [[f64; 3]; 2] {
    let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
    for p in x {
        for i in 0..3 {
            b[0][i] = b[0][i].min(p[i] - pad);
            b[1][i] = b[1][i].max(p[i] + pad);
        }
    }
    b
}

fn boxes_meet(p: &[[f64; 3]; 2], q: &[[f64; 3]; 2]) -> bool {
    (0..3).all(|i| p[0][i] <= q[1][i] && q[0][i] <= p[1][i])
}

/// The cells `[lo, hi]` (per axis) a box covers in a grid of cell size `cell`.
fn cell_range(b: &[[f64; 3]; 2], cell: f64) -> [[i64; 3]; 2] {
    let c = |v: f64| (v / cell).floor() as i64;
    [b[0].map(c), b[1].map(c)]
}

fn cells(r: [[i64; 3]; 2]) -> impl Iterator<Item = [i64; 3]> {
    (r[0][0]..=r[1][0]).flat_map(move |i| {
        (r[0][1]..=r[1][1]).flat_map(move |j| (r[0][2]..=r[1][2]).map(move |k| [i, j, k]))
    })
}

/// The pairs `(i, j)` of A face `a[i]` and B face `b[j]` whose bounding boxes come within
/// `search` of each other (A's box widened by `search` meets B's box), sorted. B's boxes are
/// binned once in a uniform grid whose cell is the largest of the mean box extent of A's faces,
/// of B's faces, and `search`; each A face queries the cells under its widened box. Every pair
/// that can have an overlap at a gap up to `search` is listed (the boxes are conservative);
/// [`super::face_pair`] decides.
///
/// # Errors
/// [`Error::InvalidInput`] for a non-finite coordinate (naming the face), a negative or
/// non-finite `search`, or faces that are all points with `search = 0`.
pub fn pair_faces(a: &[Quad], b: &[Quad], search: f64) -> Result<Vec<(usize, usize)>> {
    if !(search.is_finite() && search >= 0.0) {
        return Err(Error::InvalidInput(format!(
            "search distance must be finite and non-negative, got {search}"
        )));
    }
    for (side, faces) in [("A", a), ("B", b)] {
        if let Some(i) = faces
            .iter()
            .position(|f| f.iter().flatten().any(|v| !v.is_finite()))
        {
            return Err(Error::InvalidInput(format!(
                "{side} face {i}: non-finite corner coordinate"
            )));
        }
    }
    if a.is_empty() || b.is_empty() {
        return Ok(Vec::new());
    }
    let a_boxes: Vec<_> = a.iter().map(|f| bounding_box(f, search)).collect();
    let b_boxes: Vec<_> = b.iter().map(|f| bounding_box(f, 0.0)).collect();
    let extent = |boxes: &[[[f64; 3]; 2]]| {
        boxes
            .iter()
            .map(|b| (0..3).map(|i| b[1][i] - b[0][i]).fold(0.0, f64::max))
            .sum::<f64>()
            / boxes.len() as f64
    };
    let cell = extent(&a_boxes).max(extent(&b_boxes)).max(search);
    if !(cell > 0.0 && cell.is_finite()) {
        return Err(Error::InvalidInput(
            "every face is a point and the search distance is zero".into(),
        ));
    }
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for (j, bb) in b_boxes.iter().enumerate() {
        for c in cells(cell_range(bb, cell)) {
            grid.entry(c).or_default().push(j);
        }
    }
    let mut pairs = Vec::new();
    for (i, ab) in a_boxes.iter().enumerate() {
        let mut found: Vec<usize> = cells(cell_range(ab, cell))
            .filter_map(|c| grid.get(&c))
            .flatten()
            .copied()
            .filter(|&j| boxes_meet(ab, &b_boxes[j]))
            .collect();
        found.sort_unstable();
        found.dedup();
        pairs.extend(found.into_iter().map(|j| (i, j)));
    }
    Ok(pairs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unit squares of a `n x n` grid of size `h` at height `z`.
    fn grid_faces(n: usize, h: f64, z: f64, shift: f64) -> Vec<Quad> {
        let mut out = Vec::new();
        for j in 0..n {
            for i in 0..n {
                let (x, y) = (i as f64 * h + shift, j as f64 * h + shift);
                out.push([[x, y, z], [x + h, y, z], [x + h, y + h, z], [x, y + h, z]]);
            }
        }
        out
    }

    #[test]
    fn grid_pairs_equal_brute_force() {
        let a = grid_faces(6, 1.0, 0.0, 0.0);
        let b = grid_faces(4, 1.5, 0.2, 0.31);
        for search in [0.0, 0.1, 0.25, 2.0] {
            let pairs = pair_faces(&a, &b, search).unwrap();
            let mut brute = Vec::new();
            for (i, fa) in a.iter().enumerate() {
                for (j, fb) in b.iter().enumerate() {
                    if boxes_meet(&bounding_box(fa, search), &bounding_box(fb, 0.0)) {
                        brute.push((i, j));
                    }
                }
            }
            assert_eq!(pairs, brute, "search {search}");
            // beyond the gap of 0.2 every A face finds the B faces over it
            if search >= 0.2 {
                assert!((0..a.len()).all(|i| pairs.iter().any(|p| p.0 == i)));
            } else {
                assert!(pairs.is_empty());
            }
        }
    }

    #[test]
    fn bad_input_is_an_error() {
        let a = grid_faces(2, 1.0, 0.0, 0.0);
        let mut b = grid_faces(2, 1.0, 0.1, 0.0);
        assert!(pair_faces(&a, &b, -1.0).is_err());
        assert!(pair_faces(&a, &b, f64::NAN).is_err());
        b[1][2][0] = f64::INFINITY;
        assert!(pair_faces(&a, &b, 1.0).is_err());
        assert!(pair_faces(&a, &[], 1.0).unwrap().is_empty());
        let point = [[[1.0; 3]; 4]];
        assert!(pair_faces(&point, &point, 0.0).is_err());
    }
}
