//! The small dense system of one iteration (docs/method.md, "The mixed system with K factored once"): the rows and force columns
//! of the active nodes over the contact dofs, `S tau = b - rows . u0` with `S = rows^T F cols`,
//! bordered by the plate's force-controlled translations, solved by LU with a condition
//! estimate (the reference algebra of the test oracles, feature `oracles`; the product's
//! algebra is `boundary.rs`).

#[cfg(any(test, feature = "oracles"))]
use super::DVector;
#[cfg(feature = "oracles")]
use super::Result;
use super::boundary::Boundary;
#[cfg(feature = "oracles")]
use super::plate::Border;
use super::{ContactSurface, DMatrix, Error, FrictionLaw, NodeState, Rows, Traction, rows_of};
use crate::contact::geometry::ContactNode;
use crate::contact::space::{Frame, Vector};
#[cfg(any(test, feature = "oracles"))]
use nalgebra::{Dyn, LU};

#[cfg(feature = "oracles")]
/// `||A||_1`, the largest column sum.
pub(super) fn norm1(a: &DMatrix<f64>) -> f64 {
    a.column_iter()
        .map(|c| c.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

#[cfg(any(test, feature = "oracles"))]
/// Solve `A^T y = b` with the LU factors of `A` (`P A = L U`, so `A^T = U^T L^T P`), `l` and
/// `u` extracted once by the caller.
pub(super) fn solve_transposed(
    lu: &LU<f64, Dyn, Dyn>,
    l: &DMatrix<f64>,
    u: &DMatrix<f64>,
    b: &DVector<f64>,
) -> Option<DVector<f64>> {
    let z = u.tr_solve_upper_triangular(b)?;
    let mut w = l.tr_solve_lower_triangular(&z)?;
    lu.p().inv_permute_rows(&mut w);
    Some(w)
}

#[cfg(any(test, feature = "oracles"))]
/// `||A||_1 ||A^-1||_1` (`a_norm = ||A||_1`) with `||A^-1||_1` estimated by Hager's method from
/// the LU factors of `A` (a few solves with `A` and `A^T`, Higham's Algorithm 2.1); `None`
/// when `A` is singular.
pub(super) fn condition_estimate(a_norm: f64, lu: &LU<f64, Dyn, Dyn>) -> Option<f64> {
    let (l, u) = (lu.l(), lu.u());
    let m = l.nrows();
    let norm1 = |v: &DVector<f64>| v.iter().map(|x| x.abs()).sum::<f64>();
    let mut x = DVector::from_element(m, 1.0 / m as f64);
    let mut estimate = 0.0;
    for _ in 0..5 {
        let y = lu.solve(&x)?;
        estimate = norm1(&y);
        let sign = y.map(|v| if v >= 0.0 { 1.0 } else { -1.0 });
        let z = solve_transposed(lu, &l, &u, &sign)?;
        let j = z.iamax();
        if z[j].abs() <= z.dot(&x) {
            break;
        }
        x = DVector::zeros(m);
        x[j] = 1.0;
    }
    let condition = a_norm * estimate;
    condition.is_finite().then_some(condition)
}

/// Which row of a node an unknown belongs to: its normal, or its tangent `s_i` (the index
/// into the node's frame tangents, one in the plane and in axisymmetry, two on a 3D face).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Row {
    Normal,
    Tangent(usize),
}

impl Row {
    /// The direction `d` of the row at a node with frame `frame`: `n` or `s_i`.
    pub(super) fn direction(self, frame: &Frame) -> Vector {
        match self {
            Row::Normal => frame.normal(),
            Row::Tangent(i) => frame.tangent(i),
        }
    }
}

/// The tangents of `frame` that get rows, with their indices: all but the dropped ones
/// ([`Frame::is_dropped`]: a component that vanishes by symmetry has no row and no unknown).
pub(super) fn kept_tangents(frame: &Frame) -> impl Iterator<Item = (usize, Vector)> + '_ {
    (frame.tangents().iter().copied().enumerate()).filter(|&(i, _)| !frame.is_dropped(i))
}

/// A sparse vector over the contact dofs: `(slot, value)`.
pub(super) type Sparse = Vec<(usize, f64)>;

/// The small dense system of one iteration: one unknown per active row.
#[derive(PartialEq)]
pub(super) struct SmallSystem {
    /// `(pair, A node index, row)` of each unknown.
    pub(super) unknowns: Vec<(usize, usize, Row)>,
    /// Constraint rows (`row . u = b`).
    pub(super) rows: Vec<Sparse>,
    /// Force columns (the contact force on the contact dofs is `sum_j tau_j col_j`).
    pub(super) cols: Vec<Sparse>,
    /// Right-hand sides `b`.
    pub(super) b: Vec<f64>,
    /// Each force column as a combination of node directions:
    /// `col_j = sum coefficient * (d . c_k)` over `(pair, A node, direction, coefficient)`,
    /// `d` the node's normal (`Row::Normal`) or tangent `s_i` (`Row::Tangent(i)`).
    pub(super) basis: Vec<Vec<(usize, usize, Row, f64)>>,
}

/// Column `j` of a dense matrix as a slice (column-major storage).
pub(super) fn column(a: &DMatrix<f64>, j: usize) -> &[f64] {
    let m = a.nrows();
    &a.as_slice()[j * m..(j + 1) * m]
}

pub(super) fn dot(v: &Sparse, u: &[f64]) -> f64 {
    v.iter().map(|&(i, c)| c * u[i]).sum()
}

impl SmallSystem {
    #[cfg(feature = "oracles")]
    /// Solve `(rows^T F cols) tau = b - rows . u0` (LU with partial pivoting); with a border,
    /// also the plate translations `U` (contact rows gain `rows . w_e U_e`; each plate row
    /// reads `-sum_j tau_j w_d . col_j + sum_e D_de U_e = F_d - force0_d`).
    pub(super) fn solve(
        &self,
        u0: &[f64],
        flex: &DMatrix<f64>,
        border: Option<&Border>,
    ) -> Result<(Vec<f64>, Vec<f64>, f64)> {
        let m = self.rows.len();
        let k = border.map_or(0, |b| b.directions.len());
        if m + k == 0 {
            return Ok((Vec::new(), Vec::new(), 1.0));
        }
        let mut s = DMatrix::zeros(m + k, m + k);
        let mut fcol = vec![0.0; flex.nrows()];
        for (j, col) in self.cols.iter().enumerate() {
            fcol.iter_mut().for_each(|v| *v = 0.0);
            for &(c, v) in col {
                for (out, f) in fcol.iter_mut().zip(column(flex, c)) {
                    *out += f * v;
                }
            }
            for (i, row) in self.rows.iter().enumerate() {
                s[(i, j)] = dot(row, &fcol);
            }
        }
        let mut rhs = DVector::zeros(m + k);
        for (i, (row, b)) in self.rows.iter().zip(&self.b).enumerate() {
            rhs[i] = b - dot(row, u0);
        }
        if let Some(b) = border {
            b.fill(
                &self.rows,
                &self.cols,
                m,
                &mut |i, j, v| s[(i, j)] = v,
                &mut |i, v| rhs[i] = v,
            )?;
        }
        // beyond this the solution has fewer than 3 correct digits: treat it as singular
        let s_norm = norm1(&s);
        let lu = s.lu();
        let condition = condition_estimate(s_norm, &lu)
            .filter(|&c| c < 1e-3 / f64::EPSILON)
            .ok_or_else(singular)?;
        let tau = lu
            .solve(&rhs)
            .filter(|t| t.iter().all(|v| v.is_finite()))
            .ok_or_else(singular)?;
        Ok((
            tau.iter().take(m).copied().collect(),
            tau.iter().skip(m).copied().collect(),
            condition,
        ))
    }

    /// Append the unknowns of A node `(p, k)` with rows `rows` (its state's, `rows_of`),
    /// `directed(d)` its row along direction `d` (`d . sum_j c_kj u_j` over the contact dofs):
    /// the normal row `n . u = n . u_c - R_C . n` with column `n`, or `n + sum_i c_i s_i` at a
    /// slip node; at a stick node also one row `s_i . u = s_i . u_start` with column `s_i` per
    /// kept tangent ([`kept_tangents`]; a dropped tangent has neither).
    fn push_node(
        &mut self,
        (p, k): (usize, usize),
        node: &ContactNode,
        rows: Rows,
        directed: impl Fn(&Vector) -> Sparse,
        uc: &[f64],
        startc: &[f64],
    ) {
        if rows == Rows::None {
            return;
        }
        let normal = directed(&node.frame.normal());
        let rg = node.gap.dot(&node.frame.normal());
        let b = dot(&normal, uc) - rg;
        // the rows of the node's kept tangents (one in the plane and in axisymmetry)
        let tangents = || kept_tangents(&node.frame).map(|(i, s)| (i, directed(&s)));
        let mut col = normal.clone();
        let mut basis = vec![(p, k, Row::Normal, 1.0)];
        if let Rows::NormalSlip(c) = rows {
            // the column n + sum_i c_i s_i
            for (i, s) in tangents() {
                let w = c.components()[i];
                col.extend(s.into_iter().map(|(j, v)| (j, w * v)));
                basis.push((p, k, Row::Tangent(i), w));
            }
        }
        self.unknowns.push((p, k, Row::Normal));
        self.rows.push(normal);
        self.cols.push(col);
        self.basis.push(basis);
        self.b.push(b);
        if rows == Rows::NormalTangent {
            for (i, t) in tangents() {
                let row = Row::Tangent(i);
                self.unknowns.push((p, k, row));
                self.b.push(dot(&t, startc));
                self.rows.push(t.clone());
                self.cols.push(t);
                self.basis.push(vec![(p, k, row, 1.0)]);
            }
        }
    }

    /// Contact forces on the contact dofs: `sum_j tau_j col_j`.
    pub(super) fn forces(&self, tau: &[f64], n: usize) -> Vec<f64> {
        let mut f = vec![0.0; n];
        for (col, t) in self.cols.iter().zip(tau) {
            for &(i, c) in col {
                f[i] += c * t;
            }
        }
        f
    }

    /// The traction of every A node of `surfaces` from the unknowns, with one tangential
    /// component per frame tangent (zero at open nodes and along dropped tangents; `ts` of
    /// the law, [`FrictionLaw::slip_traction`], at slip nodes).
    pub(super) fn tractions(
        &self,
        tau: &[f64],
        surfaces: &[ContactSurface],
        states: &[Vec<NodeState>],
        laws: &[Box<dyn FrictionLaw>],
    ) -> Vec<Vec<Traction>> {
        let mut t: Vec<Vec<Traction>> = surfaces
            .iter()
            .map(|s| {
                (s.nodes.iter())
                    .map(|node| Traction::zero(node.frame.tangents().len()))
                    .collect()
            })
            .collect();
        for (&(p, k, row), &v) in self.unknowns.iter().zip(tau) {
            match row {
                Row::Normal => t[p][k].normal = v,
                Row::Tangent(i) => t[p][k].tangential.components_mut()[i] = v,
            }
        }
        for (p, s) in states.iter().enumerate() {
            for (k, state) in s.iter().enumerate() {
                if let NodeState::Slip { direction } = *state {
                    t[p][k].tangential = laws[p].slip_traction(direction, t[p][k].normal);
                }
            }
        }
        t
    }
}

impl Boundary {
    /// Assemble the rows, columns and right-hand sides for the active nodes (their rows by
    /// state: [`rows_of`]), with the pairs' friction `laws`.
    pub(super) fn build_system(
        &self,
        surfaces: &[ContactSurface],
        laws: &[Box<dyn FrictionLaw>],
        states: &[Vec<NodeState>],
        uc: &[f64],
        startc: &[f64],
    ) -> SmallSystem {
        let mut sys = SmallSystem {
            unknowns: Vec::new(),
            rows: Vec::new(),
            cols: Vec::new(),
            b: Vec::new(),
            basis: Vec::new(),
        };
        for (p, surface) in surfaces.iter().enumerate() {
            let law = &*laws[p];
            for (k, node) in surface.nodes.iter().enumerate() {
                let directed = |d: &Vector| self.directed(&node.coupling, d);
                sys.push_node(
                    (p, k),
                    node,
                    rows_of(states[p][k], law),
                    directed,
                    uc,
                    startc,
                );
            }
        }
        sys
    }
}

/// The error of a singular small system.
pub(super) fn singular() -> Error {
    Error::Singular(
        "the contact system is singular: a body held only by contact cannot take the load \
         (frictionless contact cannot resist tangential motion)"
            .into(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::friction::Coulomb;
    use crate::contact::tangent::Tangential;

    /// A 3D face node: normal `n = z`, tangents in the `xy` plane, `s2` alone when `s1` is
    /// dropped by symmetry.
    fn face_node(dropped: bool) -> ContactNode {
        let mut node = ContactNode::empty(3);
        let s1 = if dropped { [0.0; 3] } else { [0.6, 0.8, 0.0] };
        node.frame = Frame::face([0.0, 0.0, 1.0], s1, [-0.8, 0.6, 0.0]);
        node.gap = Vector::solid(0.0, 0.0, -0.5);
        node
    }

    /// A row along `d` with a unit coupling to one node whose contact dofs are slots 0..3.
    fn unit(d: &Vector) -> Sparse {
        d.components().iter().copied().enumerate().collect()
    }

    fn empty() -> SmallSystem {
        SmallSystem {
            unknowns: Vec::new(),
            rows: Vec::new(),
            cols: Vec::new(),
            b: Vec::new(),
            basis: Vec::new(),
        }
    }

    /// A sparse vector over slots 0..3, its entries summed.
    fn dense(v: &Sparse) -> [f64; 3] {
        let mut out = [0.0; 3];
        for &(i, x) in v {
            out[i] += x;
        }
        out
    }

    /// A stick node with two tangents has three rows (normal, `s1`, `s2`), each its own
    /// column, with `b = n . u_c - n . R_C` and `s_i . u_start`; a dropped tangent has no row.
    #[test]
    fn a_stick_face_node_has_a_row_per_kept_tangent() {
        let (uc, startc) = ([0.1, 0.2, 0.3], [1.0, 2.0, 4.0]);
        let mut sys = empty();
        sys.push_node(
            (0, 0),
            &face_node(false),
            Rows::NormalTangent,
            unit,
            &uc,
            &startc,
        );
        let rows = [Row::Normal, Row::Tangent(0), Row::Tangent(1)];
        assert_eq!(sys.unknowns, rows.map(|r| (0, 0, r)));
        assert_eq!(sys.rows, sys.cols);
        assert_eq!(dense(&sys.rows[1]), [0.6, 0.8, 0.0]);
        assert_eq!(dense(&sys.rows[2]), [-0.8, 0.6, 0.0]);
        assert_eq!(
            sys.b,
            [0.3 + 0.5, 0.6 * 1.0 + 0.8 * 2.0, -0.8 * 1.0 + 0.6 * 2.0]
        );
        let mut dropped = empty();
        dropped.push_node(
            (0, 1),
            &face_node(true),
            Rows::NormalTangent,
            unit,
            &uc,
            &startc,
        );
        assert_eq!(
            dropped.unknowns,
            [(0, 1, Row::Normal), (0, 1, Row::Tangent(1))]
        );
        assert_eq!(dense(&dropped.rows[1]), [-0.8, 0.6, 0.0]);
        let mut open = empty();
        open.push_node((0, 2), &face_node(false), Rows::None, unit, &uc, &startc);
        assert!(open.unknowns.is_empty() && open.b.is_empty());
    }

    /// A slip node with two tangents has one unknown, its column `n + c1 s1 + c2 s2`; with
    /// `s1` dropped the column is `n + c2 s2`.
    #[test]
    fn a_slip_face_node_has_one_column_along_its_slip() {
        let (uc, startc) = ([0.0; 3], [0.0; 3]);
        let c = Tangential::on_face(0.3, -0.4);
        let mut sys = empty();
        sys.push_node(
            (0, 0),
            &face_node(false),
            Rows::NormalSlip(c),
            unit,
            &uc,
            &startc,
        );
        assert_eq!(sys.unknowns, [(0, 0, Row::Normal)]);
        assert_eq!(dense(&sys.rows[0]), [0.0, 0.0, 1.0]);
        let col = dense(&sys.cols[0]);
        let expected = [0.3 * 0.6 + 0.4 * 0.8, 0.3 * 0.8 - 0.4 * 0.6, 1.0];
        for (a, b) in col.iter().zip(expected) {
            assert!((a - b).abs() <= 1e-15, "{col:?}");
        }
        let basis = [
            (Row::Normal, 1.0),
            (Row::Tangent(0), 0.3),
            (Row::Tangent(1), -0.4),
        ];
        assert_eq!(sys.basis, [basis.map(|(r, w)| (0, 0, r, w))]);
        let mut dropped = empty();
        dropped.push_node(
            (0, 0),
            &face_node(true),
            Rows::NormalSlip(c),
            unit,
            &uc,
            &startc,
        );
        assert_eq!(dense(&dropped.cols[0]), [0.4 * 0.8, -0.4 * 0.6, 1.0]);
        assert_eq!(dropped.basis[0].len(), 2);
    }

    /// The tractions put each unknown on its tangent and have the frame's two components:
    /// zero along a dropped tangent and at an open node.
    #[test]
    fn face_tractions_have_a_component_per_frame_tangent() {
        let (uc, startc) = ([0.0; 3], [0.0; 3]);
        let mut sys = empty();
        sys.push_node(
            (0, 0),
            &face_node(false),
            Rows::NormalTangent,
            unit,
            &uc,
            &startc,
        );
        sys.push_node(
            (0, 1),
            &face_node(true),
            Rows::NormalTangent,
            unit,
            &uc,
            &startc,
        );
        let mut surface = ContactSurface::new();
        surface.nodes = vec![face_node(false), face_node(true), face_node(false)];
        let states = vec![vec![NodeState::Stick, NodeState::Stick, NodeState::Open]];
        let laws: Vec<Box<dyn FrictionLaw>> = vec![Box::new(Coulomb::new(0.5).unwrap())];
        let t = sys.tractions(&[-1.0, 0.2, 0.3, -2.0, 0.5], &[surface], &states, &laws);
        let traction = |normal, tangential| Traction { normal, tangential };
        assert_eq!(
            t[0],
            [
                traction(-1.0, Tangential::on_face(0.2, 0.3)),
                traction(-2.0, Tangential::on_face(0.0, 0.5)),
                Traction::zero(2),
            ]
        );
    }

    /// Hager's estimate is a lower bound of the exact 1-norm condition number and, on these
    /// matrices, within a factor 3 of it (the estimator is usually exact or within a small
    /// factor).
    #[test]
    fn condition_estimate_is_close() {
        for (m, scale) in [(1, 1.0), (5, 1e-3), (40, 1e6)] {
            let a = DMatrix::from_fn(m, m, |i, j| {
                let base = if i == j {
                    4.0
                } else {
                    ((i * 7 + j * 3) % 5) as f64 / 5.0 - 0.4
                };
                base * scale * (1.0 + i as f64)
            });
            let inv = a.clone().try_inverse().unwrap();
            let norm1 =
                |b: &DMatrix<f64>| (0..m).map(|j| b.column(j).abs().sum()).fold(0.0, f64::max);
            let exact = norm1(&a) * norm1(&inv);
            let estimate = condition_estimate(norm1(&a), &a.clone().lu()).unwrap();
            assert!(
                estimate <= exact * (1.0 + 1e-12) && estimate >= exact / 3.0,
                "{m}: {estimate} vs {exact}"
            );
        }
        let zero = DMatrix::zeros(3, 3);
        assert!(condition_estimate(0.0, &zero.lu()).is_none());
    }
}
