//! Mesh generators: geometry, counts, sets, conformity of the graded transition meshes, quality.
//!
//! Tolerances: coordinates and areas that are exact in real arithmetic are compared to 1e-12
//! relative (round-off of a few operations); geometric predicates (collinearity, midpoints) to
//! 1e-12 of the element size.

use hycon::element::{self, Formulation};
use hycon::mesh::Mesh;
use hycon::mesh::generate::{self, Grading, Target, Transition};
use hycon::mesh::quality::{self, QualityReport};
use std::collections::{HashMap, HashSet};
use std::f64::consts::PI;

const TOL: f64 = 1e-12;

fn coords(mesh: &Mesh, e: usize) -> Vec<[f64; 2]> {
    mesh.element(e).iter().map(|&n| mesh.nodes[n]).collect()
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

fn shoelace(poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    0.5 * (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum::<f64>()
}

/// Sine of the turn at node `i` of a polygon and whether the turn is forward (dot > 0).
fn turn(c: &[[f64; 2]], i: usize) -> (f64, bool) {
    let n = c.len();
    let (p, q, r) = (c[(i + n - 1) % n], c[i], c[(i + 1) % n]);
    let (a, b) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
    let sine = (a[0] * b[1] - a[1] * b[0]) / (dist(p, q) * dist(q, r));
    (sine, a[0] * b[0] + a[1] * b[1] > 0.0)
}

/// Indices of the true corners of an element (mid-side nodes have a zero turn).
fn corners(c: &[[f64; 2]]) -> Vec<usize> {
    (0..c.len())
        .filter(|&i| turn(c, i).0.abs() > 1e-9)
        .collect()
}

/// Longest corner-to-corner side: the element size.
fn size(c: &[[f64; 2]]) -> f64 {
    let k = corners(c);
    (0..k.len())
        .map(|i| dist(c[k[i]], c[k[(i + 1) % k.len()]]))
        .fold(0.0, f64::max)
}

/// Every element: 4 to 6 nodes, counter-clockwise, strictly convex at its 4 corners, each
/// mid-side node alone between two corners, collinear with them and at their midpoint.
fn check_elements(mesh: &Mesh) {
    mesh.validate().expect("valid mesh");
    for e in 0..mesh.n_elements() {
        let c = coords(mesh, e);
        let n = c.len();
        assert!((4..=6).contains(&n), "element {e}: {n} nodes");
        let h = size(&c);
        assert!(
            shoelace(&c) > 0.0,
            "element {e} is not counter-clockwise: {c:?}"
        );
        let k = corners(&c);
        assert_eq!(k.len(), 4, "element {e} must have 4 corners: {c:?}");
        for i in 0..n {
            let (sine, forward) = turn(&c, i);
            if k.contains(&i) {
                assert!(
                    sine > 1e-6,
                    "element {e} is not strictly convex at node {i}: {c:?}"
                );
            } else {
                assert!(forward && k.contains(&((i + 1) % n)) && k.contains(&((i + n - 1) % n)));
                let (a, b) = (c[(i + n - 1) % n], c[(i + 1) % n]);
                let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                assert!(
                    dist(mid, c[i]) <= TOL * h,
                    "element {e}: node {i} off its edge's midpoint"
                );
            }
        }
    }
}

/// Every directed segment between consecutive element nodes appears once, and is matched by
/// its reverse in exactly one other element or is a boundary edge of one of `boundary` sets
/// (and every boundary edge is such a segment). With at most one mid-side node per side, this
/// is the hybrid conformity. Also checks the 2:1 balance: the sides (corner to corner)
/// containing a shared segment have lengths in ratio 1 or 2.
fn check_conformity(mesh: &Mesh, boundary: &[&str]) {
    let mut owner: HashMap<[usize; 2], (usize, f64)> = HashMap::new();
    for e in 0..mesh.n_elements() {
        let nodes = mesh.element(e);
        let c = coords(mesh, e);
        let k = corners(&c);
        let n = nodes.len();
        for (s, &i) in k.iter().enumerate() {
            let j = k[(s + 1) % 4];
            let side = dist(c[i], c[j]);
            let mut a = i;
            while a != j {
                let b = (a + 1) % n;
                let seg = [nodes[a], nodes[b]];
                assert!(
                    owner.insert(seg, (e, side)).is_none(),
                    "segment {seg:?} used twice"
                );
                a = b;
            }
        }
    }
    let on_boundary: HashSet<[usize; 2]> = boundary
        .iter()
        .flat_map(|name| mesh.edge_sets[*name].iter().copied())
        .collect();
    let mut n_boundary = 0;
    for (&[a, b], &(e, side)) in &owner {
        match owner.get(&[b, a]) {
            Some(&(f, other)) => {
                assert_ne!(e, f);
                assert!(
                    !on_boundary.contains(&[a, b]),
                    "interior segment {a}-{b} in a boundary set"
                );
                let ratio = side.max(other) / side.min(other);
                assert!(
                    (ratio - 1.0).abs() < 1e-9 || (ratio - 2.0).abs() < 1e-9,
                    "elements {e} and {f}: side ratio {ratio} breaks 2:1 balance"
                );
            }
            None => {
                assert!(
                    on_boundary.contains(&[a, b]),
                    "unmatched segment {a}-{b} of element {e}"
                );
                n_boundary += 1;
            }
        }
    }
    assert_eq!(
        n_boundary,
        on_boundary.len(),
        "boundary sets list edges that are no segment"
    );
}

/// Edge set `name` is one chain (each edge starts where the previous ends), and node set
/// `name` lists its nodes in the same order.
fn check_chain(mesh: &Mesh, name: &str) {
    let edges = &mesh.edge_sets[name];
    for w in edges.windows(2) {
        assert_eq!(w[0][1], w[1][0], "edge set {name} is not chained");
    }
    let mut nodes: Vec<usize> = edges.iter().map(|e| e[0]).collect();
    nodes.push(edges.last().unwrap()[1]);
    assert_eq!(
        mesh.node_sets[name], nodes,
        "node set {name} out of edge order"
    );
}

fn check_hybrid_shapes(mesh: &Mesh) {
    for e in 0..mesh.n_elements() {
        let c = coords(mesh, e);
        element::check_shape(Formulation::Hybrid, &c)
            .unwrap_or_else(|err| panic!("element {e} rejected: {err} {c:?}"));
    }
}

fn area_sum(mesh: &Mesh) -> f64 {
    (0..mesh.n_elements())
        .map(|e| shoelace(&coords(mesh, e)))
        .sum()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Elements containing point `p` (inside or on the boundary).
fn elements_at(mesh: &Mesh, p: [f64; 2]) -> Vec<usize> {
    (0..mesh.n_elements())
        .filter(|&e| {
            let c = coords(mesh, e);
            let h = size(&c);
            (0..c.len()).all(|i| {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= -1e-12 * h * h
            })
        })
        .collect()
}

fn max_size(mesh: &Mesh) -> f64 {
    (0..mesh.n_elements())
        .map(|e| size(&coords(mesh, e)))
        .fold(0.0, f64::max)
}

// ---------------------------------------------------------------------------------------------
// Cook's membrane and the beam

#[test]
fn cook_geometry_counts_sets() {
    for n in [1, 2, 4, 7, 16] {
        let mesh = generate::cooks_membrane(n);
        check_elements(&mesh);
        check_conformity(&mesh, &["left", "right", "top", "bottom"]);
        assert_eq!(
            (mesh.n_nodes(), mesh.n_elements()),
            ((n + 1) * (n + 1), n * n)
        );
        assert!(mesh.element_material.iter().all(|&m| m == 0));
        // exact area of the quadrilateral (0,0), (48,44), (48,60), (0,44)
        let exact = shoelace(&[[0.0, 0.0], [48.0, 44.0], [48.0, 60.0], [0.0, 44.0]]);
        assert_eq!(exact, 1440.0);
        assert!(rel(area_sum(&mesh), exact) < TOL);
        let clamped = &mesh.node_sets["clamped"];
        assert_eq!(clamped.len(), n + 1);
        assert!(clamped.iter().all(|&i| mesh.nodes[i][0] == 0.0));
        let loaded = &mesh.edge_sets["loaded"];
        assert_eq!(loaded.len(), n);
        check_chain(&mesh, "right");
        for &[a, b] in loaded {
            let (pa, pb) = (mesh.nodes[a], mesh.nodes[b]);
            assert!((pa[0] - 48.0).abs() < TOL * 48.0 && (pb[0] - 48.0).abs() < TOL * 48.0);
            assert!(pb[1] > pa[1], "loaded edges run bottom to top");
        }
        assert_eq!(mesh.nodes[loaded[0][0]], [48.0, 44.0]);
        let top = mesh.nodes[loaded[n - 1][1]];
        assert!(dist(top, [48.0, 60.0]) < TOL * 60.0);
        for corner in [[0.0, 0.0], [0.0, 44.0]] {
            assert!(mesh.nodes.iter().any(|&p| dist(p, corner) < TOL * 60.0));
        }
        let tip = &mesh.node_sets["tip"];
        if n % 2 == 0 {
            assert_eq!(tip.len(), 1);
            assert!(dist(mesh.nodes[tip[0]], [48.0, 52.0]) < TOL * 52.0);
        } else {
            assert!(tip.is_empty());
        }
    }
}

#[test]
fn beam_counts_area_distortion() {
    let (l, h) = (10.0, 2.0);
    for (nx, ny, d) in [(5, 2, 0.0), (5, 2, 0.5), (8, 4, 0.3), (1, 2, 0.7)] {
        let mesh = generate::beam(l, h, nx, ny, d);
        check_elements(&mesh);
        check_conformity(&mesh, &["left", "right", "top", "bottom"]);
        assert_eq!(
            (mesh.n_nodes(), mesh.n_elements()),
            ((nx + 1) * (ny + 1), nx * ny)
        );
        assert!(rel(area_sum(&mesh), l * h) < TOL);
        for side in ["left", "right", "top", "bottom"] {
            check_chain(&mesh, side);
        }
        assert_eq!(mesh.node_sets["left"].len(), ny + 1);
        assert!(
            mesh.node_sets["left"]
                .iter()
                .all(|&i| mesh.nodes[i][0] == 0.0)
        );
        assert!(
            mesh.node_sets["right"]
                .iter()
                .all(|&i| (mesh.nodes[i][0] - l).abs() < TOL * l)
        );
        // left runs downward, right upward (body on the left)
        let first = |s: &str| mesh.nodes[mesh.edge_sets[s][0][0]];
        assert_eq!(first("left"), [0.0, 1.0]);
        assert_eq!(first("right"), [l, -1.0]);
        // the documented distortion: x = i L / nx + d (2 y / h) on interior lines
        for &p in &mesh.nodes {
            let i = (p[0] / (l / nx as f64)).round();
            let on_end = i == 0.0 || i == nx as f64;
            let shift = if on_end { 0.0 } else { d * 2.0 * p[1] / h };
            assert!(
                (p[0] - (i * l / nx as f64 + shift)).abs() < TOL * l,
                "node {p:?}"
            );
            let j = (p[1] + h / 2.0) / (h / ny as f64);
            assert!((j - j.round()).abs() < 1e-12);
        }
        if d > 0.0 && nx > 1 {
            assert!(
                mesh.nodes
                    .iter()
                    .any(|p| dist(*p, [l / nx as f64 + d, 1.0]) < TOL * l)
            );
            assert!(
                mesh.nodes
                    .iter()
                    .any(|p| dist(*p, [l / nx as f64 - d, -1.0]) < TOL * l)
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Graded block

/// Block [-1, 7] x [0, 4], 4 x 2 root cells of size 2, minimum size 2 / 64.
fn block(target: Target) -> Mesh {
    let g = Grading {
        target,
        min_size: 2.0 / 64.0,
        layers: 3,
    };
    generate::graded_rectangle(-1.0, 0.0, 8.0, 4.0, 4, 2, &g)
}

/// `six`: whether 6-node elements are expected (they appear where the refined region has a
/// concave corner, e.g. along an oblique line, not around an isolated point).
fn check_block(mesh: &Mesh, points_on_target: &[[f64; 2]], six: bool) -> QualityReport {
    check_elements(mesh);
    let sides = ["left", "right", "top", "bottom"];
    check_conformity(mesh, &sides);
    for s in sides {
        check_chain(mesh, s);
    }
    assert!(rel(area_sum(mesh), 32.0) < TOL);
    let min = 2.0 / 64.0;
    for &p in points_on_target {
        let near = elements_at(mesh, p);
        assert!(!near.is_empty());
        for e in near {
            assert!(
                rel(size(&coords(mesh, e)), min) < TOL,
                "element {e} at the target"
            );
        }
    }
    // grows with distance: the coarsest elements are at least 16 times the minimum
    println!("largest element {}", max_size(mesh));
    assert!(max_size(mesh) >= 16.0 * min * (1.0 - TOL));
    let q = quality::quality(mesh);
    assert!(
        q.n_by_node_count[1] > 0 && (q.n_by_node_count[2] > 0) == six,
        "{q}"
    );
    // square cells: all corner angles are 90 degrees, aspect 1
    assert!(
        (q.min_angle_deg - 90.0).abs() < 1e-9 && (q.max_angle_deg - 90.0).abs() < 1e-9,
        "{q}"
    );
    assert!((q.max_aspect - 1.0).abs() < 1e-9, "{q}");
    assert!(rel(q.total_area, 32.0) < TOL);
    // sets: sides in order along the boundary, body on the left
    let left = &mesh.edge_sets["left"];
    assert_eq!(mesh.nodes[left[0][0]], [-1.0, 4.0]);
    assert_eq!(mesh.nodes[left.last().unwrap()[1]], [-1.0, 0.0]);
    let bottom = &mesh.node_sets["bottom"];
    assert!(
        bottom
            .windows(2)
            .all(|w| mesh.nodes[w[1]][0] > mesh.nodes[w[0]][0])
    );
    q
}

#[test]
fn graded_block_toward_point() {
    let p = [2.25, 1.5];
    let mesh = block(Target::Point(p));
    let q = check_block(&mesh, &[p], false);
    println!("block toward a point: {q}, {} nodes", mesh.n_nodes());
    assert_eq!(mesh, block(Target::Point(p)), "deterministic");
    // the target is a node
    assert!(mesh.nodes.contains(&p));
}

#[test]
fn graded_block_toward_line() {
    let (a, b) = ([0.3, 0.7], [5.1, 3.3]);
    let mesh = block(Target::Line(a, b));
    let samples: Vec<[f64; 2]> = (0..=50)
        .map(|k| {
            let t = k as f64 / 50.0;
            [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
        })
        .collect();
    let q = check_block(&mesh, &samples, true);
    println!("block toward a line: {q}, {} nodes", mesh.n_nodes());
    assert_eq!(mesh, block(Target::Line(a, b)));
}

#[test]
fn graded_mapped_uses_the_map() {
    // a sheared parallelogram: affine, so elements stay exact parallelograms
    let g = Grading::toward_point([0.0, 0.0], 0.125, 2);
    let mesh = generate::graded_mapped(2, 2, |[u, v]| [2.0 * u + v, 2.0 * v], &[g]);
    check_elements(&mesh);
    check_conformity(&mesh, &["left", "right", "top", "bottom"]);
    assert!(rel(area_sum(&mesh), 4.0) < TOL);
    let q = quality::quality(&mesh);
    assert!(q.n_by_node_count[1] > 0, "{q}");
    // cell edges map to lengths 2 du and sqrt(5) dv; roots have du = dv = 1/2; the first
    // sqrt(5) / 2^(k+1) not above 0.125 is k = 4
    for e in elements_at(&mesh, [0.0, 0.0]) {
        assert!(rel(size(&coords(&mesh, e)), 5f64.sqrt() / 32.0) < TOL);
    }
}

// ---------------------------------------------------------------------------------------------
// Half disk

fn check_half_disk(
    mesh: &Mesh,
    r: f64,
    min_size: f64,
    target: &[[f64; 2]],
    six: Option<bool>,
) -> QualityReport {
    check_elements(mesh);
    check_conformity(mesh, &["arc", "top"]);
    check_chain(mesh, "arc");
    check_chain(mesh, "top");
    let centre = [0.0, r];
    let arc = &mesh.node_sets["arc"];
    for &i in arc {
        assert!(
            rel(dist(mesh.nodes[i], centre), r) < TOL,
            "arc node {i} off the circle"
        );
    }
    // left to right along the bottom, from (-R, R) to (R, R)
    assert!(dist(mesh.nodes[arc[0]], [-r, r]) < TOL * r);
    assert!(dist(mesh.nodes[*arc.last().unwrap()], [r, r]) < TOL * r);
    assert!(
        arc.windows(2)
            .all(|w| mesh.nodes[w[1]][0] > mesh.nodes[w[0]][0])
    );
    let top = &mesh.node_sets["top"];
    assert!(top.iter().all(|&i| (mesh.nodes[i][1] - r).abs() < TOL * r));
    assert_eq!(
        (top[0], *top.last().unwrap()),
        (*arc.last().unwrap(), arc[0])
    );
    let bottom = &mesh.node_sets["bottom"];
    assert_eq!(bottom.len(), 1);
    assert!(dist(mesh.nodes[bottom[0]], [0.0, 0.0]) < TOL * r);
    // area: exactly the inscribed polygon through the arc nodes, which misses the circular
    // segments (R^2 / 2)(theta - sin theta) of the half disk's area pi R^2 / 2
    let polygon: Vec<[f64; 2]> = arc.iter().map(|&i| mesh.nodes[i]).collect();
    let inscribed = shoelace(&polygon);
    let area = area_sum(mesh);
    assert!(rel(area, inscribed) < TOL, "{area} vs {inscribed}");
    let segments: f64 = polygon
        .windows(2)
        .map(|w| {
            let theta = 2.0 * (dist(w[0], w[1]) / (2.0 * r)).asin();
            0.5 * r * r * (theta - theta.sin())
        })
        .sum();
    let half = PI * r * r / 2.0;
    assert!(area < half && segments > 0.0);
    assert!(
        rel(area + segments, half) < 1e-10,
        "{} vs {half}",
        area + segments
    );
    // size at the target: the first root size / 2^k not above min_size
    for &p in target {
        let near = elements_at(mesh, p);
        assert!(!near.is_empty());
        for e in near {
            let h = size(&coords(mesh, e));
            assert!(
                h <= min_size * (1.0 + 1e-9) && h > 0.5 * min_size,
                "element {e}: {h}"
            );
        }
    }
    assert!(max_size(mesh) > 10.0 * min_size);
    let q = quality::quality(mesh);
    match six {
        Some(six) => assert!(
            q.n_by_node_count[1] > 0 && (q.n_by_node_count[2] > 0) == six,
            "{q}"
        ),
        None => assert_eq!(q.n_by_node_count, [q.n_elements, 0, 0], "quads only: {q}"),
    }
    assert!(rel(q.total_area, area) < TOL);
    q
}

#[test]
fn half_disk_toward_contact_point() {
    for r in [1.0, 2.5] {
        let min_size = r / 100.0;
        let g = Grading::toward_point([0.0, 0.0], min_size, 3);
        let mesh = generate::half_disk(r, &g);
        let q = check_half_disk(&mesh, r, min_size, &[[0.0, 0.0]], Some(true));
        println!(
            "half disk R = {r}, toward the contact point: {q}, {} nodes",
            mesh.n_nodes()
        );
        assert!(
            q.min_angle_deg > 40.0 && q.max_angle_deg < 140.0 && q.max_aspect < 3.0,
            "{q}"
        );
        assert_eq!(mesh, generate::half_disk(r, &g), "deterministic");
    }
}

#[test]
fn half_disk_toward_contact_zone() {
    let (r, min_size) = (1.0, 0.02);
    let (a, b) = ([-0.3, 0.0], [0.3, 0.0]);
    let mesh = generate::half_disk(r, &Grading::toward_line(a, b, min_size, 2));
    // points of the zone inside the disk: on the arc below the segment
    let samples: Vec<[f64; 2]> = (0..=20)
        .map(|k| {
            let x = -0.29 + 0.58 * k as f64 / 20.0;
            [x, 0.0]
        })
        .filter(|p| !elements_at(&mesh, *p).is_empty())
        .collect();
    assert!(!samples.is_empty());
    let q = check_half_disk(&mesh, r, min_size, &samples, Some(false));
    println!(
        "half disk toward the contact zone: {q}, {} nodes",
        mesh.n_nodes()
    );
    assert!(
        q.min_angle_deg > 40.0 && q.max_angle_deg < 140.0 && q.max_aspect < 3.0,
        "{q}"
    );
}

// ---------------------------------------------------------------------------------------------
// The element kernels accept every generated element

#[test]
fn check_shape_accepts_generated_elements() {
    check_hybrid_shapes(&generate::cooks_membrane(8));
    check_hybrid_shapes(&generate::beam(10.0, 2.0, 5, 2, 0.5));
    check_hybrid_shapes(&block(Target::Point([2.0, 0.0])));
    check_hybrid_shapes(&block(Target::Line([0.3, 0.7], [5.1, 3.3])));
    check_hybrid_shapes(&generate::half_disk(
        1.0,
        &Grading::toward_point([0.0, 0.0], 0.01, 3),
    ));
    check_hybrid_shapes(&generate::half_disk(
        1.0,
        &Grading::toward_line([-0.3, 0.0], [0.3, 0.0], 0.02, 2),
    ));
}

#[test]
fn cell_with_three_or_four_finer_neighbours_is_split() {
    // 3 x 3 unit roots; refine the four edge-neighbours of the centre root once. The centre root
    // (distance 0.5 from every target, not below layers * size / 2 = 0.5) would carry four
    // hanging nodes, so it is split too; the four corner roots become 6-node elements.
    let targets = [[1.5, 0.5], [0.5, 1.5], [2.5, 1.5], [1.5, 2.5]];
    let gradings: Vec<Grading> = targets
        .iter()
        .map(|&p| Grading::toward_point(p, 0.5, 1))
        .collect();
    let mesh = generate::graded_mapped(3, 3, |[u, v]| [3.0 * u, 3.0 * v], &gradings);
    check_elements(&mesh);
    check_conformity(&mesh, &["left", "right", "top", "bottom"]);
    let q = quality::quality(&mesh);
    assert_eq!((q.n_elements, q.n_by_node_count), (24, [20, 0, 4]), "{q}");
    assert!(
        elements_at(&mesh, [1.5, 1.5])
            .iter()
            .all(|&e| rel(size(&coords(&mesh, e)), 0.5) < TOL)
    );
}

// ---------------------------------------------------------------------------------------------
// Quad-only graded meshes (Transition::Quads)

/// Every element a strictly convex counter-clockwise 4-node quadrilateral that Q4 and
/// Pian-Sumihara accept.
fn check_quads_only(mesh: &Mesh) {
    check_elements(mesh);
    for e in 0..mesh.n_elements() {
        let c = coords(mesh, e);
        assert_eq!(c.len(), 4, "element {e}");
        for f in [
            Formulation::Q4,
            Formulation::PianSumihara,
            Formulation::Hybrid,
        ] {
            element::check_shape(f, &c)
                .unwrap_or_else(|err| panic!("element {e} rejected by {f:?}: {err} {c:?}"));
        }
    }
}

#[test]
fn quad_only_block_toward_a_line() {
    let (a, b) = ([0.3, 0.7], [5.1, 3.3]);
    let min = 2.0 / 64.0;
    let g = Grading::toward_line(a, b, min, 6);
    let mesh =
        generate::graded_rectangle_with(-1.0, 0.0, [8.0, 4.0], [4, 2], &[g], Transition::Quads);
    check_quads_only(&mesh);
    let sides = ["left", "right", "top", "bottom"];
    check_conformity(&mesh, &sides);
    for s in sides {
        check_chain(&mesh, s);
    }
    assert!(rel(area_sum(&mesh), 32.0) < TOL);
    // element size min at the target, growing away from it
    for k in 0..=50 {
        let t = k as f64 / 50.0;
        let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
        for e in elements_at(&mesh, p) {
            assert!(
                rel(size(&coords(&mesh, e)), min) < TOL,
                "element {e} at the target"
            );
        }
    }
    assert!(max_size(&mesh) >= 16.0 * min * (1.0 - TOL));
    // square leaves: the templates' corner angles are 45, 90 and 135 degrees, aspect at most 2
    let q = quality::quality(&mesh);
    println!(
        "quad-only block toward a line: {q}, {} nodes",
        mesh.n_nodes()
    );
    assert!(
        q.min_angle_deg > 45.0 - 1e-9 && q.max_angle_deg < 135.0 + 1e-9,
        "{q}"
    );
    assert!(q.max_aspect <= 2.0 + 1e-9, "{q}");
    assert_eq!(
        mesh,
        generate::graded_rectangle_with(-1.0, 0.0, [8.0, 4.0], [4, 2], &[g], Transition::Quads),
        "deterministic"
    );
    // the same grading with transition elements: same element size at the target and about
    // the same band widths, so a comparable number of nodes
    let reference = generate::graded_rectangle(-1.0, 0.0, 8.0, 4.0, 4, 2, &g);
    let ratio = mesh.n_nodes() as f64 / reference.n_nodes() as f64;
    println!(
        "nodes: quads only {} / transition {} = {ratio:.2}",
        mesh.n_nodes(),
        reference.n_nodes()
    );
    assert!((0.7..2.0).contains(&ratio), "{ratio}");
}

#[test]
fn quad_only_templates_for_every_neighbour_pattern() {
    // 3 x 3 unit roots; refining the centre root's four edge-neighbours makes the corner roots
    // carry two adjacent fine edges; a column of 1 x 3 roots refined at both ends makes the
    // middle root carry two opposite fine edges; single fine edges appear along the bands
    let targets = [[1.5, 0.5], [0.5, 1.5], [2.5, 1.5], [1.5, 2.5]];
    let gradings: Vec<Grading> = targets
        .iter()
        .map(|&p| Grading::toward_point(p, 0.25, 2))
        .collect();
    let mesh = generate::graded_mapped_with(
        3,
        3,
        |[u, v]| [3.0 * u, 3.0 * v],
        &gradings,
        Transition::Quads,
    );
    check_quads_only(&mesh);
    check_conformity(&mesh, &["left", "right", "top", "bottom"]);
    assert!(rel(area_sum(&mesh), 9.0) < TOL);
    let column = [[0.5, 0.5], [0.5, 2.5]].map(|p| Grading::toward_point(p, 0.25, 2));
    // a sheared map: elements are parallelograms' images, still conforming
    let mesh = generate::graded_mapped_with(
        1,
        3,
        |[u, v]| [u + 0.3 * v, 3.0 * v],
        &column,
        Transition::Quads,
    );
    check_quads_only(&mesh);
    check_conformity(&mesh, &["left", "right", "top", "bottom"]);
    assert!(rel(area_sum(&mesh), 3.0) < TOL);
}

#[test]
fn quad_only_half_disk_toward_contact_zone() {
    let (r, min_size) = (2.0, 0.04);
    let (a, b) = ([-0.6, 0.0], [0.6, 0.0]);
    let g = Grading::toward_line(a, b, min_size, 4);
    let mesh = generate::half_disk_with(r, &[g], Transition::Quads);
    check_quads_only(&mesh);
    let samples: Vec<[f64; 2]> = (0..=20)
        .map(|k| [-0.58 + 1.16 * k as f64 / 20.0, 0.0])
        .filter(|p| !elements_at(&mesh, *p).is_empty())
        .collect();
    assert!(!samples.is_empty());
    let q = check_half_disk(&mesh, r, min_size, &samples, None);
    println!(
        "quad-only half disk toward the contact zone: {q}, {} nodes",
        mesh.n_nodes()
    );
    // the templates' 45 / 135 degree corners on top of the O-grid's own distortion (135
    // degrees where three patches meet): measured 29.1 to 154.2 degrees, aspect 3.14
    assert!(
        q.min_angle_deg > 25.0 && q.max_angle_deg < 160.0 && q.max_aspect < 4.0,
        "{q}"
    );
}

#[test]
fn element_size_cap_refines_everywhere() {
    let cap = Grading {
        target: Target::Point([0.0, 0.0]),
        min_size: 0.5,
        layers: usize::MAX / 4,
    };
    for t in [Transition::Elements, Transition::Quads] {
        let mesh = generate::graded_rectangle_with(0.0, 0.0, [8.0, 4.0], [2, 1], &[cap], t);
        assert_eq!(mesh.n_elements(), 16 * 8, "{t:?}");
        assert!(rel(max_size(&mesh), 0.5) < TOL);
    }
}
