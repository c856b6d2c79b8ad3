//! Sparse Cholesky factorization of the stiffness with the symbolic analysis kept and reused.
//!
//! The contact method factors `K` once per analysis and then only solves with it, many
//! right-hand sides at a time. [`SparseCholesky`] therefore separates the three phases of faer's
//! low-level API: [`SparseCholesky::analyze`] (fill-reducing ordering and elimination tree, once
//! per sparsity pattern), [`SparseCholesky::factorize`] (numeric values of `L`, into a buffer
//! reused across refactorizations) and [`SparseCholesky::solve_in_place`] (batched right-hand
//! sides). Everything runs sequentially (`Par::Seq`): on small machines faer's parallel solves are
//! much slower. Factorizations are counted so callers and tests can see that none is repeated.

use crate::error::{Error, Result};
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::linalg::solvers::LltError;
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, LltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
    factorize_symbolic_cholesky,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, Mat, MatMut, Par, Side};

/// How many right-hand sides one internal solve call handles (bounds the workspace).
const RHS_BATCH: usize = 64;

/// A sparse `L L^T` factorization of a symmetric positive definite matrix given by its lower
/// triangle in compressed-column form.
pub struct SparseCholesky {
    symbolic: SymbolicCholesky<usize>,
    l_values: Vec<f64>,
    workspace: MemBuffer,
    factorizations: usize,
    factored: bool,
    /// Number of unknowns ordered last (see [`SparseCholesky::analyze_with_trailing`]).
    trailing: usize,
}

impl std::fmt::Debug for SparseCholesky {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SparseCholesky")
            .field("n", &self.n())
            .field("nnz_l", &self.l_values.len())
            .field("factorizations", &self.factorizations)
            .finish()
    }
}

impl SparseCholesky {
    /// Symbolic analysis (AMD ordering, elimination tree, supernodes) of the lower-triangle pattern.
    pub fn analyze(pattern: SymbolicSparseColMatRef<'_, usize>) -> Result<Self> {
        Self::analyze_ordered(pattern, SymmetricOrdering::Amd, 0)
    }

    /// Symbolic analysis with the unknowns `trailing` eliminated last, in the given order (the
    /// others in AMD order). After [`factorize`](Self::factorize), the trailing block `L22` of
    /// the factor gives the condensed (Schur complement) matrix of those unknowns,
    /// `S = K22 - K21 K11^-1 K12 = L22 L22^T`: see [`condensed_inverse`](Self::condensed_inverse).
    pub fn analyze_with_trailing(
        pattern: SymbolicSparseColMatRef<'_, usize>,
        trailing: &[usize],
    ) -> Result<Self> {
        let n = pattern.nrows();
        let amd = Self::analyze(pattern)?;
        let mut last = vec![false; n];
        for &t in trailing {
            if t >= n || std::mem::replace(&mut last[t], true) {
                return Err(Error::InvalidInput(format!(
                    "trailing unknown {t} is out of range or repeated (order {n})"
                )));
            }
        }
        let amd_order: Vec<usize> = match amd.symbolic.perm() {
            Some(p) => p.arrays().0.to_vec(),
            None => (0..n).collect(),
        };
        let fwd: Vec<usize> = amd_order
            .into_iter()
            .filter(|&i| !last[i])
            .chain(trailing.iter().copied())
            .collect();
        let mut inv = vec![0; n];
        for (new, &old) in fwd.iter().enumerate() {
            inv[old] = new;
        }
        let perm = PermRef::new_checked(&fwd, &inv, n);
        Self::analyze_ordered(pattern, SymmetricOrdering::Custom(perm), trailing.len())
    }

    fn analyze_ordered(
        pattern: SymbolicSparseColMatRef<'_, usize>,
        ordering: SymmetricOrdering<'_, usize>,
        trailing: usize,
    ) -> Result<Self> {
        let symbolic = factorize_symbolic_cholesky(
            pattern,
            Side::Lower,
            ordering,
            CholeskySymbolicParams::default(),
        )
        .map_err(|e| Error::Solver(format!("symbolic analysis failed: {e:?}")))?;
        let par = Par::Seq;
        let req = StackReq::any_of(&[
            symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(RHS_BATCH, par),
        ]);
        Ok(SparseCholesky {
            l_values: vec![0.0; symbolic.len_val()],
            symbolic,
            workspace: MemBuffer::new(req),
            factorizations: 0,
            factored: false,
            trailing,
        })
    }

    /// The inverse of the condensed matrix of the trailing unknowns (in the order given to
    /// [`analyze_with_trailing`](Self::analyze_with_trailing)): `S^-1 = (K^-1)_22`, the
    /// flexibility of those unknowns with all others free and unloaded. Computed from the
    /// factor's trailing block, `S^-1 = L22^-T L22^-1`: no solves with `K`.
    pub fn condensed_inverse(&self) -> Result<Mat<f64>> {
        if !self.factored {
            return Err(Error::Solver(
                "condensation requested before a successful factorization".into(),
            ));
        }
        let l22 = self.trailing_block();
        let m = self.trailing;
        let mut x = Mat::<f64>::identity(m, m);
        faer::linalg::triangular_solve::solve_lower_triangular_in_place(
            l22.as_ref(),
            x.as_mut(),
            Par::Seq,
        );
        Ok(x.transpose() * &x)
    }

    /// The trailing `m x m` block of `L` (dense, lower triangular).
    fn trailing_block(&self) -> Mat<f64> {
        let (n, m) = (self.n(), self.trailing);
        let first = n - m;
        let mut l = Mat::<f64>::zeros(m, m);
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(sym) => {
                let (cp, ri) = (sym.col_ptr(), sym.row_idx());
                for j in first..n {
                    for idx in cp[j]..cp[j + 1] {
                        if ri[idx] >= first {
                            l[(ri[idx] - first, j - first)] = self.l_values[idx];
                        }
                    }
                }
            }
            SymbolicCholeskyRaw::Supernodal(sym) => {
                let llt = SupernodalLltRef::<usize, f64>::new(sym, &self.l_values);
                for s in 0..sym.n_supernodes() {
                    let node = llt.supernode(s);
                    let (start, pattern, val) = (node.start(), node.pattern(), node.val());
                    let width = val.ncols();
                    for jj in (0..width).filter(|&jj| start + jj >= first) {
                        let col = start + jj - first;
                        for ii in jj..width {
                            l[(start + ii - first, col)] = val[(ii, jj)];
                        }
                        for (k, &r) in pattern.iter().enumerate() {
                            l[(r - first, col)] = val[(width + k, jj)];
                        }
                    }
                }
            }
        }
        l
    }

    /// Order of the matrix.
    pub fn n(&self) -> usize {
        self.symbolic.nrows()
    }

    /// Number of stored entries of `L`.
    pub fn nnz_l(&self) -> usize {
        self.l_values.len()
    }

    /// Numeric factorization `A = L L^T` of a matrix with the analysed pattern (lower triangle
    /// read). A non-positive pivot is reported with the original (unpermuted) row index.
    pub fn factorize(&mut self, a: SparseColMatRef<'_, usize, f64>) -> Result<()> {
        self.factored = false;
        let result = self.symbolic.factorize_numeric_llt::<f64>(
            &mut self.l_values,
            a,
            Side::Lower,
            LltRegularization::default(),
            Par::Seq,
            MemStack::new(&mut self.workspace),
            Default::default(),
        );
        match result {
            Ok(_) => {
                self.factorizations += 1;
                self.factored = true;
                Ok(())
            }
            Err(LltError::NonPositivePivot { index }) => {
                // faer reports the pivot in the permuted order (and may report n for the last
                // supernode); translate it back to the caller's numbering when it is in range.
                let row = match self.symbolic.perm() {
                    Some(p) if index < self.n() => p.arrays().0[index],
                    _ => index.min(self.n().saturating_sub(1)),
                };
                Err(Error::Singular(format!(
                    "non-positive pivot near equation {row}: the matrix is not positive definite"
                )))
            }
        }
    }

    /// Overwrite each column `b` of `rhs` with `A^-1 b`, in batches of right-hand sides.
    pub fn solve_in_place(&mut self, mut rhs: MatMut<'_, f64>) -> Result<()> {
        if !self.factored {
            return Err(Error::Solver(
                "solve requested before a successful factorization".into(),
            ));
        }
        if rhs.nrows() != self.n() {
            return Err(Error::InvalidInput(format!(
                "right-hand side has {} rows, the matrix has order {}",
                rhs.nrows(),
                self.n()
            )));
        }
        let llt = LltRef::<usize, f64>::new(&self.symbolic, &self.l_values);
        let ncols = rhs.ncols();
        let mut j = 0;
        while j < ncols {
            let k = RHS_BATCH.min(ncols - j);
            llt.solve_in_place_with_conj(
                Conj::No,
                rhs.as_mut().subcols_mut(j, k),
                Par::Seq,
                MemStack::new(&mut self.workspace),
            );
            j += k;
        }
        Ok(())
    }

    /// How many numeric factorizations this object has performed.
    pub fn factorizations(&self) -> usize {
        self.factorizations
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use faer::Mat;
    use faer::sparse::{SparseColMat, Triplet};

    /// 1D Laplacian (lower triangle) of order n, plus its full form for residuals.
    fn laplacian(n: usize) -> (SparseColMat<usize, f64>, Mat<f64>) {
        let mut t = Vec::new();
        let mut full = Mat::<f64>::zeros(n, n);
        for i in 0..n {
            t.push(Triplet::new(i, i, 2.0));
            full[(i, i)] = 2.0;
            if i + 1 < n {
                t.push(Triplet::new(i + 1, i, -1.0));
                full[(i + 1, i)] = -1.0;
                full[(i, i + 1)] = -1.0;
            }
        }
        (SparseColMat::try_new_from_triplets(n, n, &t).unwrap(), full)
    }

    #[test]
    fn solves_many_rhs_and_counts_factorizations() {
        let n = 200;
        let (a, full) = laplacian(n);
        let mut chol = SparseCholesky::analyze(a.symbolic()).unwrap();
        chol.factorize(a.as_ref()).unwrap();
        let b = Mat::<f64>::from_fn(n, 150, |i, j| ((i * 7 + j * 3) % 11) as f64 - 5.0);
        let mut x = b.clone();
        chol.solve_in_place(x.as_mut()).unwrap();
        let r = &full * &x - &b;
        assert!(r.norm_max() < 1e-10 * b.norm_max() * (n * n) as f64 / 4.0);
        assert_eq!(chol.factorizations(), 1);
    }

    /// The condensed inverse from the factor's trailing block equals `(A^-1)_22` computed by
    /// solves, for a trailing set in arbitrary order, both simplicial and supernodal sizes.
    #[test]
    fn condensed_inverse_matches_solves() {
        for n in [30, 40_000] {
            // 2D Laplacian-like band: i coupled to i+1 and i+k
            let k = (n as f64).sqrt() as usize;
            let mut t = Vec::new();
            for i in 0..n {
                t.push(Triplet::new(i, i, 4.5));
                for j in [i + 1, i + k] {
                    if j < n {
                        t.push(Triplet::new(j, i, -1.0));
                    }
                }
            }
            let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &t).unwrap();
            let trailing: Vec<usize> = vec![n / 2, 3, n - 1, n / 3, 7];
            let mut chol = SparseCholesky::analyze_with_trailing(a.symbolic(), &trailing).unwrap();
            let supernodal = matches!(chol.symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_));
            assert_eq!(
                supernodal,
                n > 100,
                "n = {n} should exercise the other storage"
            );
            chol.factorize(a.as_ref()).unwrap();
            let f = chol.condensed_inverse().unwrap();
            let mut e = Mat::<f64>::zeros(n, trailing.len());
            for (j, &d) in trailing.iter().enumerate() {
                e[(d, j)] = 1.0;
            }
            chol.solve_in_place(e.as_mut()).unwrap();
            for (i, &d) in trailing.iter().enumerate() {
                for j in 0..trailing.len() {
                    assert!((f[(i, j)] - e[(d, j)]).abs() < 1e-13, "n = {n}: ({i}, {j})");
                }
            }
        }
    }

    #[test]
    fn reports_indefinite_matrix() {
        let t = [
            Triplet::new(0, 0, 1.0),
            Triplet::new(1, 0, 2.0),
            Triplet::new(1, 1, 1.0),
        ];
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(2, 2, &t).unwrap();
        let mut chol = SparseCholesky::analyze(a.symbolic()).unwrap();
        let err = chol.factorize(a.as_ref()).unwrap_err();
        assert!(matches!(err, Error::Singular(_)), "{err}");
        let mut x = Mat::<f64>::zeros(2, 1);
        assert!(chol.solve_in_place(x.as_mut()).is_err());
    }
}
