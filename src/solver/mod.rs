//! Sparse Cholesky factorization of the stiffness with the symbolic analysis kept and reused.
//!
//! The contact method factors `K` once per analysis and then only solves with it, many
//! right-hand sides at a time. [`SparseCholesky`] therefore separates three phases:
//! [`SparseCholesky::analyze`] (fill-reducing ordering and elimination tree, once per sparsity
//! pattern), [`SparseCholesky::factorize`] (numeric values of `L`, into storage reused across
//! refactorizations) and [`SparseCholesky::solve_in_place`] (batched right-hand sides).
//! Factorizations are counted so callers and tests can see that none is repeated.
//!
//! Two libraries can do the work, chosen at run time with [`Backend`]:
//! * [`Backend::Faer`] (the default, always available): faer's low-level supernodal API, run
//!   sequentially (`Par::Seq`): on small machines faer's parallel solves are much slower.
//! * [`Backend::Cholmod`]: SuiteSparse's CHOLMOD through bindgen bindings, only when hycon is
//!   built with the cargo feature `suitesparse` (needs libsuitesparse-dev and libclang).
//!
//! Both give the same answers to round-off, report a non-positive pivot as
//! [`Error::Singular`] naming the original equation, and support trailing unknowns for
//! [`SparseCholesky::condensed_inverse`].

#[cfg(feature = "suitesparse")]
mod cholmod;
pub mod ordering;
pub(crate) mod vector_state;

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
pub use ordering::{FillOrdering, OrderingRule};

/// How many right-hand sides one internal solve call handles (bounds the workspace).
const RHS_BATCH: usize = 64;

/// Which sparse Cholesky library factors K.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Backend {
    /// faer's supernodal Cholesky (pure Rust, always available).
    #[default]
    Faer,
    /// SuiteSparse's CHOLMOD (supernodal, BLAS-based); needs the cargo feature `suitesparse`.
    Cholmod,
}

impl Backend {
    /// Whether this build of hycon can use the backend (CHOLMOD needs the feature
    /// `suitesparse`).
    pub fn available(self) -> bool {
        match self {
            Backend::Faer => true,
            Backend::Cholmod => cfg!(feature = "suitesparse"),
        }
    }

    /// Short lower-case name: `"faer"` or `"cholmod"`.
    pub fn name(self) -> &'static str {
        match self {
            Backend::Faer => "faer",
            Backend::Cholmod => "cholmod",
        }
    }

    /// `Ok` when [`available`](Self::available), else the error every entry point returns.
    pub(crate) fn check_available(self) -> Result<()> {
        if self.available() {
            Ok(())
        } else {
            Err(Error::Solver(
                "hycon was built without the `suitesparse` feature: CHOLMOD is not available"
                    .into(),
            ))
        }
    }
}

impl std::fmt::Display for Backend {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A sparse `L L^T` factorization of a symmetric positive definite matrix given by its lower
/// triangle in compressed-column form.
///
/// `Send` and `Sync` with either backend: each object owns its own factor and workspaces (and,
/// for CHOLMOD, its own `cholmod_common`), so distinct objects can be used on distinct threads.
pub struct SparseCholesky {
    engine: Engine,
    factorizations: usize,
    factored: bool,
    /// Number of unknowns ordered last (see [`SparseCholesky::analyze`]).
    trailing: usize,
    ordering: FillOrdering,
}

/// The library-specific part of [`SparseCholesky`].
enum Engine {
    /// Boxed: faer's symbolic structure is large, and `SparseCholesky` is kept in enums.
    Faer(Box<FaerLlt>),
    #[cfg(feature = "suitesparse")]
    Cholmod(cholmod::CholmodLlt),
}

/// faer's symbolic factorization, the values of `L` and the workspace of factor and solve.
struct FaerLlt {
    symbolic: SymbolicCholesky<usize>,
    l_values: Vec<f64>,
    workspace: MemBuffer,
}

impl std::fmt::Debug for SparseCholesky {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SparseCholesky")
            .field("backend", &self.backend())
            .field("ordering", &self.ordering)
            .field("n", &self.n())
            .field("nnz_l", &self.nnz_l())
            .field("factorizations", &self.factorizations)
            .finish()
    }
}

impl SparseCholesky {
    /// Symbolic analysis (fill-reducing ordering, elimination tree, supernodes) of the
    /// lower-triangle pattern with the given backend and [`OrderingRule::Auto`]: for faer, AMD
    /// or METIS's nested dissection, whichever needs fewer flops; for CHOLMOD, its default
    /// strategy (AMD, METIS when AMD fills badly). An unavailable backend is an
    /// [`Error::Solver`].
    ///
    /// The unknowns `trailing` (none: `&[]`) are eliminated last, in the order given, the
    /// others keeping the backend's own order. After [`factorize`](Self::factorize), the
    /// trailing block `L22` of the factor gives the condensed (Schur complement) matrix of those
    /// unknowns, `S = K22 - K21 K11^-1 K12 = L22 L22^T`: see
    /// [`condensed_inverse`](Self::condensed_inverse).
    pub fn analyze(
        pattern: SymbolicSparseColMatRef<'_, usize>,
        backend: Backend,
        trailing: &[usize],
    ) -> Result<Self> {
        Self::analyze_ordered(pattern, backend, trailing, OrderingRule::Auto)
    }

    /// [`analyze`](Self::analyze) with the fill-reducing ordering chosen by `rule` (the
    /// trailing unknowns moved to the end of it); [`ordering`](Self::ordering) reports the one
    /// used. A nested dissection requested without METIS, or a given order that is not a
    /// permutation, is an error.
    pub fn analyze_ordered(
        pattern: SymbolicSparseColMatRef<'_, usize>,
        backend: Backend,
        trailing: &[usize],
        rule: OrderingRule<'_>,
    ) -> Result<Self> {
        backend.check_available()?;
        let n = pattern.nrows();
        let mut last = vec![false; n];
        for &t in trailing {
            if t >= n || std::mem::replace(&mut last[t], true) {
                return Err(Error::InvalidInput(format!(
                    "trailing unknown {t} is out of range or repeated (order {n})"
                )));
            }
        }
        // An elimination order with the trailing unknowns moved to the end.
        let moved = |own: &[usize]| -> Vec<usize> {
            own.iter()
                .copied()
                .filter(|&i| !last[i])
                .chain(trailing.iter().copied())
                .collect()
        };
        let (engine, ordering) = match backend {
            Backend::Faer => {
                let (symbolic, ordering) =
                    faer_symbolic(pattern, rule, &moved, !trailing.is_empty())?;
                (Engine::Faer(Box::new(FaerLlt::new(symbolic)?)), ordering)
            }
            #[cfg(feature = "suitesparse")]
            Backend::Cholmod => {
                let (order, ordering) = match rule {
                    OrderingRule::Auto => (None, FillOrdering::CholmodDefault),
                    OrderingRule::Amd => (Some(amd_order(pattern)?), FillOrdering::Amd),
                    OrderingRule::NestedDissection => (
                        Some(ordering::nested_dissection(pattern)?),
                        FillOrdering::NestedDissection,
                    ),
                    OrderingRule::Given(o) => (Some(o.to_vec()), FillOrdering::Given),
                };
                let mut llt =
                    cholmod::CholmodLlt::analyze(pattern, order.map(|o| moved(&o)).as_deref())?;
                if ordering == FillOrdering::CholmodDefault && !trailing.is_empty() {
                    let own: Vec<usize> = llt.perm().iter().map(|&i| i as usize).collect();
                    llt.reorder(&moved(&own))?;
                }
                (Engine::Cholmod(llt), ordering)
            }
            #[cfg(not(feature = "suitesparse"))]
            Backend::Cholmod => unreachable!("checked by check_available"),
        };
        Ok(SparseCholesky {
            engine,
            factorizations: 0,
            factored: false,
            trailing: trailing.len(),
            ordering,
        })
    }

    /// The fill-reducing ordering in use.
    pub fn ordering(&self) -> FillOrdering {
        self.ordering
    }

    /// The elimination order: `order()[k]` is the original index of the `k`-th pivot (to give
    /// another backend the same permutation with [`OrderingRule::Given`]).
    pub fn order(&self) -> Vec<usize> {
        match &self.engine {
            Engine::Faer(f) => match f.symbolic.perm() {
                Some(p) => p.arrays().0.to_vec(),
                None => (0..f.n()).collect(),
            },
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.perm().iter().map(|&i| i as usize).collect(),
        }
    }

    /// Floating-point operations of one numeric factorization, `sum_j c_j^2` over the columns
    /// of `L` with `c_j` entries (see [`ordering::factor_flops`]; CHOLMOD's own count for it).
    pub fn flops(&self) -> f64 {
        match &self.engine {
            Engine::Faer(f) => ordering::factor_flops(&f.symbolic),
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.flops(),
        }
    }

    /// The library doing the work.
    pub fn backend(&self) -> Backend {
        match self.engine {
            Engine::Faer(_) => Backend::Faer,
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(_) => Backend::Cholmod,
        }
    }

    /// The inverse of the condensed matrix of the trailing unknowns (in the order given to
    /// [`analyze`](Self::analyze) with trailing unknowns): `S^-1 = (K^-1)_22`, the
    /// flexibility of those unknowns with all others free and unloaded. Computed from the
    /// factor's trailing block, `S^-1 = L22^-T L22^-1`: no solves with `K`.
    pub fn condensed_inverse(&self) -> Result<Mat<f64>> {
        if !self.factored {
            return Err(Error::Solver(
                "condensation requested before a successful factorization".into(),
            ));
        }
        let l22 = match &self.engine {
            Engine::Faer(f) => f.trailing_block(self.trailing),
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.trailing_block(self.trailing)?,
        };
        Ok(inverse_from_factor(l22.as_ref()))
    }

    /// Order of the matrix.
    pub fn n(&self) -> usize {
        match &self.engine {
            Engine::Faer(f) => f.symbolic.nrows(),
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.n(),
        }
    }

    /// Number of stored entries of `L` (for supernodal factors, the dense supernode blocks).
    pub fn nnz_l(&self) -> usize {
        match &self.engine {
            Engine::Faer(f) => f.nnz_l(),
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.nnz_l(),
        }
    }

    /// Numeric factorization `A = L L^T` of a matrix with the analysed pattern (lower triangle
    /// read). A non-positive pivot is reported with the original (unpermuted) row index.
    pub fn factorize(&mut self, a: SparseColMatRef<'_, usize, f64>) -> Result<()> {
        self.factored = false;
        match &mut self.engine {
            Engine::Faer(f) => f.factorize(a)?,
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.factorize(a)?,
        }
        self.factorizations += 1;
        self.factored = true;
        Ok(())
    }

    /// Overwrite each column `b` of `rhs` with `A^-1 b`, in batches of right-hand sides.
    pub fn solve_in_place(&mut self, rhs: MatMut<'_, f64>) -> Result<()> {
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
        match &mut self.engine {
            Engine::Faer(f) => {
                f.solve_in_place(rhs);
                Ok(())
            }
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(c) => c.solve_in_place(rhs),
        }
    }

    /// How many numeric factorizations this object has performed.
    pub fn factorizations(&self) -> usize {
        self.factorizations
    }
}

/// The unknowns that a set of unknowns reaches in the elimination tree of a factor (the set
/// and all its ancestors), grouped by the factor's blocks (supernodes, or columns of a
/// simplicial factor), with a compact numbering of their rows. Solutions of `A x = b` with `b`
/// zero outside the reach are known on the reach from forward and backward substitution over
/// its blocks alone: `L y = b` leaves `y` zero outside it (a column only updates its
/// ancestors), and `L^T x = y` at an unknown needs `x` at its ancestors only. See
/// [`SparseCholesky::reach`] and [`SparseCholesky::solve_within`].
#[derive(Debug, Clone)]
pub struct Reach {
    /// Blocks in reach, ascending: `(block, first factor column, width, compact offset)`.
    blocks: Vec<(usize, usize, usize, usize)>,
    /// Compact row of each factor column (`usize::MAX`: not in reach).
    compact: Vec<usize>,
    /// Compact rows of the off-diagonal pattern of the blocks, block after block
    /// (`pattern_start[b]..pattern_start[b + 1]` for the `b`-th block in reach).
    pattern: Vec<usize>,
    pattern_start: Vec<usize>,
    /// Factor column of each unknown of the caller's numbering.
    column_of: Vec<usize>,
    /// Number of rows in reach.
    len: usize,
    /// Entries of `L` in reach (the work of one substitution).
    entries: usize,
    /// Position in `blocks` of each block's parent in the elimination tree (`None`: a root).
    parent: Vec<Option<usize>>,
    /// Threads a substitution over this reach may use (see [`Reach::with_threads`]).
    threads: usize,
    /// How a backward substitution shares the blocks among `threads` (`None`: one thread).
    partition: Option<Partition>,
}

/// The fewest entries of `L` in a reach whose backward substitution is shared among threads:
/// below it a substitution takes a few tenths of a millisecond and starting threads costs what
/// they save (the reference Hertz scene at n = 16, 235k entries, gained nothing measurable with
/// 2 threads; at n = 64, 956k entries, 2 threads took the substitutions and images from about
/// 42 to 32 ms).
const MIN_SHARED_ENTRIES: usize = 400_000;

/// How a backward substitution over a reach shares its blocks among threads: subtrees of the
/// reach's elimination forest, none inside another, grouped per thread, and the blocks above
/// them (the `top`, closed under taking parents). Substituting backward, a block needs `x` at
/// its ancestors only, so once the top is done every subtree can be done on its own, each
/// block with the same operations in the same order as one thread would do them: the result
/// is the same to the bit.
#[derive(Debug, Clone)]
struct Partition {
    /// Positions (in `Reach::blocks`) of the blocks in no subtree, descending.
    top: Vec<usize>,
    /// Per thread, its subtrees as ranges of positions (a subtree is contiguous, the
    /// factor's blocks being in postorder), ascending.
    groups: Vec<Vec<std::ops::Range<usize>>>,
}

impl Reach {
    /// Number of unknowns in reach.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether nothing is in reach.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Stored entries of `L` in the reach's blocks: the flops of one right-hand side's forward
    /// (or backward) substitution.
    pub fn entries(&self) -> usize {
        self.entries
    }

    /// The compact rows of the off-diagonal pattern of the `b`-th block in reach.
    fn block_pattern(&self, b: usize) -> &[usize] {
        &self.pattern[self.pattern_start[b]..self.pattern_start[b + 1]]
    }

    /// Entries of `L` in the `b`-th block in reach: its dense lower triangle and the rows of
    /// its pattern.
    fn block_entries(&self, b: usize) -> usize {
        let width = self.blocks[b].2;
        width * (width + 1) / 2 + width * self.block_pattern(b).len()
    }

    /// The compact rows `first..end` of the blocks at positions `blocks`.
    fn block_rows(&self, blocks: &std::ops::Range<usize>) -> std::ops::Range<usize> {
        let (_, _, width, off) = self.blocks[blocks.end - 1];
        self.blocks[blocks.start].3..off + width
    }

    /// This reach with a backward substitution over it sharing the work among up to `threads`
    /// threads (1, or a reach of fewer than 400k entries of `L`: none started;
    /// [`Bodies::images`](crate::contact::bodies::Bodies::images) shares its batches among the
    /// same number): each thread gets whole subtrees of the reach's elimination forest, after
    /// the blocks above them are done by the calling thread. Every value is computed as one
    /// thread would compute it, to the bit. The threads are started per substitution
    /// (`std::thread::scope`), none is kept.
    pub fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads.max(1);
        self.partition = (self.threads > 1 && self.entries >= MIN_SHARED_ENTRIES)
            .then(|| self.partition(self.threads))
            .flatten();
        self
    }

    /// Threads a substitution over this reach may use.
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// Share the reach's forest among `threads`: split the heaviest subtree (by entries of
    /// `L`) at its root, the root joining the top, while it holds more than a quarter of a
    /// thread's share and has children, then deal the subtrees out heaviest first, each to the
    /// thread with the least work so far. `None` when fewer than two subtrees result, or the
    /// blocks are not in postorder (every subtree must be a contiguous run).
    fn partition(&self, threads: usize) -> Option<Partition> {
        let n = self.blocks.len();
        let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut weight: Vec<usize> = (0..n).map(|b| self.block_entries(b)).collect();
        let mut first: Vec<usize> = (0..n).collect();
        let mut roots = Vec::new();
        for b in 0..n {
            match self.parent[b] {
                Some(p) if p > b => {
                    children[p].push(b);
                    weight[p] += weight[b];
                    first[p] = first[p].min(first[b]);
                }
                Some(_) => return None,
                None => roots.push(b),
            }
        }
        // postorder: each subtree's blocks are the run first[b]..=b and nothing else
        let mut size = vec![1usize; n];
        for b in 0..n {
            if let Some(p) = self.parent[b] {
                size[p] += size[b];
            }
            if b + 1 - first[b] != size[b] {
                return None;
            }
        }
        let total: usize = roots.iter().map(|&r| weight[r]).sum();
        let grain = total / (4 * threads);
        let mut subtrees =
            std::collections::BinaryHeap::from_iter(roots.iter().map(|&r| (weight[r], r)));
        let mut top = Vec::new();
        while let Some(&(w, b)) = subtrees.peek() {
            if w <= grain || children[b].is_empty() {
                break;
            }
            subtrees.pop();
            top.push(b);
            subtrees.extend(children[b].iter().map(|&c| (weight[c], c)));
        }
        if subtrees.len() < 2 {
            return None;
        }
        let mut groups = vec![(0usize, Vec::new()); threads];
        for (w, b) in subtrees.into_sorted_vec().into_iter().rev() {
            let lightest = groups
                .iter_mut()
                .min_by_key(|(load, _)| *load)
                .expect("threads > 1");
            lightest.0 += w;
            lightest.1.push(first[b]..b + 1);
        }
        top.sort_unstable_by(|a, b| b.cmp(a));
        Some(Partition {
            top,
            groups: groups
                .into_iter()
                .map(|(_, mut g)| {
                    g.sort_unstable_by_key(|r| r.start);
                    g
                })
                .filter(|g| !g.is_empty())
                .collect(),
        })
    }

    /// The factor column of each compact row, ascending (compact rows follow the factor's
    /// order): two reaches' rows meet where these columns are equal.
    pub fn columns(&self) -> Vec<usize> {
        self.blocks
            .iter()
            .flat_map(|&(_, start, width, _)| start..start + width)
            .collect()
    }

    /// Compact row of factor column `c`, if in reach.
    pub fn row_of_column(&self, c: usize) -> Option<usize> {
        let r = self.compact[c];
        (r != usize::MAX).then_some(r)
    }

    /// Compact row of unknown `i` (caller's numbering), if in reach.
    pub fn row(&self, i: usize) -> Option<usize> {
        let r = self.compact[self.column_of[i]];
        (r != usize::MAX).then_some(r)
    }
}

impl SparseCholesky {
    /// The reach of the unknowns `unknowns` (caller's numbering): themselves and their
    /// ancestors in the elimination tree of the factor. `None` for CHOLMOD (whose factor hycon
    /// does not walk).
    pub fn reach(&self, unknowns: &[usize]) -> Option<Reach> {
        match &self.engine {
            Engine::Faer(f) => Some(f.reach(unknowns)),
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(_) => None,
        }
    }

    /// `x = A^-1 b` on the reach for right-hand sides `b` (columns of `rhs`, compact rows of
    /// `reach`) that are zero outside it: forward substitution `L y = P b` and backward
    /// substitution `L^T z = y` over the reach's blocks only, `x = P^T z` (`P` the fill-reducing
    /// permutation). Costs `2 reach.entries()` flops per right-hand side against `2 nnz(L)` for
    /// a whole solve.
    pub fn solve_within(&self, reach: &Reach, rhs: MatMut<'_, f64>) -> Result<()> {
        self.substitute_on_reach(reach, rhs, true, true)
    }

    /// `y = L^-1 P b` on the reach, the forward half of
    /// [`solve_within`](Self::solve_within): the image of `b` in the factor's space, zero
    /// outside the reach (so `b^T A^-1 c = (L^-1 P b) . (L^-1 P c)`).
    pub fn forward_within(&self, reach: &Reach, rhs: MatMut<'_, f64>) -> Result<()> {
        self.substitute_on_reach(reach, rhs, true, false)
    }

    /// `x = P^T L^-T y` on the reach, the backward half of
    /// [`solve_within`](Self::solve_within), for `y` zero outside the reach.
    pub fn backward_within(&self, reach: &Reach, rhs: MatMut<'_, f64>) -> Result<()> {
        self.substitute_on_reach(reach, rhs, false, true)
    }

    fn substitute_on_reach(
        &self,
        reach: &Reach,
        rhs: MatMut<'_, f64>,
        forward: bool,
        backward: bool,
    ) -> Result<()> {
        if !self.factored {
            return Err(Error::Solver(
                "solve requested before a successful factorization".into(),
            ));
        }
        match &self.engine {
            Engine::Faer(f) => {
                f.substitute_within(reach, rhs, forward, backward);
                Ok(())
            }
            #[cfg(feature = "suitesparse")]
            Engine::Cholmod(_) => Err(Error::Solver(
                "solves within a reach need the faer backend".into(),
            )),
        }
    }
}

impl FaerLlt {
    fn reach(&self, unknowns: &[usize]) -> Reach {
        let n = self.n();
        let column_of: Vec<usize> = match self.symbolic.perm() {
            Some(p) => p.arrays().1.to_vec(),
            None => (0..n).collect(),
        };
        // blocks: (first column, width, first off-diagonal row) per block; block of a column
        // (first column, width) of each block, the block of each column, each block's parent
        #[allow(clippy::type_complexity)]
        let (starts, block_of, parents): (
            Vec<(usize, usize)>,
            Vec<usize>,
            Vec<Option<usize>>,
        ) = match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(sym) => {
                let (cp, ri) = (sym.col_ptr(), sym.row_idx());
                let parents = (0..n)
                    .map(|j| ri[cp[j]..cp[j + 1]].iter().copied().find(|&r| r > j))
                    .collect();
                ((0..n).map(|j| (j, 1)).collect(), (0..n).collect(), parents)
            }
            SymbolicCholeskyRaw::Supernodal(sym) => {
                let ns = sym.n_supernodes();
                let (b, e) = (sym.supernode_begin(), sym.supernode_end());
                let mut block_of = vec![0; n];
                for s in 0..ns {
                    block_of[b[s]..e[s]].iter_mut().for_each(|x| *x = s);
                }
                let starts = (0..ns).map(|s| (b[s], e[s] - b[s])).collect();
                let parents = (0..ns)
                    .map(|s| sym.supernode(s).pattern().first().map(|&r| block_of[r]))
                    .collect();
                (starts, block_of, parents)
            }
        };
        let mut marked = vec![false; starts.len()];
        for &u in unknowns {
            let mut b = Some(block_of[column_of[u]]);
            while let Some(s) = b {
                if std::mem::replace(&mut marked[s], true) {
                    break;
                }
                b = parents[s];
            }
        }
        let mut compact = vec![usize::MAX; n];
        let mut blocks = Vec::new();
        let (mut len, mut entries) = (0, 0);
        let col_ptr_val: Option<&[usize]> = match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(sym) => Some(sym.col_ptr()),
            SymbolicCholeskyRaw::Supernodal(_) => None,
        };
        for (s, &(start, width)) in starts.iter().enumerate().filter(|(s, _)| marked[*s]) {
            blocks.push((s, start, width, len));
            for c in 0..width {
                compact[start + c] = len + c;
            }
            len += width;
            entries += match (self.symbolic.raw(), col_ptr_val) {
                (SymbolicCholeskyRaw::Supernodal(sym), _) => {
                    width * (width + 1) / 2 + width * sym.supernode(s).pattern().len()
                }
                (_, Some(cp)) => cp[s + 1] - cp[s],
                _ => 0,
            };
        }
        // the blocks' patterns in compact rows (every pattern row is an ancestor: in reach)
        let mut pattern = Vec::new();
        let mut pattern_start = vec![0];
        for &(s, c, _, _) in &blocks {
            match self.symbolic.raw() {
                SymbolicCholeskyRaw::Simplicial(sym) => {
                    let (cp, ri) = (sym.col_ptr(), sym.row_idx());
                    // the diagonal is the column's first entry
                    pattern.extend(ri[cp[c] + 1..cp[c + 1]].iter().map(|&r| compact[r]));
                }
                SymbolicCholeskyRaw::Supernodal(sym) => {
                    pattern.extend(sym.supernode(s).pattern().iter().map(|&r| compact[r]));
                }
            }
            pattern_start.push(pattern.len());
        }
        let mut position = vec![usize::MAX; starts.len()];
        for (b, &(s, ..)) in blocks.iter().enumerate() {
            position[s] = b;
        }
        // every ancestor of a block in reach is in reach
        let parent = blocks
            .iter()
            .map(|&(s, ..)| parents[s].map(|p| position[p]))
            .collect();
        Reach {
            blocks,
            compact,
            pattern,
            pattern_start,
            column_of,
            len,
            entries,
            parent,
            threads: 1,
            partition: None,
        }
    }

    /// Forward (`L y = b`) and/or backward (`L^T x = y`) substitution over the reach's blocks,
    /// the backward one on up to `reach.threads()` threads (see [`Reach::with_threads`]).
    fn substitute_within(
        &self,
        reach: &Reach,
        mut x: MatMut<'_, f64>,
        forward: bool,
        backward: bool,
    ) {
        let factor = self.blocks();
        if forward {
            factor.forward(reach, x.as_mut());
        }
        if backward {
            match &reach.partition {
                Some(partition) => factor.backward_shared(reach, partition, x),
                _ => {
                    let mut tmp = Mat::<f64>::zeros(0, x.ncols());
                    let mut rows = Rows::whole(x);
                    for b in (0..reach.blocks.len()).rev() {
                        factor.backward_block(reach, b, &mut rows, &mut tmp);
                    }
                }
            }
        }
    }

    /// The factor's blocks, for substitutions.
    fn blocks(&self) -> Blocks<'_> {
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(sym) => Blocks::Simplicial {
                col_ptr: sym.col_ptr(),
                values: &self.l_values,
            },
            SymbolicCholeskyRaw::Supernodal(sym) => {
                Blocks::Supernodal(SupernodalLltRef::new(sym, &self.l_values))
            }
        }
    }
}

/// A factor's values by block (columns of a simplicial factor, supernodes of a supernodal one),
/// shareable among threads.
#[derive(Clone, Copy)]
enum Blocks<'a> {
    Simplicial {
        col_ptr: &'a [usize],
        values: &'a [f64],
    },
    Supernodal(SupernodalLltRef<'a, usize, f64>),
}

/// The rows of `x` a backward substitution step reads and writes: compact rows `base..end`
/// are `own`'s (written), the rows from `end` on are read from `done` (the blocks above a
/// subtree, already substituted). One thread's whole `x` has `base = 0`, `end` its length.
struct Rows<'a> {
    own: MatMut<'a, f64>,
    base: usize,
    end: usize,
    done: Option<faer::MatRef<'a, f64>>,
}

impl<'a> Rows<'a> {
    fn whole(x: MatMut<'a, f64>) -> Self {
        let end = x.nrows();
        Rows {
            own: x,
            base: 0,
            end,
            done: None,
        }
    }

    /// `x[r, j]` for a row `r >= base`.
    fn get(&self, r: usize, j: usize) -> f64 {
        match self.done {
            Some(done) if r >= self.end => done[(r, j)],
            _ => self.own[(r - self.base, j)],
        }
    }
}

impl Blocks<'_> {
    /// Forward substitution `L y = b` over the reach's blocks, in place.
    fn forward(self, reach: &Reach, mut x: MatMut<'_, f64>) {
        use faer::linalg::matmul::matmul;
        use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
        let k = x.ncols();
        match self {
            Blocks::Simplicial { col_ptr, values } => {
                for (b, &(_, c, _, off)) in reach.blocks.iter().enumerate() {
                    // the diagonal is the column's first entry, the pattern the rest
                    let (first, rows) = (col_ptr[c], reach.block_pattern(b));
                    for j in 0..k {
                        if x[(off, j)] == 0.0 {
                            continue;
                        }
                        let xc = x[(off, j)] / values[first];
                        x[(off, j)] = xc;
                        for (&r, l) in rows.iter().zip(&values[first + 1..]) {
                            x[(r, j)] -= l * xc;
                        }
                    }
                }
            }
            Blocks::Supernodal(llt) => {
                let mut tmp = Mat::<f64>::zeros(0, k);
                for (b, &(s, _, width, off)) in reach.blocks.iter().enumerate() {
                    let node = llt.supernode(s);
                    let (top, bottom) = node.val().split_at_row(width);
                    let pattern = reach.block_pattern(b);
                    let mut xs = x.as_mut().subrows_mut(off, width);
                    // a block the right-hand sides have not reached yet stays zero
                    if (0..k).all(|j| (0..width).all(|i| xs[(i, j)] == 0.0)) {
                        continue;
                    }
                    solve_lower_triangular_in_place(top, xs.as_mut(), Par::Seq);
                    tmp.resize_with(pattern.len(), k, |_, _| 0.0);
                    matmul(
                        tmp.as_mut(),
                        faer::Accum::Replace,
                        bottom,
                        xs.as_ref(),
                        1.0,
                        Par::Seq,
                    );
                    for j in 0..k {
                        let (xj, tj) = (x.as_mut().col_mut(j), tmp.col(j));
                        let (xj, tj) = (
                            xj.try_as_col_major_mut().unwrap(),
                            tj.try_as_col_major().unwrap(),
                        );
                        let (xj, tj) = (xj.as_slice_mut(), tj.as_slice());
                        for (&r, t) in pattern.iter().zip(tj) {
                            xj[r] -= t;
                        }
                    }
                }
            }
        }
    }

    /// The backward substitution's step at the `b`-th block in reach,
    /// `x_b <- L_bb^-T (x_b - L_pb^T x_p)` over its pattern `p` (ancestors of the block, whose
    /// `x` is final). `tmp` is scratch.
    fn backward_block(self, reach: &Reach, b: usize, x: &mut Rows<'_>, tmp: &mut Mat<f64>) {
        use faer::linalg::matmul::matmul;
        use faer::linalg::triangular_solve::solve_upper_triangular_in_place;
        let k = x.own.ncols();
        let pattern = reach.block_pattern(b);
        let (s, c, width, off) = reach.blocks[b];
        match self {
            Blocks::Simplicial { col_ptr, values } => {
                let first = col_ptr[c];
                for j in 0..k {
                    let mut xc = x.own[(off - x.base, j)];
                    for (&r, l) in pattern.iter().zip(&values[first + 1..]) {
                        xc -= l * x.get(r, j);
                    }
                    x.own[(off - x.base, j)] = xc / values[first];
                }
            }
            Blocks::Supernodal(llt) => {
                let node = llt.supernode(s);
                let (top, bottom) = node.val().split_at_row(width);
                tmp.resize_with(pattern.len(), k, |_, _| 0.0);
                for j in 0..k {
                    let tj = tmp.as_mut().col_mut(j);
                    let tj = tj.try_as_col_major_mut().unwrap().as_slice_mut();
                    for (&r, t) in pattern.iter().zip(tj) {
                        *t = x.get(r, j);
                    }
                }
                let mut xs = x.own.as_mut().subrows_mut(off - x.base, width);
                matmul(
                    xs.as_mut(),
                    faer::Accum::Add,
                    bottom.transpose(),
                    tmp.as_ref(),
                    -1.0,
                    Par::Seq,
                );
                solve_upper_triangular_in_place(top.transpose(), xs.as_mut(), Par::Seq);
            }
        }
    }

    /// Backward substitution shared among threads by `partition`: the top blocks first, on
    /// this thread, then each thread's subtrees, reading the top from a copy of `x`.
    fn backward_shared(self, reach: &Reach, partition: &Partition, mut x: MatMut<'_, f64>) {
        let k = x.ncols();
        let mut tmp = Mat::<f64>::zeros(0, k);
        {
            let mut rows = Rows::whole(x.as_mut());
            for &b in &partition.top {
                self.backward_block(reach, b, &mut rows, &mut tmp);
            }
        }
        let done = x.to_owned();
        // the subtrees' rows, carved out of x in ascending order
        let mut subtrees: Vec<(usize, &std::ops::Range<usize>)> = partition
            .groups
            .iter()
            .enumerate()
            .flat_map(|(g, ranges)| ranges.iter().map(move |r| (g, r)))
            .collect();
        subtrees.sort_unstable_by_key(|(_, r)| r.start);
        let mut pieces: Vec<Vec<(std::ops::Range<usize>, Rows<'_>)>> =
            partition.groups.iter().map(|_| Vec::new()).collect();
        let (mut rest, mut consumed) = (x, 0);
        for (g, blocks) in subtrees {
            let rows = reach.block_rows(blocks);
            let (_, tail) = rest.split_at_row_mut(rows.start - consumed);
            let (own, tail) = tail.split_at_row_mut(rows.len());
            (rest, consumed) = (tail, rows.end);
            pieces[g].push((
                blocks.clone(),
                Rows {
                    own,
                    base: rows.start,
                    end: rows.end,
                    done: Some(done.as_ref()),
                },
            ));
        }
        let work = |mut subtrees: Vec<(std::ops::Range<usize>, Rows<'_>)>| {
            let mut tmp = Mat::<f64>::zeros(0, k);
            for (blocks, rows) in &mut subtrees {
                for b in blocks.clone().rev() {
                    self.backward_block(reach, b, rows, &mut tmp);
                }
            }
        };
        let mut pieces = pieces.into_iter();
        let own = pieces.next().expect("a partition has two groups");
        std::thread::scope(|scope| {
            for group in pieces {
                scope.spawn(move || work(group));
            }
            work(own);
        });
    }
}

/// faer's symbolic factorization with the ordering `rule` (see
/// [`SparseCholesky::analyze_ordered`]), `moved` putting the trailing unknowns last.
fn faer_symbolic(
    pattern: SymbolicSparseColMatRef<'_, usize>,
    rule: OrderingRule<'_>,
    moved: &dyn Fn(&[usize]) -> Vec<usize>,
    has_trailing: bool,
) -> Result<(SymbolicCholesky<usize>, FillOrdering)> {
    let custom = |order: &[usize]| symbolic_with(pattern, Some(&moved(order)));
    let amd = || {
        if has_trailing {
            custom(&amd_order(pattern)?)
        } else {
            symbolic_with(pattern, None)
        }
    };
    match rule {
        OrderingRule::Auto => {
            let amd = amd()?;
            if ordering::factor_flops(&amd) < ordering::ND_TRIAL_FLOPS {
                return Ok((amd, FillOrdering::Amd));
            }
            if ordering::metis_status().is_err() {
                return Ok((amd, FillOrdering::AmdWithoutMetis));
            }
            let nd = custom(&ordering::nested_dissection(pattern)?)?;
            Ok(
                if ordering::factor_flops(&nd) < ordering::factor_flops(&amd) {
                    (nd, FillOrdering::NestedDissection)
                } else {
                    (amd, FillOrdering::Amd)
                },
            )
        }
        OrderingRule::Amd => Ok((amd()?, FillOrdering::Amd)),
        OrderingRule::NestedDissection => Ok((
            custom(&ordering::nested_dissection(pattern)?)?,
            FillOrdering::NestedDissection,
        )),
        OrderingRule::Given(order) => Ok((custom(order)?, FillOrdering::Given)),
    }
}

/// faer's AMD elimination order of the pattern.
fn amd_order(pattern: SymbolicSparseColMatRef<'_, usize>) -> Result<Vec<usize>> {
    let symbolic = symbolic_with(pattern, None)?;
    Ok(match symbolic.perm() {
        Some(p) => p.arrays().0.to_vec(),
        None => (0..pattern.nrows()).collect(),
    })
}

/// faer's symbolic factorization with the elimination order `order` (`None`: AMD); an order
/// that is not a permutation of the unknowns is an error.
fn symbolic_with(
    pattern: SymbolicSparseColMatRef<'_, usize>,
    order: Option<&[usize]>,
) -> Result<SymbolicCholesky<usize>> {
    let n = pattern.nrows();
    let mut inv;
    let ordering = match order {
        None => SymmetricOrdering::Amd,
        Some(fwd) => {
            inv = vec![usize::MAX; n];
            if fwd.len() != n {
                return Err(Error::InvalidInput(format!(
                    "elimination order of length {}, the matrix has order {n}",
                    fwd.len()
                )));
            }
            for (new, &old) in fwd.iter().enumerate() {
                if old >= n || inv[old] != usize::MAX {
                    return Err(Error::InvalidInput(format!(
                        "elimination order: unknown {old} is out of range or repeated"
                    )));
                }
                inv[old] = new;
            }
            SymmetricOrdering::Custom(PermRef::new_checked(fwd, &inv, n))
        }
    };
    factorize_symbolic_cholesky(
        pattern,
        Side::Lower,
        ordering,
        CholeskySymbolicParams::default(),
    )
    .map_err(|e| Error::Solver(format!("symbolic analysis failed: {e:?}")))
}

impl FaerLlt {
    /// The workspace of factor and solve for a symbolic factorization.
    fn new(symbolic: SymbolicCholesky<usize>) -> Result<Self> {
        let par = Par::Seq;
        let req = StackReq::any_of(&[
            symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(RHS_BATCH, par),
        ]);
        let workspace = MemBuffer::try_new(req).map_err(|_| {
            Error::Solver(format!(
                "out of memory: the factorization workspace of {} equations could not be allocated",
                symbolic.nrows()
            ))
        })?;
        Ok(FaerLlt {
            l_values: Vec::new(),
            symbolic,
            workspace,
        })
    }

    fn n(&self) -> usize {
        self.symbolic.nrows()
    }

    /// Stored entries of `L`, known from the symbolic analysis alone.
    fn nnz_l(&self) -> usize {
        self.symbolic.len_val()
    }

    /// Allocate `L`'s values on the first factorization (the analysis alone sizes a problem
    /// without holding its factor). Fallible: a factor larger than the machine's memory is an
    /// error the host can report, not an abort.
    fn allocate_factor(&mut self) -> Result<()> {
        let len = self.nnz_l();
        if self.l_values.len() == len {
            return Ok(());
        }
        self.l_values.try_reserve_exact(len).map_err(|_| {
            Error::Solver(format!(
                "out of memory: the factor L needs {len} entries ({:.1} GB)",
                len as f64 * 8e-9
            ))
        })?;
        self.l_values.resize(len, 0.0);
        Ok(())
    }

    fn factorize(&mut self, a: SparseColMatRef<'_, usize, f64>) -> Result<()> {
        self.allocate_factor()?;
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
            Ok(_) => Ok(()),
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

    fn solve_in_place(&mut self, mut rhs: MatMut<'_, f64>) {
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
    }

    /// The trailing `m x m` block of `L` (dense, lower triangular).
    fn trailing_block(&self, m: usize) -> Mat<f64> {
        let n = self.n();
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
}

/// `(L L^T)^-1 = L^-T L^-1` for a dense lower triangular `L`, block by block: `L` splits into
/// the independent groups of unknowns that it couples (one per body when the unknowns are on
/// several bodies, whose condensed matrices do not couple), each group's block is inverted as a
/// triangle (`m^3 / 3` flops) and multiplied as triangles (`m^3 / 3`), and the blocks between
/// groups are zero. Two equal bodies cost a quarter of the whole.
pub(crate) fn inverse_from_factor(l: faer::MatRef<'_, f64>) -> Mat<f64> {
    use faer::linalg::matmul::triangular::{BlockStructure, matmul};
    let m = l.nrows();
    let mut out = Mat::<f64>::zeros(m, m);
    for group in coupled_groups(l) {
        let k = group.len();
        let block = Mat::<f64>::from_fn(k, k, |i, j| l[(group[i], group[j])]);
        let mut x = Mat::<f64>::zeros(k, k);
        faer::linalg::triangular_inverse::invert_lower_triangular(
            x.as_mut(),
            block.as_ref(),
            Par::Seq,
        );
        let mut inv = Mat::<f64>::zeros(k, k);
        matmul(
            inv.as_mut(),
            BlockStructure::TriangularLower,
            faer::Accum::Replace,
            x.transpose(),
            BlockStructure::TriangularUpper,
            x.as_ref(),
            BlockStructure::TriangularLower,
            1.0,
            Par::Seq,
        );
        for j in 0..k {
            for i in j..k {
                let v = inv[(i, j)];
                out[(group[i], group[j])] = v;
                out[(group[j], group[i])] = v;
            }
        }
    }
    out
}

/// The groups of unknowns (each sorted) that the nonzero pattern of `L` connects.
fn coupled_groups(l: faer::MatRef<'_, f64>) -> Vec<Vec<usize>> {
    let m = l.nrows();
    let mut parent: Vec<usize> = (0..m).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for j in 0..m {
        for i in j + 1..m {
            if l[(i, j)] != 0.0 {
                let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                parent[a.max(b)] = a.min(b);
            }
        }
    }
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut index = vec![usize::MAX; m];
    for i in 0..m {
        let r = root(&mut parent, i);
        if index[r] == usize::MAX {
            index[r] = groups.len();
            groups.push(Vec::new());
        }
        groups[index[r]].push(i);
    }
    groups
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

    /// The block-wise inverse equals the dense `(L L^T)^-1` when `L` couples its unknowns in
    /// interleaved groups (two "bodies" numbered alternately) and when it couples all of them.
    #[test]
    fn inverse_from_factor_matches_the_dense_inverse() {
        let m = 9;
        for interleaved in [true, false] {
            let coupled = |i: usize, j: usize| !interleaved || i % 2 == j % 2;
            let l = Mat::<f64>::from_fn(m, m, |i, j| match (i.cmp(&j), coupled(i, j)) {
                (std::cmp::Ordering::Equal, _) => 2.0 + i as f64 / 3.0,
                (std::cmp::Ordering::Greater, true) => ((i * 5 + j * 3) % 7) as f64 / 7.0 - 0.4,
                _ => 0.0,
            });
            let groups = coupled_groups(l.as_ref());
            assert_eq!(groups.len(), if interleaved { 2 } else { 1 });
            let inv = inverse_from_factor(l.as_ref());
            let product = &l * l.transpose() * &inv;
            let identity = Mat::<f64>::identity(m, m);
            assert!((product - identity).norm_max() < 1e-12);
        }
    }

    #[test]
    fn solves_many_rhs_and_counts_factorizations() {
        let n = 200;
        let (a, full) = laplacian(n);
        let mut chol = SparseCholesky::analyze(a.symbolic(), Backend::Faer, &[]).unwrap();
        chol.factorize(a.as_ref()).unwrap();
        let b = Mat::<f64>::from_fn(n, 150, |i, j| ((i * 7 + j * 3) % 11) as f64 - 5.0);
        let mut x = b.clone();
        chol.solve_in_place(x.as_mut()).unwrap();
        let r = &full * &x - &b;
        assert!(r.norm_max() < 1e-10 * b.norm_max() * (n * n) as f64 / 4.0);
        assert_eq!(chol.factorizations(), 1);
    }

    /// 2D 5-point Laplacian on a `k x k` grid plus the identity (lower triangle).
    fn grid(k: usize) -> SparseColMat<usize, f64> {
        let mut t = Vec::new();
        for y in 0..k {
            for x in 0..k {
                let i = y * k + x;
                t.push(Triplet::new(i, i, 5.0));
                if x + 1 < k {
                    t.push(Triplet::new(i + 1, i, -1.0));
                }
                if y + 1 < k {
                    t.push(Triplet::new(i + k, i, -1.0));
                }
            }
        }
        SparseColMat::try_new_from_triplets(k * k, k * k, &t).unwrap()
    }

    /// Substitution within the reach of a set of unknowns (one grid edge and a few scattered
    /// ones) gives a whole solve's values there, for right-hand sides that vanish outside the
    /// set, on a simplicial and a supernodal factor; the reach is a part of the factor.
    #[test]
    fn solve_within_a_reach_matches_a_whole_solve() {
        for k in [6, 120] {
            let a = grid(k);
            let n = k * k;
            let mut chol = SparseCholesky::analyze(a.symbolic(), Backend::Faer, &[]).unwrap();
            chol.factorize(a.as_ref()).unwrap();
            let mut set: Vec<usize> = (0..k).collect();
            set.extend([n / 2, n - 1, 3 * k + 2]);
            let reach = chol.reach(&set).unwrap();
            assert!(reach.len() >= set.len() && reach.len() <= n);
            assert!(reach.entries() <= chol.nnz_l());
            let nrhs = 5;
            let b = Mat::<f64>::from_fn(n, nrhs, |i, j| {
                if set.contains(&i) {
                    ((i * 7 + j * 3) % 11) as f64 - 5.0
                } else {
                    0.0
                }
            });
            let mut whole = b.clone();
            chol.solve_in_place(whole.as_mut()).unwrap();
            let mut within = Mat::<f64>::zeros(reach.len(), nrhs);
            for &i in &set {
                for j in 0..nrhs {
                    within[(reach.row(i).unwrap(), j)] = b[(i, j)];
                }
            }
            chol.solve_within(&reach, within.as_mut()).unwrap();
            for &i in &set {
                for j in 0..nrhs {
                    let (w, x) = (within[(reach.row(i).unwrap(), j)], whole[(i, j)]);
                    assert!(
                        (w - x).abs() <= 1e-12 * whole.norm_max(),
                        "{k}: {i}: {w} vs {x}"
                    );
                }
            }
            if k == 120 {
                assert!(reach.entries() < chol.nnz_l(), "the reach is a part of L");
            }
        }
    }

    /// A backward substitution shared among threads gives the one-thread values to the bit,
    /// on a simplicial and a supernodal factor; its partition puts every block in reach either
    /// in the top (closed under taking parents) or in exactly one subtree (a contiguous run
    /// holding every descendant of its last block).
    #[test]
    fn backward_substitution_on_threads_is_the_same_to_the_bit() {
        for k in [6, 120] {
            let a = grid(k);
            let mut chol = SparseCholesky::analyze(a.symbolic(), Backend::Faer, &[]).unwrap();
            chol.factorize(a.as_ref()).unwrap();
            let mut set: Vec<usize> = (0..k).collect();
            set.extend((0..k).map(|i| i * k + k / 2));
            let reach = chol.reach(&set).unwrap();
            let y = Mat::<f64>::from_fn(reach.len(), 3, |i, j| ((i * 7 + j * 3) % 11) as f64 - 5.0);
            let mut one = y.clone();
            chol.backward_within(&reach, one.as_mut()).unwrap();
            for threads in [2, 3, 8] {
                let mut shared = reach.clone().with_threads(threads);
                assert_eq!(shared.threads(), threads);
                // shared whatever the size (a reach this small is not, by default)
                shared.partition = shared.partition(threads);
                if let Some(p) = &shared.partition {
                    let blocks = shared.blocks.len();
                    let mut owner = vec![None; blocks];
                    for &b in &p.top {
                        owner[b] = Some(usize::MAX);
                    }
                    for (g, ranges) in p.groups.iter().enumerate() {
                        for r in ranges {
                            for b in r.clone() {
                                assert!(owner[b].is_none(), "block {b} given twice");
                                owner[b] = Some(g);
                            }
                            // the run is the subtree of its last block
                            for b in r.start..r.end - 1 {
                                let mut a = shared.parent[b];
                                while a.is_some_and(|a| a < r.end - 1) {
                                    a = shared.parent[a.unwrap()];
                                }
                                assert_eq!(a, Some(r.end - 1), "block {b} leaves its subtree");
                            }
                        }
                    }
                    assert!(owner.iter().all(Option::is_some), "every block is done");
                    for &b in &p.top {
                        if let Some(parent) = shared.parent[b] {
                            assert_eq!(owner[parent], Some(usize::MAX), "the top is closed");
                        }
                    }
                    assert!(p.groups.len() >= 2 && p.groups.len() <= threads);
                } else {
                    assert_eq!(k, 6, "a supernodal reach of a grid is shared");
                }
                let mut x = y.clone();
                chol.backward_within(&shared, x.as_mut()).unwrap();
                for i in 0..reach.len() {
                    for j in 0..3 {
                        assert_eq!(x[(i, j)].to_bits(), one[(i, j)].to_bits(), "{k} {threads}");
                    }
                }
            }
        }
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
            let mut chol = SparseCholesky::analyze(a.symbolic(), Backend::Faer, &trailing).unwrap();
            #[allow(irrefutable_let_patterns)] // irrefutable without the CHOLMOD variant
            let Engine::Faer(f) = &chol.engine else {
                panic!("analyze on faer must use faer")
            };
            let supernodal = matches!(f.symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_));
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
        let mut chol = SparseCholesky::analyze(a.symbolic(), Backend::Faer, &[]).unwrap();
        let err = chol.factorize(a.as_ref()).unwrap_err();
        assert!(matches!(err, Error::Singular(_)), "{err}");
        let mut x = Mat::<f64>::zeros(2, 1);
        assert!(chol.solve_in_place(x.as_mut()).is_err());
    }

    #[test]
    fn send_and_sync() {
        fn check<T: Send + Sync>() {}
        check::<SparseCholesky>();
    }

    #[test]
    fn backend_names_and_default() {
        assert_eq!(Backend::default(), Backend::Faer);
        assert!(Backend::Faer.available());
        assert_eq!(Backend::Faer.name(), "faer");
        assert_eq!(Backend::Cholmod.to_string(), "cholmod");
        assert_eq!(Backend::Cholmod.available(), cfg!(feature = "suitesparse"));
    }

    /// Without the feature, every CHOLMOD entry point is an error, not a panic.
    #[cfg(not(feature = "suitesparse"))]
    #[test]
    fn cholmod_without_feature_is_an_error() {
        let (a, _) = laplacian(5);
        let expected = Error::Solver(
            "hycon was built without the `suitesparse` feature: CHOLMOD is not available".into(),
        );
        let err = SparseCholesky::analyze(a.symbolic(), Backend::Cholmod, &[]).unwrap_err();
        assert_eq!(err, expected);
        let err = SparseCholesky::analyze(a.symbolic(), Backend::Cholmod, &[1]).unwrap_err();
        assert_eq!(err, expected);
    }

    /// Both backends, same small problems: solves, condensed inverse (both storage sizes on
    /// the faer side), an empty matrix, a changed pattern, a repeated trailing unknown.
    #[cfg(feature = "suitesparse")]
    #[test]
    fn cholmod_matches_faer_on_small_matrices() {
        for n in [1, 30, 2_000] {
            let (a, full) = laplacian(n);
            let b = Mat::<f64>::from_fn(n, 70, |i, j| ((i * 5 + j * 3) % 13) as f64 - 6.0);
            let trailing: Vec<usize> = [n / 2, 0, n - 1]
                .into_iter()
                .collect::<std::collections::BTreeSet<_>>()
                .into_iter()
                .rev()
                .collect();
            let mut results = Vec::new();
            for backend in [Backend::Faer, Backend::Cholmod] {
                let mut chol = SparseCholesky::analyze(a.symbolic(), backend, &trailing).unwrap();
                assert_eq!(chol.backend(), backend);
                assert_eq!(chol.n(), n);
                chol.factorize(a.as_ref()).unwrap();
                chol.factorize(a.as_ref()).unwrap();
                assert_eq!(chol.factorizations(), 2);
                let mut x = b.clone();
                chol.solve_in_place(x.as_mut()).unwrap();
                let r = &full * &x - &b;
                assert!(
                    r.norm_max() < 1e-12 * (n * n) as f64,
                    "{backend}: {}",
                    r.norm_max()
                );
                results.push((x, chol.condensed_inverse().unwrap()));
            }
            let (xf, sf) = &results[0];
            let (xc, sc) = &results[1];
            assert!((xf - xc).norm_max() <= 1e-12 * xf.norm_max(), "n = {n}");
            assert!((sf - sc).norm_max() <= 1e-12 * sf.norm_max(), "n = {n}");
        }
        let empty = SparseColMat::<usize, f64>::try_new_from_triplets(0, 0, &[]).unwrap();
        let mut chol = SparseCholesky::analyze(empty.symbolic(), Backend::Cholmod, &[]).unwrap();
        chol.factorize(empty.as_ref()).unwrap();
        chol.solve_in_place(Mat::<f64>::zeros(0, 3).as_mut())
            .unwrap();
        assert_eq!(chol.condensed_inverse().unwrap().nrows(), 0);

        let (a, _) = laplacian(4);
        let mut chol = SparseCholesky::analyze(a.symbolic(), Backend::Cholmod, &[]).unwrap();
        let (other, _) = laplacian(5);
        assert!(matches!(
            chol.factorize(other.as_ref()),
            Err(Error::InvalidInput(_))
        ));
        let diag = SparseColMat::<usize, f64>::try_new_from_triplets(
            4,
            4,
            &(0..4).map(|i| Triplet::new(i, i, 1.0)).collect::<Vec<_>>(),
        )
        .unwrap();
        assert!(matches!(
            chol.factorize(diag.as_ref()),
            Err(Error::InvalidInput(_))
        ));
        assert!(matches!(
            SparseCholesky::analyze(a.symbolic(), Backend::Cholmod, &[1, 1]),
            Err(Error::InvalidInput(_))
        ));
    }

    /// The same indefinite matrix gives the same error, with the same equation, on both.
    #[cfg(feature = "suitesparse")]
    #[test]
    fn cholmod_reports_indefinite_matrix_like_faer() {
        // SPD leading 3 x 3 block, then a row that makes the 4th pivot negative.
        let t = [
            Triplet::new(0, 0, 4.0),
            Triplet::new(1, 1, 4.0),
            Triplet::new(2, 2, 4.0),
            Triplet::new(3, 3, 1.0),
            Triplet::new(3, 0, 2.0),
            Triplet::new(3, 2, 2.0),
        ];
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(4, 4, &t).unwrap();
        let errs: Vec<Error> = [Backend::Faer, Backend::Cholmod]
            .into_iter()
            .map(|backend| {
                let mut chol = SparseCholesky::analyze(a.symbolic(), backend, &[]).unwrap();
                let err = chol.factorize(a.as_ref()).unwrap_err();
                assert_eq!(chol.factorizations(), 0);
                assert!(
                    chol.solve_in_place(Mat::<f64>::zeros(4, 1).as_mut())
                        .is_err()
                );
                err
            })
            .collect();
        for e in &errs {
            assert!(
                matches!(e, Error::Singular(m) if m.contains("not positive definite")),
                "{e}"
            );
        }
    }
}
