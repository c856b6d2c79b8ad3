//! A frictional 3D press whose converged state depended on the node numbering
//! (`c_examples/solid_randomized.c`, seed 1, round 106): 20 A nodes, all slipping under the
//! press. On a face the iteration takes its states from the contact conditions linearized at
//! each iterate (`Proposer::Linearized`), solved by the semi-smooth Newton method and, where
//! that does not settle, projected Gauss-Seidel. Here the Newton method with the slip
//! directions held from step to step did not settle, and Gauss-Seidel cycled in the original
//! node order (it converged in the permuted one): the iteration settled on slip directions
//! up to 0.41 rad from the slips (their part across the direction 3.3e-2 of the motion
//! scale), which the checks at convergence did not measure, and the normal tractions differed
//! from the permuted numbering's by 3.5e-3 of their peak.

// the round's values as `solid_randomized` printed them (`%.17g`), to the bit
#![allow(clippy::excessive_precision)]

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair};
use hycon::solid::mesh::SolidMesh;
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};

/// A block of `n` bricks from `x0` of `size` into `mesh` (materials into `materials`), as
/// `solid_randomized.c` builds it: node ids x fastest, then y, then z; its node ids.
fn block(
    mesh: &mut SolidMesh,
    x0: [f64; 3],
    size: [f64; 3],
    n: [usize; 3],
    material: usize,
) -> Vec<usize> {
    let (nx, nxy) = (n[0] + 1, (n[0] + 1) * (n[1] + 1));
    let mut ids = Vec::new();
    for k in 0..=n[2] {
        for j in 0..=n[1] {
            for i in 0..=n[0] {
                ids.push(mesh.nodes.len());
                let index = [i, j, k];
                mesh.nodes.push(std::array::from_fn(|d| {
                    x0[d] + size[d] * index[d] as f64 / n[d] as f64
                }));
            }
        }
    }
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                let c = i + nx * j + nxy * k;
                let corners = [c, c + 1, c + 1 + nx, c + nx];
                let brick: [usize; 8] =
                    std::array::from_fn(|q| ids[corners[q % 4] + if q < 4 { 0 } else { nxy }]);
                mesh.elements.push(brick);
                mesh.element_material.push(material);
            }
        }
    }
    ids
}

/// The press of round 106 with the nodes renumbered `perm[old] = new` and the bricks
/// `bricks[old] = new` (`None`: as built): a block of 3 x 4 x 2 bricks (0.43 x 0.49 x 1, on
/// top, A its bottom faces) on one of 3 x 1 x 1 (2 x 2 x 1, B its top faces), its top moved
/// down by 4.7e-4 and then slid, the flat's bottom held, `mu = 0.398`. The normal traction of
/// each A node (by its id as built) after each of the three increments (pressed, slid, the
/// same totals again), and the largest violation of the conditions of each converged
/// iteration.
fn press(perm: Option<(&[usize], &[usize])>) -> (Vec<Vec<(usize, f64)>>, f64) {
    let mut built = SolidMesh::default();
    let lower = block(&mut built, [0.0, 0.0, -1.0], [2.0, 2.0, 1.0], [3, 1, 1], 0);
    let first_upper = built.elements.len();
    let corner = [0.48070526249618573, 0.18266723331056667];
    let size = [0.42791637905780833, 0.48981969553227223, 1.0];
    let upper = block(&mut built, [corner[0], corner[1], 0.0], size, [3, 4, 2], 1);
    let a: Vec<[usize; 4]> = (0..12)
        .map(|i| built.brick_face(first_upper + i, 4).unwrap())
        .collect();
    let b: Vec<[usize; 4]> = (0..3)
        .map(|i| built.brick_face(first_upper - 3 + i, 5).unwrap())
        .collect();
    let n = built.nodes.len();
    let node = |i: usize| perm.map_or(i, |(p, _)| p[i]);
    let brick = |e: usize| perm.map_or(e, |(_, p)| p[e]);
    let mut mesh = SolidMesh {
        nodes: vec![[0.0; 3]; n],
        elements: vec![[0; 8]; built.elements.len()],
        element_material: vec![0; built.elements.len()],
        ..SolidMesh::default()
    };
    for (i, x) in built.nodes.iter().enumerate() {
        mesh.nodes[node(i)] = *x;
    }
    for (e, nodes) in built.elements.iter().enumerate() {
        mesh.elements[brick(e)] = nodes.map(node);
        mesh.element_material[brick(e)] = built.element_material[e];
    }
    let materials = vec![
        Isotropic::new(1.0, 0.024780244794793377).unwrap(),
        Isotropic::new(0.56779627182165204, 0.31871628385947909).unwrap(),
    ];
    let mut model = SolidModel::new(mesh, materials, BrickFormulation::Hybrid18).unwrap();
    let top: Vec<usize> = upper[60 - 20..].iter().map(|&k| node(k)).collect();
    let bottom: Vec<usize> = lower[..8].iter().map(|&k| node(k)).collect();
    model.prescribe(&bottom, &[0, 1, 2]).unwrap();
    model.prescribe(&top, &[0, 1, 2]).unwrap();
    let pair = FacePair {
        a: a.iter().map(|f| f.map(node)).collect(),
        b: b.iter().map(|f| f.map(node)).collect(),
        friction: 0.39759239179670591,
    };
    let options = ContactOptions::default();
    let mut analysis = ContactAnalysis::solid(model, vec![pair], &[], options).unwrap();
    let mut built_id = vec![0; n];
    for i in 0..n {
        built_id[node(i)] = i;
    }
    let depth = 0.00047300192507717607;
    let slid = [-1.1335989897629697e-06, 2.2575149579783614e-05, -depth];
    let (mut tractions, mut violation) = (Vec::new(), 0.0f64);
    for u in [[0.0, 0.0, -depth], slid, slid] {
        let mut qp = vec![0.0; 3 * n];
        for &k in &top {
            qp[3 * k..3 * k + 3].copy_from_slice(&u);
        }
        analysis.increment(&vec![0.0; 3 * n], &qp).unwrap();
        // the converged iteration's
        violation = violation.max(analysis.records().last().unwrap().violation);
        let results = analysis.node_results(0).unwrap();
        if tractions.is_empty() {
            let slipping = results.iter().filter(|r| r.state.name() == "slip");
            assert_eq!((results.len(), slipping.count()), (20, 20));
        }
        let mut tn: Vec<(usize, f64)> =
            (results.iter()).map(|r| (built_id[r.node], r.tn)).collect();
        tn.sort_by_key(|&(k, _)| k);
        tractions.push(tn);
    }
    (tractions, violation)
}

/// The press of round 106 and the same press renumbered (the permutation that round drew):
/// the same normal tractions to `1e-8` of their peak (the rounds' tolerance with friction is
/// `1e-5`; 0.12.0's differed by `3.5e-3`), after the press with every A node slipping, and
/// every converged state within `1e-9` of the conditions, slips along their directions
/// included.
#[test]
fn a_press_whose_gauss_seidel_cycles_in_one_node_order_converges_alike_in_both() {
    let perm: Vec<usize> = [
        8, 34, 20, 70, 49, 69, 30, 26, 10, 31, 56, 60, 9, 1, 73, 12, 45, 36, 23, 11, 51, 54, 16,
        39, 58, 55, 14, 46, 44, 43, 52, 27, 40, 18, 0, 19, 66, 68, 32, 42, 67, 47, 29, 41, 15, 7,
        62, 37, 74, 75, 24, 72, 35, 61, 21, 38, 13, 17, 4, 63, 50, 59, 57, 2, 22, 33, 25, 5, 48,
        65, 3, 6, 53, 64, 28, 71,
    ]
    .to_vec();
    let bricks: Vec<usize> = [
        0, 8, 1, 4, 9, 26, 11, 6, 3, 20, 12, 7, 2, 23, 15, 10, 25, 22, 5, 13, 17, 16, 14, 18, 24,
        19, 21,
    ]
    .to_vec();
    let (base, base_violation) = press(None);
    let (renumbered, renumbered_violation) = press(Some((&perm, &bricks)));
    let peak = (base.iter().flatten()).fold(0.0f64, |m, &(_, tn)| m.max(tn.abs()));
    let mut worst = 0.0f64;
    for (a, b) in base.iter().zip(&renumbered) {
        for (&(i, x), &(j, y)) in a.iter().zip(b) {
            assert_eq!(i, j);
            worst = worst.max((x - y).abs() / peak);
        }
    }
    eprintln!(
        "renumbered: {worst:.1e} of the peak; violations {base_violation:.1e}, \
         {renumbered_violation:.1e}"
    );
    assert!(worst < 1e-8, "{worst}");
    assert!(base_violation < 1e-9 && renumbered_violation < 1e-9);
}
