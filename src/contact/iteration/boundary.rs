//! The contact boundary as the iteration uses it (docs/method.md, "The contact boundary's algebra"): the flexibility
//! `F = E^T K^-1 E`, either whole (read off a factor's trailing block) or lazily: under small
//! kinematics the node flexibility `N_ab = v_a^T F v_b` of the node directions that become
//! active, computed once per direction from their images `W v_a = L^-1 P E v_a` (hycon's own
//! factor) or their responses `F v_a` (a host's callback, CHOLMOD); under finite kinematics
//! the columns of `F` the active nodes touch. The small system `S tau = b - rows . u0`,
//! `S = rows^T F cols`, is factored by blocked dense Cholesky (extending the previous
//! iteration's factor) and LU for the slip unknowns' Schur complement (faer), formed from
//! forward images of the slip directions kept along with that factor; read off `N`, `S` is
//! not stored (its one-norm from column sums kept with the rows, see [`RowSums`]).
//!
//! The dense reference of the same algebra (every column of `F` built up front, `F c` formed
//! from `F` in every iteration, nalgebra's unblocked LU) is a test oracle behind the feature
//! `oracles` (`oracles.rs`); the tests compare the two.

use super::loads::LoadSolve;
use super::surfaces::{PairNodes, Surfaces};
use super::{
    Border, ContactSurface, DMatrix, Kinematics, Mat, Result, Sparse, column, dot, small_system,
};
use crate::contact::bodies::{Bodies, Images};
use crate::contact::space::{Vector, node};
use crate::contact::tangent::MAX_TANGENTS;
use crate::solver::vector_state::clean_after;
use faer::Par;
use faer::linalg::solvers::{PartialPivLu, Solve};
use small_system::{Row, SmallSystem, kept_tangents, singular};
use std::collections::HashMap;
use std::ops::Range;

/// The boundary algebra part of the analysis: the contact dofs, the flexibility over them,
/// the small system's storage, the converged contact displacement and the kept load solves.
pub(super) struct Boundary {
    /// Global dofs of the contact nodes (A and B of every pair), sorted.
    pub(super) dofs: Vec<usize>,
    /// Position of each global dof in `dofs` (`None`: not a contact dof).
    pub(super) slot: Vec<Option<usize>>,
    /// Seconds spent building `F` (see [`Timings::flexibility`](super::Timings::flexibility)).
    pub(super) flexibility_seconds: f64,
    /// Seconds spent in load solves (see [`Timings::load_solves`](super::Timings::load_solves)).
    pub(super) load_seconds: f64,
    /// `F = E^T K^-1 E` over `dofs` (zero rows and columns at prescribed dofs), its columns
    /// built when first needed (all at once from a factor; a host callback's as nodes become
    /// active).
    pub(super) flexibility: Flexibility,
    /// Under small kinematics, the node flexibility of the directions that have been active.
    pub(super) node_flexibility: NodeFlexibility,
    /// The storage of the small system `S` (see `solve_boundary`), kept between iterations: a
    /// fresh `S` beyond glibc's 32 MiB mmap threshold (m > 2,048) had its pages faulted in
    /// and zeroed again in every iteration.
    pub(super) small_matrix: Mat<f64>,
    /// Converged displacement of the contact dofs (`dofs` order).
    pub(super) qc: Vec<f64>,
    /// Recent load solves, reused when a new load is a combination of their loads.
    /// (Shared, so that the cutback's snapshot copies no vector.)
    pub(super) loads: Vec<std::sync::Arc<LoadSolve>>,
    /// Iterate on the dense reference algebra (see `ContactAnalysis::set_reference_algebra`,
    /// feature `oracles`).
    #[cfg(feature = "oracles")]
    pub(super) reference_algebra: bool,
    /// Factor `K` again in every iteration (a benchmark's control, see
    /// `ContactAnalysis::set_refactor_each_iteration`, feature `oracles`).
    #[cfg(feature = "oracles")]
    pub(super) refactor_each_iteration: bool,
}

impl Boundary {
    /// The algebra over the contact `dofs` of positions of length `n`, with `flexibility` and
    /// the node flexibility of `a_nodes` A nodes per pair.
    pub(super) fn new(
        dofs: Vec<usize>,
        n: usize,
        flexibility: Flexibility,
        a_nodes: impl Iterator<Item = usize>,
    ) -> Self {
        let mut slot = vec![None; n];
        for (i, &d) in dofs.iter().enumerate() {
            slot[d] = Some(i);
        }
        Boundary {
            qc: vec![0.0; dofs.len()],
            node_flexibility: NodeFlexibility::new(a_nodes),
            small_matrix: Mat::new(),
            #[cfg(feature = "oracles")]
            reference_algebra: false,
            #[cfg(feature = "oracles")]
            refactor_each_iteration: false,
            loads: Vec::new(),
            flexibility,
            dofs,
            slot,
            flexibility_seconds: 0.0,
            load_seconds: 0.0,
        }
    }

    /// Position of contact dof `d` in `dofs`. Coupling rows and the pairs name contact nodes
    /// only, so every dof asked for has one.
    pub(super) fn contact_slot(&self, d: usize) -> usize {
        self.slot[d].expect("a dof of a contact node")
    }

    /// Contact node `n`'s vector of `u` over the contact dofs, `dim` the bodies' equations per
    /// node ([`Bodies::dim`]: its dofs are `dim n + c`, the bodies' numbering of their
    /// positions and displacements).
    pub(super) fn node_vector(&self, (n, dim): (usize, usize), uc: &[f64]) -> Vector {
        let mut v = Vector::zero(dim);
        for (c, out) in v.components_mut().iter_mut().enumerate() {
            *out = uc[self.contact_slot(dim * n + c)];
        }
        v
    }

    /// `sum_j c_kj u_j` for a coupling row over node ids and `u` over the contact dofs, `dim`
    /// the bodies' equations per node.
    pub(super) fn coupled(&self, (coupling, dim): (&[(usize, f64)], usize), uc: &[f64]) -> Vector {
        (coupling.iter()).fold(Vector::zero(dim), |acc, &(j, c)| {
            acc.add_scaled(c, &self.node_vector((j, dim), uc))
        })
    }

    /// Rows over the contact dofs of node `k`: `d . sum_j c_kj u_j` for direction `d` (of the
    /// bodies' dimension).
    pub(super) fn directed(&self, coupling: &[(usize, f64)], d: &Vector) -> Sparse {
        let (dim, d) = (d.dim(), d.components());
        let mut row = Vec::with_capacity(coupling.len() * dim);
        for &(j, c) in coupling {
            for (i, &di) in d.iter().enumerate() {
                row.push((self.contact_slot(dim * j + i), c * di));
            }
        }
        row
    }

    /// Current positions `X + u` of the nodes from their reference positions `x0`, with `u`
    /// given at the contact dofs (the other nodes keep their reference positions: the contact
    /// geometry never reads them).
    pub(super) fn positions(&self, x0: &[f64], uc: &[f64]) -> Vec<f64> {
        let mut x = x0.to_vec();
        for (&d, &u) in self.dofs.iter().zip(uc) {
            x[d] += u;
        }
        x
    }

    /// Forget the node flexibility of every direction (see [`NodeFlexibility::forget`]).
    pub(super) fn forget_directions(&mut self) {
        self.node_flexibility.forget();
    }

    /// What an increment changes of the boundary algebra, as it is (the cutback's snapshot):
    /// the kept load solves (shared: no solve is copied) and the converged contact
    /// displacement. (`F`, the node flexibility and the small system's storage are caches of
    /// `K`'s responses, true of any state.)
    pub(super) fn snapshot(&self) -> Snapshot {
        Snapshot {
            loads: self.loads.clone(),
            qc: self.qc.clone(),
        }
    }

    /// Put back what [`snapshot`](Self::snapshot) took.
    pub(super) fn restore(&mut self, s: Snapshot) {
        (self.loads, self.qc) = (s.loads, s.qc);
    }
}

/// What an increment changes of the [`Boundary`] (see [`Boundary::snapshot`]).
pub(super) struct Snapshot {
    loads: Vec<std::sync::Arc<LoadSolve>>,
    qc: Vec<f64>,
}

/// Directions whose images one forward substitution computes (neighbouring nodes' directions:
/// their elimination-tree paths mostly coincide).
const IMAGE_BATCH: usize = 64;

/// The flexibility `F = E^T K^-1 E` over the contact dofs, column by column: a column is
/// either known (computed once, then kept) or not yet asked for.
#[derive(Debug, Clone)]
pub(super) struct Flexibility {
    /// `F` (`m x m`; empty until a first column is known: small kinematics on hycon's own
    /// factor never asks for one, and at n = 512 the zeros alone were 443 MB); unknown columns
    /// hold zeros.
    pub(super) matrix: DMatrix<f64>,
    /// Whether column `j` is known.
    known: Vec<bool>,
}

impl Flexibility {
    /// Every column known.
    pub(super) fn full(matrix: DMatrix<f64>) -> Self {
        let known = vec![true; matrix.ncols()];
        Flexibility { matrix, known }
    }

    /// No column known yet (order `m`).
    pub(super) fn lazy(m: usize) -> Self {
        Flexibility {
            matrix: DMatrix::zeros(0, 0),
            known: vec![false; m],
        }
    }

    /// Make column `j` known with the values `f`.
    fn set_column(&mut self, j: usize, f: impl Iterator<Item = f64>) {
        let m = self.known.len();
        if self.matrix.ncols() != m {
            self.matrix = DMatrix::zeros(m, m);
        }
        self.matrix
            .column_mut(j)
            .iter_mut()
            .zip(f)
            .for_each(|(c, v)| *c = v);
        self.known[j] = true;
    }

    /// Whether every column is known.
    pub(super) fn is_full(&self) -> bool {
        self.known.iter().all(|&k| k)
    }

    /// Column `j` (known).
    pub(super) fn column(&self, j: usize) -> &[f64] {
        debug_assert!(
            self.known[j],
            "column {j} of F asked for before it was built"
        );
        column(&self.matrix, j)
    }
}

/// Under small kinematics, the node directions that have been active and their flexibility:
/// `v_a = d . c_k` for direction `a = (pair, A node k, d)` (`d` the node's normal or a tangent,
/// `c_k` its coupling row) and the node flexibility `N_ab = v_a^T F v_b`. The frames and the
/// coupling never change under small kinematics, so a direction is added once, when its node
/// first becomes active, and the small system of every iteration is read off `N`. What is
/// kept of a direction to form `N` and the contact dofs' displacement depends on the solver:
/// * with hycon's own (faer) factor `K = P^T L L^T P`, its image `w_a = L^-1 P E v_a`, one
///   forward substitution along the direction's own elimination-tree path (a small part of
///   `L`); then `N_ab = w_a . w_b`, and the displacement `F sum_b t_b v_b` of an iteration is
///   one backward substitution of `sum_b t_b w_b` ([`Bodies::back_substitute`]);
/// * otherwise (a host's solve callback, CHOLMOD, or all of `F` known) its response
///   `y_a = F v_a` over the contact dofs; then `N_ab = v_a . y_b`.
#[derive(Debug, Clone, Default)]
pub(super) struct NodeFlexibility {
    /// Index of each direction, per pair, per A node, `[normal, tangents..]`
    /// ([`NodeFlexibility::slot`]).
    index: Vec<Vec<[Option<usize>; 1 + MAX_TANGENTS]>>,
    /// `v_a`.
    vectors: Vec<Sparse>,
    /// What is kept of each direction.
    kept: Vec<Kept>,
    /// The batches of images, each with the direction of its columns.
    batches: Vec<(Images, Vec<usize>)>,
    /// `N_ab` as rows `a`.
    n: Vec<Vec<f64>>,
    /// The factor of the last symmetric block.
    factor: KeptFactor,
    /// Forward images on that factor of the directions the last slip unknowns needed.
    slip: SlipImages,
    /// The one-norms of `N`'s columns over the last small system's row directions.
    sums: RowSums,
}

/// What [`NodeFlexibility`] keeps of a direction.
#[derive(Debug, Clone)]
enum Kept {
    /// `y = F v` over the contact dofs.
    Response(Vec<f64>),
    /// Column `column` of the images of batch `batch`.
    Image { batch: usize, column: usize },
}

impl NodeFlexibility {
    /// No direction known, for pairs with `a_nodes[p]` A nodes.
    pub(super) fn new(a_nodes: impl Iterator<Item = usize>) -> Self {
        NodeFlexibility {
            index: a_nodes.map(|n| vec![[None; 1 + MAX_TANGENTS]; n]).collect(),
            ..Default::default()
        }
    }

    /// Forget every direction (their flexibility is stale, see `Surfaces::widen`).
    pub(super) fn forget(&mut self) {
        *self = Self::new(self.index.iter().map(Vec::len));
    }

    /// The place of `row` in a node's `index`: 0 for the normal, `1 + i` for tangent `s_i`.
    fn slot(row: Row) -> usize {
        match row {
            Row::Normal => 0,
            Row::Tangent(i) => 1 + i,
        }
    }

    fn get(&self, (p, k, row): (usize, usize, Row)) -> Option<usize> {
        self.index[p][k][Self::slot(row)]
    }

    /// Whether a direction of A node `k` of pair `p` is known (it has been active).
    pub(super) fn knows(&self, p: usize, k: usize) -> bool {
        self.index[p][k].iter().any(Option::is_some)
    }

    /// Register direction `key` with vector `v` as number `vectors.len()`.
    fn register(&mut self, (p, k, row): (usize, usize, Row), v: Sparse, kept: Kept) {
        self.index[p][k][Self::slot(row)] = Some(self.vectors.len());
        self.vectors.push(v);
        self.kept.push(kept);
    }

    /// Append the new directions' rows and columns to `N`: `cross[a][j] = N_(a, c0 + j)` for
    /// every known `a` (`c0` of them) and `within(i, j) = N_(c0 + i, c0 + j)`, read for
    /// `i <= j` only, so that `N` stays exactly symmetric.
    fn extend_n(&mut self, cross: Vec<Vec<f64>>, new: usize, within: impl Fn(usize, usize) -> f64) {
        let c0 = self.n.len();
        for (na, ca) in self.n.iter_mut().zip(&cross) {
            na.extend_from_slice(ca);
        }
        for j in 0..new {
            let mut row: Vec<f64> = cross.iter().map(|ca| ca[j]).collect();
            row.extend((0..new).map(|i| within(i.min(j), i.max(j))));
            self.n.push(row);
        }
        debug_assert_eq!(self.n.len(), c0 + new);
    }

    /// The rows `v_b . y_a` of the new directions `vs` against the known responses `y_a`
    /// (zero against images, filled by the caller).
    fn cross_responses(&self, vs: &[Sparse]) -> Vec<Vec<f64>> {
        self.kept
            .iter()
            .map(|kept| match kept {
                Kept::Response(y) => vs.iter().map(|v| dot(v, y)).collect(),
                Kept::Image { .. } => vec![0.0; vs.len()],
            })
            .collect()
    }

    /// Add directions `keys` with vectors `vs` and responses `y_b = F v_b` (columns of `y`):
    /// `N_ab = v_a . y_b` for every known response `a`, `v_b . y_a` against known responses
    /// (`F` is symmetric).
    fn add_responses(&mut self, keys: &[(usize, usize, Row)], vs: Vec<Sparse>, y: &DMatrix<f64>) {
        let ys: Vec<Vec<f64>> = (0..vs.len()).map(|c| column(y, c).to_vec()).collect();
        let cross = self.cross_responses(&vs);
        self.extend_n(cross, vs.len(), |i, j| dot(&vs[i], &ys[j]));
        for ((&key, v), y) in keys.iter().zip(vs).zip(ys) {
            self.register(key, v, Kept::Response(y));
        }
    }

    /// Add directions `keys` with vectors `vs` and their images `W v_b` (the columns of
    /// `images`): `N_ab = w_a . w_b` against every earlier batch of images (one product over
    /// the rows the two reaches share) and within the batch, `v_b . y_a` against known
    /// responses.
    fn add_images(&mut self, keys: &[(usize, usize, Row)], vs: Vec<Sparse>, images: Images) {
        let mut cross = self.cross_responses(&vs);
        for (batch, directions) in &self.batches {
            let g = gram(batch, &images);
            for (i, &a) in directions.iter().enumerate() {
                for (j, c) in cross[a].iter_mut().enumerate() {
                    *c = g[(i, j)];
                }
            }
        }
        let within = clean_after(|| images.values.transpose() * &images.values);
        self.extend_n(cross, vs.len(), |i, j| within[(i, j)]);
        let (batch, c0) = (self.batches.len(), self.vectors.len());
        for (column, (&key, v)) in keys.iter().zip(vs).enumerate() {
            self.register(key, v, Kept::Image { batch, column });
        }
        self.batches.push((images, (c0..c0 + keys.len()).collect()));
    }
}

/// `A^T B` for two batches of images: over the rows their reaches share (equal factor
/// columns; a row of one reach alone meets zeros of the other image), one product per run of
/// rows consecutive in both, read in place (the reaches share a few long runs: the paths to
/// the elimination tree's root).
fn gram(a: &Images, b: &Images) -> Mat<f64> {
    let mut g = Mat::<f64>::zeros(a.values.ncols(), b.values.ncols());
    clean_after(|| {
        for (ra, rb, len) in shared_runs(&a.columns, &b.columns) {
            faer::linalg::matmul::matmul(
                g.as_mut(),
                faer::Accum::Add,
                a.values.subrows(ra, len).transpose(),
                b.values.subrows(rb, len),
                1.0,
                faer::Par::Seq,
            );
        }
    });
    g
}

/// The entries two ascending lists share, as maximal runs `(i, j, len)` of positions
/// consecutive in both: `a[i + r] == b[j + r]` for every `r < len`.
fn shared_runs(a: &[usize], b: &[usize]) -> Vec<(usize, usize, usize)> {
    let mut runs: Vec<(usize, usize, usize)> = Vec::new();
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                match runs.last_mut() {
                    Some((ri, rj, len)) if *ri + *len == i && *rj + *len == j => *len += 1,
                    _ => runs.push((i, j, 1)),
                }
                i += 1;
                j += 1;
            }
        }
    }
    runs
}

/// What [`Boundary::solve_boundary`] gives: the unknowns `tau`, the plate's
/// force-controlled translations, the condition estimate of the small system and the new
/// displacement of the contact dofs.
pub(super) type Solution = (Vec<f64>, Vec<f64>, f64, Vec<f64>);

/// A dense factorization of the small system `S`:
/// * block elimination on the symmetric part: the unknowns `P` whose column is their row
///   (stick rows, normal rows without friction; all of them when there is no slip node under
///   friction, `S = R^T F R` being then symmetric positive definite) and the slip normal
///   unknowns `Q` (column `n + mu sign s`), `S = [S_PP S_PQ; S_QP S_QQ]` with
///   `S_PP = L L^T` by Cholesky and the Schur complement `Z = S_QQ - S_QP S_PP^-1 S_PQ` by LU:
///   `|P|^3 / 3 + |P|^2 |Q| + 2 |Q|^3 / 3` flops instead of `2 (|P| + |Q|)^3 / 3`, and under
///   small kinematics much less, as `L` extends the kept factor of an earlier iteration (see
///   [`KeptFactor`]) and `L^-1 S_PQ` combines forward images kept with it (see
///   [`SlipImages`]);
/// * else (a plate border, or a Cholesky that fails) LU with partial pivoting `P S = L U`.
enum Dense {
    Lu(PartialPivLu<f64>),
    Block(Box<Blocks>),
}

/// The block form of [`Dense`]: `p` the symmetric unknowns in the order of `l`
/// (`S_PP` permuted to that order `= L L^T`).
struct Blocks {
    p: Vec<usize>,
    l: Mat<f64>,
    slip: Option<Slip>,
}

/// The slip unknowns `Q` of [`Blocks`] and their Schur complement
/// `Z = S_QQ - S_QP S_PP^-1 S_PQ = S_QQ - Y^T X`.
struct Slip {
    q: Vec<usize>,
    /// `X = L^-1 S_PQ`.
    x: Mat<f64>,
    /// `Y = L^-1 S_QP^T`.
    y: Mat<f64>,
    z: PartialPivLu<f64>,
}

/// The Cholesky factor of the symmetric block of the last small system under small kinematics,
/// kept for the next one. Its entries `N_ab` never change, so when the next system's symmetric
/// unknowns begin with the same directions `keys[..p]`, the leading `p x p` block of `l` is
/// theirs: only the rows of the new and reordered unknowns are computed
/// ([`cholesky_extending`]). Between iterations the contact set changes at the zone's edges,
/// so the unknowns are ordered with those of the kept factor first and new ones by distance
/// from the zone's centre ([`Boundary::factor_order`]).
#[derive(Debug, Clone)]
pub(super) struct KeptFactor {
    /// The direction (node-flexibility index) of each row of `l`.
    keys: Vec<usize>,
    l: Mat<f64>,
}

impl Default for KeptFactor {
    fn default() -> Self {
        KeptFactor {
            keys: Vec::new(),
            l: Mat::new(),
        }
    }
}

impl KeptFactor {
    /// How many leading directions of `order` (node-flexibility indices) the kept factor
    /// shares with it.
    fn common_prefix(&self, order: &[usize]) -> usize {
        self.keys
            .iter()
            .zip(order)
            .take(self.l.nrows())
            .take_while(|(a, b)| a == b)
            .count()
    }
}

/// Forward images `x_d = L^-1 N_(K, d)` of node directions `d` on the kept factor `L` of the
/// symmetric block (`K` its directions, in the factor's order), for the slip unknowns `Q`
/// under friction. `S_PQ`'s column `j` is `sum_b c_jb N_(K, b)` and `S_QP^T`'s is
/// `N_(K, row_j)`, so `X = L^-1 S_PQ` and `Y = L^-1 S_QP^T`, which give the Schur complement
/// `Z = S_QQ - Y^T X` and every solve (see [`Slip`]), combine these images.
///
/// A forward substitution reads `L` from the top, so the first rows of an image stay right
/// while the factor keeps its first directions (see [`KeptFactor`]): an image is completed
/// only below them, `x_2 = L_22^-1 (N_(K_2, d) - L_21 x_1)`, and computed whole only for a
/// direction new to the slip set. Where forming `S_PP^-1 S_PQ` took `2 |P|^2 |Q|` flops in
/// every iteration (3 Gflop at n = 512, `|P|` = 2,300, `|Q|` = 300), an iteration now costs
/// `|P|^2` per new direction and little else. A direction's image is kept for
/// [`SLIP_IMAGE_UPDATES`] updates without use: slip sets with hundreds of nodes were seen
/// to alternate between two sets in consecutive iterations.
#[derive(Debug, Clone, Default)]
pub(super) struct SlipImages {
    images: HashMap<usize, SlipImage>,
    /// For each factor since the first, how many leading directions it kept of the one
    /// before (its generation is its index + 1).
    prefixes: Vec<usize>,
    /// Updates made.
    updates: usize,
}

/// A direction's image in [`SlipImages`].
#[derive(Debug, Clone)]
struct SlipImage {
    x: Vec<f64>,
    /// How many leading rows hold for the factor of `generation`.
    valid: usize,
    generation: usize,
    /// The update that last used it.
    used: usize,
}

/// How many updates of [`SlipImages`] an unused image is kept for.
const SLIP_IMAGE_UPDATES: usize = 3;

impl SlipImages {
    /// A new factor keeps the first `prefix` directions of the last one.
    fn keep(&mut self, prefix: usize) {
        self.prefixes.push(prefix);
    }

    /// Make the images of the distinct directions `needed` right on the current factor `l` of
    /// the directions `keys` (`N` by rows `n`): each is completed below the rows that still
    /// hold (all of them for a new direction), one batch per count of such rows.
    fn update(&mut self, l: &Mat<f64>, keys: &[usize], n: &[Vec<f64>], needed: &[usize]) {
        use faer::linalg::matmul::matmul;
        use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
        let (k, generation) = (keys.len(), self.prefixes.len());
        let holds = |image: &SlipImage| {
            self.prefixes[image.generation..]
                .iter()
                .fold(image.valid, |v, &p| v.min(p))
        };
        let mut batches: Vec<(usize, Vec<usize>)> = Vec::new();
        for &d in needed {
            let v = self.images.get(&d).map_or(0, holds).min(k);
            match batches.iter_mut().find(|(valid, _)| *valid == v) {
                Some((_, ds)) => ds.push(d),
                None => batches.push((v, vec![d])),
            }
        }
        for (v, ds) in batches.into_iter().filter(|(v, _)| *v < k) {
            // the rows that hold (none for a new direction)
            let heads: Vec<&[f64]> = ds
                .iter()
                .map(|d| self.images.get(d).map_or(&[][..], |image| &image.x[..v]))
                .collect();
            let mut x2 = Mat::<f64>::zeros(k - v, ds.len());
            for (j, d) in ds.iter().enumerate() {
                gather(&n[*d], &keys[v..], col_slice(&mut x2, j));
            }
            let x1 = Mat::<f64>::from_fn(v, ds.len(), |i, j| heads[j][i]);
            clean_after(|| {
                matmul(
                    x2.as_mut(),
                    faer::Accum::Add,
                    l.as_ref().submatrix(v, 0, k - v, v),
                    x1.as_ref(),
                    -1.0,
                    Par::Seq,
                );
                let l22 = l.as_ref().submatrix(v, v, k - v, k - v);
                solve_lower_triangular_in_place(l22, x2.as_mut(), Par::Seq);
            });
            for (j, d) in ds.into_iter().enumerate() {
                let image = self.images.entry(d).or_insert(SlipImage {
                    x: Vec::new(),
                    valid: 0,
                    generation,
                    used: 0,
                });
                image.x.resize(k, 0.0);
                image.x[v..].copy_from_slice(col_slice(&mut x2, j));
            }
        }
        self.updates += 1;
        for &d in needed {
            let image = self.images.get_mut(&d).expect("updated above");
            image.x.truncate(k);
            (image.valid, image.generation, image.used) = (k, generation, self.updates);
        }
        let updates = self.updates;
        self.images
            .retain(|_, image| image.used + SLIP_IMAGE_UPDATES > updates);
    }

    /// The image of direction `d` (made right by the last [`update`](Self::update)).
    fn image(&self, d: usize) -> &[f64] {
        &self.images[&d].x
    }
}

/// The one-norms `sum_(a in R) |N_ab|` of the columns of `N` over the row directions `R` of the
/// last small system, for `||S||_1` (the condition estimate's scale): a column of `S` whose
/// unknown is not slipping is `N_(R, b)`, and `R` changes at the zone's edges between
/// iterations, so a sum is updated by the rows that left and entered,
/// `|R| (|added| + |removed|)` reads of `N` instead of `|R|^2` (at n = 512 with friction,
/// reading the 2,900^2 entries in every iteration took 0.22 s).
#[derive(Debug, Clone, Default)]
pub(super) struct RowSums {
    /// Whether direction `a` is in `R`.
    member: Vec<bool>,
    /// `R`.
    rows: Vec<usize>,
    /// `sum_(a in R) |N_ab|`, for `b` in `R` (stale elsewhere).
    sums: Vec<f64>,
}

impl RowSums {
    /// Move to the (distinct) row directions `rows` of `N` (rows `n`), in the `runs` of
    /// consecutive directions of [`consecutive_runs`]; every sum computed afresh when more
    /// than half of them changed.
    fn update(&mut self, n: &[Vec<f64>], rows: &[usize], runs: &[(usize, usize, usize)]) {
        let d = n.len();
        self.member.resize(d, false);
        self.sums.resize(d, 0.0);
        let mut member = vec![false; d];
        rows.iter().for_each(|&a| member[a] = true);
        let added: Vec<usize> = rows.iter().copied().filter(|&a| !self.member[a]).collect();
        let removed: Vec<usize> = self.rows.iter().copied().filter(|&a| !member[a]).collect();
        let fresh = |b: usize| {
            runs.iter()
                .map(|&(_, a, len)| abs_sum(&n[b][a..a + len]))
                .sum::<f64>()
        };
        let afresh = 2 * (added.len() + removed.len()) > rows.len();
        for &b in rows {
            self.sums[b] = if afresh || !self.member[b] {
                fresh(b)
            } else {
                let nb = &n[b];
                let entered: f64 = added.iter().map(|&a| nb[a].abs()).sum();
                let left: f64 = removed.iter().map(|&a| nb[a].abs()).sum();
                self.sums[b] + entered - left
            };
        }
        (self.member, self.rows) = (member, rows.to_vec());
    }

    /// `||S||_1 = max_j sum_i |S_ij|` of the small system `nodes` (a column with more than one
    /// part read whole), updating the sums to its rows.
    fn norm1(&mut self, nodes: &NodeColumns) -> f64 {
        let NodeColumns {
            n,
            rows,
            runs,
            cols,
        } = nodes;
        self.update(n, rows, runs);
        let mut column = vec![0.0; rows.len()];
        cols.iter().enumerate().fold(0.0, |norm, (j, parts)| {
            let sum = match parts[..] {
                [(b, c)] => c.abs() * self.sums[b],
                _ => {
                    nodes.column(j, &mut column);
                    abs_sum(&column)
                }
            };
            norm.max(sum)
        })
    }
}

/// `out[i] = row[keys[i]]`: a column of the symmetric `N` read from one row of it (which
/// stays in cache) rather than an entry from each of its rows.
fn gather(row: &[f64], keys: &[usize], out: &mut [f64]) {
    for (o, &k) in out.iter_mut().zip(keys) {
        *o = row[k];
    }
}

/// The lower Cholesky factor `L` of the symmetric positive definite `A` (`n x n`, read by
/// columns: `column(j, rows, out)` writes `A[rows, j]`, see [`by_entries`]) whose leading
/// `p x p` block `A11 = L11 L11^T` is already factored: `L11` is the leading block of `l`
/// (which may be larger), `L21 = A21 L11^-T` by one triangular solve and
/// `L22 L22^T = A22 - L21 L21^T` by a blocked Cholesky, `n^2 (n - p) - ...` flops instead of
/// `n^3 / 3` when few unknowns are new. `l` is cut to `p x p` and grown to `n x n` in place,
/// and `A22`'s lower triangle is read, updated and factored in `L22`'s place: an unchanged
/// factor costs nothing, a grown one only its new rows (a fresh `n x n` copy took 20 ms at
/// n = 2,150; at n = 2,890, copying `A22` in and `L22` out took a third of the fresh factor's
/// time). `None` when `A` is not numerically positive definite.
fn cholesky_extending(
    mut l: Mat<f64>,
    p: usize,
    n: usize,
    column: impl Fn(usize, Range<usize>, &mut [f64]),
) -> Option<Mat<f64>> {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::cholesky::llt::factor::{cholesky_in_place, cholesky_in_place_scratch};
    use faer::linalg::matmul::triangular::{BlockStructure, matmul};
    use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
    let r = n - p;
    l.truncate(p, p);
    l.resize_with(n, n, |_, _| 0.0);
    if r == 0 {
        return Some(l);
    }
    let mut l21t = Mat::<f64>::zeros(p, r);
    for j in 0..r {
        if p > 0 {
            column(p + j, 0..p, col_slice(&mut l21t, j));
        }
        column(p + j, p + j..n, &mut col_slice(&mut l, p + j)[p + j..]);
    }
    // L21^T = L11^-1 A21^T
    solve_lower_triangular_in_place(l.as_ref().submatrix(0, 0, p, p), l21t.as_mut(), Par::Seq);
    let mut l22 = l.as_mut().submatrix_mut(p, p, r, r);
    matmul(
        l22.as_mut(),
        BlockStructure::TriangularLower,
        faer::Accum::Add,
        l21t.transpose(),
        BlockStructure::Rectangular,
        l21t.as_ref(),
        BlockStructure::Rectangular,
        -1.0,
        Par::Seq,
    );
    let mut scratch = MemBuffer::new(cholesky_in_place_scratch::<f64>(
        r,
        Par::Seq,
        Default::default(),
    ));
    let stack = MemStack::new(&mut scratch);
    cholesky_in_place(
        l22.as_mut(),
        Default::default(),
        Par::Seq,
        stack,
        Default::default(),
    )
    .ok()?;
    // the factorization may leave values above the diagonal
    for j in 1..r {
        l22.as_mut().col_mut(j).subrows_mut(0, j).fill(0.0);
    }
    l.as_mut()
        .submatrix_mut(p, 0, r, p)
        .copy_from(l21t.transpose());
    Some(l)
}

/// A column reader for [`cholesky_extending`] from the entries `a(i, j)` of a symmetric
/// matrix, read for `j <= i` only (the lower triangle decides when rounding has left the
/// upper one slightly different).
fn by_entries(a: impl Fn(usize, usize) -> f64) -> impl Fn(usize, Range<usize>, &mut [f64]) {
    move |j, rows, out| {
        for (o, i) in out.iter_mut().zip(rows) {
            *o = a(i.max(j), i.min(j));
        }
    }
}

impl Dense {
    /// `S` factored; `p` the symmetric unknowns in the order of their factor `l` (`None`: not
    /// factored yet, or not symmetric positive definite), `q` the unknowns whose column is not
    /// their row, `images` as for [`block`](Self::block).
    fn new(
        s: &Mat<f64>,
        symmetric: Option<(Vec<usize>, Mat<f64>)>,
        q: Vec<usize>,
        images: Option<(Mat<f64>, Mat<f64>)>,
    ) -> Self {
        match symmetric {
            Some((p, l)) => Dense::block(p, l, q, |i, j| s[(i, j)], images),
            None => Dense::Lu(s.partial_piv_lu()),
        }
    }

    /// The block form of `S` (entries `entry(i, j)`, read only in the slip block's rows or
    /// columns) from the factor `l` of its symmetric unknowns `p` (in `l`'s order) and the
    /// slip unknowns `q`, whose block is `(X, Y) = (L^-1 S_PQ, L^-1 S_QP^T)` when the caller
    /// has them (see [`SlipImages`]; else two forward substitutions make them).
    fn block(
        p: Vec<usize>,
        l: Mat<f64>,
        q: Vec<usize>,
        entry: impl Fn(usize, usize) -> f64,
        images: Option<(Mat<f64>, Mat<f64>)>,
    ) -> Self {
        use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
        let slip = (!q.is_empty()).then(|| {
            let sub = |r: &[usize], c: &[usize]| {
                Mat::<f64>::from_fn(r.len(), c.len(), |i, j| entry(r[i], c[j]))
            };
            let (x, y) = images.unwrap_or_else(|| {
                let (mut x, mut y) = (sub(&p, &q), sub(&q, &p).transpose().to_owned());
                solve_lower_triangular_in_place(l.as_ref(), x.as_mut(), Par::Seq);
                solve_lower_triangular_in_place(l.as_ref(), y.as_mut(), Par::Seq);
                (x, y)
            });
            let z = clean_after(|| sub(&q, &q) - y.transpose() * &x);
            Slip {
                z: z.partial_piv_lu(),
                q,
                x,
                y,
            }
        });
        Dense::Block(Box::new(Blocks { p, l, slip }))
    }

    /// `x <- S^-1 x`, or `S^-T x` when `transpose`. For the block form, with `z = L^-1 x_P`:
    /// `S^-1 x`: `x_Q <- Z^-1 (x_Q - Y^T z)`, `x_P <- L^-T (z - X x_Q)`;
    /// `S^-T x`: `x_Q <- Z^-T (x_Q - X^T z)`, `x_P <- L^-T (z - Y x_Q)`
    /// (`S_QP S_PP^-1 = Y^T L^-1`, `S_PQ^T S_PP^-1 = X^T L^-1`): either way one forward and
    /// one backward substitution with `L`.
    fn solve(&self, mut x: faer::MatMut<'_, f64>, transpose: bool) {
        use faer::linalg::triangular_solve::{
            solve_lower_triangular_in_place, solve_upper_triangular_in_place,
        };
        match self {
            Dense::Lu(f) if transpose => f.solve_transpose_in_place(x),
            Dense::Lu(f) => f.solve_in_place(x),
            Dense::Block(b) => {
                let Blocks { p, l, slip } = b.as_ref();
                let k = x.ncols();
                let mut xp = Mat::<f64>::from_fn(p.len(), k, |i, j| x[(p[i], j)]);
                // rows above the first nonzero stay zero (the condition estimate's unit
                // vectors: a slip unknown's has none, and the zone's edges are factored last)
                let nonzero = |i: &usize| (0..k).any(|j| xp[(*i, j)] != 0.0);
                let first = (0..p.len()).find(nonzero).unwrap_or(p.len());
                let rest = p.len() - first;
                solve_lower_triangular_in_place(
                    l.as_ref().submatrix(first, first, rest, rest),
                    xp.as_mut().subrows_mut(first, rest),
                    Par::Seq,
                );
                if let Some(Slip { q, x: sx, y: sy, z }) = slip {
                    let xq = Mat::<f64>::from_fn(q.len(), k, |i, j| x[(q[i], j)]);
                    let (by_q, by_p) = if transpose { (sx, sy) } else { (sy, sx) };
                    let mut rq = clean_after(|| xq - by_q.transpose() * &xp);
                    if transpose {
                        z.solve_transpose_in_place(rq.as_mut());
                    } else {
                        z.solve_in_place(rq.as_mut());
                    }
                    xp = clean_after(|| xp - by_p * &rq);
                    scatter(&rq, q, x.as_mut());
                }
                solve_upper_triangular_in_place(l.transpose(), xp.as_mut(), Par::Seq);
                scatter(&xp, p, x);
            }
        }
    }
}

/// The first `m` rows of the small system's `S`, a column or an entry at a time, without
/// storing it (its one-norm: see [`RowSums`]).
enum Columns<'a> {
    /// Small kinematics.
    Nodes(NodeColumns<'a>),
    /// Finite kinematics: `S_ij = row_i . y_j` with the responses `y_j = F col_j` (`mc`
    /// values each).
    Responses {
        rows: &'a [Sparse],
        y: &'a [f64],
        mc: usize,
    },
}

/// `S_ij = sum_(b, c) c N_(b, row_i)` over the parts `(b, c)` of column `j` (small
/// kinematics; `N` is symmetric: a column reads along the rows `N_b`, in the `runs` of
/// consecutive directions that `rows` come in: slices, not gathers).
struct NodeColumns<'a> {
    n: &'a [Vec<f64>],
    rows: &'a [usize],
    runs: Vec<(usize, usize, usize)>,
    cols: &'a [Vec<(usize, f64)>],
}

impl NodeColumns<'_> {
    /// Column `j` into `out` (`m` values).
    fn column(&self, j: usize, out: &mut [f64]) {
        out.fill(0.0);
        for &(b, c) in &self.cols[j] {
            for &(i, a, len) in &self.runs {
                for (o, v) in out[i..i + len].iter_mut().zip(&self.n[b][a..a + len]) {
                    *o += c * v;
                }
            }
        }
    }

    /// `S_ij`, summed as [`column`](Self::column) sums it.
    fn entry(&self, i: usize, j: usize) -> f64 {
        let row = self.rows[i];
        self.cols[j]
            .iter()
            .fold(0.0, |sum, &(b, c)| sum + c * self.n[b][row])
    }
}

impl Columns<'_> {
    /// Column `j` into `out` (`m` values).
    fn column(&self, j: usize, out: &mut [f64]) {
        match self {
            Columns::Nodes(nodes) => nodes.column(j, out),
            Columns::Responses { rows, y, mc } => {
                let yj = &y[j * mc..(j + 1) * mc];
                for (o, row) in out.iter_mut().zip(rows.iter()) {
                    *o = dot(row, yj);
                }
            }
        }
    }

    /// `S_ij`, summed as [`column`](Self::column) sums it.
    fn entry(&self, i: usize, j: usize) -> f64 {
        match self {
            Columns::Nodes(nodes) => nodes.entry(i, j),
            Columns::Responses { rows, y, mc } => dot(&rows[i], &y[j * mc..(j + 1) * mc]),
        }
    }
}

/// Column `j` of `s` as a slice.
fn col_slice(s: &mut Mat<f64>, j: usize) -> &mut [f64] {
    s.as_mut()
        .col_mut(j)
        .try_as_col_major_mut()
        .expect("a Mat's columns are contiguous")
        .as_slice_mut()
}

/// `indices` as runs of consecutive values, `(position, first value, length)`: the directions
/// of the unknowns, numbered as their nodes entered, come in a few long runs.
fn consecutive_runs(indices: &[usize]) -> Vec<(usize, usize, usize)> {
    let mut runs: Vec<(usize, usize, usize)> = Vec::new();
    for (i, &a) in indices.iter().enumerate() {
        match runs.last_mut() {
            Some((_, first, len)) if *first + *len == a => *len += 1,
            _ => runs.push((i, a, 1)),
        }
    }
    runs
}

/// `sum_i |x_i|` in four interleaved partial sums, which the compiler vectorizes (a single
/// running sum must keep its order of additions and stays scalar).
fn abs_sum(x: &[f64]) -> f64 {
    let mut chunks = x.chunks_exact(4);
    let mut partial = [0.0; 4];
    for c in chunks.by_ref() {
        for (p, v) in partial.iter_mut().zip(c) {
            *p += v.abs();
        }
    }
    let rest: f64 = chunks.remainder().iter().map(|v| v.abs()).sum();
    (partial[0] + partial[1]) + (partial[2] + partial[3]) + rest
}

/// `x[rows[i], j] = v[i, j]`.
fn scatter(v: &Mat<f64>, rows: &[usize], mut x: faer::MatMut<'_, f64>) {
    for j in 0..v.ncols() {
        for (i, &r) in rows.iter().enumerate() {
            x[(r, j)] = v[(i, j)];
        }
    }
}

/// `rhs <- A^-1 rhs` and `||A||_1 ||A^-1||_1` (`a_norm = ||A||_1`) with `||A^-1||_1`
/// estimated by Hager's method from the factors of `A` (Higham's Algorithm 2.1, the same steps
/// as `small_system::condition_estimate`); the first step's solve and `rhs`'s share one pass
/// over the factors, which costs what one of them does. `None` when a solve is not finite
/// (singular `A`).
fn solve_and_estimate(a_norm: f64, lu: &Dense, rhs: faer::MatMut<'_, f64>) -> Option<f64> {
    let m = rhs.nrows();
    let norm1 = |v: &Mat<f64>| (0..m).map(|i| v[(i, 0)].abs()).sum::<f64>();
    let mut x = Mat::<f64>::from_fn(m, 1, |_, _| 1.0 / m as f64);
    let mut first = Mat::<f64>::from_fn(m, 2, |i, j| if j == 0 { x[(i, 0)] } else { rhs[(i, 0)] });
    lu.solve(first.as_mut(), false);
    rhs.col_mut(0).copy_from(first.col(1));
    let mut y = first.get(.., ..1).to_owned();
    let mut estimate = 0.0;
    for step in 0..5 {
        if step > 0 {
            y = x.clone();
            lu.solve(y.as_mut(), false);
        }
        if !(0..m).all(|i| y[(i, 0)].is_finite()) {
            return None;
        }
        estimate = norm1(&y);
        let mut z = Mat::<f64>::from_fn(m, 1, |i, _| if y[(i, 0)] >= 0.0 { 1.0 } else { -1.0 });
        lu.solve(z.as_mut(), true);
        if !(0..m).all(|i| z[(i, 0)].is_finite()) {
            return None;
        }
        // the first largest |z_j|, as nalgebra's iamax
        let mut j = 0;
        for i in 1..m {
            if z[(i, 0)].abs() > z[(j, 0)].abs() {
                j = i;
            }
        }
        let zx: f64 = (0..m).map(|i| z[(i, 0)] * x[(i, 0)]).sum();
        if z[(j, 0)].abs() <= zx {
            break;
        }
        x = Mat::zeros(m, 1);
        x[(j, 0)] = 1.0;
    }
    let condition = a_norm * estimate;
    condition.is_finite().then_some(condition)
}

impl Boundary {
    /// Make the columns `slots` of `F` known: a lazy flexibility gets the missing ones from
    /// one batch of solves, `F e_j = E^T K^-1 e_j` (see [`Bodies::flexibility_times`]); the
    /// time counts as flexibility.
    pub(super) fn ensure_columns(
        &mut self,
        bodies: &mut dyn Bodies,
        slots: impl IntoIterator<Item = usize>,
    ) -> Result<()> {
        let mut missing: Vec<usize> = slots
            .into_iter()
            .filter(|&j| !self.flexibility.known[j])
            .collect();
        if missing.is_empty() {
            return Ok(());
        }
        missing.sort_unstable();
        missing.dedup();
        let clock = std::time::Instant::now();
        let units: Vec<Sparse> = missing.iter().map(|&j| vec![(j, 1.0)]).collect();
        let columns = bodies.flexibility_times(&self.dofs, &units)?;
        for (c, &j) in missing.iter().enumerate() {
            self.flexibility
                .set_column(j, columns.column(c).iter().copied());
        }
        self.flexibility_seconds += clock.elapsed().as_secs_f64();
        Ok(())
    }

    /// `F v` over the contact dofs for a sparse `v` whose columns are known: `sum_c v_c F e_c`.
    fn apply_flexibility(&self, v: &Sparse, out: &mut [f64]) {
        out.iter_mut().for_each(|o| *o = 0.0);
        for &(c, w) in v {
            for (o, f) in out.iter_mut().zip(self.flexibility.column(c)) {
                *o += f * w;
            }
        }
    }

    /// Add the directions of `system`'s unknowns that are not known yet to the node
    /// flexibility (small kinematics), building the columns of `F` they touch; returns the
    /// direction of each row (`a_i`, `row_i = v_a_i`) and each column as `(b, coefficient)`
    /// pairs (`col_j = sum coefficient v_b`).
    #[allow(clippy::type_complexity)]
    fn node_directions(
        &mut self,
        bodies: &mut dyn Bodies,
        reference: &[ContactSurface],
        system: &SmallSystem,
    ) -> Result<(Vec<usize>, Vec<Vec<(usize, f64)>>)> {
        let mut new: Vec<(usize, usize, Row)> = Vec::new();
        let keys = system.unknowns.iter().copied().chain(
            system
                .basis
                .iter()
                .flatten()
                .map(|&(p, k, row, _)| (p, k, row)),
        );
        for key in keys {
            if self.node_flexibility.get(key).is_none() && !new.contains(&key) {
                new.push(key);
            }
        }
        let vectors: Vec<Sparse> = new
            .iter()
            .map(|&(p, k, row)| {
                let node = &reference[p].nodes[k];
                self.directed(&node.coupling, &row.direction(&node.frame))
            })
            .collect();
        if new.is_empty() {
        } else if self.flexibility.is_full() {
            let m = self.dofs.len();
            let mut y = DMatrix::zeros(m, new.len());
            for (c, v) in vectors.iter().enumerate() {
                self.apply_flexibility(v, &mut y.as_mut_slice()[c * m..(c + 1) * m]);
            }
            self.node_flexibility.add_responses(&new, vectors, &y);
        } else {
            let clock = std::time::Instant::now();
            if bodies.has_images() {
                // batches of neighbouring directions share most of their reach
                let mut vectors = vectors.into_iter();
                let batches: Vec<Vec<Sparse>> = new
                    .chunks(IMAGE_BATCH)
                    .map(|keys| vectors.by_ref().take(keys.len()).collect())
                    .collect();
                let images = bodies
                    .images(&self.dofs, &batches)?
                    .expect("the bodies have images");
                for ((keys, vs), images) in new.chunks(IMAGE_BATCH).zip(batches).zip(images) {
                    self.node_flexibility.add_images(keys, vs, images);
                }
            } else {
                // one right-hand side per new direction, not one per dof it touches
                let y = bodies.flexibility_times(&self.dofs, &vectors)?;
                self.node_flexibility.add_responses(&new, vectors, &y);
            }
            self.flexibility_seconds += clock.elapsed().as_secs_f64();
        }
        let nf = &self.node_flexibility;
        let rows = system
            .unknowns
            .iter()
            .map(|&key| nf.get(key).expect("added above"))
            .collect();
        let cols = system
            .basis
            .iter()
            .map(|parts| {
                parts
                    .iter()
                    .map(|&(p, k, row, c)| (nf.get((p, k, row)).expect("added above"), c))
                    .collect()
            })
            .collect();
        Ok((rows, cols))
    }

    /// The symmetric unknowns `symmetric` (indices into `system.unknowns`, `rows` their
    /// directions) in the order of their Cholesky factor, and the factor of `S_PP` in that
    /// order (`S_PP,ij = N_(a_i, a_j)`), extending the kept factor over the directions it
    /// shares with them (see [`KeptFactor`]), which it then replaces. `None` when `S_PP` is not
    /// numerically positive definite.
    fn symmetric_factor(
        &mut self,
        (bodies, pairs): (&dyn Bodies, &[PairNodes]),
        system: &SmallSystem,
        rows: &[usize],
        symmetric: Vec<usize>,
    ) -> Option<(Vec<usize>, Mat<f64>)> {
        let order = self.factor_order((bodies, pairs), system, rows, symmetric);
        let keys: Vec<usize> = order.iter().map(|&i| rows[i]).collect();
        let nf = &mut self.node_flexibility;
        let prefix = nf.factor.common_prefix(&keys);
        nf.slip.keep(prefix);
        let kept = std::mem::replace(&mut nf.factor.l, Mat::new());
        let n = &nf.n;
        // N is exactly symmetric: column j of the block is row keys[j] of N
        let column = |j: usize, rows: Range<usize>, out: &mut [f64]| {
            gather(&n[keys[j]], &keys[rows], out);
        };
        let l = cholesky_extending(kept, prefix, keys.len(), column);
        // the factor itself comes back after the solve (see `solve_boundary`)
        nf.factor.keys = keys;
        l.map(|l| (order, l))
    }

    /// `(X, Y) = (L^-1 S_PQ, L^-1 S_QP^T)` for the slip unknowns `q` (indices into the
    /// system's unknowns, `rows` and `cols` their directions as [`node_directions`] gives
    /// them) on the factor `l` of the symmetric block, from the images of their directions
    /// kept and completed by [`SlipImages`]: `X`'s column `j` is `sum_b c_jb x_b` over the
    /// parts of its column, `Y`'s is `x_(row_j)`.
    ///
    /// [`node_directions`]: Self::node_directions
    fn slip_images(
        &mut self,
        rows: &[usize],
        cols: &[Vec<(usize, f64)>],
        q: &[usize],
        l: &Mat<f64>,
    ) -> (Mat<f64>, Mat<f64>) {
        let mut needed: Vec<usize> = q
            .iter()
            .flat_map(|&j| cols[j].iter().map(|&(b, _)| b).chain([rows[j]]))
            .collect();
        needed.sort_unstable();
        needed.dedup();
        let nf = &mut self.node_flexibility;
        nf.slip.update(l, &nf.factor.keys, &nf.n, &needed);
        let (slip, k) = (&nf.slip, l.nrows());
        let (mut x, mut y) = (Mat::<f64>::zeros(k, q.len()), Mat::<f64>::zeros(k, q.len()));
        for (j, &u) in q.iter().enumerate() {
            col_slice(&mut y, j).copy_from_slice(slip.image(rows[u]));
            let xj = col_slice(&mut x, j);
            for &(b, c) in &cols[u] {
                for (xi, v) in xj.iter_mut().zip(slip.image(b).iter()) {
                    *xi += c * v;
                }
            }
        }
        (x, y)
    }

    /// The order in which the symmetric unknowns `symmetric` (indices into `system.unknowns`,
    /// `rows` their directions) are factored: those the kept factor has, in its order (its
    /// leading block up to the first one missing is then reused), followed by the new ones by
    /// distance of their node from the centroid of the pair's kept ones (of all its symmetric
    /// ones when none is kept), nearest first, so that the next change at the zone's edges
    /// falls near the end.
    fn factor_order(
        &self,
        (bodies, pairs): (&dyn Bodies, &[PairNodes]),
        system: &SmallSystem,
        rows: &[usize],
        symmetric: Vec<usize>,
    ) -> Vec<usize> {
        let kept = &self.node_flexibility.factor.keys;
        let mut rank = vec![usize::MAX; self.node_flexibility.n.len()];
        kept.iter().enumerate().for_each(|(r, &a)| rank[a] = r);
        let (mut old, mut new): (Vec<usize>, Vec<usize>) = symmetric
            .into_iter()
            .partition(|&i| rank[rows[i]] != usize::MAX);
        old.sort_unstable_by_key(|&i| rank[rows[i]]);
        let (x, dim) = (bodies.positions(), bodies.dim());
        let position = |i: usize| {
            let (p, k, _) = system.unknowns[i];
            node(x, dim, pairs[p].a[k])
        };
        let pair = |i: usize| system.unknowns[i].0;
        let mut has_old = vec![false; pairs.len()];
        old.iter().for_each(|&i| has_old[pair(i)] = true);
        let mut centroids = vec![(Vector::zero(dim), 0usize); pairs.len()];
        for &i in old.iter().chain(new.iter().filter(|&&i| !has_old[pair(i)])) {
            let ((c, count), y) = (&mut centroids[pair(i)], position(i));
            (*c, *count) = (*c + y, *count + 1);
        }
        let distance = |i: usize| {
            let (c, count) = centroids[pair(i)];
            let mut d = position(i);
            for (d, c) in d.components_mut().iter_mut().zip(c.components()) {
                *d -= c / count as f64;
            }
            d.norm()
        };
        new.sort_by(|&i, &j| {
            (pair(i), distance(i))
                .partial_cmp(&(pair(j), distance(j)))
                .expect("finite positions")
        });
        old.extend(new);
        old
    }

    /// The unknowns and the new contact displacement of one iteration: on the lazy, cached
    /// algebra ([`solve_boundary`](Self::solve_boundary)), or with the feature `oracles` on the
    /// dense reference when it is switched on (`oracles.rs`).
    pub(super) fn solve_iteration(
        &mut self,
        bodies: &mut dyn Bodies,
        surfaces: &Surfaces,
        system: &SmallSystem,
        u0c: &[f64],
        border: Option<&Border>,
    ) -> Result<Solution> {
        #[cfg(feature = "oracles")]
        if self.reference_algebra {
            return self.solve_reference(system, u0c, border);
        }
        self.solve_boundary(bodies, surfaces, system, u0c, border)
    }

    /// Solve the small system (docs/method.md, "The contact boundary's algebra"): `S tau = b - rows . u0` with
    /// `S_ij = row_i . F col_j`, bordered by the force-controlled plate translations `U` as in
    /// the reference (`SmallSystem::solve`). Without a border, the block of the unknowns whose
    /// column is their row, `S_PP`, is factored by Cholesky (under small kinematics straight
    /// from `N`, extending the kept factor) and the slip unknowns by LU of their Schur
    /// complement ([`Dense::block`]); with a border, or an `S_PP` that is not positive
    /// definite, `S` is stored and factored by LU with partial pivoting (faer). Also
    /// the new displacement of the contact dofs, `u = u0 + F sum_j tau_j col_j + sum_e U_e w_e`
    /// (`w_e` the plate's response). Small kinematics read `S` off the node flexibility,
    /// `S_ij = sum_b coefficient_jb N_(a_i, b)`, and form `u` from the kept directions with
    /// the weights `c_b = sum_j tau_j coefficient_jb`, `F sum_j tau_j col_j = sum_b c_b F v_b`:
    /// a kept response `y_b = F v_b` is added as it is, the kept images `W v_b` are combined
    /// and substituted backward once ([`Bodies::back_substitute`]); finite kinematics form
    /// `y_j = F col_j` from the columns of `F`. Returns `(tau, U, condition estimate, u)`.
    pub(super) fn solve_boundary(
        &mut self,
        bodies: &mut dyn Bodies,
        surfaces: &Surfaces,
        system: &SmallSystem,
        u0c: &[f64],
        border: Option<&Border>,
    ) -> Result<Solution> {
        let m = system.rows.len();
        let k = border.map_or(0, |b| b.directions.len());
        if m + k == 0 {
            return Ok((Vec::new(), Vec::new(), 1.0, u0c.to_vec()));
        }
        let mc = self.dofs.len();
        // small kinematics: directions of rows and columns; finite: the responses y_j
        let (directions, responses) = match surfaces.kinematics {
            Kinematics::Small => {
                let reference = &surfaces.reference;
                (
                    Some(self.node_directions(bodies, reference, system)?),
                    Vec::new(),
                )
            }
            Kinematics::Finite => {
                self.ensure_columns(bodies, system.cols.iter().flatten().map(|&(c, _)| c))?;
                let mut y = vec![0.0; mc * m];
                for (j, col) in system.cols.iter().enumerate() {
                    self.apply_flexibility(col, &mut y[j * mc..(j + 1) * mc]);
                }
                (None, y)
            }
        };
        let mut rhs = Mat::<f64>::zeros(m + k, 1);
        for (i, (row, b)) in system.rows.iter().zip(&system.b).enumerate() {
            rhs[(i, 0)] = b - dot(row, u0c);
        }
        // the unknowns whose column is not their row: slip nodes under friction
        let (unsymmetric, symmetric): (Vec<usize>, Vec<usize>) =
            (0..m).partition(|&j| system.basis[j].len() > 1);
        let block = k == 0 && !symmetric.is_empty();
        // under small kinematics S_PP is factored from N itself, and the slip block needs
        // only S_QQ and the images: S is not stored (at n = 512 with friction, zeroing,
        // filling and summing its 2,900^2 entries in every iteration took 0.46 s)
        let factor = match &directions {
            Some((rows, _)) if block => {
                let pairs = (&*bodies, &surfaces.pairs[..]);
                self.symmetric_factor(pairs, system, rows, symmetric.clone())
            }
            _ => None,
        };
        let images = match (&directions, &factor) {
            (Some((rows, cols)), Some((_, l))) if !unsymmetric.is_empty() => {
                Some(self.slip_images(rows, cols, &unsymmetric, l))
            }
            _ => None,
        };
        let columns = match &directions {
            Some((rows, cols)) => Columns::Nodes(NodeColumns {
                n: &self.node_flexibility.n,
                rows,
                runs: consecutive_runs(rows),
                cols,
            }),
            None => Columns::Responses {
                rows: &system.rows,
                y: &responses,
                mc,
            },
        };
        // a factor here came from N (small kinematics); finite kinematics factor S_PP below
        let (lu, s_norm) = match (factor, &columns) {
            (Some((p, l)), Columns::Nodes(nodes)) => {
                let s_norm = self.node_flexibility.sums.norm1(nodes);
                let entry = |i: usize, j: usize| columns.entry(i, j);
                (Dense::block(p, l, unsymmetric, entry, images), s_norm)
            }
            _ => {
                let mut s = std::mem::replace(&mut self.small_matrix, Mat::new());
                s.truncate(0, 0);
                s.resize_with(m + k, m + k, |_, _| 0.0);
                for j in 0..m {
                    columns.column(j, &mut col_slice(&mut s, j)[..m]);
                }
                if let Some(b) = border {
                    b.fill(
                        &system.rows,
                        &system.cols,
                        m,
                        &mut |i, j, v| s[(i, j)] = v,
                        &mut |i, v| rhs[(i, 0)] = v,
                    )?;
                }
                let s_norm = (0..m + k)
                    .map(|j| abs_sum(col_slice(&mut s, j)))
                    .fold(0.0, f64::max);
                // finite kinematics: S_PP's factor from S
                let factor = (block && directions.is_none()).then(|| {
                    let p = &symmetric;
                    let entries = by_entries(|i, j| s[(p[i], p[j])]);
                    cholesky_extending(Mat::new(), 0, p.len(), entries).map(|l| (symmetric, l))
                });
                let lu = Dense::new(&s, factor.flatten(), unsymmetric, None);
                self.small_matrix = s;
                (lu, s_norm)
            }
        };
        if !s_norm.is_finite() {
            // the geometry of the iterate overflowed (a finite-kinematics press so deep that
            // the surfaces stretch beyond double precision): not a singular system but an
            // iterate that is not finite, which the iteration reports as such
            // (`ContactError::NonFinite`)
            let none = vec![f64::NAN; u0c.len()];
            return Ok((vec![0.0; m], vec![0.0; k], f64::NAN, none));
        }
        // beyond this the solution has fewer than 3 correct digits: treat it as singular
        let condition = solve_and_estimate(s_norm, &lu, rhs.as_mut())
            .filter(|&c| c < 1e-3 / f64::EPSILON)
            .ok_or_else(singular)?;
        if let (Dense::Block(b), Kinematics::Small) = (lu, surfaces.kinematics) {
            self.node_flexibility.factor.l = b.l;
        }
        let tau: Vec<f64> = (0..m + k).map(|i| rhs[(i, 0)]).collect();
        if !tau.iter().all(|v| v.is_finite()) {
            // the system passed the condition check, so its right-hand side overflowed on the
            // way (a press of 1e300): the iterate is not finite, which the iteration reports
            // as such (`ContactError::NonFinite`), not as a singular system
            let none = vec![f64::NAN; u0c.len()];
            return Ok((tau[..m].to_vec(), tau[m..].to_vec(), condition, none));
        }
        let mut uc = u0c.to_vec();
        match directions {
            Some((_, cols)) => {
                let nf = &self.node_flexibility;
                let mut weights = vec![0.0; nf.kept.len()];
                for (parts, &t) in cols.iter().zip(&tau) {
                    for &(b, c) in parts {
                        weights[b] += t * c;
                    }
                }
                let mut coefficients: Vec<Vec<f64>> = nf
                    .batches
                    .iter()
                    .map(|(images, _)| vec![0.0; images.values.ncols()])
                    .collect();
                for (kept, &w) in nf.kept.iter().zip(&weights).filter(|(_, w)| **w != 0.0) {
                    match kept {
                        Kept::Response(y) => {
                            for (u, v) in uc.iter_mut().zip(y) {
                                *u += w * v;
                            }
                        }
                        Kept::Image { batch, column } => coefficients[*batch][*column] = w,
                    }
                }
                let parts: Vec<(&Images, &[f64])> = nf
                    .batches
                    .iter()
                    .zip(&coefficients)
                    .filter(|(_, c)| c.iter().any(|&w| w != 0.0))
                    .map(|((images, _), c)| (images, &c[..]))
                    .collect();
                if !parts.is_empty() {
                    let clock = std::time::Instant::now();
                    let x = bodies.back_substitute(&self.dofs, &parts)?;
                    for (u, v) in uc.iter_mut().zip(x) {
                        *u += v;
                    }
                    self.flexibility_seconds += clock.elapsed().as_secs_f64();
                }
            }
            None => {
                for (j, &t) in tau.iter().take(m).enumerate() {
                    if t != 0.0 {
                        for (u, v) in uc.iter_mut().zip(&responses[j * mc..(j + 1) * mc]) {
                            *u += t * v;
                        }
                    }
                }
            }
        }
        let plate_motion: Vec<f64> = tau[m..].to_vec();
        if let Some(b) = border {
            for (&d, &motion) in b.directions.iter().zip(&plate_motion) {
                for (u, w) in uc.iter_mut().zip(&b.response[d]) {
                    *u += motion * w;
                }
            }
        }
        Ok((tau[..m].to_vec(), plate_motion, condition, uc))
    }

    /// The small matrix `S_ij = row_i . F col_j` of `system`, dense (the fallback of
    /// `fallback.rs` works on it): from the node flexibility under small kinematics, from the
    /// columns of `F` under finite kinematics or the reference algebra.
    pub(super) fn dense_matrix(
        &mut self,
        bodies: &mut dyn Bodies,
        surfaces: &Surfaces,
        system: &SmallSystem,
    ) -> Result<DMatrix<f64>> {
        let m = system.rows.len();
        let mut s = DMatrix::zeros(m, m);
        if surfaces.kinematics == Kinematics::Small && !self.on_reference_algebra() {
            let (rows, cols) = self.node_directions(bodies, &surfaces.reference, system)?;
            let n = &self.node_flexibility.n;
            for (j, parts) in cols.iter().enumerate() {
                for (i, &row) in rows.iter().enumerate() {
                    s[(i, j)] = parts.iter().fold(0.0, |sum, &(b, c)| sum + c * n[b][row]);
                }
            }
        } else {
            self.ensure_columns(bodies, system.cols.iter().flatten().map(|&(c, _)| c))?;
            let mut y = vec![0.0; self.dofs.len()];
            for (j, col) in system.cols.iter().enumerate() {
                self.apply_flexibility(col, &mut y);
                for (i, row) in system.rows.iter().enumerate() {
                    s[(i, j)] = dot(row, &y);
                }
            }
        }
        Ok(s)
    }

    /// Build the part of a lazy `F` that the first increment certainly needs: under small
    /// kinematics the directions of each pair's A node with the smallest reference gap (the
    /// first to close; normal, and the kept tangents with friction), under finite kinematics
    /// the columns its coupling touches. A failing host solver is thus reported when the
    /// analysis is created, as with an eager `F`.
    pub(super) fn prime(&mut self, bodies: &mut dyn Bodies, surfaces: &Surfaces) -> Result<()> {
        let mut rows = Vec::new();
        let mut keys = Vec::new();
        for (p, surface) in surfaces.reference.iter().enumerate() {
            let nearest = surface
                .nodes
                .iter()
                .enumerate()
                .filter(|(_, n)| n.is_covered())
                .min_by(|a, b| a.1.normal_gap.total_cmp(&b.1.normal_gap));
            if let Some((k, node)) = nearest {
                rows.push((p, k, Row::Normal));
                keys.push(self.directed(&node.coupling, &node.frame.normal()));
                if !surfaces.laws[p].is_frictionless() {
                    for (i, s) in kept_tangents(&node.frame) {
                        rows.push((p, k, Row::Tangent(i)));
                        keys.push(self.directed(&node.coupling, &s));
                    }
                }
            }
        }
        match surfaces.kinematics {
            Kinematics::Small => {
                let system = SmallSystem {
                    unknowns: rows.clone(),
                    b: vec![0.0; rows.len()],
                    basis: rows.iter().map(|&(p, k, r)| vec![(p, k, r, 1.0)]).collect(),
                    cols: keys.clone(),
                    rows: keys,
                };
                self.node_directions(bodies, &surfaces.reference, &system)
                    .map(|_| ())
            }
            Kinematics::Finite => {
                self.ensure_columns(bodies, keys.iter().flatten().map(|&(c, _)| c))
            }
        }
    }

    /// Whether the iteration runs on the dense reference algebra (a test oracle, feature
    /// `oracles`; never without it).
    fn on_reference_algebra(&self) -> bool {
        #[cfg(feature = "oracles")]
        return self.reference_algebra;
        #[cfg(not(feature = "oracles"))]
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The runs of the unknowns' directions cover every index once, in order, and a gather
    /// through them is the plain gather.
    #[test]
    fn consecutive_runs_cover_the_indices() {
        let indices = [3, 4, 5, 9, 10, 2, 7, 8];
        let runs = consecutive_runs(&indices);
        assert_eq!(runs, vec![(0, 3, 3), (3, 9, 2), (5, 2, 1), (6, 7, 2)]);
        let flat: Vec<usize> = runs.iter().flat_map(|&(_, a, len)| a..a + len).collect();
        assert_eq!(flat, indices);
        assert!(consecutive_runs(&[]).is_empty());
    }

    /// The Gram product of two batches of images, run by run over the rows they share, is
    /// the plain product of the two batches spread over the union of their rows; the runs
    /// are maximal and in order.
    #[test]
    fn gram_of_images_is_the_product_over_shared_rows() {
        let a = Images {
            columns: vec![1, 2, 3, 5, 6, 9, 12],
            values: Mat::from_fn(7, 3, |i, j| (i as f64 + 1.0) * (j as f64 - 0.5)),
        };
        let b = Images {
            columns: vec![0, 2, 3, 4, 5, 6, 9, 11],
            values: Mat::from_fn(8, 2, |i, j| 1.0 / (i as f64 + 2.0 * j as f64 + 1.0)),
        };
        assert_eq!(
            shared_runs(&a.columns, &b.columns),
            vec![(1, 1, 2), (3, 4, 3)]
        );
        let spread = |im: &Images| {
            Mat::<f64>::from_fn(13, im.values.ncols(), |r, c| {
                im.columns
                    .iter()
                    .position(|&x| x == r)
                    .map_or(0.0, |i| im.values[(i, c)])
            })
        };
        let plain = spread(&a).transpose() * spread(&b);
        let g = gram(&a, &b);
        for i in 0..3 {
            for j in 0..2 {
                assert!((g[(i, j)] - plain[(i, j)]).abs() <= 1e-14, "{i} {j}");
            }
        }
        assert!(shared_runs(&[1, 3], &[2, 4]).is_empty());
    }

    /// The vectorized `sum |x_i|` agrees with the running sum to round-off at every length
    /// around the chunk size, signs mixed.
    #[test]
    fn columns_read_s_without_storing_it() {
        // N symmetric over 8 directions; rows in two runs, columns of one and two parts
        let n: Vec<Vec<f64>> = (0..8)
            .map(|a| {
                (0..8)
                    .map(|b| (((a * b) % 7) as f64 - 3.0) / (1 + a + b) as f64)
                    .collect()
            })
            .collect();
        let rows = [3, 4, 5, 0, 1, 7];
        let cols: Vec<Vec<(usize, f64)>> = vec![
            vec![(3, 1.0)],
            vec![(4, 1.0), (2, -0.3)],
            vec![(5, 1.0)],
            vec![(0, 1.0), (6, 0.3)],
            vec![(1, 1.0)],
            vec![(7, 1.0)],
        ];
        let nodes = NodeColumns {
            n: &n,
            rows: &rows,
            runs: consecutive_runs(&rows),
            cols: &cols,
        };
        let m = rows.len();
        let s =
            |i: usize, j: usize| -> f64 { cols[j].iter().map(|&(b, c)| c * n[b][rows[i]]).sum() };
        let mut column = vec![f64::NAN; m];
        let mut norm = 0.0f64;
        for j in 0..m {
            nodes.column(j, &mut column);
            for (i, &v) in column.iter().enumerate() {
                assert!((v - s(i, j)).abs() < 1e-15, "S[{i}, {j}]");
                assert_eq!(nodes.entry(i, j), v, "entry {i}, {j} as the column sums it");
            }
            norm = norm.max((0..m).map(|i| s(i, j).abs()).sum());
        }
        let mut sums = RowSums::default();
        let s_norm = sums.norm1(&nodes);
        assert!(
            (s_norm - norm).abs() < 1e-14 * norm,
            "{s_norm} against {norm}"
        );
        // finite kinematics: S_ij = row_i . y_j
        let sparse_rows: Vec<Sparse> = vec![vec![(0, 1.0), (2, -2.0)], vec![(1, 0.5)]];
        let y = [1.0, 2.0, 3.0, -1.0, 0.0, 4.0];
        let columns = Columns::Responses {
            rows: &sparse_rows,
            y: &y,
            mc: 3,
        };
        let mut column = [0.0; 2];
        columns.column(1, &mut column);
        assert_eq!(column, [-9.0, 0.0]);
        assert_eq!(columns.entry(0, 0), -5.0);
    }

    #[test]
    fn row_sums_follow_the_row_set() {
        let d = 40;
        let n: Vec<Vec<f64>> = (0..d)
            .map(|a| {
                (0..d)
                    .map(|b| ((a * b + 3) % 11) as f64 - 5.0 + 0.01 * (a + b) as f64)
                    .collect()
            })
            .collect();
        // grow, shrink at both ends, drop from the middle, reorder, change more than half
        let sets: [Vec<usize>; 6] = [
            (10..20).collect(),
            (8..24).collect(),
            (9..22).collect(),
            (9..22).filter(|&a| a != 15).chain([30, 31]).collect(),
            vec![31, 30, 9, 10, 11, 12, 13, 14, 16, 17, 18, 19, 20, 21],
            (0..6).chain(30..33).collect(),
        ];
        let mut sums = RowSums::default();
        for rows in &sets {
            sums.update(&n, rows, &consecutive_runs(rows));
            for &b in rows {
                let fresh: f64 = rows.iter().map(|&a| n[b][a].abs()).sum();
                assert!(
                    (sums.sums[b] - fresh).abs() <= 1e-13 * fresh,
                    "direction {b} of {rows:?}: {} against {fresh}",
                    sums.sums[b]
                );
            }
        }
    }

    #[test]
    fn abs_sum_is_the_one_norm() {
        for len in 0..12 {
            let x: Vec<f64> = (0..len).map(|i| (i as f64 - 4.5) * 1.25).collect();
            let plain: f64 = x.iter().map(|v| v.abs()).sum();
            assert!((abs_sum(&x) - plain).abs() <= 1e-15 * plain, "{len}");
        }
    }

    /// Extending the factor of a leading block gives the factor of the whole matrix, and a
    /// matrix that is not positive definite is refused at any prefix. The kept factor may be
    /// exactly `L11`, or larger (a factor whose unknowns after the prefix changed: here that of
    /// another matrix with the same leading block).
    #[test]
    fn cholesky_extending_matches_a_fresh_factor() {
        let n = 9;
        let b = Mat::<f64>::from_fn(n, n, |i, j| ((3 * i + 7 * j) % 11) as f64 / 11.0 - 0.4);
        let a = &b * b.transpose() + Mat::<f64>::identity(n, n);
        let whole = a.llt(faer::Side::Lower).unwrap();
        let mut other = a.clone();
        for i in 0..n {
            other[(i, i)] += 1.0 + i as f64;
        }
        let llt_other = |p: usize| {
            let mut o = other.clone();
            o.as_mut()
                .submatrix_mut(0, 0, p, p)
                .copy_from(a.as_ref().submatrix(0, 0, p, p));
            o.llt(faer::Side::Lower).unwrap().L().to_owned()
        };
        for p in [0, 1, 5, n] {
            let l11 = a.as_ref().submatrix(0, 0, p, p).to_owned();
            let l11 = l11.llt(faer::Side::Lower).unwrap().L().to_owned();
            for kept in [l11, llt_other(p)] {
                let l = cholesky_extending(kept, p, n, by_entries(|i, j| a[(i, j)])).unwrap();
                let difference = (&l - whole.L()).norm_max();
                assert!(difference < 1e-13, "prefix {p}: {difference:e}");
            }
        }
        let mut indefinite = a.clone();
        indefinite[(n - 1, n - 1)] = -1.0;
        let l11 = a.as_ref().submatrix(0, 0, 5, 5).to_owned();
        let l11 = l11.llt(faer::Side::Lower).unwrap().L().to_owned();
        assert!(cholesky_extending(l11, 5, n, by_entries(|i, j| indefinite[(i, j)])).is_none());
    }

    /// The small system's dense algebra leaves the upper halves of the AVX registers clean at
    /// sizes where faer's assembly kernels run (see `solver::vector_state`): the Gram products
    /// of images (cleaned by `clean_after`), and the extended factor, the block factorization
    /// with slip unknowns and its solves (clean on their own).
    #[cfg(target_arch = "x86_64")]
    /// A symmetric positive definite `n x n` matrix with entries of either sign.
    fn spd(n: usize) -> Mat<f64> {
        let b = Mat::<f64>::from_fn(n, n, |i, j| ((3 * i + 7 * j) % 11) as f64 / 11.0 - 0.4);
        &b * b.transpose() + Mat::<f64>::identity(n, n)
    }

    #[test]
    fn slip_images_follow_the_kept_factor() {
        use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
        let a = spd(14);
        let n: Vec<Vec<f64>> = (0..14)
            .map(|i| (0..14).map(|j| a[(i, j)]).collect())
            .collect();
        // the factor of N over `keys`, grown from the last one as the iteration grows it
        let factor = |kept: Mat<f64>, prefix: usize, keys: &[usize]| {
            let column = |j: usize, rows: Range<usize>, out: &mut [f64]| {
                gather(&n[keys[j]], &keys[rows], out);
            };
            cholesky_extending(kept, prefix, keys.len(), column).unwrap()
        };
        let fresh = |l: &Mat<f64>, keys: &[usize], d: usize| {
            let mut x = Mat::<f64>::from_fn(keys.len(), 1, |i, _| n[keys[i]][d]);
            solve_lower_triangular_in_place(l.as_ref(), x.as_mut(), Par::Seq);
            x
        };
        let mut slip = SlipImages::default();
        let mut l = Mat::new();
        let mut last: Vec<usize> = Vec::new();
        // (the factor's directions, the slip directions): a grown factor, one that lost a
        // direction in its middle, one reordered from its third
        let steps: [(&[usize], &[usize]); 4] = [
            (&[0, 1, 2, 3, 4, 5], &[8, 9]),
            (&[0, 1, 2, 3, 4, 5, 7, 10], &[8, 11]),
            (&[0, 1, 3, 4, 5, 7, 10], &[11]),
            (&[0, 1, 10, 7, 5, 4, 3, 6], &[9, 8, 12]),
        ];
        for (keys, needed) in steps {
            let prefix = last.iter().zip(keys).take_while(|(a, b)| a == b).count();
            slip.keep(prefix);
            l = factor(l, prefix, keys);
            slip.update(&l, keys, &n, needed);
            for &d in needed {
                let x = fresh(&l, keys, d);
                let image = slip.image(d);
                assert_eq!(image.len(), keys.len());
                for (i, v) in image.iter().enumerate() {
                    assert!((v - x[(i, 0)]).abs() < 1e-12, "direction {d}, row {i}");
                }
            }
            last = keys.to_vec();
        }
        // 9 was last used SLIP_IMAGE_UPDATES updates ago, 8 and 12 just now
        assert!(slip.images.contains_key(&9) && slip.images.contains_key(&12));
        for _ in 0..SLIP_IMAGE_UPDATES {
            slip.keep(last.len());
            slip.update(&l, &last, &n, &[8]);
        }
        let mut kept: Vec<usize> = slip.images.keys().copied().collect();
        kept.sort_unstable();
        assert_eq!(kept, [8], "unused images are dropped");
    }

    #[test]
    fn block_form_with_slip_columns_solves_both_ways() {
        use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
        let n = 12;
        // the last three unknowns' columns are not their rows, as a slip node's
        let mut a = spd(n);
        for j in n - 3..n {
            for i in 0..n {
                a[(i, j)] += 0.3 * ((i * j) % 5) as f64 / 5.0;
            }
        }
        let p: Vec<usize> = (0..n - 3).rev().collect();
        let q: Vec<usize> = (n - 3..n).collect();
        let s_pp = Mat::<f64>::from_fn(p.len(), p.len(), |i, j| a[(p[i], p[j])]);
        let l = s_pp.llt(faer::Side::Lower).unwrap().L().to_owned();
        let mut x = Mat::<f64>::from_fn(p.len(), q.len(), |i, j| a[(p[i], q[j])]);
        let mut y = Mat::<f64>::from_fn(p.len(), q.len(), |i, j| a[(q[j], p[i])]);
        solve_lower_triangular_in_place(l.as_ref(), x.as_mut(), Par::Seq);
        solve_lower_triangular_in_place(l.as_ref(), y.as_mut(), Par::Seq);
        for images in [None, Some((x, y))] {
            let dense = Dense::new(&a, Some((p.clone(), l.clone())), q.clone(), images);
            for transpose in [false, true] {
                let b = Mat::<f64>::from_fn(n, 2, |i, j| (i + 3 * j) as f64 - 4.0);
                let mut t = b.clone();
                dense.solve(t.as_mut(), transpose);
                let a = if transpose {
                    a.transpose().to_owned()
                } else {
                    a.clone()
                };
                let r = (a * &t - &b).norm_max();
                assert!(r < 1e-11, "residual {r:e} (transpose {transpose})");
            }
        }
    }

    #[test]
    fn dense_algebra_leaves_the_upper_registers_clean() {
        use crate::solver::vector_state::upper_in_use;
        if upper_in_use().is_none() {
            eprintln!("this CPU does not report the registers' state: nothing to check");
            return;
        }
        let n = 80;
        let b = Mat::<f64>::from_fn(n, n, |i, j| ((3 * i + 7 * j) % 11) as f64 / 11.0 - 0.4);
        let a = &b * b.transpose() + Mat::<f64>::identity(n, n);
        let images = |rows: usize| Images {
            columns: (0..rows).collect(),
            values: Mat::from_fn(rows, 64, |i, j| ((i * j) % 13) as f64),
        };
        let g = gram(&images(500), &images(400));
        assert_eq!(upper_in_use(), Some(false), "after a Gram product");
        assert_eq!((g.nrows(), g.ncols()), (64, 64));
        let l11 = a.as_ref().submatrix(0, 0, 40, 40).to_owned();
        let l11 = l11.llt(faer::Side::Lower).unwrap().L().to_owned();
        let l = cholesky_extending(l11, 40, n - 10, by_entries(|i, j| a[(i, j)])).unwrap();
        assert_eq!(upper_in_use(), Some(false), "after extending a factor");
        let dense = Dense::new(
            &a,
            Some(((0..n - 10).collect(), l)),
            (n - 10..n).collect(),
            None,
        );
        assert_eq!(upper_in_use(), Some(false), "after the block factorization");
        for transpose in [false, true] {
            let mut x = Mat::<f64>::from_fn(n, 8, |i, j| (i + j) as f64);
            dense.solve(x.as_mut(), transpose);
            assert_eq!(upper_in_use(), Some(false), "after a solve ({transpose})");
            let a = if transpose {
                a.transpose().to_owned()
            } else {
                a.clone()
            };
            let r = a * &x - Mat::<f64>::from_fn(n, 8, |i, j| (i + j) as f64);
            assert!(
                r.norm_max() < 1e-8 * n as f64,
                "the solve is right ({transpose}): {:e}",
                r.norm_max()
            );
        }
    }
}
