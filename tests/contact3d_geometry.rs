//! The 3D contact geometry on the validation meshes: the nodal frames of the cap's contact
//! surface with its symmetry planes, and the mortar integrals of the cap against the block
//! (coverage, the initial weighted gap against the paraboloid's height).

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
