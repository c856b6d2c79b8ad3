//! The 3D contact geometry on the validation meshes: the nodal frames of the cap's contact
//! surface with its symmetry planes, and the mortar integrals of the cap against the block
//! (coverage, the initial weighted gap against the paraboloid's height); and the pair geometry
//! behind the contact core's seam, `FaceGeometry` (flat patches, the quarter cap, rigid-motion
//! invariance, the orientation checks, bad input).

use hycon::contact::faces::{SurfaceFaces, SurfaceFrames, SurfaceMortar};
use hycon::solid::contact_meshes::ContactMesh;
use hycon::solid::contact_meshes::{CapModel, CapOnBlock};
use std::collections::{BTreeMap, BTreeSet};

/// A's nodes inside A (not on its free edge): 4 faces, 2 on a symmetry plane, 1 on two.
fn inside(c: &ContactMesh) -> BTreeSet<usize> {
    let mut faces = BTreeMap::<usize, usize>::new();
    for f in &c.a_faces {
        for &k in f {
            *faces.entry(k).or_default() += 1;
        }
    }
    faces
        .into_iter()
        .filter(|(k, n)| n << c.symmetry.iter().filter(|(_, s)| s.contains(k)).count() == 4)
        .map(|(k, _)| k)
        .collect()
}

#[test]
fn the_quarter_caps_frames_drop_the_symmetry_components() {
    for a_over_h in [4, 8] {
        let spec = CapOnBlock::new(CapModel::Quarter, a_over_h);
        let c = spec.build().unwrap();
        let planes: Vec<_> = c.symmetry.iter().map(|(p, _)| *p).collect();
        let a = SurfaceFaces {
            x: &c.mesh.nodes,
            faces: &c.a_faces,
        };
        let frames = SurfaceFrames::new(a, None, &planes).unwrap();
        let on: Vec<BTreeSet<usize>> = c
            .symmetry
            .iter()
            .map(|(_, nodes)| nodes.iter().copied().collect())
            .collect();
        let inner = inside(&c);
        let (mut worst, mut worst_edge): (f64, f64) = (0.0, 0.0);
        for (k, f) in &frames.frames {
            let count = on.iter().filter(|s| s.contains(k)).count();
            let dropped = f.dropped.iter().filter(|&&d| d).count();
            assert_eq!(dropped, count, "node {k}");
            // the paraboloid's outward (downward) normal (x, y, -1) / sqrt(1 + r^2), R = 1
            let [x, y, _] = c.mesh.nodes[*k];
            let exact = [x, y, -1.0].map(|v| v / (1.0 + x * x + y * y).sqrt());
            let err = (0..3)
                .map(|i| (f.normal[i] - exact[i]).powi(2))
                .sum::<f64>()
                .sqrt();
            if inner.contains(k) {
                worst = worst.max(err);
            } else {
                worst_edge = worst_edge.max(err);
            }
            if count > 0 {
                // on a plane, the normal lies in it: exactly, by the projection
                for (plane, nodes) in &c.symmetry {
                    if nodes.contains(k) {
                        let m = plane.normal;
                        let along: f64 = (0..3).map(|i| f.normal[i] * m[i]).sum();
                        assert!(along.abs() < 1e-15, "node {k}");
                    }
                }
            }
        }
        // inside, exact: on a uniform grid the average of the faces' normals of a quadratic
        // surface is the exact normal; on A's free edge the normal is one-sided (first order)
        eprintln!(
            "a/h = {a_over_h}: worst nodal normal error {worst:.2e} inside, {worst_edge:.2e} \
             on the free edge, h = {:.3e}",
            c.h
        );
        assert!(worst <= 1e-14, "{worst}");
        assert!(worst_edge <= c.h, "{worst_edge}");
    }
}

#[test]
fn the_cap_is_covered_by_the_block_and_its_gap_is_the_paraboloid() {
    let spec = CapOnBlock::new(CapModel::Half, 8);
    let c = spec.build().unwrap();
    let a = SurfaceFaces {
        x: &c.mesh.nodes,
        faces: &c.a_faces,
    };
    let b = SurfaceFaces {
        x: &c.mesh.nodes,
        faces: &c.b_faces,
    };
    let m = SurfaceMortar::new(a, b, 0.1 * spec.contact_radius()).unwrap();
    let nodes: Vec<usize> = m.weight.keys().copied().collect();
    m.require_covered(&nodes).unwrap();
    // the weighted gap over the weight: the hat-weighted mean over the node's support of the
    // faces' height, the bilinear interpolant of f: on the uniform grid each direction adds
    // h^2 / 6 to x^2 (the mean of x^2) and h^2 / 6 more (the interpolant's excess over x^2),
    // f(x_k) + h^2 / 3 in all, inside A (on its free edge the support is one-sided); the
    // projection along each face's tilted normal is the rest
    let mut worst: f64 = 0.0;
    for &k in &inside(&c) {
        let [x, y, _] = c.mesh.nodes[k];
        let g = m.mismatch[&k][2] / m.weight[&k];
        let expect = spec.height(x, y) + c.h * c.h / 3.0;
        worst = worst.max((g - expect).abs() / expect);
    }
    eprintln!("weighted gap / weight against f + h^2/3: worst relative error {worst:.2e}");
    assert!(worst < 1e-3, "{worst}");
}

// ---------------------------------------------------------------------------------------------
// The pair geometry behind the contact core's seam: `FaceGeometry`.

mod face_geometry {
    use super::inside;
    use hycon::contact::faces::{FaceGeometry, SymmetryPlane};
    use hycon::contact::geometry::{ContactGeometry, ContactSurface};
    use hycon::contact::space::Vector;
    use hycon::solid::contact_meshes::{CapModel, CapOnBlock};
    use hycon::solid::geometry::FACES;
    use hycon::solid::mesh::SolidMesh;
    use nalgebra::{Rotation3, Vector3};

    /// Two bodies' contact faces and all positions, flat.
    struct Pair {
        x: Vec<f64>,
        a: Vec<[usize; 4]>,
        b: Vec<[usize; 4]>,
        /// The number of A's body's nodes (B's ids follow).
        a_nodes: usize,
    }

    /// A: the top `z = 1` of the block `[0, 1]^2 x [0, 1]` of `na x na x 1` bricks; B: the
    /// bottom of a one-layer block of `nb x nb` bricks over `[0, 1]^2` mapped by `place`,
    /// at `z = 1 + g`.
    fn blocks(na: usize, nb: usize, g: f64, place: impl Fn([f64; 2]) -> [f64; 2]) -> Pair {
        let a = SolidMesh::uniform([1.0, 1.0, 1.0], [na, na, 1]);
        let b = SolidMesh::uniform([1.0, 1.0, 1.0], [nb, nb, 1]).map(|p| {
            let q = place([p[0], p[1]]);
            [q[0], q[1], p[2] + 1.0 + g]
        });
        let faces = |m: &SolidMesh, z: f64, offset: usize| -> Vec<[usize; 4]> {
            m.faces_where(|p| (p[2] - z).abs() < 1e-12)
                .into_iter()
                .map(|(e, f)| FACES[f].map(|k| m.elements[e][k] + offset))
                .collect()
        };
        let n = a.n_nodes();
        Pair {
            x: a.nodes.iter().chain(&b.nodes).flatten().copied().collect(),
            a: faces(&a, 1.0, 0),
            b: faces(&b, 1.0 + g, n),
            a_nodes: n,
        }
    }

    /// B 1.6 times A's size (so that it covers A), turned by `deg` about the vertical through
    /// A's centre and offset by `shift` (in B faces of size `1.6 / nb`) in both directions.
    fn placed(deg: f64, shift: f64, nb: usize) -> impl Fn([f64; 2]) -> [f64; 2] {
        move |p| {
            let (sn, cs) = deg.to_radians().sin_cos();
            let d = shift * 1.6 / nb as f64;
            let (u, v) = (1.6 * (p[0] - 0.5) + d, 1.6 * (p[1] - 0.5) + d);
            [0.5 + cs * u - sn * v, 0.5 + sn * u + cs * v]
        }
    }

    fn geometry(p: &Pair) -> FaceGeometry {
        FaceGeometry::new(p.a.clone(), p.b.clone(), &p.x, None, &[]).unwrap()
    }

    /// `u` at every node of B (ids from `p.a_nodes`), zero at A's.
    fn move_b(p: &Pair, u: [f64; 3]) -> Vec<f64> {
        (0..p.x.len() / 3)
            .flat_map(|i| if i >= p.a_nodes { u } else { [0.0; 3] })
            .collect()
    }

    fn add(x: &[f64], du: &[f64]) -> Vec<f64> {
        x.iter().zip(du).map(|(a, b)| a + b).collect()
    }

    /// Flat conforming or non-conforming faces at the uniform gap `g`: every A node fully
    /// covered with `normal_gap = mean_distance = g` and `R_k` along `n_k`; the patch-test
    /// condition `sum_j c_kj = 0`; a translation `t n` of B changes `n . sum_j c_kj du_j` by
    /// `-t covered_weight` (the normal gap by `t`), as re-evaluating at the moved positions
    /// does. Returns the worst relative errors seen (gap, patch test).
    fn check_flat(what: &str, p: &Pair, g: f64) -> (f64, f64) {
        let geo = geometry(p);
        let s = geo.evaluate(&p.x, 0.1).unwrap();
        assert_eq!(s.nodes.len(), geo.a_nodes().len());
        assert!(s.all_covered(), "{what}");
        let t = 0.3 * g;
        let du = move_b(p, [0.0, 0.0, t]);
        let moved = geo.evaluate(&add(&p.x, &du), 0.1).unwrap();
        let (mut worst_gap, mut worst_patch): (f64, f64) = (0.0, 0.0);
        for (nd, after) in s.nodes.iter().zip(&moved.nodes) {
            let n = nd.frame.normal();
            let up = Vector::solid(0.0, 0.0, 1.0);
            assert!((n - up).norm() <= 1e-15, "{what}: node {}: {n:?}", nd.node);
            assert_eq!(nd.coverage, 1.0);
            let err = [
                nd.normal_gap - g,
                nd.mean_distance - g,
                after.normal_gap - (g + t),
            ]
            .map(f64::abs)
            .into_iter()
            .fold(0.0, f64::max)
                / g;
            worst_gap = worst_gap.max(err);
            // R_k parallel to n_k
            let along = nd.gap.add_scaled(-n.dot(&nd.gap), &n);
            assert!(
                along.norm() <= 1e-12 * nd.gap.norm(),
                "{what}: node {}",
                nd.node
            );
            // the coupling row times B's translation: the normal gap changes by t
            let dn = -n.dot(&nd.coupling_times(&du)) / nd.covered_weight;
            worst_gap = worst_gap.max((dn - t).abs() / t);
            let sum: f64 = nd.coupling.iter().map(|(_, c)| c).sum();
            worst_patch = worst_patch.max(sum.abs() / nd.weight);
            assert!(nd.coupling.windows(2).all(|w| w[0].0 < w[1].0), "sorted");
            assert!(nd.coupling.iter().all(|&(_, c)| c != 0.0));
        }
        eprintln!(
            "{what}: worst gap error {worst_gap:.1e}, worst |sum_j c_kj| / w {worst_patch:.1e}"
        );
        assert!(worst_gap <= 1e-12, "{what}: {worst_gap}");
        assert!(worst_patch <= 1e-12, "{what}: {worst_patch}");
        (worst_gap, worst_patch)
    }

    #[test]
    fn a_conforming_patch_has_the_uniform_gap() {
        let g = 0.01;
        let p = blocks(4, 4, g, |q| q);
        check_flat("conforming", &p, g);
        // the whole weight is A's area, and the frames are the reference direction's
        let geo = geometry(&p);
        let s = geo.evaluate(&p.x, 0.1).unwrap();
        let area: f64 = s.nodes.iter().map(|n| n.weight).sum();
        assert!((area - 1.0).abs() < 1e-14, "{area}");
        assert_eq!(geo.mean_size(&p.x), 0.25);
        for nd in &s.nodes {
            assert!(!nd.frame.is_dropped(0) && !nd.frame.is_dropped(1));
        }
    }

    #[test]
    fn offset_and_turned_patches_pass_the_patch_test() {
        let g = 0.01;
        for (na, nb) in [(4, 5), (6, 3)] {
            check_flat(
                "offset a third",
                &blocks(na, nb, g, placed(0.0, 1.0 / 3.0, nb)),
                g,
            );
            for deg in [15.0, 45.0] {
                let what = format!("turned {deg}");
                check_flat(&what, &blocks(na, nb, g, placed(deg, 0.0, nb)), g);
            }
        }
    }

    /// B's nodes over open A faces lie at the gap; the pair faces and its orientation checks
    /// see B in front, A's body below A.
    #[test]
    fn orientation_checks_and_b_node_distances() {
        let g = 0.01;
        let p = blocks(4, 5, g, placed(15.0, 1.0 / 3.0, 5));
        let mut geo = geometry(&p);
        let f = geo.facing(&p.x, 0.1);
        assert_eq!((f.touching, f.facing, f.same_way, f.behind), (25, 0, 0, 0));
        let far = blocks(4, 5, 0.2, placed(15.0, 1.0 / 3.0, 5));
        assert_eq!(geometry(&far).facing(&far.x, 1.0).facing, 25);
        geo.check_inside(&p.x, &Vector::solid(0.5, 0.5, 0.5))
            .unwrap();
        let err = geo
            .check_inside(&p.x, &Vector::solid(0.5, 0.5, 1.5))
            .unwrap_err();
        assert!(err.to_string().contains("outward side"), "{err}");
        let err = geo
            .check_inside(&p.x, &Vector::solid(2.0, 0.5, 0.5))
            .unwrap_err();
        assert!(err.to_string().contains("free edge"), "{err}");
        // B is the bottom of its block: its outward normal points down, at every node
        for i in 0..geo.b_nodes().len() {
            let n = geo.b_node_normal(i, &p.x);
            assert!(
                (n[2] + 1.0).abs() <= 1e-14 && n[0].hypot(n[1]) <= 1e-14,
                "{n:?}"
            );
        }
        let open = vec![true; geo.a_nodes().len()];
        let all = geo.b_node_distances(&open, &p.x, &p.x);
        geo.freeze_b_nodes(&p.x);
        assert_eq!(geo.b_node_distances(&open, &p.x, &p.x), all);
        // B's nodes over A's interior: each inside exactly one face
        assert!(all.len() >= 9, "{}", all.len());
        for d in &all {
            assert!((d.distance - g).abs() <= 1e-12 * g, "{d:?}");
        }
        // an A node pushed 0.5 up through B is behind it
        let k = geo.a_nodes().len() / 2;
        let mut x = p.x.clone();
        x[3 * geo.a_nodes()[k] + 2] += 0.5;
        let (_, depth) = geo.behind(k, &x, 0.1).unwrap();
        assert!((depth - (0.5 - g)).abs() < 1e-12, "{depth}");
        assert_eq!(geo.behind(k, &p.x, 0.0), None);
    }

    /// B tilted to `z = 1 + g + alpha (x + 2 y)`: at an A node whose neighbours are all
    /// inside A the hat-weighted gaps are the plane's values, and the slope is
    /// `alpha sqrt(5)`; a B node moved by 1 makes its faces (of size 0.32 in `x, y`)
    /// unresolvable at a round-off of 0.5, not at 0.1.
    #[test]
    fn gap_slope_and_unresolved_faces() {
        let (g, alpha) = (0.01, 0.02);
        let mut p = blocks(6, 5, g, placed(0.0, 0.0, 5));
        for i in p.a_nodes..p.x.len() / 3 {
            p.x[3 * i + 2] += alpha * (p.x[3 * i] + 2.0 * p.x[3 * i + 1]);
        }
        let geo = geometry(&p);
        let s = geo.evaluate(&p.x, 0.2).unwrap();
        let k = (0..s.nodes.len())
            .find(|&k| {
                let i = 3 * s.nodes[k].node;
                (p.x[i] - 0.5).abs() < 1e-12 && (p.x[i + 1] - 0.5).abs() < 1e-12
            })
            .unwrap();
        let slope = geo.gap_slope(&s, k, &p.x);
        let exact = alpha * 5f64.sqrt();
        eprintln!("gap slope {slope} against {exact}");
        assert!((slope - exact).abs() <= 1e-12 * exact, "{slope}");
        let j = p.a_nodes + 7;
        let mut x = p.x.clone();
        x[3 * j + 2] += 1.0;
        let u = geo.unresolved(&x, &p.x, 0.5).unwrap();
        assert_eq!((u.node, u.motion), (j, 1.0));
        // its face's shortest edge, along x on the tilted plane
        let edge = 0.32 * (1.0 + alpha * alpha).sqrt();
        assert!((u.length - edge).abs() < 1e-12, "{u:?}");
        assert_eq!(geo.unresolved(&x, &p.x, 0.1), None);
    }

    #[test]
    fn the_quarter_caps_nodes_carry_their_symmetry() {
        let spec = CapOnBlock::new(CapModel::Quarter, 4);
        let c = spec.build().unwrap();
        let planes: Vec<SymmetryPlane> = c.symmetry.iter().map(|(p, _)| *p).collect();
        let x: Vec<f64> = c.mesh.nodes.iter().flatten().copied().collect();
        let geo =
            FaceGeometry::new(c.a_faces.clone(), c.b_faces.clone(), &x, None, &planes).unwrap();
        let s = geo.evaluate(&x, 0.1 * spec.contact_radius()).unwrap();
        assert!(s.all_covered());
        let inner = inside(&c);
        let mut worst: f64 = 0.0;
        for (k, nd) in s.nodes.iter().enumerate() {
            let on = c
                .symmetry
                .iter()
                .filter(|(_, nodes)| nodes.contains(&nd.node))
                .count();
            let dropped = (0..2).filter(|&i| nd.frame.is_dropped(i)).count();
            assert_eq!(dropped, on, "node {}", nd.node);
            assert_eq!(geo.frictionless_at(k, &x), on == 2, "node {}", nd.node);
            for (plane, nodes) in &c.symmetry {
                if nodes.contains(&nd.node) {
                    // the kept tangent and the normal lie in the plane
                    let m = Vector::from(plane.normal);
                    assert!(nd.frame.normal().dot(&m).abs() < 1e-15);
                    for s in nd.frame.tangents() {
                        assert!(s.dot(&m).abs() < 1e-15);
                    }
                    // a traction along the plane's normal has no component left
                    assert!(
                        nd.frame
                            .tangential(&m)
                            .components()
                            .iter()
                            .all(|&t| t.abs() < 1e-15)
                    );
                }
            }
            if inner.contains(&nd.node) {
                let [px, py, _] = c.mesh.nodes[nd.node];
                let exact =
                    Vector::solid(px, py, -1.0).scaled(1.0 / (1.0 + px * px + py * py).sqrt());
                worst = worst.max((nd.frame.normal() - exact).norm());
            }
        }
        // the cap's body lies above its curved contact surface, the block below it
        let a = spec.contact_radius();
        let (h, d) = (c.h, 2.0 * c.h);
        geo.check_inside(&x, &Vector::solid(d, d, a)).unwrap();
        let err = geo.check_inside(&x, &Vector::solid(d, d, -a)).unwrap_err();
        assert!(err.to_string().contains("outward side"), "{err}");
        // A touches B at the centre: within half a face of it there, facing it farther out
        let f = geo.facing(&x, a);
        assert_eq!((f.same_way, f.behind), (0, 0));
        assert!(
            f.touching > 0 && f.touching + f.facing == s.nodes.len(),
            "{f:?}, h = {h}"
        );
        eprintln!("quarter cap a/h = 4: worst nodal normal error inside A {worst:.1e}");
        assert!(worst <= 1e-14, "{worst}");
        assert_eq!(
            (0..s.nodes.len())
                .filter(|&k| geo.frictionless_at(k, &x))
                .count(),
            1,
            "the corner on both planes"
        );
    }

    /// Rotate and translate `x` (flat) rigidly.
    fn moved(x: &[f64], q: &Rotation3<f64>, shift: Vector3<f64>) -> Vec<f64> {
        x.chunks(3)
            .flat_map(|p| {
                let v = q * Vector3::new(p[0], p[1], p[2]) + shift;
                [v[0], v[1], v[2]]
            })
            .collect()
    }

    fn turn(q: &Rotation3<f64>, v: &Vector) -> Vector {
        let r = q * Vector3::new(v[0], v[1], v[2]);
        Vector::solid(r[0], r[1], r[2])
    }

    /// The half cap on its block (curved A, one symmetry plane) and a turned flat patch: a
    /// rigid motion of everything (with the reference direction and the symmetry plane) turns
    /// the normals, tangents and gaps and leaves the weights, gaps and coupling rows.
    #[test]
    fn a_rigid_motion_turns_frames_and_gaps_and_leaves_the_rest() {
        let q = Rotation3::from_axis_angle(
            &nalgebra::Unit::new_normalize(Vector3::new(1.0, 2.0, 3.0)),
            0.7,
        );
        let shift = Vector3::new(0.3, -1.2, 2.5);
        let r = [1.0, 0.2, 0.1];
        let rq = turn(&q, &Vector::from(r));
        let spec = CapOnBlock::new(CapModel::Half, 4);
        let c = spec.build().unwrap();
        let cap = Pair {
            x: c.mesh.nodes.iter().flatten().copied().collect(),
            a: c.a_faces.clone(),
            b: c.b_faces.clone(),
            a_nodes: c.a_nodes,
        };
        let plane = c.symmetry[0].0;
        let pq = turn(&q, &Vector::from(plane.point));
        let plane_q = SymmetryPlane::new(
            [pq[0] + shift[0], pq[1] + shift[1], pq[2] + shift[2]],
            turn(&q, &Vector::from(plane.normal))
                .components()
                .try_into()
                .unwrap(),
        )
        .unwrap();
        let patch = blocks(4, 5, 0.01, placed(15.0, 1.0 / 3.0, 5));
        // reaches covering each pair's gaps (pairing is by bounding boxes, which turn with the
        // pair: see `FaceGeometry::evaluate_into`)
        for (what, p, planes, planes_q, reach) in [
            (
                "half cap",
                &cap,
                vec![plane],
                vec![plane_q],
                spec.contact_radius(),
            ),
            ("turned patch", &patch, vec![], vec![], 0.1),
        ] {
            let y = moved(&p.x, &q, shift);
            let geo = FaceGeometry::new(p.a.clone(), p.b.clone(), &p.x, Some(r), &planes).unwrap();
            let geo_q = FaceGeometry::new(
                p.a.clone(),
                p.b.clone(),
                &y,
                Some(rq.components().try_into().unwrap()),
                &planes_q,
            )
            .unwrap();
            let (s, sq): (ContactSurface, ContactSurface) = (
                geo.evaluate(&p.x, reach).unwrap(),
                geo_q.evaluate(&y, reach).unwrap(),
            );
            // the scales: the largest gap and weighted gap of the pair
            let gap = s
                .nodes
                .iter()
                .map(|n| n.normal_gap.abs())
                .fold(0.0, f64::max);
            let r = s.nodes.iter().map(|n| n.gap.norm()).fold(0.0, f64::max);
            let mut worst: f64 = 0.0;
            for (u, v) in s.nodes.iter().zip(&sq.nodes) {
                assert_eq!(u.node, v.node);
                let w = u.weight;
                let mut errs = vec![
                    (turn(&q, &u.frame.normal()) - v.frame.normal()).norm(),
                    (turn(&q, &u.gap) - v.gap).norm() / r,
                    (u.weight - v.weight).abs() / w,
                    (u.covered_weight - v.covered_weight).abs() / w,
                    (u.coverage - v.coverage).abs(),
                    (u.normal_gap - v.normal_gap).abs() / gap,
                    (u.mean_distance - v.mean_distance).abs() / gap,
                ];
                for i in 0..2 {
                    assert_eq!(u.frame.is_dropped(i), v.frame.is_dropped(i));
                    errs.push((turn(&q, &u.frame.tangent(i)) - v.frame.tangent(i)).norm());
                }
                assert_eq!(
                    u.coupling.len(),
                    v.coupling.len(),
                    "{what}: node {}",
                    u.node
                );
                for (a, b) in u.coupling.iter().zip(&v.coupling) {
                    assert_eq!(a.0, b.0);
                    errs.push((a.1 - b.1).abs() / w);
                }
                let e = errs.into_iter().fold(0.0, f64::max);
                assert!(e <= 1e-12, "{what}: node {}: {e}", u.node);
                worst = worst.max(e);
            }
            eprintln!(
                "{what}: worst relative change under the rigid motion {worst:.1e} (largest \
                 gap {gap:.3e})"
            );
        }
    }

    #[test]
    fn bad_faces_are_named() {
        let p = blocks(2, 2, 0.01, |q| q);
        let n = p.x.len() / 3;
        let new = |a: Vec<[usize; 4]>, b: Vec<[usize; 4]>, x: &[f64]| {
            FaceGeometry::new(a, b, x, None, &[])
                .unwrap_err()
                .to_string()
        };
        let mut a = p.a.clone();
        a[1][2] = n + 7;
        let err = new(a, p.b.clone(), &p.x);
        assert!(
            err.contains(&format!("A face 1 uses node {}", n + 7)),
            "{err}"
        );
        let mut b = p.b.clone();
        b[3][0] = n;
        let err = new(p.a.clone(), b, &p.x);
        assert!(err.contains(&format!("B face 3 uses node {n}")), "{err}");
        // a face with a corner collapsed onto its neighbour
        let mut x = p.x.clone();
        let [k0, k1, ..] = p.a[0];
        for c in 0..3 {
            x[3 * k1 + c] = x[3 * k0 + c];
        }
        let err = new(p.a.clone(), p.b.clone(), &x);
        assert!(err.contains("A face 0: corners 0 and 1 coincide"), "{err}");
        let mut b = p.b.clone();
        b[0][1] = p.a[3][2];
        let err = new(p.a.clone(), b, &p.x);
        assert!(
            err.contains(&format!("node {} belongs to both sides", p.a[3][2]))
                && err.contains("B face 0"),
            "{err}"
        );
        let err = new(p.a.clone(), p.b.clone(), &p.x[1..]);
        assert!(err.contains("3 values per node"), "{err}");
        let err = new(vec![], p.b.clone(), &p.x);
        assert!(err.contains("side A has no face"), "{err}");
    }
}

// ---------------------------------------------------------------------------------------------
// The 3D contact analysis of the brick model: `ContactAnalysis::solid`.

mod solid_analysis {
    use hycon::contact::faces::SymmetryPlane;
    use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeState};
    use hycon::error::{ContactError, Error};
    use hycon::solid::contact_meshes::{BlockOnFlat, ContactMesh};
    use hycon::solid::geometry::FACES;
    use hycon::solid::model::SolidModel;
    use hycon::solid::{BrickFormulation, Isotropic};

    /// A unit cube of 2 x 2 bricks (A, its bottom) on a unit cube of 3 x 3 bricks (B, its
    /// top): non-conforming faces, the same footprint.
    fn stack() -> ContactMesh {
        BlockOnFlat {
            size: [1.0; 3],
            cells: [2, 2, 1],
            flat: [1.0; 3],
            flat_cells: [3, 3, 1],
            angle: 0.0,
        }
        .build()
        .unwrap()
    }

    /// The stack's model (`E = 1`, `nu = 0.3`): the flat's bottom held along `z`, the block's
    /// top prescribed along `z`; each body held in its plane by a corner (`x`, `y`) and the
    /// next corner along `x` (`y`), which the lateral expansion about the first leaves at
    /// rest.
    fn model(c: &ContactMesh) -> SolidModel {
        let m = Isotropic::new(1.0, 0.3).unwrap();
        let mut model =
            SolidModel::new(c.mesh.clone(), vec![m, m], BrickFormulation::Hybrid18).unwrap();
        for (nodes, z) in [(&c.a_top, 1.0), (&c.b_bottom, -1.0)] {
            for &n in nodes {
                model.fix(n, 2, 0.0);
            }
            let at = |x: f64, y: f64| {
                *(nodes.iter())
                    .find(|&&n| c.mesh.nodes[n] == [x, y, z])
                    .unwrap()
            };
            model.fix(at(-0.5, -0.5), 0, 0.0);
            model.fix(at(-0.5, -0.5), 1, 0.0);
            model.fix(at(0.5, -0.5), 1, 0.0);
        }
        model
    }

    fn pair(c: &ContactMesh, friction: f64) -> FacePair {
        FacePair {
            a: c.a_faces.clone(),
            b: c.b_faces.clone(),
            friction,
        }
    }

    /// The contact patch test through the whole analysis: the stack pressed by `d` is in
    /// uniaxial stress `p = E d / 2` (two unit heights of `E = 1`), which the bricks and the
    /// mortar integrals of non-conforming faces represent exactly, so every A node's multiplier
    /// is `-p` to round-off, frictionless and with friction (the lateral expansions of the two
    /// bodies match: no shear).
    #[test]
    fn a_pressed_stack_passes_the_contact_patch_test() {
        let c = stack();
        for friction in [0.0, 0.3] {
            let mut analysis = ContactAnalysis::solid(
                model(&c),
                vec![pair(&c, friction)],
                &[],
                ContactOptions::default(),
            )
            .unwrap();
            let n = 3 * c.mesh.n_nodes();
            let d = 1e-3;
            let mut qp = vec![0.0; n];
            for &k in &c.a_top {
                qp[3 * k + 2] = -d;
            }
            analysis.increment(&vec![0.0; n], &qp).unwrap();
            let nodes = analysis.node_results(0).unwrap();
            assert_eq!(nodes.len(), 9);
            let p = d / 2.0;
            for r in &nodes {
                let expected = if friction == 0.0 {
                    NodeState::Frictionless
                } else {
                    NodeState::Stick
                };
                assert_eq!(r.state, expected, "{r:?}");
                assert!((r.tn + p).abs() < 1e-9 * p, "{r:?}");
                assert!(r.ts.norm() < 1e-9 * p, "{r:?}");
            }
            let load: f64 = nodes.iter().map(|r| r.force.components()[2]).sum();
            assert!((load - p).abs() < 1e-9 * p, "{load} vs {p}");
            // the constraint rows, 3 per A node (normal, s1, s2), times the recovered field:
            // every normal gap closed (the stack touched at the start)
            let rows = analysis.constraint_rows(0).unwrap();
            assert_eq!(rows.row_ptr.len(), 3 * nodes.len() + 1);
            let q = analysis.displacement().unwrap();
            for (k, r) in nodes.iter().enumerate() {
                let row = rows.row_ptr[3 * k]..rows.row_ptr[3 * k + 1];
                let closing: f64 = row.map(|i| rows.values[i] * q[rows.columns[i]]).sum();
                assert!(closing.abs() < 1e-12 * d * r.weight, "{closing} {r:?}");
            }
        }
    }

    /// A B node deeper than the search distance under an open A face fails the increment,
    /// naming the node and the face's 4 nodes: the stack with the block's bottom lifted by
    /// `g0 = 0.04`
    /// and B's top node at `(1/6, 1/6)` raised by `0.12`, `0.08` into A's face over
    /// `[0, 0.5]^2`, beyond the reach `0.1` mean A faces `= 0.05` (no load moves anything).
    /// The bump raises B under A's nearest node `(0, 0)` by a quarter of it, `0.03`, which
    /// leaves that node `0.01` open: every node of the face is open.
    #[test]
    fn a_b_node_beyond_the_search_distance_names_the_face() {
        let mut c = stack();
        let (g0, bump) = (0.04, 0.12);
        for x in c.mesh.nodes[..c.a_nodes].iter_mut().filter(|x| x[2] == 0.0) {
            x[2] = g0;
        }
        let b_top = |x: f64, y: f64| {
            let at = |n: usize| {
                let p = c.mesh.nodes[n];
                (p[0] - x).abs() < 1e-12 && (p[1] - y).abs() < 1e-12 && p[2] == 0.0
            };
            (c.a_nodes..c.mesh.n_nodes()).find(|&n| at(n)).unwrap()
        };
        let raised = b_top(1.0 / 6.0, 1.0 / 6.0);
        c.mesh.nodes[raised][2] = bump;
        let under = |f: &[usize; 4]| {
            f.iter().all(|&n| {
                let p = c.mesh.nodes[n];
                p[0] >= 0.0 && p[1] >= 0.0
            })
        };
        let face = *c.a_faces.iter().find(|f| under(f)).unwrap();
        let options = ContactOptions {
            search_distance: 0.1,
            ..ContactOptions::default()
        };
        let mut analysis =
            ContactAnalysis::solid(model(&c), vec![pair(&c, 0.0)], &[], options).unwrap();
        let n = 3 * c.mesh.n_nodes();
        let e = analysis
            .increment(&vec![0.0; n], &vec![0.0; n])
            .unwrap_err();
        let message = e.to_string();
        let Error::Contact(ContactError::BeyondSearchDistance {
            node,
            element,
            depth,
            search_distance,
        }) = e
        else {
            panic!("{message}");
        };
        assert_eq!(node, raised, "{message}");
        let mut named = element.clone();
        named.sort_unstable();
        let mut expected = face.to_vec();
        expected.sort_unstable();
        assert_eq!(named, expected, "{message}");
        assert!((depth - (bump - g0)).abs() < 1e-12, "{message}");
        assert!((search_distance - 0.05).abs() < 1e-12, "{message}");
        let ids: Vec<String> = element.iter().map(usize::to_string).collect();
        let face = format!("face ({})", ids.join(", "));
        assert!(message.contains(&face), "{message}");
        assert!(analysis.records().is_empty());
    }

    /// The constructor's checks, each named: friction, an empty side, a node out of range, a
    /// face listed clockwise, an interior face, a face listed twice, a side in two pieces, a
    /// non-finite position, a bad symmetry plane.
    #[test]
    fn bad_pairs_are_named() {
        let c = stack();
        let refused = |model: SolidModel, p: FacePair, symmetry: &[SymmetryPlane]| {
            ContactAnalysis::solid(model, vec![p], symmetry, ContactOptions::default())
                .unwrap_err()
                .to_string()
        };
        let bad = |p: FacePair, what: &str| {
            let e = refused(model(&c), p, &[]);
            assert!(e.contains("contact pair 0") && e.contains(what), "{e}");
        };
        bad(pair(&c, -0.1), "friction");
        bad(
            FacePair {
                a: Vec::new(),
                ..pair(&c, 0.0)
            },
            "side A has no face",
        );
        let n = c.mesh.n_nodes();
        let mut p = pair(&c, 0.0);
        p.b[2][1] = n + 3;
        let face = p.b[2];
        bad(
            p,
            &format!(
                "B face 2 {face:?}: node {} is not a node of the model ({n} nodes)",
                n + 3
            ),
        );
        let mut p = pair(&c, 0.0);
        p.a[1].reverse();
        let face = p.a[1];
        bad(p, &format!("A face 1 {face:?}: listed clockwise"));
        // the face between the block's first two bricks
        let [e0, e1] = [c.mesh.elements[0], c.mesh.elements[1]];
        let shared = (FACES.iter())
            .map(|f| f.map(|k| e0[k]))
            .find(|f| f.iter().all(|k| e1.contains(k)))
            .unwrap();
        let mut p = pair(&c, 0.0);
        p.a.push(shared);
        bad(p, "an interior face");
        let mut p = pair(&c, 0.0);
        p.a.push(p.a[0]);
        bad(p, "listed twice");
        // a side face of the block at its bottom edge shares two nodes with A, and none with
        // B's faces: B is no longer one surface (A and B sharing a node is refused by
        // `FaceGeometry::new` too: `face_geometry::bad_faces_are_named`)
        let side = (FACES.iter())
            .map(|f| f.map(|k| e0[k]))
            .find(|f| f.iter().all(|&k| c.mesh.nodes[k][0] == -0.5))
            .unwrap();
        let mut p = pair(&c, 0.0);
        p.b.push(side);
        bad(p, "contact side B is not one connected surface");
        let mut m = model(&c);
        m.mesh.nodes[c.a_faces[0][0]][2] = f64::NAN;
        let e = refused(m, pair(&c, 0.0), &[]);
        assert!(e.contains("non-finite position"), "{e}");
        let plane = SymmetryPlane {
            point: [0.0; 3],
            normal: [f64::NAN, 0.0, 0.0],
        };
        let e = refused(model(&c), pair(&c, 0.0), &[plane]);
        assert!(e.contains("contact pair 0"), "{e}");
    }
}
