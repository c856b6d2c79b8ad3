//! The contact boundary as the iteration uses it (METHOD.md section 3): the flexibility
//! `F = E^T K^-1 E`, either whole (read off a factor's trailing block) or lazily: under small
//! kinematics the responses `y_a = F v_a` of the node directions that become active and the
//! node flexibility `N_ab = v_a^T F v_b`, computed once per direction; under finite kinematics
//! the columns of `F` the active nodes touch. The small system `S tau = b - rows . u0`,
//! `S = rows^T F cols`, is factored by blocked dense Cholesky / LU (faer).
//!
//! The dense reference of the same algebra (every column of `F` built up front, `F c` formed
//! from `F` in every iteration, nalgebra's unblocked LU) is kept behind
//! [`ContactAnalysis::set_reference_algebra`]; the tests compare the two.

use super::*;
use faer::linalg::solvers::{Llt, PartialPivLu, Solve};
use small_system::{Row, SmallSystem, singular};

/// The flexibility `F = E^T K^-1 E` over the contact dofs, column by column: a column is
/// either known (computed once, then kept) or not yet asked for.
#[derive(Debug, Clone)]
pub(super) struct Flexibility {
    /// `F` (`m x m`); unknown columns hold zeros.
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
            matrix: DMatrix::zeros(m, m),
            known: vec![false; m],
        }
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
/// `v_a = d . c_k` for direction `a = (pair, A node k, d)` (`d` the node's normal or tangent,
/// `c_k` its coupling row), the response `y_a = F v_a` over the contact dofs, and the node
/// flexibility `N_ab = v_a . y_b = v_a^T F v_b`. The frames and the coupling never change under
/// small kinematics, so a direction is added once, when its node first becomes active (its
/// response costs the columns of `F` it touches, its row and column of `N` one dot product per
/// direction known), and the small system of every iteration is read off `N`.
#[derive(Debug, Clone, Default)]
pub(super) struct NodeFlexibility {
    /// Index of each direction, per pair, per A node, `[normal, tangent]`.
    index: Vec<Vec<[Option<usize>; 2]>>,
    /// `v_a`.
    vectors: Vec<Sparse>,
    /// `y_a = F v_a`.
    responses: Vec<Vec<f64>>,
    /// `N_ab` as rows `a`.
    n: Vec<Vec<f64>>,
}

impl NodeFlexibility {
    /// No direction known, for pairs with `a_nodes[p]` A nodes.
    pub(super) fn new(a_nodes: impl Iterator<Item = usize>) -> Self {
        NodeFlexibility {
            index: a_nodes.map(|n| vec![[None, None]; n]).collect(),
            ..Default::default()
        }
    }

    fn get(&self, (p, k, row): (usize, usize, Row)) -> Option<usize> {
        self.index[p][k][row as usize]
    }

    /// Add direction `key` with its vector `v` and response `y = F v`: `N_ac = v_a . y` for
    /// every known `a`, `N_ca = N_ac` (`F` is symmetric: `v . y_a = v_a . y`, read from the
    /// new response alone), and `N_cc = v . y`.
    fn add(&mut self, (p, k, row): (usize, usize, Row), v: Sparse, y: Vec<f64>) {
        let c = self.vectors.len();
        let mut nc = Vec::with_capacity(c + 1);
        for (a, na) in self.n.iter_mut().enumerate() {
            let value = dot(&self.vectors[a], &y);
            na.push(value);
            nc.push(value);
        }
        nc.push(dot(&v, &y));
        self.n.push(nc);
        self.vectors.push(v);
        self.responses.push(y);
        self.index[p][k][row as usize] = Some(c);
    }
}

/// What [`ContactAnalysis::solve_boundary`] gives: the unknowns `tau`, the plate's
/// force-controlled translations, the condition estimate of the small system and the new
/// displacement of the contact dofs.
pub(super) type Solution = (Vec<f64>, Vec<f64>, f64, Vec<f64>);

/// A dense factorization of the small system `S`:
/// * Cholesky `S = L L^T` when `S` is symmetric (no slip node with friction, no plate border:
///   `rows = cols`, so `S = R^T F R` is symmetric positive definite);
/// * with slip nodes under friction, block elimination on the symmetric part: the unknowns `P`
///   whose column is their row (stick rows, normal rows without friction) and the slip normal
///   unknowns `Q` (column `n + mu sign s`), `S = [S_PP S_PQ; S_QP S_QQ]` with `S_PP` symmetric
///   positive definite, factored by Cholesky, and the Schur complement
///   `Z = S_QQ - S_QP S_PP^-1 S_PQ` by LU: `|P|^3 / 3 + |P|^2 |Q| + 2 |Q|^3 / 3` flops
///   instead of `2 (|P| + |Q|)^3 / 3`;
/// * else (a plate border, or a Cholesky that fails) LU with partial pivoting `P S = L U`.
enum Dense {
    Llt(Llt<f64>),
    Lu(PartialPivLu<f64>),
    Block(Box<Blocks>),
}

/// The block form of [`Dense`].
struct Blocks {
    p: Vec<usize>,
    q: Vec<usize>,
    llt: Llt<f64>,
    /// `W = S_PP^-1 S_PQ`.
    w: Mat<f64>,
    s_qp: Mat<f64>,
    z: PartialPivLu<f64>,
}

impl Dense {
    /// `S` factored; `q` lists the unknowns whose column is not their row (empty: `S` is
    /// symmetric), `border` whether `S` is bordered by plate rows.
    fn new(s: Mat<f64>, q: Vec<usize>, border: bool) -> Self {
        let n = s.nrows();
        if !border && q.is_empty() {
            if let Ok(llt) = s.llt(faer::Side::Lower) {
                return Dense::Llt(llt);
            }
        } else if !border && q.len() < n {
            let mut in_q = vec![false; n];
            q.iter().for_each(|&i| in_q[i] = true);
            let p: Vec<usize> = (0..n).filter(|&i| !in_q[i]).collect();
            let sub = |r: &[usize], c: &[usize]| {
                Mat::<f64>::from_fn(r.len(), c.len(), |i, j| s[(r[i], c[j])])
            };
            if let Ok(llt) = sub(&p, &p).llt(faer::Side::Lower) {
                let mut w = sub(&p, &q);
                llt.solve_in_place(w.as_mut());
                let s_qp = sub(&q, &p);
                let z = sub(&q, &q) - &s_qp * &w;
                return Dense::Block(Box::new(Blocks {
                    z: z.partial_piv_lu(),
                    p,
                    q,
                    llt,
                    w,
                    s_qp,
                }));
            }
        }
        Dense::Lu(s.partial_piv_lu())
    }

    /// `x <- S^-1 x`, or `S^-T x` when `transpose`. For the block form,
    /// `S^-1 x`: `y = S_PP^-1 x_P`, `x_Q <- Z^-1 (x_Q - S_QP y)`, `x_P <- y - W x_Q`;
    /// `S^-T x`: `y = S_PP^-1 x_P`, `x_Q <- Z^-T (x_Q - W^T x_P)`,
    /// `x_P <- y - S_PP^-1 S_QP^T x_Q` (`S_PQ^T S_PP^-1 = W^T`).
    fn solve(&self, mut x: faer::MatMut<'_, f64>, transpose: bool) {
        match (self, transpose) {
            (Dense::Llt(f), _) => f.solve_in_place(x),
            (Dense::Lu(f), false) => f.solve_in_place(x),
            (Dense::Lu(f), true) => f.solve_transpose_in_place(x),
            (Dense::Block(b), _) => {
                let Blocks {
                    p,
                    q,
                    llt,
                    w,
                    s_qp,
                    z,
                } = b.as_ref();
                let k = x.ncols();
                let xp = Mat::<f64>::from_fn(p.len(), k, |i, j| x[(p[i], j)]);
                let xq = Mat::<f64>::from_fn(q.len(), k, |i, j| x[(q[i], j)]);
                let mut y = xp.clone();
                llt.solve_in_place(y.as_mut());
                let (out_p, out_q) = if transpose {
                    let mut rq = xq - w.transpose() * &xp;
                    z.solve_transpose_in_place(rq.as_mut());
                    let mut back = s_qp.transpose() * &rq;
                    llt.solve_in_place(back.as_mut());
                    (y - back, rq)
                } else {
                    let mut rq = xq - s_qp * &y;
                    z.solve_in_place(rq.as_mut());
                    (y - w * &rq, rq)
                };
                for j in 0..k {
                    for (i, &r) in p.iter().enumerate() {
                        x[(r, j)] = out_p[(i, j)];
                    }
                    for (i, &r) in q.iter().enumerate() {
                        x[(r, j)] = out_q[(i, j)];
                    }
                }
            }
        }
    }
}

/// `||A||_1 ||A^-1||_1` (`a_norm = ||A||_1`) with `||A^-1||_1` estimated by Hager's method from
/// the factors of `A` (Higham's Algorithm 2.1, the same steps as
/// `small_system::condition_estimate`); `None` when a solve is not finite (singular `A`).
fn condition_estimate(a_norm: f64, lu: &Dense, m: usize) -> Option<f64> {
    let norm1 = |v: &Mat<f64>| (0..m).map(|i| v[(i, 0)].abs()).sum::<f64>();
    let mut x = Mat::<f64>::from_fn(m, 1, |_, _| 1.0 / m as f64);
    let mut estimate = 0.0;
    for _ in 0..5 {
        let mut y = x.clone();
        lu.solve(y.as_mut(), false);
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

impl ContactAnalysis {
    /// Make the columns `slots` of `F` known: a lazy flexibility gets the missing ones from
    /// one batch of solves, `F e_j = E^T K^-1 e_j` (see [`Bodies::flexibility_times`]); the
    /// time counts as flexibility.
    pub(super) fn ensure_columns(&mut self, slots: impl IntoIterator<Item = usize>) -> Result<()> {
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
        let columns = self.bodies.flexibility_times(&self.dofs, &units)?;
        for (c, &j) in missing.iter().enumerate() {
            self.flexibility
                .matrix
                .column_mut(j)
                .copy_from(&columns.column(c));
            self.flexibility.known[j] = true;
        }
        self.timings.flexibility += clock.elapsed().as_secs_f64();
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
                let node = &self.reference[p].nodes[k];
                let d = match row {
                    Row::Normal => node.normal,
                    Row::Tangent => node.tangent,
                };
                self.directed(&node.coupling, d)
            })
            .collect();
        let m = self.dofs.len();
        if self.flexibility.is_full() {
            for (key, v) in new.into_iter().zip(vectors) {
                let mut y = vec![0.0; m];
                self.apply_flexibility(&v, &mut y);
                self.node_flexibility.add(key, v, y);
            }
        } else if !new.is_empty() {
            // one right-hand side per new direction, not one per dof it touches
            let clock = std::time::Instant::now();
            let y = self.bodies.flexibility_times(&self.dofs, &vectors)?;
            self.timings.flexibility += clock.elapsed().as_secs_f64();
            for (c, (key, v)) in new.into_iter().zip(vectors).enumerate() {
                self.node_flexibility.add(key, v, column(&y, c).to_vec());
            }
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

    /// Solve the small system (METHOD.md section 3): `S tau = b - rows . u0` with
    /// `S_ij = row_i . F col_j`, bordered by the force-controlled plate translations `U` as in
    /// the reference (`SmallSystem::solve`), by a blocked Cholesky factorization when `S` is
    /// symmetric (no slip node with friction, no border) or else a blocked LU with partial
    /// pivoting (faer), and
    /// the new displacement of the contact dofs, `u = u0 + F sum_j tau_j col_j + sum_e U_e w_e`
    /// (`w_e` the plate's response). Small kinematics read `S` off the node flexibility,
    /// `S_ij = sum_b coefficient_jb N_(a_i, b)`, and form `u` from the node responses,
    /// `F sum_j tau_j col_j = sum_b (sum_j tau_j coefficient_jb) y_b`; finite kinematics form
    /// `y_j = F col_j` from the columns of `F`. Returns `(tau, U, condition estimate, u)`.
    pub(super) fn solve_boundary(
        &mut self,
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
        let mut s = Mat::<f64>::zeros(m + k, m + k);
        // small kinematics: directions of rows and columns; finite: the responses y_j
        let (directions, responses) = match self.options.kinematics {
            Kinematics::Small => {
                let (rows, cols) = self.node_directions(system)?;
                let n = &self.node_flexibility.n;
                for (j, parts) in cols.iter().enumerate() {
                    for (i, &a) in rows.iter().enumerate() {
                        s[(i, j)] = parts.iter().map(|&(b, c)| c * n[a][b]).sum();
                    }
                }
                (Some(cols), Vec::new())
            }
            Kinematics::Finite => {
                self.ensure_columns(system.cols.iter().flatten().map(|&(c, _)| c))?;
                let mut y = vec![0.0; mc * m];
                for (j, col) in system.cols.iter().enumerate() {
                    let yj = &mut y[j * mc..(j + 1) * mc];
                    self.apply_flexibility(col, yj);
                    for (i, row) in system.rows.iter().enumerate() {
                        s[(i, j)] = dot(row, yj);
                    }
                }
                (None, y)
            }
        };
        let mut rhs = Mat::<f64>::zeros(m + k, 1);
        for (i, (row, b)) in system.rows.iter().zip(&system.b).enumerate() {
            rhs[(i, 0)] = b - dot(row, u0c);
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
            .map(|j| (0..m + k).map(|i| s[(i, j)].abs()).sum::<f64>())
            .fold(0.0, f64::max);
        // the unknowns whose column is not their row: slip nodes under friction
        let unsymmetric: Vec<usize> = (0..m).filter(|&j| system.basis[j].len() > 1).collect();
        let lu = Dense::new(s, unsymmetric, k > 0);
        // beyond this the solution has fewer than 3 correct digits: treat it as singular
        let condition = condition_estimate(s_norm, &lu, m + k)
            .filter(|&c| c < 1e-3 / f64::EPSILON)
            .ok_or_else(singular)?;
        lu.solve(rhs.as_mut(), false);
        let tau: Vec<f64> = (0..m + k).map(|i| rhs[(i, 0)]).collect();
        if !tau.iter().all(|v| v.is_finite()) {
            return Err(singular());
        }
        let mut uc = u0c.to_vec();
        match directions {
            Some(cols) => {
                let mut weights = vec![0.0; self.node_flexibility.responses.len()];
                for (parts, &t) in cols.iter().zip(&tau) {
                    for &(b, c) in parts {
                        weights[b] += t * c;
                    }
                }
                for (yb, &w) in self.node_flexibility.responses.iter().zip(&weights) {
                    if w != 0.0 {
                        for (u, v) in uc.iter_mut().zip(yb) {
                            *u += w * v;
                        }
                    }
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

    /// Build the part of a lazy `F` that the first increment certainly needs: under small
    /// kinematics the directions of each pair's A node with the smallest reference gap (the
    /// first to close; normal, and tangent with friction), under finite kinematics the columns
    /// its coupling touches. A failing host solver is thus reported when the analysis is
    /// created, as with an eager `F`.
    pub(super) fn prime(&mut self) -> Result<()> {
        let mut rows = Vec::new();
        let mut keys = Vec::new();
        for (p, surface) in self.reference.iter().enumerate() {
            let nearest = surface
                .nodes
                .iter()
                .enumerate()
                .filter(|(_, n)| n.is_covered())
                .min_by(|a, b| a.1.normal_gap.total_cmp(&b.1.normal_gap));
            if let Some((k, node)) = nearest {
                rows.push((p, k, Row::Normal));
                keys.push(self.directed(&node.coupling, node.normal));
                if !self.laws[p].is_frictionless() {
                    rows.push((p, k, Row::Tangent));
                    keys.push(self.directed(&node.coupling, node.tangent));
                }
            }
        }
        match self.options.kinematics {
            Kinematics::Small => {
                let system = SmallSystem {
                    unknowns: rows.clone(),
                    b: vec![0.0; rows.len()],
                    basis: rows.iter().map(|&(p, k, r)| vec![(p, k, r, 1.0)]).collect(),
                    cols: keys.clone(),
                    rows: keys,
                };
                self.node_directions(&system).map(|_| ())
            }
            Kinematics::Finite => self.ensure_columns(keys.iter().flatten().map(|&(c, _)| c)),
        }
    }

    /// Run the iteration on the dense reference algebra (`true`) or on the lazy, cached one
    /// (`false`, the default). The reference builds every column of `F` up front (a host's
    /// callback then solves for every contact dof), forms `F col_j` and `F f` from `F` in every
    /// iteration and factors the small system with nalgebra's unblocked LU: the algebra of
    /// hycon 0.3, kept so that tests can show that both give the same contact states and
    /// tractions.
    ///
    /// # Errors
    /// A failed host solve while building the missing columns of `F`.
    pub fn set_reference_algebra(&mut self, on: bool) -> Result<()> {
        if on && !self.flexibility.is_full() {
            self.ensure_columns(0..self.dofs.len())?;
        }
        self.reference_algebra = on;
        Ok(())
    }
}
