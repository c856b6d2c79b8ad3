//! Contact-element kernels (`hycon::contact::plane::mortar`): conventions, mortar integrals, coverage,
//! the choice of hit, invariance, the coupling against finite differences, input checks.
//!
//! Tolerances: quantities that are exact in real arithmetic (the split-and-Gauss rule integrates
//! every product exactly) are compared to `1e-13` of their natural scale (`L` for lengths,
//! `L * h` for `R_C` and couplings, `L` = the surface length, about 1 here): round-off of a few
//! dozen operations. Invariance under translation, rotation and scaling is checked to `1e-12` of
//! the same scales. The finite-difference check states its own tolerance.

use hycon::Error;
use hycon::contact::plane::mortar::{
    ContactNode, ContactSurface, SurfaceMeasure, evaluate, evaluate_into,
};
use hycon::contact::space::Vector;
use std::collections::BTreeMap;
use std::f64::consts::PI;

/// Plane, unit thickness (the measure of every test here but the measure tests).
const UNIT: SurfaceMeasure = SurfaceMeasure::Plane { thickness: 1.0 };

const EXACT: f64 = 1e-13;
const INVARIANT: f64 = 1e-12;

/// Small deterministic generator in `[0, 1)`.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A flat interface: A on `y = 0` with nodes at `xa` (listed right to left so that A lies below
/// and `n = +y`), B on `y = gap + slope * x` with nodes at `xb` (left to right: B above, facing
/// A). Returns `(a, b, x)`; A's ids are `0..xa.len()` in A's order.
fn flat(xa: &[f64], xb: &[f64], gap: f64, slope: f64) -> (Vec<usize>, Vec<usize>, Vec<[f64; 2]>) {
    let mut x = Vec::new();
    let mut a = Vec::new();
    for &v in xa.iter().rev() {
        x.push([v, 0.0]);
        a.push(x.len() - 1);
    }
    let mut b = Vec::new();
    for &v in xb {
        x.push([v, gap + slope * v]);
        b.push(x.len() - 1);
    }
    (a, b, x)
}

fn uniform(x0: f64, x1: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|i| x0 + (x1 - x0) * i as f64 / n as f64)
        .collect()
}

/// `n` segments on `[x0, x1]` with random spacing (each between 0.3 and 1.7 of the mean).
fn random_spacing(x0: f64, x1: f64, n: usize, rng: &mut Rng) -> Vec<f64> {
    let w: Vec<f64> = (0..n).map(|_| 0.3 + 1.4 * rng.next()).collect();
    let total: f64 = w.iter().sum();
    let mut v = vec![x0];
    let mut acc = 0.0;
    for wi in &w[..n - 1] {
        acc += wi;
        v.push(x0 + (x1 - x0) * acc / total);
    }
    v.push(x1);
    v
}

/// Coupling entries of a node split into (A part, B part) by node id.
fn split(node: &ContactNode, a: &[usize]) -> (BTreeMap<usize, f64>, BTreeMap<usize, f64>) {
    let mut fa = BTreeMap::new();
    let mut fb = BTreeMap::new();
    for &(j, c) in &node.coupling {
        if a.contains(&j) {
            fa.insert(j, c);
        } else {
            fb.insert(j, -c);
        }
    }
    (fa, fb)
}

fn close(u: f64, v: f64, tol: f64) -> bool {
    (u - v).abs() <= tol
}

// ------------------------------------------------------------------------------------------------
// Conventions
// ------------------------------------------------------------------------------------------------

/// n = (b - a) rotated clockwise points away from A (into B), s = (n_y, -n_x); an open gap is
/// positive and penetration negative; R_C = -g n.
#[test]
fn sign_conventions() {
    // A below y = 0 going right to left; B above
    for (gap, name) in [(0.05, "open"), (-0.03, "penetrating")] {
        let (a, b, x) = flat(&[0.0, 1.0, 2.0], &[-0.5, 2.5], gap, 0.0);
        let s = evaluate(&a, &b, &x, 1.0, UNIT).unwrap();
        for nd in &s.nodes {
            assert_eq!(nd.frame.normal(), [0.0, 1.0].into(), "{name}");
            assert_eq!(nd.frame.tangent(0), [1.0, 0.0].into(), "{name}");
            assert!(
                close(nd.normal_gap, gap, EXACT),
                "{name}: {}",
                nd.normal_gap
            );
            assert!(close(nd.mean_distance, gap, EXACT), "{name}");
            assert!(close(nd.gap[0], 0.0, EXACT), "{name}");
            assert!(close(nd.gap[1], -gap * nd.weight, EXACT), "{name}");
        }
    }
    // a B oriented the same way as A (not facing: its outward normal is +y too) is ignored
    let (a, _, mut x) = flat(&[0.0, 1.0, 2.0], &[], 0.0, 0.0);
    x.push([2.5, 0.1]);
    x.push([-0.5, 0.1]);
    let s = evaluate(&a, &[3, 4], &x, 1.0, UNIT).unwrap();
    for nd in &s.nodes {
        assert_eq!(nd.coverage, 0.0);
        assert_eq!(nd.normal_gap, f64::INFINITY);
        assert!(nd.coupling.iter().all(|&(j, _)| j < 3), "only A entries");
    }
}

/// The nodal normal is the length-weighted average of the adjacent segment normals.
#[test]
fn nodal_frame_is_length_weighted() {
    // A: (2,0) -> (0,0) -> (0,-1)... keep the body on the left: A goes (0,-1) -> (0,0) -> (-2, 0)
    // segment normals: (1, 0) (length 1) and (0, 1) (length 2)
    let x = vec![
        [0.0, -1.0],
        [0.0, 0.0],
        [-2.0, 0.0],
        [5.0, 5.0],
        [-5.0, 5.0],
    ];
    let s = evaluate(&[0, 1, 2], &[3, 4], &x, 100.0, UNIT).unwrap();
    let m = s.nodes[1].frame.normal();
    let norm = 5f64.sqrt();
    assert!(
        close(m[0], 1.0 / norm, EXACT) && close(m[1], 2.0 / norm, EXACT),
        "{m:?}"
    );
    let t = s.nodes[1].frame.tangent(0);
    assert_eq!(t, [m[1], -m[0]].into());
    assert_eq!(s.nodes[0].frame.normal(), [1.0, 0.0].into());
    assert_eq!(s.nodes[2].frame.normal(), [0.0, 1.0].into());
}

// ------------------------------------------------------------------------------------------------
// Node-to-node and node-to-internode
// ------------------------------------------------------------------------------------------------

/// Matching nodes: F^B equals F^A entry by entry; rows sum to the weight; weights sum to L.
#[test]
fn node_to_node_fb_equals_fa() {
    let xs = [0.0, 0.7, 1.5, 2.0, 3.2];
    let (a, b, x) = flat(&xs, &xs, 0.0, 0.0);
    // the A node at the same place as B node j
    let partner = |j: usize| *a.iter().find(|&&m| x[m] == x[j]).unwrap();
    let s = evaluate(&a, &b, &x, 1.0, UNIT).unwrap();
    let total: f64 = s.nodes.iter().map(|n| n.weight).sum();
    assert!(close(total, 3.2, EXACT));
    for nd in &s.nodes {
        assert_eq!(nd.coverage, 1.0);
        let (fa, fb) = split(nd, &a);
        // F^B mapped onto the coinciding A nodes equals F^A entry by entry
        let mut diff: BTreeMap<usize, f64> = fa.clone();
        for (&j, &v) in &fb {
            *diff.entry(partner(j)).or_default() -= v;
        }
        for (j, d) in diff {
            assert!(
                d.abs() <= EXACT,
                "node {}: F^A - F^B at {j} is {d}",
                nd.node
            );
        }
        let (sa, sb): (f64, f64) = (fa.values().sum(), fb.values().sum());
        assert!(close(sa, nd.weight, EXACT) && close(sb, nd.weight, EXACT));
        assert!(close(nd.gap[0], 0.0, EXACT) && close(nd.gap[1], 0.0, EXACT));
    }
    // the consistent pattern h/3, h/6 at an interior node
    let (fa, _) = split(&s.nodes[2], &a);
    // node a[2] sits at x = 1.5, between a[1] (x = 2.0) and a[3] (x = 0.7)
    let (h1, h2) = (2.0 - 1.5, 1.5 - 0.7);
    assert!(close(fa[&a[2]], (h1 + h2) / 3.0, EXACT));
    assert!(close(fa[&a[1]], h1 / 6.0, EXACT));
    assert!(close(fa[&a[3]], h2 / 6.0, EXACT));
}

/// Non-matching meshes (B finer, equal, coarser, random, shifted and of equal extent): row sums
/// equal the weight, a constant gap is reproduced at every node, a linear gap gives the exact
/// integral of M_k g.
#[test]
fn node_to_internode_row_sums_constant_and_linear_gap() {
    let mut rng = Rng(7);
    let xa = random_spacing(0.0, 1.0, 9, &mut rng);
    let cases: Vec<(&str, Vec<f64>)> = vec![
        ("finer", uniform(0.0, 1.0, 23)),
        ("equal count", uniform(0.0, 1.0, 9)),
        ("coarser", uniform(-0.05, 1.05, 4)),
        ("random", random_spacing(-0.01, 1.02, 14, &mut rng)),
        ("one segment", vec![-0.2, 1.2]),
    ];
    for (name, xb) in cases {
        for (g0, slope) in [(0.0, 0.0), (0.013, 0.0), (-0.007, 0.0), (0.004, 0.011)] {
            let (a, b, x) = flat(&xa, &xb, g0, slope);
            let s = evaluate(&a, &b, &x, 0.5, UNIT).unwrap();
            let total: f64 = s.nodes.iter().map(|n| n.weight).sum();
            assert!(close(total, 1.0, EXACT), "{name}");
            for (k, nd) in s.nodes.iter().enumerate() {
                let tag = format!("{name} g0 {g0} slope {slope} node {k}");
                assert_eq!(nd.coverage, 1.0, "{tag}");
                assert!(close(nd.covered_weight, nd.weight, EXACT), "{tag}");
                let (fa, fb) = split(nd, &a);
                let (sa, sb): (f64, f64) = (fa.values().sum(), fb.values().sum());
                assert!(close(sa, nd.weight, EXACT), "{tag}: {sa} vs {}", nd.weight);
                assert!(close(sb, nd.weight, EXACT), "{tag}: {sb} vs {}", nd.weight);
                // exact integral of M_k (g0 + slope x) over the hat of node k
                let xk = x[nd.node][0];
                let mut exact = 0.0;
                if k > 0 {
                    let xr = x[a[k - 1]][0]; // A runs right to left
                    exact += (xr - xk) * (2.0 * (g0 + slope * xk) + (g0 + slope * xr)) / 6.0;
                }
                if k + 1 < a.len() {
                    let xl = x[a[k + 1]][0];
                    exact += (xk - xl) * (2.0 * (g0 + slope * xk) + (g0 + slope * xl)) / 6.0;
                }
                assert!(close(nd.gap[0], 0.0, EXACT), "{tag}");
                assert!(
                    close(nd.gap[1], -exact, EXACT),
                    "{tag}: {} vs {}",
                    nd.gap[1],
                    -exact
                );
                if slope == 0.0 {
                    assert!(close(nd.normal_gap, g0, EXACT), "{tag}: {}", nd.normal_gap);
                }
            }
        }
    }
}

/// F^B integrates B's hat functions at the projected points: with B carrying the nodal values
/// of a linear field f(x) = c0 + c1 x, sum_j F^B_kj f_j equals the exact integral of M_k f.
#[test]
fn fb_reproduces_linear_fields_of_b() {
    let mut rng = Rng(99);
    let xa = random_spacing(0.0, 2.0, 7, &mut rng);
    let xb = random_spacing(-0.1, 2.1, 19, &mut rng);
    let (a, b, x) = flat(&xa, &xb, 0.02, 0.0);
    let s = evaluate(&a, &b, &x, 0.5, UNIT).unwrap();
    let f = |v: f64| 0.3 - 1.7 * v;
    for (k, nd) in s.nodes.iter().enumerate() {
        let (_, fb) = split(nd, &a);
        let got: f64 = fb.iter().map(|(&j, &c)| c * f(x[j][0])).sum();
        let xk = x[nd.node][0];
        let mut exact = 0.0;
        for nb in [k.wrapping_sub(1), k + 1] {
            if let Some(&j) = a.get(nb) {
                let xo = x[j][0];
                exact += (xo - xk).abs() * (2.0 * f(xk) + f(xo)) / 6.0;
            }
        }
        assert!(close(got, exact, EXACT), "node {k}: {got} vs {exact}");
    }
    // column sums of F^B: integral of L^B_j over the projected overlap; they add up to |A|
    let mut cols: BTreeMap<usize, f64> = BTreeMap::new();
    for nd in &s.nodes {
        for (j, c) in split(nd, &a).1 {
            *cols.entry(j).or_default() += c;
        }
    }
    assert!(close(cols.values().sum::<f64>(), 2.0, EXACT));
}

// ------------------------------------------------------------------------------------------------
// Coverage, multiple hits, search distance
// ------------------------------------------------------------------------------------------------

/// A longer than B: the end node's coverage is exactly the covered fraction of its support;
/// a part of B farther than the search distance is a hole, reported exactly.
#[test]
fn coverage_is_the_exact_covered_fraction() {
    let xa = uniform(0.0, 10.0, 10);
    // B starts at x = 0.3; between x = 4 and 6 it leaves the search distance (d = 1)
    let mut x = Vec::new();
    let mut a = Vec::new();
    for &v in xa.iter().rev() {
        x.push([v, 0.0]);
        a.push(x.len() - 1);
    }
    let bpts = [
        [0.3, 0.1],
        [2.0, 0.1],
        [3.9, 0.1],
        [4.0, 5.0],
        [6.0, 5.0],
        [6.1, 0.1],
        [10.0, 0.1],
    ];
    let b: Vec<usize> = bpts
        .iter()
        .map(|p| {
            x.push(*p);
            x.len() - 1
        })
        .collect();
    let s = evaluate(&a, &b, &x, 1.0, UNIT).unwrap();
    let by_x = |v: f64| s.nodes.iter().find(|n| x[n.node][0] == v).unwrap();
    // |g| = 1 on the flanks at x = 3.9 + 0.1 * 0.9 / 4.9 and symmetric
    let xa_ = 3.9 + 0.1 * 0.9 / 4.9;
    let xb_ = 6.1 - 0.1 * 0.9 / 4.9;
    let expect = [
        (0.0, 0.7),
        (1.0, 1.0 - 0.3 / 2.0),
        (2.0, 1.0),
        (3.0, 1.0 - (4.0 - xa_) / 2.0),
        (4.0, 1.0 - (5.0 - xa_) / 2.0),
        (5.0, 0.0),
        (6.0, 1.0 - (xb_ - 5.0) / 2.0),
        (7.0, 1.0 - (xb_ - 6.0) / 2.0),
        (8.0, 1.0),
        (10.0, 1.0),
    ];
    for (v, c) in expect {
        let nd = by_x(v);
        assert!(
            close(nd.coverage, c, EXACT),
            "x = {v}: {} vs {c}",
            nd.coverage
        );
        assert_eq!(nd.is_covered(), c == 1.0, "x = {v}");
    }
    assert_eq!(
        by_x(10.0).coverage,
        1.0,
        "equal extent at the right end: exactly 1"
    );
    assert_eq!(by_x(5.0).normal_gap, f64::INFINITY);
    assert!(!s.all_covered());
    // the partially covered end node: covered weight = integral of M over [0.3, 1]
    let end = by_x(0.0);
    assert!(close(end.covered_weight, 0.7 * 0.7 / 2.0, EXACT));
    assert!(close(end.normal_gap, 0.1, EXACT));
    // node 3 sees the flank: covered weight is the integral of M_3 over [2, xa_]
    let n3 = by_x(3.0);
    let cw = 0.5 + (xa_ - 3.0) - 0.5 * (xa_ - 3.0) * (xa_ - 3.0);
    assert!(
        close(n3.covered_weight, cw, EXACT),
        "{} vs {cw}",
        n3.covered_weight
    );
}

/// A partly covered node (B ends inside its support: the flat side of a contact taken as A
/// under a smaller B, or a search window cutting a support). Its normal gap is the mean of `g`
/// over the covered part, `integral_cov M_k g dS / integral_cov M_k dS`, and its coupling row
/// is the change of `R_C,k` over that same part: `F^A` over the covered part as `F^B` is, so
/// `sum_j c_kj = 0` (a rigid translation leaves `R_C,k` unchanged) and the linearised gap
/// `-n_k . (R_C,k + sum_j c_kj du_j) / covered weight` (the iteration's gap under small
/// kinematics) equals the gap evaluated at the moved positions. With A's whole-support `F^A`
/// in the row, an approach `delta` of A closed a partly covered node's gap by
/// `delta * weight / covered weight` (4 times `delta` here) and a translation changed it. A
/// node with nothing covered has an infinite gap and A's whole-support `F^A` as its row.
#[test]
fn partly_covered_node_gap_and_row_agree() {
    let cases = [
        (UNIT, 0.0),
        (SurfaceMeasure::Plane { thickness: 0.3 }, 0.0),
        (SurfaceMeasure::Axisymmetric, 1.0),
    ];
    for (measure, x0) in cases {
        // A on y = 0, nodes at x0 + 0..=4; B on y = g(x) from x0 + 1.3 to beyond A's end: the
        // node at x0 + 1 is covered over [x0 + 1.3, x0 + 2] of its support, the one at x0 not
        let m = |v: f64| match measure {
            SurfaceMeasure::Plane { thickness } => thickness,
            SurfaceMeasure::Axisymmetric => 2.0 * PI * v,
        };
        let start = x0 + 1.3;
        for (g0, slope) in [(0.02, 0.0), (-0.01, 0.0), (0.02, 0.05)] {
            let tag = format!("{measure:?} g0 {g0} slope {slope}");
            let g = |v: f64| g0 + slope * v;
            let xa = uniform(x0, x0 + 4.0, 4);
            let (a, b, x) = flat(&xa, &[start, x0 + 2.6, x0 + 5.0], g0, slope);
            let s = evaluate(&a, &b, &x, 1.0, measure).unwrap();
            let scale = s.nodes.iter().map(|n| n.weight).fold(0.0, f64::max);
            // integral of f over the part of node k's support from `from` on (a cubic at most:
            // M_k, L_j, g and m are affine), by Simpson's rule on each piece
            let over = |k: usize, from: f64, f: &dyn Fn(f64) -> f64| -> f64 {
                let xk = x[a[k]][0];
                [k.wrapping_sub(1), k + 1]
                    .iter()
                    .filter_map(|&j| a.get(j))
                    .map(|&j| {
                        let xo = x[j][0];
                        let hat = |v: f64| 1.0 - (v - xk).abs() / (xo - xk).abs();
                        let (l, u) = (xk.min(xo).max(from), xk.max(xo));
                        if l >= u {
                            return 0.0;
                        }
                        let h = |v: f64| hat(v) * f(v) * m(v);
                        (u - l) / 6.0 * (h(l) + 4.0 * h(0.5 * (l + u)) + h(u))
                    })
                    .sum()
            };
            let approach = 0.005;
            let mut du = vec![0.0; 2 * x.len()];
            let mut moved = x.clone();
            for &i in &a {
                du[2 * i + 1] = approach;
                moved[i][1] += approach;
            }
            let after = evaluate(&a, &b, &moved, 1.0, measure).unwrap();
            let translation: Vec<f64> = x.iter().flat_map(|_| [0.7, -1.9]).collect();
            let mut partly = 0;
            for (k, nd) in s.nodes.iter().enumerate() {
                let tag = format!("{tag} node at x = {}", x[nd.node][0]);
                if nd.covered_weight == 0.0 {
                    assert_eq!(nd.normal_gap, f64::INFINITY, "{tag}");
                } else {
                    partly += usize::from(!nd.is_covered());
                    // the gap: the covered mean of g
                    let mean = over(k, start, &g) / over(k, start, &|_| 1.0);
                    assert!(
                        close(nd.normal_gap, mean, EXACT),
                        "{tag}: {} vs {mean}",
                        nd.normal_gap
                    );
                    // linearised and evaluated after A's approach along n = +y: both close
                    // by it
                    let n = nd.frame.normal();
                    let linear = -n.dot(&(nd.gap + nd.coupling_times(&du))) / nd.covered_weight;
                    let evaluated = after.nodes[k].normal_gap;
                    assert!(
                        close(evaluated, mean - approach, EXACT),
                        "{tag}: {evaluated}"
                    );
                    assert!(
                        close(linear, evaluated, EXACT),
                        "{tag}: linearised {linear} vs evaluated {evaluated}"
                    );
                }
                // F^A over the covered part, entry by entry, and the row sums to zero; a node
                // with nothing covered keeps the whole support's F^A (a regular row)
                let from = if nd.covered_weight == 0.0 {
                    f64::NEG_INFINITY
                } else {
                    start
                };
                let (fa, _) = split(nd, &a);
                for &j in &a {
                    let xj = x[j][0];
                    let lj = |v: f64| (1.0 - (v - xj).abs()).max(0.0);
                    let exact = over(k, from, &lj);
                    let got = fa.get(&j).copied().unwrap_or(0.0);
                    assert!(
                        close(got, exact, EXACT * scale),
                        "{tag}: F^A at {xj}: {got} vs {exact}"
                    );
                }
                let rigid = nd.coupling_times(&translation);
                assert!(
                    nd.covered_weight == 0.0 || rigid.norm() <= EXACT * scale,
                    "{tag}: a translation changes R_C by {rigid:?}"
                );
            }
            assert_eq!(partly, 2, "{tag}: two partly covered nodes");
        }
    }
}

/// B folding back: several hits along the normal; the facing one with the smallest |g| wins,
/// a nearer non-facing (back side) hit is ignored, penetration counts by |g|.
#[test]
fn b_curving_back_picks_the_nearest_facing_hit() {
    let xa = uniform(0.0, 10.0, 5);
    // a zig-zag B: facing at y = 0.6, then back side at y = 0.3 (nearer, non-facing), then a
    // facing sheet at y = y3 (nearer or farther than 0.6 in |g|)
    for (y3, expect) in [(-0.5, -0.5), (-0.7, 0.6), (1.2, 0.6), (0.45, 0.45)] {
        let (a, _, mut x) = flat(&xa, &[], 0.0, 0.0);
        let pts = [
            [-1.0, 0.6],
            [12.0, 0.6],
            [12.0, 0.3],
            [-1.0, 0.3],
            [-1.0, y3],
            [12.0, y3],
        ];
        let b: Vec<usize> = pts
            .iter()
            .map(|p| {
                x.push(*p);
                x.len() - 1
            })
            .collect();
        let s = evaluate(&a, &b, &x, 2.0, UNIT).unwrap();
        for nd in &s.nodes {
            assert_eq!(nd.coverage, 1.0);
            assert!(
                close(nd.normal_gap, expect, EXACT),
                "y3 {y3}: {}",
                nd.normal_gap
            );
            let (_, fb) = split(nd, &a);
            // the chosen sheet's nodes carry the whole row
            let sheet = if expect == 0.6 {
                [b[0], b[1]]
            } else {
                [b[4], b[5]]
            };
            let sum: f64 = sheet
                .iter()
                .map(|j| fb.get(j).copied().unwrap_or(0.0))
                .sum();
            assert!(close(sum, nd.weight, EXACT), "y3 {y3}");
        }
    }
}

/// Two facing sheets that cross above A: the choice switches exactly where |g1| = |g2|
/// (inside an A segment), and the integrals stay exact.
#[test]
fn switch_between_crossing_sheets_is_exact() {
    let xa = uniform(0.0, 2.0, 2);
    let (a, _, mut x) = flat(&xa, &[], 0.0, 0.0);
    // sheet 1: y = 0.2 + 0.1 x; sheet 2: y = 0.38 - 0.2 x (both facing), joined on the right by
    // a back side beyond the search distance; |g1| = |g2| at x = 0.6, g2 < g1 beyond
    let pts = [
        [-1.0, 0.1],
        [3.0, 0.5],
        [3.0, 5.0],
        [-1.0, 5.0],
        [-1.0, 0.58],
        [3.0, -0.22],
    ];
    let b: Vec<usize> = pts
        .iter()
        .map(|p| {
            x.push(*p);
            x.len() - 1
        })
        .collect();
    let s = evaluate(&a, &b, &x, 1.0, UNIT).unwrap();
    let g = |v: f64| {
        if v < 0.6 {
            0.2 + 0.1 * v
        } else {
            0.38 - 0.2 * v
        }
    };
    // Simpson's rule is exact for the quadratic M_k g on each smooth piece
    let simpson = |f: &dyn Fn(f64) -> f64, l: f64, u: f64| {
        (u - l) / 6.0 * (f(l) + 4.0 * f(0.5 * (l + u)) + f(u))
    };
    let hats: [&dyn Fn(f64) -> f64; 3] = [
        &|v| (v - 1.0).max(0.0),    // node at x = 2 (first in A's order)
        &|v| 1.0 - (v - 1.0).abs(), // x = 1
        &|v| (1.0 - v).max(0.0),    // x = 0
    ];
    for (k, m) in hats.iter().enumerate() {
        let f = |v: f64| m(v) * g(v);
        let exact = simpson(&f, 0.0, 0.6) + simpson(&f, 0.6, 1.0) + simpson(&f, 1.0, 2.0);
        let nd = &s.nodes[k];
        assert!(
            close(nd.gap[1], -exact, EXACT),
            "node {k}: {} vs {}",
            nd.gap[1],
            -exact
        );
        assert!(close(nd.gap[0], 0.0, EXACT));
        // the row's B part still sums to the weight
        let (_, fb) = split(nd, &a);
        assert!(close(fb.values().sum::<f64>(), nd.weight, EXACT));
    }
}

// ------------------------------------------------------------------------------------------------
// Invariance
// ------------------------------------------------------------------------------------------------

/// A curved, non-matching pair with gaps and penetration (wavy A and B, partly covered ends).
fn wavy_pair(rng: &mut Rng) -> (Vec<usize>, Vec<usize>, Vec<[f64; 2]>) {
    let mut x = Vec::new();
    let mut a = Vec::new();
    for v in random_spacing(0.0, 1.0, 13, rng).iter().rev() {
        x.push([*v, 0.05 * (5.0 * v).sin()]);
        a.push(x.len() - 1);
    }
    let mut b = Vec::new();
    for v in random_spacing(0.04, 1.1, 17, rng) {
        x.push([v, 0.05 * (5.0 * v).sin() + 0.01 * (rng.next() - 0.4)]);
        b.push(x.len() - 1);
    }
    (a, b, x)
}

fn assert_same(
    s: &ContactSurface,
    t: &ContactSurface,
    rot: [[f64; 2]; 2],
    scale: f64,
    tol: f64,
    what: &str,
) {
    let r = |v: Vector| {
        [
            rot[0][0] * v[0] + rot[0][1] * v[1],
            rot[1][0] * v[0] + rot[1][1] * v[1],
        ]
    };
    for (p, q) in s.nodes.iter().zip(&t.nodes) {
        let tag = format!("{what}, node {}", p.node);
        assert_eq!(p.node, q.node);
        let (n, sv, g) = (r(p.frame.normal()), r(p.frame.tangent(0)), r(p.gap));
        for i in 0..2 {
            assert!(close(n[i], q.frame.normal()[i], tol), "{tag}: normal");
            assert!(close(sv[i], q.frame.tangent(0)[i], tol), "{tag}: tangent");
            assert!(
                close(scale * scale * g[i], q.gap[i], tol * scale * scale),
                "{tag}: R_C"
            );
        }
        assert!(close(scale * p.weight, q.weight, tol * scale), "{tag}");
        assert!(
            close(scale * p.covered_weight, q.covered_weight, tol * scale),
            "{tag}"
        );
        assert!(close(p.coverage, q.coverage, tol), "{tag}: coverage");
        if p.normal_gap.is_finite() {
            assert!(
                close(scale * p.normal_gap, q.normal_gap, tol * scale),
                "{tag}"
            );
            assert!(
                close(scale * p.mean_distance, q.mean_distance, tol * scale),
                "{tag}"
            );
        } else {
            assert_eq!(p.normal_gap, q.normal_gap);
        }
        let mut diff: BTreeMap<usize, f64> = BTreeMap::new();
        for &(j, c) in &p.coupling {
            *diff.entry(j).or_default() += scale * c;
        }
        for &(j, c) in &q.coupling {
            *diff.entry(j).or_default() -= c;
        }
        for (j, d) in diff {
            assert!(
                d.abs() <= tol * scale,
                "{tag}: coupling at {j} differs by {d}"
            );
        }
    }
}

/// Translation, rotation and scaling of both surfaces together: normals, tangents and R_C rotate,
/// lengths and couplings scale, nothing else changes (1e-12 of the natural scale).
#[test]
fn invariance_under_rigid_motion_and_scaling() {
    let mut rng = Rng(2024);
    for trial in 0..5 {
        let (a, b, x) = wavy_pair(&mut rng);
        let s = evaluate(&a, &b, &x, 0.2, UNIT).unwrap();
        assert!(
            s.nodes.iter().any(|n| n.normal_gap < 0.0),
            "some penetration"
        );
        assert!(s.nodes.iter().any(|n| n.normal_gap > 0.0), "some gap");
        assert!(
            s.nodes.iter().any(|n| n.coverage < 1.0),
            "a partly covered end"
        );
        let id = [[1.0, 0.0], [0.0, 1.0]];
        let moved: Vec<[f64; 2]> = x.iter().map(|p| [p[0] + 3.7, p[1] - 2.1]).collect();
        let t = evaluate(&a, &b, &moved, 0.2, UNIT).unwrap();
        assert_same(
            &s,
            &t,
            id,
            1.0,
            INVARIANT,
            &format!("trial {trial}, translation"),
        );
        let th = 0.3 + trial as f64;
        let (c, sn) = (th.cos(), th.sin());
        let rot = [[c, -sn], [sn, c]];
        let turned: Vec<[f64; 2]> = x
            .iter()
            .map(|p| [c * p[0] - sn * p[1] + 0.5, sn * p[0] + c * p[1] - 0.25])
            .collect();
        let t = evaluate(&a, &b, &turned, 0.2, UNIT).unwrap();
        assert_same(
            &s,
            &t,
            rot,
            1.0,
            INVARIANT,
            &format!("trial {trial}, rotation"),
        );
        let scaled: Vec<[f64; 2]> = x.iter().map(|p| [1e3 * p[0], 1e3 * p[1]]).collect();
        let t = evaluate(&a, &b, &scaled, 200.0, UNIT).unwrap();
        assert_same(
            &s,
            &t,
            id,
            1e3,
            INVARIANT,
            &format!("trial {trial}, scaling"),
        );
    }
}

// ------------------------------------------------------------------------------------------------
// Finite-difference check of the coupling
// ------------------------------------------------------------------------------------------------

/// A closed (zero-gap everywhere) pair on a curved B: B's nodes on a circle of radius 1 (B is
/// the disk, counter-clockwise); A (outside, clockwise) has a node at each B vertex it spans and
/// 0 to 2 extra nodes at random points of each B chord, so A lies on B and the meshes do not
/// match. Returns `(a, b, x, flat)`, `flat[k]` = whether A is straight across node k.
fn closed_circle_pair(rng: &mut Rng) -> (Vec<usize>, Vec<usize>, Vec<[f64; 2]>, Vec<bool>) {
    let nb = 8;
    let (t0, t1) = (PI / 4.0, 3.0 * PI / 4.0);
    let mut x = Vec::new();
    let b: Vec<usize> = (0..=nb)
        .map(|j| {
            let t = t0 + (t1 - t0) * j as f64 / nb as f64;
            x.push([t.cos(), t.sin()]);
            x.len() - 1
        })
        .collect();
    let bx = x.clone();
    // A spans B vertices 1..=nb-1, clockwise (decreasing angle)
    let mut a = Vec::new();
    let mut flat = Vec::new();
    for j in (1..nb).rev() {
        x.push(bx[j]);
        a.push(x.len() - 1);
        flat.push(false);
        if j > 1 {
            // 0, 1 or 2 extra nodes, at least a tenth of the chord apart
            let f: Vec<f64> = match (rng.next() * 3.0) as usize {
                0 => vec![],
                1 => vec![0.2 + 0.6 * rng.next()],
                _ => vec![0.15 + 0.3 * rng.next(), 0.55 + 0.3 * rng.next()],
            };
            for s in f {
                // from vertex j towards vertex j - 1
                let p = [
                    bx[j][0] + s * (bx[j - 1][0] - bx[j][0]),
                    bx[j][1] + s * (bx[j - 1][1] - bx[j][1]),
                ];
                x.push(p);
                a.push(x.len() - 1);
                flat.push(true);
            }
        }
    }
    (a, b, x, flat)
}

/// The normal row of the coupling is the first-order change of the weighted normal gap:
/// `(n_k . R_C,k(x + eps e_j,d) - n_k . R_C,k(x)) / eps -> n_k . (c_kj e_d)`.
///
/// At zero gap the geometric terms (change of length, of normal, of the hit point along B)
/// multiply the gap or move the hit point tangentially, so they vanish to first order; what is
/// left is O(eps) (curvature of the map) where A is straight across node k. At a kink of A of
/// angle theta the row misses a tangential term of relative size sin(theta / 2) (the pairing
/// follows tangential motion, the frozen-pairing coupling does not), so there the bound is
/// `sin(theta / 2) * |c| + O(eps)`.
///
/// Tolerance: `|FD - c| <= 2 * eps / h * |c|_max + 1e-9 * h` on straight rows (`h` = B's chord,
/// A's segments 0.1 h to h; eps = 1e-4 h, 1e-5 h, 1e-6 h; observed: 0.2 * eps / h * |c|_max),
/// and the largest error must shrink by at least 5x per factor 10 of eps until it reaches
/// round-off (observed: 10x). At kinks (theta = pi / 16 here) the observed mismatch is about
/// 1.8e-3 for every eps, within `sin(theta / 2) * |c|_max`, about 1e-2.
#[test]
fn coupling_matches_finite_differences_at_zero_gap() {
    let mut rng = Rng(31);
    for trial in 0..3 {
        let (a, b, x, flat) = closed_circle_pair(&mut rng);
        let base = evaluate(&a, &b, &x, 0.1, UNIT).unwrap();
        let h = 2.0 * (PI / 32.0).sin(); // B's chord; A's segments are 0.1 h to h
        assert!(base.all_covered());
        for nd in &base.nodes {
            assert!(nd.gap[0].abs() < 1e-15 && nd.gap[1].abs() < 1e-15, "closed");
        }
        let cmax = base
            .nodes
            .iter()
            .flat_map(|n| n.coupling.iter().map(|e| e.1.abs()))
            .fold(0.0, f64::max);
        let mut worst = Vec::new();
        for eps in [1e-4 * h, 1e-5 * h, 1e-6 * h] {
            let mut worst_flat: f64 = 0.0;
            for &j in a.iter().chain(&b[1..b.len() - 1]) {
                for dir in 0..2 {
                    let mut xp = x.clone();
                    xp[j][dir] += eps;
                    let pert = evaluate(&a, &b, &xp, 0.1, UNIT).unwrap();
                    for (k, (p, q)) in base.nodes.iter().zip(&pert.nodes).enumerate() {
                        let n = p.frame.normal();
                        let fd =
                            (n[0] * (q.gap[0] - p.gap[0]) + n[1] * (q.gap[1] - p.gap[1])) / eps;
                        let c = p
                            .coupling
                            .iter()
                            .find(|e| e.0 == j)
                            .map_or(0.0, |e| e.1 * n[dir]);
                        let err = (fd - c).abs();
                        if flat[k] {
                            worst_flat = worst_flat.max(err);
                            let tol = 2.0 * eps / h * cmax + 1e-9 * h;
                            assert!(err <= tol, "trial {trial} node {k} pert {j}/{dir}: {err}");
                        } else {
                            // kink: theta = angle between the adjacent segment normals
                            let kink = if k == 0 || k + 1 == a.len() {
                                0.0
                            } else {
                                let d1 = [x[a[k]][0] - x[a[k - 1]][0], x[a[k]][1] - x[a[k - 1]][1]];
                                let d2 = [x[a[k + 1]][0] - x[a[k]][0], x[a[k + 1]][1] - x[a[k]][1]];
                                let cross = d1[0] * d2[1] - d1[1] * d2[0];
                                let dotp = d1[0] * d2[0] + d1[1] * d2[1];
                                cross.atan2(dotp).abs()
                            };
                            let tol = (0.5 * kink).sin() * cmax + 2.0 * eps / h * cmax + 1e-9 * h;
                            assert!(
                                err <= tol,
                                "trial {trial} kink node {k} pert {j}/{dir}: {err} > {tol}"
                            );
                        }
                    }
                }
            }
            worst.push(worst_flat);
        }
        for w in worst.windows(2) {
            assert!(
                w[1] <= w[0] / 5.0 || w[1] <= 1e-8 * h,
                "trial {trial}: FD error does not shrink with eps: {worst:?}"
            );
        }
    }
}

// ------------------------------------------------------------------------------------------------
// The surface measure (plane thickness, axisymmetric 2 pi r)
// ------------------------------------------------------------------------------------------------

/// Plane, thickness `t`: every integral (weights, covered weights, `R_C`, coupling) is `t` times
/// the unit-thickness one, to round-off (one product); frames, coverage and the gaps as lengths
/// do not change. Random non-matching, tilted surfaces.
#[test]
fn plane_thickness_scales_every_integral() {
    let mut rng = Rng(5);
    for trial in 0..6 {
        let xa = random_spacing(0.0, 1.0, 5 + trial, &mut rng);
        let xb = random_spacing(-0.1, 1.05, 3 + 2 * trial, &mut rng);
        let (a, b, x) = flat(&xa, &xb, 0.02 * (rng.next() - 0.3), 0.03 * rng.next());
        let t = 0.1 + 4.0 * rng.next();
        let one = evaluate(&a, &b, &x, 1.0, UNIT).unwrap();
        let thick = evaluate(&a, &b, &x, 1.0, SurfaceMeasure::Plane { thickness: t }).unwrap();
        let same = |u: f64, v: f64| (u - v).abs() <= 4.0 * f64::EPSILON * u.abs().max(v.abs());
        for (p, q) in one.nodes.iter().zip(&thick.nodes) {
            assert!(same(t * p.weight, q.weight) && same(t * p.covered_weight, q.covered_weight));
            assert!(same(t * p.gap[0], q.gap[0]) && same(t * p.gap[1], q.gap[1]));
            assert_eq!(p.coupling.len(), q.coupling.len());
            for (u, v) in p.coupling.iter().zip(&q.coupling) {
                assert!(u.0 == v.0 && same(t * u.1, v.1), "trial {trial}");
            }
            assert_eq!(
                (p.frame.normal(), p.frame.tangent(0), p.coverage),
                (q.frame.normal(), q.frame.tangent(0), q.coverage)
            );
            assert!(same(p.normal_gap, q.normal_gap) && same(p.mean_distance, q.mean_distance));
        }
    }
}

/// Axisymmetric: `dS = 2 pi r ds`. A flat meridian `z = 0` from the axis to `r = R` (A below,
/// `n = +z`, random spacing, its first node in r on the axis) against a non-matching, tilted
/// B above (`z = g0 + slope r`, B's nodes at random r):
/// * the weights sum to the disk's area `pi R^2`; a node on the axis has the weight
///   `integral_0^h (1 - (r/h)^2) 2 pi r dr = pi h^2 / 2 > 0` (the zero-slope shapes of the
///   segment ending on the axis, `1 - (r/h)^2` and `(r/h)^2`) and its segment's normal;
/// * every `F^A`, `F^B` and `R_C` entry equals its integral (`M_k` linear in r, quadratic on
///   the axis segment, `L^B_j`, `g` linear, times `2 pi r`: at most quintics, integrated here
///   by 3-point Gauss split at A's and B's nodes, exact);
/// * row sums: `sum_j F^A_kj = weight_k`, `sum_j F^B_kj = covered weight_k`;
/// * a constant gap is reproduced: `normal_gap = mean_distance = g0`.
#[test]
fn axisymmetric_integrals_are_exact() {
    let mut rng = Rng(17);
    let big_r = 2.0;
    for trial in 0..6 {
        let xa = random_spacing(0.0, big_r, 4 + trial, &mut rng);
        let xb = random_spacing(0.0, 1.1 * big_r, 3 + 2 * trial, &mut rng);
        let slope = if trial % 2 == 0 { 0.0 } else { 0.01 };
        let g0 = 0.01;
        let (a, b, x) = flat(&xa, &xb, g0, slope);
        let s = evaluate(&a, &b, &x, 1.0, SurfaceMeasure::Axisymmetric).unwrap();
        let area = PI * big_r * big_r;
        let total: f64 = s.nodes.iter().map(|n| n.weight).sum();
        assert!(
            close(total, area, EXACT * area),
            "trial {trial}: {total} vs {area}"
        );
        // A is listed right to left: the last node is on the axis
        let axis = s.nodes.last().unwrap();
        let h = xa[1];
        assert_eq!(x[axis.node][0], 0.0);
        assert!(close(axis.weight, PI * h * h / 2.0, EXACT * area));
        assert_eq!(axis.frame.normal(), [0.0, 1.0].into());
        let g = |r: f64| g0 + slope * r;
        let hat = |nodes: &[f64], j: usize, r: f64| -> f64 {
            let left = j > 0 && r >= nodes[j - 1] && r <= nodes[j];
            let right = j + 1 < nodes.len() && r >= nodes[j] && r <= nodes[j + 1];
            if left {
                (r - nodes[j - 1]) / (nodes[j] - nodes[j - 1])
            } else if right {
                (nodes[j + 1] - r) / (nodes[j + 1] - nodes[j])
            } else {
                0.0
            }
        };
        // the multiplier's shapes: the hats, quadratic on the axis segment [0, h]
        let shape = |k: usize, r: f64| -> f64 {
            match k {
                0 if r <= h => 1.0 - (r / h).powi(2),
                1 if r <= h => (r / h).powi(2),
                _ => hat(&xa, k, r),
            }
        };
        // integral over [0, R] of f(r) 2 pi r dr, split at A's and B's nodes
        let mut cuts: Vec<f64> = xa
            .iter()
            .chain(&xb)
            .copied()
            .filter(|&r| r <= big_r)
            .collect();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let gauss3 = [
            (0.5 - 0.5 * 0.6f64.sqrt(), 5.0 / 18.0),
            (0.5, 8.0 / 18.0),
            (0.5 + 0.5 * 0.6f64.sqrt(), 5.0 / 18.0),
        ];
        let integral = |f: &dyn Fn(f64) -> f64| -> f64 {
            cuts.windows(2)
                .flat_map(|w| {
                    gauss3.map(|(u, wt)| {
                        let r = w[0] + u * (w[1] - w[0]);
                        wt * (w[1] - w[0]) * f(r) * 2.0 * PI * r
                    })
                })
                .sum()
        };
        for node in &s.nodes {
            // A's node index in xa (ascending r)
            let ka = xa.iter().position(|&r| r == x[node.node][0]).unwrap();
            let mk = |r: f64| shape(ka, r);
            let scale = area;
            assert!(close(node.weight, integral(&mk), EXACT * scale));
            assert!(node.is_covered());
            let gap_y = -integral(&|r| mk(r) * g(r));
            assert!(close(node.gap[1], gap_y, EXACT * scale), "trial {trial}");
            assert_eq!(node.gap[0], 0.0);
            let (fa, fb) = split(node, &a);
            for (&j, &v) in &fa {
                let ja = xa.iter().position(|&r| r == x[j][0]).unwrap();
                let exact = integral(&|r| mk(r) * hat(&xa, ja, r));
                assert!(close(v, exact, EXACT * scale), "F^A trial {trial}");
            }
            for (&j, &v) in &fb {
                let jb = xb.iter().position(|&r| r == x[j][0]).unwrap();
                let exact = integral(&|r| mk(r) * hat(&xb, jb, r));
                assert!(close(v, exact, EXACT * scale), "F^B trial {trial}");
            }
            let (sa, sb) = (fa.values().sum::<f64>(), fb.values().sum::<f64>());
            assert!(
                close(sa, node.weight, EXACT * scale)
                    && close(sb, node.covered_weight, EXACT * scale)
            );
            if slope == 0.0 {
                assert!(close(node.normal_gap, g0, EXACT) && close(node.mean_distance, g0, EXACT));
            }
        }
    }
}

/// Axisymmetric, a curved meridian (a quarter of the unit circle from the pole on the axis to
/// the equator, random angles): the weights sum to the area of the polyline's surface of
/// revolution, `sum_e pi (r_e0 + r_e1) h_e` (frustums), and each nodal normal is the direction
/// of `sum_e w_ke n_e` (`w_ke = integral_e M_k dS`), so a constant offset `g` of B along A's
/// segment normals gives `R_C,k` parallel to `n_k`.
#[test]
fn axisymmetric_curved_meridian() {
    let mut rng = Rng(23);
    for trial in 0..4 {
        let n = 6 + 3 * trial;
        let angles = random_spacing(0.0, 0.5 * PI, n, &mut rng);
        // the sphere's surface, body inside: counter-clockwise about the centre means from the
        // equator (r = 1, z = 0) up to the pole (r = 0, z = 1): body on the left
        let mut x: Vec<[f64; 2]> = angles.iter().rev().map(|&t| [t.sin(), t.cos()]).collect();
        x[n][0] = 0.0; // the pole exactly on the axis
        let a: Vec<usize> = (0..=n).collect();
        // B: the same polyline moved outward by g along each node's circle radius, reversed
        let g = 1e-3;
        let b: Vec<usize> = (0..=n).rev().map(|k| k + n + 1).collect();
        let outer: Vec<[f64; 2]> = x
            .iter()
            .map(|p| [p[0] * (1.0 + g), p[1] * (1.0 + g)])
            .collect();
        x.extend(outer);
        let s = evaluate(&a, &b, &x, 0.1, SurfaceMeasure::Axisymmetric).unwrap();
        let frustums: f64 = a
            .windows(2)
            .map(|w| {
                let (p, q) = (x[w[0]], x[w[1]]);
                PI * (p[0] + q[0]) * (q[0] - p[0]).hypot(q[1] - p[1])
            })
            .sum();
        let total: f64 = s.nodes.iter().map(|n| n.weight).sum();
        assert!(close(total, frustums, EXACT * frustums), "trial {trial}");
        assert!((total / (2.0 * PI) - 1.0).abs() < 0.05); // about a hemisphere's 2 pi
        for node in &s.nodes {
            let cross = node.frame.normal()[0] * node.gap[1] - node.frame.normal()[1] * node.gap[0];
            let along =
                -(node.frame.normal()[0] * node.gap[0] + node.frame.normal()[1] * node.gap[1]);
            assert!(
                along > 0.0 && cross.abs() < 1e-2 * along,
                "trial {trial}: {node:?}"
            );
        }
        let pole = s.nodes.last().unwrap();
        assert!(
            pole.weight > 0.0 && pole.frame.normal()[1] > 0.9,
            "{pole:?}"
        );
    }
}

/// Axisymmetric coupling rows are the first-order change of the weighted normal gap at zero
/// gap (the measure's own change multiplies the gap): a straight meridian away from the axis,
/// non-matching B on it, every A and B node perturbed in r and z. Tolerance as in
/// `coupling_matches_finite_differences_at_zero_gap` (straight rows), relative to the largest
/// coupling entry.
#[test]
fn axisymmetric_coupling_matches_finite_differences() {
    let mut rng = Rng(41);
    let xa = random_spacing(1.0, 2.0, 7, &mut rng);
    let xb = random_spacing(0.9, 2.1, 5, &mut rng);
    let (a, b, x) = flat(&xa, &xb, 0.0, 0.0);
    let m = SurfaceMeasure::Axisymmetric;
    let base = evaluate(&a, &b, &x, 0.1, m).unwrap();
    let cmax = base
        .nodes
        .iter()
        .flat_map(|n| n.coupling.iter().map(|e| e.1.abs()))
        .fold(0.0, f64::max);
    let h = 1.0 / 7.0;
    for eps in [1e-5 * h, 1e-6 * h] {
        for &j in a.iter().chain(&b[1..b.len() - 1]) {
            for dir in 0..2 {
                let mut xp = x.clone();
                xp[j][dir] += eps;
                let pert = evaluate(&a, &b, &xp, 0.1, m).unwrap();
                for (p, q) in base.nodes.iter().zip(&pert.nodes) {
                    let n = p.frame.normal();
                    let fd = (n[0] * (q.gap[0] - p.gap[0]) + n[1] * (q.gap[1] - p.gap[1])) / eps;
                    let c = p
                        .coupling
                        .iter()
                        .find(|e| e.0 == j)
                        .map_or(0.0, |e| e.1 * n[dir]);
                    let tol = 2.0 * eps / h * cmax + 1e-9 * cmax;
                    assert!(
                        (fd - c).abs() <= tol,
                        "node {} pert {j}/{dir}: {fd} vs {c}",
                        p.node
                    );
                }
            }
        }
    }
}

/// The measure's input checks: a plane thickness that is not finite and positive, an A node at
/// `r < 0` in axisymmetry.
#[test]
fn measure_input_checks() {
    let (a, b, x) = flat(&[0.0, 1.0], &[0.0, 1.0], 0.01, 0.0);
    for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let m = message(evaluate(
            &a,
            &b,
            &x,
            1.0,
            SurfaceMeasure::Plane { thickness: t },
        ));
        assert!(m.contains("thickness"), "{m}");
    }
    let (a, b, x) = flat(&[-0.5, 1.0], &[-0.5, 1.0], 0.01, 0.0);
    let m = message(evaluate(&a, &b, &x, 1.0, SurfaceMeasure::Axisymmetric));
    assert!(m.contains("r = -0.5 < 0"), "{m}");
}

/// Both surfaces ending on the axis, A's axis segment tilted by `±2e-4` (as a finite
/// deformation leaves it): B's axis node projects a sliver of `gap * tilt / h` (4e-6 of the
/// segment) away from A's, and B's end covers it, so every A node is fully covered (0.7.0
/// left the sliver uncovered, and an active axis node failed the increment). A radius of
/// round-off below zero (a free axis node's drift) is on the axis; one beyond round-off of
/// the segments' length is rejected.
#[test]
fn surfaces_ending_on_the_axis_cover_each_other() {
    for tilt in [-1e-4, 1e-4] {
        for r0 in [0.0, -1.9e-20] {
            // A below, right to left (n = +z), its last node on the axis; B above
            let x = vec![[1.0, 0.0], [0.5, 0.0], [r0, tilt], [0.0, 0.01], [1.0, 0.01]];
            let s = evaluate(&[0, 1, 2], &[3, 4], &x, 1.0, SurfaceMeasure::Axisymmetric).unwrap();
            for node in &s.nodes {
                assert!(node.is_covered(), "tilt {tilt}, r0 {r0}: {node:?}");
            }
        }
    }
    let x = vec![
        [1.0, 0.0],
        [0.5, 0.0],
        [-1e-9, 0.0],
        [0.0, 0.01],
        [1.0, 0.01],
    ];
    let m = message(evaluate(
        &[0, 1, 2],
        &[3, 4],
        &x,
        1.0,
        SurfaceMeasure::Axisymmetric,
    ));
    assert!(m.contains("node 2 has r = -0.000000001 < 0"), "{m}");
}

// ------------------------------------------------------------------------------------------------
// Input checks
// ------------------------------------------------------------------------------------------------

fn message(r: Result<ContactSurface, Error>) -> String {
    match r {
        Err(Error::InvalidInput(m)) => m,
        other => panic!("expected InvalidInput, got {other:?}"),
    }
}

#[test]
fn invalid_input_names_the_node() {
    let (a, b, x) = flat(&[0.0, 1.0, 2.0], &[0.0, 1.0, 2.0], 0.1, 0.0);
    // a = [0, 1, 2] (x = 2, 1, 0), b = [3, 4, 5]
    let m = message(evaluate(&a[..1], &b, &x, 1.0, UNIT));
    assert!(m.contains("A") && m.contains("at least 2"), "{m}");
    let m = message(evaluate(&a, &[3, 17], &x, 1.0, UNIT));
    assert!(m.contains("node 17") && m.contains("out of range"), "{m}");
    let m = message(evaluate(&[0, 1, 1, 2], &b, &x, 1.0, UNIT));
    assert!(m.contains("node 1") && m.contains("consecutively"), "{m}");
    let m = message(evaluate(&[0, 1, 2, 0], &b, &x, 1.0, UNIT));
    assert!(m.contains("node 0") && m.contains("twice"), "{m}");
    let m = message(evaluate(&a, &[3, 4, 5, 4], &x, 1.0, UNIT));
    assert!(
        m.contains("B") && m.contains("node 4") && m.contains("twice"),
        "{m}"
    );
    let m = message(evaluate(&a, &[3, 2, 5], &x, 1.0, UNIT));
    assert!(m.contains("node 2") && m.contains("both"), "{m}");
    // zero-length segment: a node placed on top of its neighbour
    let mut y = x.clone();
    y[1] = y[0];
    let m = message(evaluate(&a, &b, &y, 1.0, UNIT));
    assert!(
        m.contains("nodes 0 and 1") && m.contains("zero-length"),
        "{m}"
    );
    // A folding back onto itself: node 2 placed where node 0 is (different ids)
    let mut y = x.clone();
    y[2] = y[0];
    let m = message(evaluate(&a, &b, &y, 1.0, UNIT));
    assert!(m.contains("node 1") && m.contains("folds back"), "{m}");
    // non-finite coordinates, anywhere on A or B; never a panic
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for node in [0, 1, 4] {
            for c in 0..2 {
                let mut y = x.clone();
                y[node][c] = bad;
                let m = message(evaluate(&a, &b, &y, 1.0, UNIT));
                assert!(
                    m.contains(&format!("node {node}")) && m.contains("non-finite"),
                    "{m}"
                );
            }
        }
    }
    // a non-finite coordinate of a node outside the pair is none of its business
    let mut y = x.clone();
    y.push([f64::NAN, 0.0]);
    assert!(evaluate(&a, &b, &y, 1.0, UNIT).is_ok());
    for d in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let m = message(evaluate(&a, &b, &x, d, UNIT));
        assert!(m.contains("search distance"), "{m}");
    }
}

// ------------------------------------------------------------------------------------------------
// Reuse and scale
// ------------------------------------------------------------------------------------------------

/// evaluate_into reuses a surface from another pair and gives the same result as evaluate.
#[test]
fn evaluate_into_reuses_buffers() {
    let mut rng = Rng(5);
    let (a, b, x) = wavy_pair(&mut rng);
    let fresh = evaluate(&a, &b, &x, 0.2, UNIT).unwrap();
    let (a2, b2, x2) = flat(&[0.0, 0.5, 1.0], &[0.0, 1.0], 0.0, 0.0);
    let mut reused = evaluate(&a2, &b2, &x2, 1.0, UNIT).unwrap();
    evaluate_into(&a, &b, &x, 0.2, UNIT, &mut reused).unwrap();
    assert_eq!(fresh.nodes, reused.nodes);
}

/// 2000 A segments against 3000 B segments on a circle (a disk in a conforming hole, slightly
/// penetrating): runs in near-linear time (reported, not asserted) and is fully covered.
#[test]
fn large_surfaces_evaluate_fast() {
    let (na, nb) = (2000, 3000);
    let mut x = Vec::new();
    // B: disk of radius 1, counter-clockwise, arc from 0.05 to 2 pi - 0.05
    let (t0, t1) = (0.05, 2.0 * PI - 0.05);
    let b: Vec<usize> = (0..=nb)
        .map(|j| {
            let t = t0 + (t1 - t0) * j as f64 / nb as f64;
            x.push([t.cos(), t.sin()]);
            x.len() - 1
        })
        .collect();
    // A: the hole's boundary, radius 1 - 1e-4, clockwise, inside B's arc
    let (s0, s1) = (0.1, 2.0 * PI - 0.1);
    let a: Vec<usize> = (0..=na)
        .map(|j| {
            let t = s1 - (s1 - s0) * j as f64 / na as f64;
            x.push([(1.0 - 1e-4) * t.cos(), (1.0 - 1e-4) * t.sin()]);
            x.len() - 1
        })
        .collect();
    let h = (s1 - s0) / na as f64;
    let start = std::time::Instant::now();
    let s = evaluate(&a, &b, &x, 3.0 * h, UNIT).unwrap();
    let elapsed = start.elapsed();
    eprintln!("evaluate, {na} + {nb} segments: {elapsed:?}");
    assert!(s.all_covered());
    let total: f64 = s.nodes.iter().map(|n| n.weight).sum();
    let arc = 2.0 * (1.0 - 1e-4) * (0.5 * (s1 - s0) / na as f64).sin() * na as f64;
    assert!(close(total, arc, 1e-12));
    for nd in &s.nodes {
        // gap to the coarser chord polygon of B: within the sagittas of both polygons
        assert!((nd.normal_gap + 1e-4).abs() < 1e-5, "{}", nd.normal_gap);
    }
}
