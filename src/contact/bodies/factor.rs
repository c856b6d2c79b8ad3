//! `F = E^T K^-1 E` and its products from hycon's sparse Cholesky factor `K = P^T L L^T P`,
//! whichever bodies hold it (a plane model, a solid model, a host's CSR matrix): substitutions
//! within the reach of the contact equations in the elimination tree, and the images
//! `W V = L^-1 P E V` with their backward substitution. Positions in the contact dofs map to
//! factor equations through `rows` (`None` at a fixed dof).

use super::{CALLBACK_BATCH, Images};
use crate::error::{Error, Result};
use crate::solver::{Reach, SparseCholesky};
use faer::Mat;
use nalgebra::DMatrix;

/// `F V` from the whole `F` (`all`), for the columns `V` sparse over its rows.
pub(super) fn times_whole(all: &DMatrix<f64>, vectors: &[Vec<(usize, f64)>]) -> DMatrix<f64> {
    let n = all.nrows();
    let mut out = DMatrix::zeros(n, vectors.len());
    for (c, v) in vectors.iter().enumerate() {
        for &(j, w) in v {
            for i in 0..n {
                out[(i, c)] += w * all[(i, j)];
            }
        }
    }
    out
}

/// `F V` for the columns `V` (sparse over the positions of `rows`) by substitutions within the
/// contact equations' `reach` ([`SparseCholesky::solve_within`]), in batches of at most
/// `CALLBACK_BATCH` columns and about 32 MB. Rows at fixed dofs are zero.
pub(super) fn times_within(
    factor: &SparseCholesky,
    reach: &Reach,
    rows: &[Option<usize>],
    vectors: &[Vec<(usize, f64)>],
) -> Result<DMatrix<f64>> {
    let mut out = DMatrix::zeros(rows.len(), vectors.len());
    let row = |e: usize| {
        reach
            .row(e)
            .expect("the contact equations are in their reach")
    };
    let len = reach.len();
    let batch = CALLBACK_BATCH.min((4 << 20) / len.max(1)).max(1);
    for start in (0..vectors.len()).step_by(batch) {
        let cols = batch.min(vectors.len() - start);
        let mut rhs = Mat::<f64>::zeros(len, cols);
        for c in 0..cols {
            for &(j, w) in &vectors[start + c] {
                if let Some(e) = rows[j] {
                    rhs[(row(e), c)] += w;
                }
            }
        }
        factor.solve_within(reach, rhs.as_mut())?;
        for c in 0..cols {
            for (i, e) in rows.iter().enumerate() {
                if let Some(e) = e {
                    out[(i, start + c)] = rhs[(row(*e), c)];
                }
            }
        }
    }
    Ok(out)
}

/// The images `W V = L^-1 P E V` of the columns `V` of each batch: per batch one forward
/// substitution within its columns' own elimination-tree reach, so that
/// `V^T F V = (W V)^T (W V)`. The batches are shared among the threads of the contact
/// equations' `reach` ([`Reach::with_threads`]), each substituted whole by one thread: the
/// images do not depend on the number of threads.
pub(super) fn images(
    factor: &SparseCholesky,
    reach: &Reach,
    rows: &[Option<usize>],
    batches: &[Vec<Vec<(usize, f64)>>],
) -> Result<Vec<Images>> {
    let one = move |vectors: &Vec<Vec<(usize, f64)>>| images_of(factor, rows, vectors);
    let threads = reach.threads().min(batches.len());
    if threads <= 1 {
        return batches.iter().map(one).collect::<Result<_>>();
    }
    // each thread takes a run of consecutive batches
    let run = batches.len().div_ceil(threads);
    let images: Vec<Vec<Result<Images>>> = std::thread::scope(|scope| {
        let handles: Vec<_> = batches
            .chunks(run)
            .map(|run| scope.spawn(move || run.iter().map(one).collect::<Vec<_>>()))
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    });
    images.into_iter().flatten().collect::<Result<_>>()
}

/// `F sum_i V_i c_i` at the positions of `rows` from the images `W V_i` and their
/// coefficients `c_i`: `z = sum_i (W V_i) c_i`, then one backward substitution
/// `P^T L^-T z` over the contact equations' `reach`. Zero at fixed dofs.
pub(super) fn back_substitute(
    factor: &SparseCholesky,
    reach: &Reach,
    rows: &[Option<usize>],
    parts: &[(&Images, &[f64])],
) -> Result<Vec<f64>> {
    let mut z = Mat::<f64>::zeros(reach.len(), 1);
    for &(images, coefficients) in parts {
        let c = Mat::<f64>::from_fn(coefficients.len(), 1, |i, _| coefficients[i]);
        let combined = &images.values * c;
        for (r, &column) in images.columns.iter().enumerate() {
            let row = reach
                .row_of_column(column)
                .expect("the contact dofs' reach holds every image");
            z[(row, 0)] += combined[(r, 0)];
        }
    }
    factor.backward_within(reach, z.as_mut())?;
    Ok(rows
        .iter()
        .map(|e| e.map_or(0.0, |e| z[(reach.row(e).expect("a contact dof"), 0)]))
        .collect())
}

/// The images `W V = L^-1 P E V` of one batch of vectors `V` (sparse over the positions of
/// `rows`, the equation of each position): one forward substitution within their reach.
fn images_of(
    factor: &SparseCholesky,
    rows: &[Option<usize>],
    vectors: &[Vec<(usize, f64)>],
) -> Result<Images> {
    let equations: Vec<usize> = vectors
        .iter()
        .flatten()
        .filter_map(|&(j, _)| rows[j])
        .collect();
    let reach = factor
        .reach(&equations)
        .ok_or_else(|| Error::Solver("a lazy factor has a reach".into()))?;
    let mut values = Mat::<f64>::zeros(reach.len(), vectors.len());
    for (c, v) in vectors.iter().enumerate() {
        for &(j, w) in v {
            if let Some(r) = rows[j].and_then(|e| reach.row(e)) {
                values[(r, c)] += w;
            }
        }
    }
    factor.forward_within(&reach, values.as_mut())?;
    Ok(Images {
        columns: reach.columns(),
        values,
    })
}
