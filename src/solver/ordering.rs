//! Fill-reducing orderings: faer's approximate minimum degree (AMD) or METIS's nested
//! dissection of the node graph, and the rule that picks between them.
//!
//! # Nested dissection of the node graph
//! Unknowns of one node (2 in the plane, 3 in a brick mesh) couple to exactly the same
//! unknowns: their columns of the full pattern, diagonal included, are identical. Consecutive
//! columns with identical patterns are merged into one vertex weighted by their count, the
//! vertices are ordered by `METIS_NodeND` (nested dissection: a small vertex separator is
//! eliminated last, each half recursively the same way), and the vertex order is expanded back
//! to the unknowns. The graph METIS sees is 3x smaller in 3D and its separators never split a
//! node. The merge reads only the pattern, so the host's CSR path gets it as well as hycon's
//! own meshes.
//!
//! # Where METIS comes from
//! METIS is loaded at run time (`dlopen("libmetis.so.5")` with `RTLD_LOCAL | RTLD_DEEPBIND`;
//! Debian's `libmetis5`), never linked: hycon's static library defines no METIS symbol, so a
//! host that links its own METIS (PETSc, MUMPS) sees no clash, and no configuration compiles
//! METIS. A METIS already loaded by the host under the same name is used as it is, with its
//! own index width: [`idx_width`] finds 32- or 64-bit `idx_t` from how much
//! `METIS_SetDefaultOptions` writes. Without METIS the automatic rule keeps AMD and says so
//! ([`FillOrdering::AmdWithoutMetis`]). Under a sanitizer runtime (a host built with
//! AddressSanitizer, ThreadSanitizer, MemorySanitizer or LeakSanitizer) METIS is not loaded:
//! the runtime intercepts `dlopen` and ends the process on `RTLD_DEEPBIND`, and without that
//! flag METIS could bind to a host's own METIS of another index width; AMD is used instead.
//!
//! # The rule
//! [`OrderingRule::Auto`] computes the symbolic factorization with AMD; when it needs at least
//! [`ND_TRIAL_FLOPS`], also with nested dissection, and keeps the one with fewer factorization
//! flops ([`factor_flops`]; AMD on a tie). Below that the factorization takes about a second
//! or less and a second analysis would cost a noticeable part of it: the plane meshes of the
//! contact examples (25k dofs, a few 1e8 flops) keep AMD without calling METIS.

use crate::error::{Error, Result};
use faer::sparse::SymbolicSparseColMatRef;
use faer::sparse::linalg::cholesky::{SymbolicCholesky, SymbolicCholeskyRaw};
use std::ffi::{c_int, c_void};
use std::sync::{Mutex, OnceLock};

/// Factorization flops of AMD's order from which [`OrderingRule::Auto`] also tries nested
/// dissection (about 1 to 2 s of faer's sequential factorization).
pub const ND_TRIAL_FLOPS: f64 = 1e10;

/// How [`SparseCholesky::analyze_ordered`](super::SparseCholesky::analyze_ordered) orders the
/// unknowns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OrderingRule<'a> {
    /// faer: AMD, and when its factorization needs at least [`ND_TRIAL_FLOPS`] nested
    /// dissection too, the one with fewer flops kept (AMD when METIS is absent). CHOLMOD: its
    /// own default strategy.
    #[default]
    Auto,
    /// Approximate minimum degree (faer's AMD, for either backend).
    Amd,
    /// METIS's nested dissection of the node graph; an error when METIS cannot be loaded.
    NestedDissection,
    /// This elimination order (`order[k]` = original index of the `k`-th pivot).
    Given(&'a [usize]),
}

/// The ordering a factorization uses (its report).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FillOrdering {
    /// faer's AMD.
    Amd,
    /// faer's AMD because METIS could not be loaded (see [`metis_status`]).
    AmdWithoutMetis,
    /// METIS nested dissection of the node graph.
    NestedDissection,
    /// An order given by the caller.
    Given,
    /// CHOLMOD's own default strategy (AMD, METIS when AMD fills badly).
    CholmodDefault,
}

impl FillOrdering {
    /// Short name for reports: `"amd"`, `"amd (no metis)"`, `"nd"`, `"given"`, `"cholmod"`.
    pub fn name(self) -> &'static str {
        match self {
            FillOrdering::Amd => "amd",
            FillOrdering::AmdWithoutMetis => "amd (no metis)",
            FillOrdering::NestedDissection => "nd",
            FillOrdering::Given => "given",
            FillOrdering::CholmodDefault => "cholmod",
        }
    }
}

impl std::fmt::Display for FillOrdering {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Factorization flops of a symbolic Cholesky factor, `sum_j c_j^2` over the columns `j` of
/// `L` with `c_j` entries each (diagonal included; CHOLMOD's `Common->fl` counts the same).
/// A supernode of `w` columns over `r` rows below its diagonal block has
/// `c = r + w, r + w - 1, ..., r + 1`.
pub fn factor_flops(symbolic: &SymbolicCholesky<usize>) -> f64 {
    let squares = |c: usize| (c as f64) * (c as f64);
    match symbolic.raw() {
        SymbolicCholeskyRaw::Simplicial(s) => {
            s.col_ptr().windows(2).map(|w| squares(w[1] - w[0])).sum()
        }
        SymbolicCholeskyRaw::Supernodal(s) => {
            let rows = s.col_ptr_for_row_idx();
            (0..s.n_supernodes())
                .map(|k| {
                    let width = s.supernode_end()[k] - s.supernode_begin()[k];
                    let below = rows[k + 1] - rows[k];
                    (below + 1..=below + width).map(squares).sum::<f64>()
                })
                .sum()
        }
    }
}

/// Nested-dissection elimination order of the lower-triangle `pattern` (`order[k]` = original
/// index of the `k`-th pivot): identical consecutive columns merged into weighted vertices,
/// the vertex graph ordered by `METIS_NodeND`, the order expanded to the unknowns.
pub fn nested_dissection(pattern: SymbolicSparseColMatRef<'_, usize>) -> Result<Vec<usize>> {
    let n = pattern.nrows();
    if n == 0 {
        return Ok(Vec::new());
    }
    let metis = metis().map_err(|e| Error::Solver(format!("nested dissection: {e}")))?;
    let full = FullPattern::of(pattern)?;
    let groups = full.node_groups();
    let graph = full.node_graph(&groups);
    let vertex_order = metis.node_nd(&graph)?;
    Ok(vertex_order
        .into_iter()
        .flat_map(|v| groups[v]..groups[v + 1])
        .collect())
}

/// Whether METIS can be loaded: its index width in bits, or why not.
pub fn metis_status() -> std::result::Result<u32, String> {
    metis().map(|m| if m.idx64 { 64 } else { 32 })
}

/// The symmetric pattern with the diagonal, both triangles (`u32` indices: the full pattern of
/// a large 3D model is the biggest array of the ordering).
struct FullPattern {
    col_ptr: Vec<usize>,
    row_idx: Vec<u32>,
}

impl FullPattern {
    /// Both triangles of the lower-triangle pattern (entries above the diagonal ignored, as
    /// by the factorization), each column sorted, the diagonal always present.
    fn of(pattern: SymbolicSparseColMatRef<'_, usize>) -> Result<Self> {
        let n = pattern.nrows();
        u32::try_from(n).map_err(|_| {
            Error::Solver(format!(
                "nested dissection: {n} unknowns exceed 32-bit indices"
            ))
        })?;
        let below = |j: usize| pattern.row_idx_of_col(j).filter(move |&i| i > j && i < n);
        let mut count = vec![1usize; n];
        for j in 0..n {
            for i in below(j) {
                count[i] += 1;
                count[j] += 1;
            }
        }
        let mut col_ptr = vec![0; n + 1];
        for j in 0..n {
            col_ptr[j + 1] = col_ptr[j] + count[j];
        }
        let mut next = col_ptr[..n].to_vec();
        let mut row_idx = vec![0u32; col_ptr[n]];
        // columns filled in increasing j: the upper entries (i < j) of column j arrive from
        // earlier columns in increasing order, then the diagonal, then the lower entries
        for j in 0..n {
            row_idx[next[j]] = j as u32;
            next[j] += 1;
            let start = next[j];
            for i in below(j) {
                row_idx[next[j]] = i as u32;
                next[j] += 1;
                row_idx[next[i]] = j as u32;
                next[i] += 1;
            }
            row_idx[start..next[j]].sort_unstable();
        }
        Ok(FullPattern { col_ptr, row_idx })
    }

    fn col(&self, j: usize) -> &[u32] {
        &self.row_idx[self.col_ptr[j]..self.col_ptr[j + 1]]
    }

    /// Boundaries of the runs of consecutive identical columns: group `g` is the unknowns
    /// `groups[g]..groups[g + 1]`.
    fn node_groups(&self) -> Vec<usize> {
        let n = self.col_ptr.len() - 1;
        let mut groups = vec![0];
        for j in 1..n {
            if self.col(j) != self.col(j - 1) {
                groups.push(j);
            }
        }
        groups.push(n);
        groups
    }

    /// The graph of the groups (no self loops, no repeated edges), weighted by group size.
    fn node_graph(&self, groups: &[usize]) -> NodeGraph {
        let n = self.col_ptr.len() - 1;
        let mut group_of = vec![0usize; n];
        for g in 0..groups.len() - 1 {
            group_of[groups[g]..groups[g + 1]].fill(g);
        }
        let mut graph = NodeGraph {
            xadj: vec![0],
            adjncy: Vec::new(),
            weight: Vec::with_capacity(groups.len() - 1),
        };
        for g in 0..groups.len() - 1 {
            let mut last = usize::MAX;
            for &i in self.col(groups[g]) {
                let h = group_of[i as usize];
                if h != g && h != last {
                    graph.adjncy.push(h);
                }
                last = h;
            }
            graph.xadj.push(graph.adjncy.len());
            graph.weight.push(groups[g + 1] - groups[g]);
        }
        graph
    }
}

/// A graph in METIS's compressed form, with vertex weights.
struct NodeGraph {
    xadj: Vec<usize>,
    adjncy: Vec<usize>,
    weight: Vec<usize>,
}

/// `METIS_SetDefaultOptions(idx_t *options)`.
type SetDefaultOptions = unsafe extern "C" fn(*mut c_void) -> c_int;
/// `METIS_NodeND(nvtxs, xadj, adjncy, vwgt, options, perm, iperm)`, all `idx_t *`.
type NodeNd = unsafe extern "C" fn(
    *mut c_void,
    *mut c_void,
    *mut c_void,
    *mut c_void,
    *mut c_void,
    *mut c_void,
    *mut c_void,
) -> c_int;

/// `METIS_OK`.
const METIS_OK: c_int = 1;

/// The loaded METIS library: its `METIS_NodeND` and index width.
struct Metis {
    node_nd: NodeNd,
    idx64: bool,
    /// METIS (GKlib) installs process-wide signal handlers around each call: calls are
    /// serialised.
    lock: Mutex<()>,
}

/// METIS, loaded once per process.
fn metis() -> std::result::Result<&'static Metis, String> {
    static METIS: OnceLock<std::result::Result<Metis, String>> = OnceLock::new();
    METIS.get_or_init(load_metis).as_ref().map_err(Clone::clone)
}

/// `dlopen("libmetis.so.5")` local to hycon (and binding the library to its own symbols
/// first), its two entry points, and its index width.
fn load_metis() -> std::result::Result<Metis, String> {
    #[cfg(target_env = "gnu")]
    const FLAGS: c_int = libc::RTLD_NOW | libc::RTLD_LOCAL | libc::RTLD_DEEPBIND;
    #[cfg(target_env = "gnu")]
    if sanitizer_runtime() {
        return Err(
            "libmetis.so.5 is not loaded under a sanitizer runtime, which refuses \
                    dlopen with RTLD_DEEPBIND"
                .into(),
        );
    }
    #[cfg(not(target_env = "gnu"))]
    const FLAGS: c_int = libc::RTLD_NOW | libc::RTLD_LOCAL;
    // SAFETY: dlopen with a NUL-terminated name; the handle is kept for the process's life.
    let handle = unsafe { libc::dlopen(c"libmetis.so.5".as_ptr(), FLAGS) };
    if handle.is_null() {
        return Err("libmetis.so.5 could not be loaded (install libmetis5)".into());
    }
    let symbol = |name: &std::ffi::CStr| {
        // SAFETY: a valid handle and a NUL-terminated name.
        let p = unsafe { libc::dlsym(handle, name.as_ptr()) };
        if p.is_null() {
            Err(format!("libmetis.so.5 has no {}", name.to_string_lossy()))
        } else {
            Ok(p)
        }
    };
    let (set_default, node_nd) = (
        symbol(c"METIS_SetDefaultOptions")?,
        symbol(c"METIS_NodeND")?,
    );
    // SAFETY: both symbols are METIS 5's functions of these C signatures.
    let (set_default, node_nd) = unsafe {
        (
            std::mem::transmute::<*mut c_void, SetDefaultOptions>(set_default),
            std::mem::transmute::<*mut c_void, NodeNd>(node_nd),
        )
    };
    // SAFETY: `set_default` is METIS_SetDefaultOptions, which writes METIS_NOPTIONS (40)
    // idx_t values, at most 320 bytes, within idx_width's buffer.
    let bits = unsafe { idx_width(set_default) }
        .ok_or("libmetis.so.5: METIS_SetDefaultOptions wrote an unexpected amount")?;
    Ok(Metis {
        node_nd,
        idx64: bits == 64,
        lock: Mutex::new(()),
    })
}

/// Whether a sanitizer runtime with its own allocator (ASan, TSan, MSan, HWASan, LSan; not
/// UBSan alone, which lets `RTLD_DEEPBIND` through) is in the process: its interface function
/// `__sanitizer_get_allocated_size` is a global symbol.
#[cfg(target_env = "gnu")]
fn sanitizer_runtime() -> bool {
    // SAFETY: dlsym in the global scope with a NUL-terminated name; the result is only
    // compared with NULL.
    let symbol = unsafe {
        libc::dlsym(
            libc::RTLD_DEFAULT,
            c"__sanitizer_get_allocated_size".as_ptr(),
        )
    };
    !symbol.is_null()
}

/// Width of METIS's `idx_t` in bits, from `METIS_SetDefaultOptions`, which sets its
/// `METIS_NOPTIONS = 40` entries to -1: 40 8-byte slots of a sentinel-filled buffer are
/// overwritten by a 64-bit METIS, 20 by a 32-bit one (two -1 `int32`s read as one -1 `int64`).
/// `None` for any other outcome.
///
/// # Safety
/// `set_default` must write at most 512 bytes through its argument.
pub unsafe fn idx_width(set_default: SetDefaultOptions) -> Option<u32> {
    const SENTINEL: i64 = 0x5A5A_5A5A_5A5A_5A5A;
    let mut options = [SENTINEL; 64];
    // SAFETY: the caller guarantees the write fits in the 512-byte buffer.
    unsafe { set_default(options.as_mut_ptr().cast()) };
    let written = options.iter().take_while(|&&o| o == -1).count();
    let untouched = options[written..].iter().all(|&o| o == SENTINEL);
    match (written, untouched) {
        (40, true) => Some(64),
        (20, true) => Some(32),
        _ => None,
    }
}

impl Metis {
    /// `METIS_NodeND` of the graph with default options: the vertex elimination order.
    fn node_nd(&self, graph: &NodeGraph) -> Result<Vec<usize>> {
        if self.idx64 {
            self.call::<i64>(graph)
        } else {
            self.call::<i32>(graph)
        }
    }

    fn call<T>(&self, graph: &NodeGraph) -> Result<Vec<usize>>
    where
        T: Copy + Default + TryFrom<usize> + TryInto<usize>,
    {
        let too_big = || Error::Solver("nested dissection: the graph exceeds METIS's idx_t".into());
        let convert = |v: &[usize]| -> Result<Vec<T>> {
            v.iter()
                .map(|&x| T::try_from(x).map_err(|_| too_big()))
                .collect()
        };
        let nv = graph.weight.len();
        let mut nvtxs = [T::try_from(nv).map_err(|_| too_big())?];
        let (mut xadj, mut adjncy, mut vwgt) = (
            convert(&graph.xadj)?,
            convert(&graph.adjncy)?,
            convert(&graph.weight)?,
        );
        let (mut perm, mut iperm) = (vec![T::default(); nv], vec![T::default(); nv]);
        let status = {
            let _serial = self.lock.lock().unwrap_or_else(|e| e.into_inner());
            // SAFETY: METIS_NodeND with idx_t = T: nvtxs vertices, xadj of nvtxs + 1 offsets
            // into adjncy, vwgt and the outputs perm, iperm of nvtxs entries; options NULL
            // (defaults). METIS only reads the inputs and writes perm and iperm.
            unsafe {
                (self.node_nd)(
                    nvtxs.as_mut_ptr().cast(),
                    xadj.as_mut_ptr().cast(),
                    adjncy.as_mut_ptr().cast(),
                    vwgt.as_mut_ptr().cast(),
                    std::ptr::null_mut(),
                    perm.as_mut_ptr().cast(),
                    iperm.as_mut_ptr().cast(),
                )
            }
        };
        if status != METIS_OK {
            return Err(Error::Solver(format!(
                "METIS_NodeND failed (status {status})"
            )));
        }
        // perm[k] is the original vertex eliminated k-th; check it is a permutation
        let mut seen = vec![false; nv];
        perm.into_iter()
            .map(|p| {
                let v: usize = p.try_into().ok().filter(|&v| v < nv).ok_or_else(too_big)?;
                if std::mem::replace(&mut seen[v], true) {
                    return Err(Error::Solver("METIS_NodeND returned no permutation".into()));
                }
                Ok(v)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use faer::sparse::SymbolicSparseColMat;

    /// Lower pattern of a 3D grid of `m^3` nodes, 27-node coupling, `per` unknowns per node.
    fn grid_pattern(m: usize, per: usize) -> SymbolicSparseColMat<usize> {
        let id = |x: usize, y: usize, z: usize| (x * m + y) * m + z;
        let mut col_ptr = vec![0];
        let mut row_idx = Vec::new();
        for x in 0..m {
            for y in 0..m {
                for z in 0..m {
                    let mut nbrs = Vec::new();
                    for (dx, dy, dz) in (0..27).map(|k| (k / 9, k / 3 % 3, k % 3)) {
                        let (a, b, c) = (x + dx, y + dy, z + dz);
                        if (1..=m).contains(&a) && (1..=m).contains(&b) && (1..=m).contains(&c) {
                            nbrs.push(id(a - 1, b - 1, c - 1));
                        }
                    }
                    nbrs.sort_unstable();
                    for d in 0..per {
                        let col = per * id(x, y, z) + d;
                        for &o in &nbrs {
                            row_idx.extend((0..per).map(|e| per * o + e).filter(|&r| r >= col));
                        }
                        col_ptr.push(row_idx.len());
                    }
                }
            }
        }
        let n = per * m * m * m;
        SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx)
    }

    #[test]
    fn nested_dissection_is_a_permutation_keeping_nodes_together() {
        let a = grid_pattern(6, 3);
        let order = nested_dissection(a.as_ref()).expect("Debian's libmetis5 is installed");
        let mut seen = vec![false; a.nrows()];
        for &i in &order {
            assert!(!std::mem::replace(&mut seen[i], true), "{i} repeated");
        }
        assert!(seen.iter().all(|&s| s));
        // the three unknowns of each node are eliminated together, in order
        for chunk in order.chunks(3) {
            assert_eq!(chunk[0] % 3, 0);
            assert_eq!([chunk[1], chunk[2]], [chunk[0] + 1, chunk[0] + 2]);
        }
    }

    /// The pattern's graph Laplacian plus the identity (symmetric positive definite).
    fn laplacian(a: &SymbolicSparseColMat<usize>) -> Vec<f64> {
        let n = a.nrows();
        let mut degree = vec![1.0; n];
        for j in 0..n {
            for i in a.row_idx_of_col(j).filter(|&i| i > j) {
                degree[i] += 1.0;
                degree[j] += 1.0;
            }
        }
        (0..n)
            .flat_map(|j| {
                let d = degree[j];
                a.row_idx_of_col(j)
                    .map(move |i| if i == j { d } else { -1.0 })
            })
            .collect()
    }

    #[test]
    fn nested_dissection_solves_as_amd_does_with_less_fill_on_a_cube() {
        use crate::solver::{Backend, SparseCholesky};
        use faer::sparse::SparseColMatRef;
        let a = grid_pattern(14, 3);
        let values = laplacian(&a);
        let matrix = SparseColMatRef::new(a.as_ref(), &values);
        let n = a.nrows();
        let solve = |rule| {
            let mut chol =
                SparseCholesky::analyze_ordered(a.as_ref(), Backend::Faer, &[], rule).unwrap();
            chol.factorize(matrix).unwrap();
            let mut x = faer::Mat::<f64>::from_fn(n, 1, |i, _| ((i * 7) % 11) as f64 - 5.0);
            chol.solve_in_place(x.as_mut()).unwrap();
            (chol, x)
        };
        let (amd, x_amd) = solve(OrderingRule::Amd);
        let (nd, x_nd) = solve(OrderingRule::NestedDissection);
        assert_eq!(amd.ordering(), FillOrdering::Amd);
        assert_eq!(nd.ordering(), FillOrdering::NestedDissection);
        let scale = x_amd.norm_max();
        assert!((&x_nd - &x_amd).norm_max() <= 1e-12 * scale);
        let (fill, work) = (
            nd.nnz_l() as f64 / amd.nnz_l() as f64,
            nd.flops() / amd.flops(),
        );
        assert!(fill < 0.80, "nnz(L) nd / amd = {fill}");
        assert!(work < 0.62, "flops nd / amd = {work}");
        // below the trial threshold the automatic rule keeps AMD without calling METIS
        assert!(amd.flops() < ND_TRIAL_FLOPS);
        let auto = |a: &SymbolicSparseColMat<usize>| {
            SparseCholesky::analyze_ordered(a.as_ref(), Backend::Faer, &[], OrderingRule::Auto)
                .unwrap()
        };
        assert_eq!(auto(&a).order(), amd.order());
    }

    #[test]
    fn automatic_rule_keeps_the_cheaper_order_of_a_larger_cube() {
        use crate::solver::{Backend, SparseCholesky};
        let a = grid_pattern(20, 3);
        let analyze =
            |rule| SparseCholesky::analyze_ordered(a.as_ref(), Backend::Faer, &[], rule).unwrap();
        let (amd, nd, auto) = (
            analyze(OrderingRule::Amd),
            analyze(OrderingRule::NestedDissection),
            analyze(OrderingRule::Auto),
        );
        assert!(amd.flops() >= ND_TRIAL_FLOPS);
        assert!(nd.flops() < 0.5 * amd.flops());
        assert_eq!(auto.ordering(), FillOrdering::NestedDissection);
        assert_eq!(auto.order(), nd.order());
        assert_eq!(auto.flops(), nd.flops());
    }

    #[cfg(feature = "suitesparse")]
    #[test]
    fn cholmod_with_faer_s_nested_dissection_counts_the_same_flops() {
        use crate::solver::{Backend, SparseCholesky};
        use faer::sparse::SparseColMatRef;
        let a = grid_pattern(10, 3);
        let values = laplacian(&a);
        let matrix = SparseColMatRef::new(a.as_ref(), &values);
        let rule = OrderingRule::NestedDissection;
        let mut faer =
            SparseCholesky::analyze_ordered(a.as_ref(), Backend::Faer, &[], rule).unwrap();
        let order = faer.order();
        let mut cholmod = SparseCholesky::analyze_ordered(
            a.as_ref(),
            Backend::Cholmod,
            &[],
            OrderingRule::Given(&order),
        )
        .unwrap();
        assert_eq!(cholmod.ordering(), FillOrdering::Given);
        assert_eq!(cholmod.order(), order);
        // the same elimination order: the same column counts, up to the explicit zeros of
        // faer's relaxed supernodes (CHOLMOD counts the exact columns)
        let ratio = cholmod.flops() / faer.flops();
        assert!((0.97..=1.0).contains(&ratio), "{ratio}");
        let n = a.nrows();
        let b = faer::Mat::<f64>::from_fn(n, 1, |i, _| (i % 5) as f64 - 2.0);
        let (mut x, mut y) = (b.clone(), b);
        faer.factorize(matrix).unwrap();
        cholmod.factorize(matrix).unwrap();
        faer.solve_in_place(x.as_mut()).unwrap();
        cholmod.solve_in_place(y.as_mut()).unwrap();
        assert!((&x - &y).norm_max() <= 1e-12 * x.norm_max());
    }

    #[test]
    fn given_order_must_be_a_permutation() {
        use crate::solver::{Backend, SparseCholesky};
        let a = grid_pattern(2, 1);
        for bad in [&[0, 1, 2, 3, 4, 5, 6][..], &[0, 1, 2, 3, 4, 5, 6, 6]] {
            let r = SparseCholesky::analyze_ordered(
                a.as_ref(),
                Backend::Faer,
                &[],
                OrderingRule::Given(bad),
            );
            assert!(matches!(r, Err(Error::InvalidInput(_))), "{bad:?}");
        }
        let reversed: Vec<usize> = (0..8).rev().collect();
        let chol = SparseCholesky::analyze_ordered(
            a.as_ref(),
            Backend::Faer,
            &[],
            OrderingRule::Given(&reversed),
        )
        .unwrap();
        assert_eq!(chol.ordering(), FillOrdering::Given);
        assert_eq!(chol.order(), reversed);
    }

    #[test]
    fn groups_merge_identical_columns_only() {
        let a = grid_pattern(3, 3);
        let full = FullPattern::of(a.as_ref()).unwrap();
        let groups = full.node_groups();
        assert_eq!(groups, (0..=27).map(|g| 3 * g).collect::<Vec<_>>());
        let graph = full.node_graph(&groups);
        // the corner node couples to the 7 others of its 2x2x2 block, the centre to all 26
        assert_eq!(graph.xadj[1] - graph.xadj[0], 7);
        assert_eq!(graph.xadj[14] - graph.xadj[13], 26);
        assert!(graph.weight.iter().all(|&w| w == 3));
    }

    #[test]
    fn installed_metis_is_found_with_its_width() {
        assert_eq!(
            metis_status(),
            Ok(32),
            "Debian's libmetis5 has 32-bit idx_t"
        );
    }

    unsafe extern "C" fn defaults32(options: *mut c_void) -> c_int {
        // SAFETY: the test buffer holds 64 i64s
        unsafe { std::slice::from_raw_parts_mut(options.cast::<i32>(), 40).fill(-1) };
        METIS_OK
    }

    unsafe extern "C" fn defaults64(options: *mut c_void) -> c_int {
        // SAFETY: the test buffer holds 64 i64s
        unsafe { std::slice::from_raw_parts_mut(options.cast::<i64>(), 40).fill(-1) };
        METIS_OK
    }

    unsafe extern "C" fn defaults_other(options: *mut c_void) -> c_int {
        // SAFETY: the test buffer holds 64 i64s
        unsafe { std::slice::from_raw_parts_mut(options.cast::<i32>(), 30).fill(-1) };
        METIS_OK
    }

    #[test]
    fn index_width_is_read_from_the_default_options() {
        // SAFETY: the fakes write at most 320 bytes
        unsafe {
            assert_eq!(idx_width(defaults32), Some(32));
            assert_eq!(idx_width(defaults64), Some(64));
            assert_eq!(idx_width(defaults_other), None);
        }
    }
}
