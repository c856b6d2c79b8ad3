//! The 3D contact analysis (`ContactAnalysis::solid`) against issue #43's validation list:
//! the contact patch test through the whole analysis for both bricks and every face layout,
//! invariance of the results under a rigid motion of the whole model, renumbering and a change
//! of units, and a named error for each bad input. (The geometry-level patch tests and the
//! frames' test with normals on both sides of `n_z = 0` are in `contact3d_geometry` and
//! `contact::faces::frames`; the random problems' invariance in `contact_properties`.)

use crate::common::permutation;
use crate::common::press3d::{Press, Variant, difference, run};
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeState};
use hycon::solid::contact_meshes::{BlockOnFlat, ContactMesh};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use nalgebra::{Rotation3, Unit, Vector3};

// ---------------------------------------------------------------------------------------------
// The contact patch test

/// A layout of the two faces sets: A (the block's bottom, `na x na` faces over the unit square,
/// turned `angle` degrees about `z`) on B (the flat's top, `nb x nb` faces over a square of
/// side `side`, offset by `offset` of its faces in `x` and `y`).
struct Layout {
    what: &'static str,
    na: usize,
    nb: usize,
    side: f64,
    angle: f64,
    offset: f64,
}

const LAYOUTS: [Layout; 6] = [
    Layout {
        what: "conforming",
        na: 3,
        nb: 3,
        side: 1.0,
        angle: 0.0,
        offset: 0.0,
    },
    Layout {
        what: "A finer",
        na: 5,
        nb: 3,
        side: 1.0,
        angle: 0.0,
        offset: 0.0,
    },
    Layout {
        what: "A coarser",
        na: 3,
        nb: 5,
        side: 1.0,
        angle: 0.0,
        offset: 0.0,
    },
    Layout {
        what: "B offset a third of a face",
        na: 3,
        nb: 5,
        side: 1.6,
        angle: 0.0,
        offset: 1.0 / 3.0,
    },
    Layout {
        what: "turned 15 degrees",
        na: 3,
        nb: 5,
        side: 1.6,
        angle: 15.0,
        offset: 0.0,
    },
    Layout {
        what: "turned 45 degrees",
        na: 3,
        nb: 5,
        side: 1.6,
        angle: 45.0,
        offset: 0.0,
    },
];

impl Layout {
    /// The block `[-1/2, 1/2]^2 x [0, 1]` (turned) on the flat `[-side/2, side/2]^2 x [-1, 0]`
    /// (offset), one brick layer each.
    fn build(&self) -> ContactMesh {
        let mut c = BlockOnFlat {
            size: [1.0; 3],
            cells: [self.na, self.na, 1],
            flat: [self.side, self.side, 1.0],
            flat_cells: [self.nb, self.nb, 1],
            angle: self.angle,
        }
        .build()
        .unwrap();
        let d = self.offset * self.side / self.nb as f64;
        for x in &mut c.mesh.nodes[c.a_nodes..] {
            x[0] += d;
            x[1] += d;
        }
        c
    }
}

/// The uniaxial stress `sigma_zz = -p` of both bodies (`E`, `nu` alike), the flat's bottom
/// `z = -1` at rest: `u = (p / E) (nu x, nu y, -(z + 1))`.
fn uniaxial(x: [f64; 3], p: f64, e: f64, nu: f64) -> [f64; 3] {
    let s = p / e;
    [s * nu * x[0], s * nu * x[1], -s * (x[2] + 1.0)]
}

/// The contact patch test through the whole analysis: the block and the flat (`E = 1`,
/// `nu = 0.3` both) with the uniaxial stress `sigma_zz = -p` prescribed on the block's top and
/// the flat's bottom (all three components, [`uniaxial`]), the flat's top beyond A loaded by
/// the pressure `p` too (`-p (integral M_b dA - sum_k M_kb)` at each B node: the consistent
/// force of `p` over B's top less the part the mortar transmits from A; none where B is A's
/// size). Bricks that pass the patch test and mortar integrals that transmit a uniform
/// pressure exactly reproduce the uniform state: every A node's multiplier is `-p`, with no
/// tangential traction, frictionless and in stick, and every node's displacement is the
/// uniaxial field's. For both bricks and every layout of [`LAYOUTS`] (conforming, A finer, A
/// coarser, B offset by a third of a face in both directions, turned 15 and 45 degrees: every
/// overlap a general polygon), to `1e-10` of `p`.
#[test]
fn a_uniform_pressure_is_transmitted_for_both_bricks_and_every_layout() {
    let (e, nu, p) = (1.0, 0.3, 1e-3);
    let mut worst: f64 = 0.0;
    for formulation in BrickFormulation::ALL {
        for layout in &LAYOUTS {
            let c = layout.build();
            let n = c.mesh.n_nodes();
            let m = Isotropic::new(e, nu).unwrap();
            let mut model = SolidModel::new(c.mesh.clone(), vec![m, m], formulation).unwrap();
            model.prescribe(&c.a_top, &[0, 1, 2]).unwrap();
            model.prescribe(&c.b_bottom, &[0, 1, 2]).unwrap();
            let mut qp = vec![0.0; 3 * n];
            for &k in c.a_top.iter().chain(&c.b_bottom) {
                qp[3 * k..3 * k + 3].copy_from_slice(&uniaxial(c.mesh.nodes[k], p, e, nu));
            }
            for friction in [0.0, 0.3] {
                let what = format!("{}, {}, mu = {friction}", formulation.name(), layout.what);
                let pair = FacePair {
                    a: c.a_faces.clone(),
                    b: c.b_faces.clone(),
                    friction,
                };
                let mut analysis = ContactAnalysis::solid(
                    model.clone(),
                    vec![pair],
                    &[],
                    ContactOptions::default(),
                )
                .unwrap();
                let f = flat_load(&c, &analysis, p);
                analysis.increment(&f, &qp).unwrap();
                let nodes = analysis.node_results(0).unwrap();
                assert_eq!(nodes.len(), (layout.na + 1).pow(2), "{what}");
                let state = if friction == 0.0 {
                    NodeState::Frictionless
                } else {
                    NodeState::Stick
                };
                let mut err: f64 = 0.0;
                for r in &nodes {
                    assert_eq!(r.state, state, "{what}: {r:?}");
                    err = err.max((r.tn + p).abs() / p).max(r.ts.norm() / p);
                }
                let load: f64 = nodes.iter().map(|r| r.force.components()[2]).sum();
                err = err.max((load - p).abs() / p);
                let q = analysis.displacement().unwrap();
                let scale = 2.0 * p / e;
                for (k, x) in c.mesh.nodes.iter().enumerate() {
                    let exact = uniaxial(*x, p, e, nu);
                    for i in 0..3 {
                        err = err.max((q[3 * k + i] - exact[i]).abs() / scale);
                    }
                }
                eprintln!("{what}: worst relative error {err:.1e}");
                assert!(err <= 1e-10, "{what}: {err}");
                worst = worst.max(err);
            }
        }
    }
    eprintln!("patch tests: worst relative error {worst:.1e}");
}

/// The load on the flat's top beyond A: at each B node `b`, `-p (integral M_b dA - sum_k
/// M_kb)` along `z`, the first from the consistent forces of a unit pressure on B's faces,
/// the second from the coupling rows (`c_kb = -M_kb`) of the reference surface.
fn flat_load(c: &ContactMesh, analysis: &ContactAnalysis, p: f64) -> Vec<f64> {
    let mut f = vec![0.0; 3 * c.mesh.n_nodes()];
    let top = c.mesh.faces_where(|x| x[2] == 0.0);
    for (e, face) in top
        .into_iter()
        .filter(|&(e, _)| c.mesh.element_material[e] == 1)
    {
        for (node, force) in c.mesh.face_forces(e, face, |_, n| n) {
            f[3 * node + 2] -= p * force[2];
        }
    }
    for node in analysis.surface(0).unwrap().nodes {
        for (j, v) in node.coupling.into_iter().filter(|&(j, _)| j >= c.a_nodes) {
            f[3 * j + 2] -= p * v;
        }
    }
    f
}

// ---------------------------------------------------------------------------------------------
// Invariance

/// A block of `2 x 3` bricks turned 20 degrees on a flat of `3 x 4 x 2` (A coarser than B,
/// every overlap a general polygon), stiffer below, with friction: pressed by 0.01, then slid
/// by `(0.004, 0.002)` with stick and slip nodes.
fn press(formulation: BrickFormulation) -> Press {
    Press {
        meshes: BlockOnFlat {
            size: [1.0, 0.8, 0.6],
            cells: [2, 3, 1],
            flat: [1.6, 1.6, 0.5],
            flat_cells: [3, 4, 2],
            angle: 20.0,
        },
        gap: 1e-3,
        moduli: [1.0, 3.0],
        poisson: [0.3, 0.2],
        friction: 0.3,
        formulation,
        steps: vec![[0.0, 0.0, -0.01], [0.004, 0.002, -0.01]],
    }
}

/// A rigid motion of the whole model (coordinates and prescribed motions) rotates the
/// displacements, the tractions, the forces and the frames' normals, and leaves `tn`, the
/// weights and the states; a rotation taking the coordinate axes to each other (120 degrees
/// about `(1, 1, 1)`) rotates the tangents too (a general one turns them about the normal: the
/// reference direction is the coordinate axis farthest from the normals). Renumbering the nodes,
/// listing the bricks and faces in another order and each face from another corner changes
/// nothing; lengths times `1e3` and moduli times `2.5e6` scale the displacements by `1e3`, the
/// tractions by `2.5e6`. Both bricks, to `1e-9` of each quantity's scale.
#[test]
fn rigid_motion_renumbering_and_units_change_nothing() {
    let axes = Rotation3::from_axis_angle(
        &Unit::new_normalize(Vector3::new(1.0, 1.0, 1.0)),
        2.0 * std::f64::consts::FRAC_PI_3,
    );
    assert!((axes * Vector3::x() - Vector3::y()).norm() < 1e-15);
    for formulation in BrickFormulation::ALL {
        let p = press(formulation);
        let base = run(&p, &Variant::identity(), ContactOptions::default()).unwrap();
        let last = &base[base.len() - 1];
        let count = |s: &str| last.nodes.iter().filter(|r| r.state == s).count();
        eprintln!(
            "{}: {} stick, {} slip of {} A nodes",
            formulation.name(),
            count("stick"),
            count("slip"),
            last.nodes.len()
        );
        assert!(count("stick") > 0 && count("slip") > 0);
        let n = p.meshes.build().unwrap().mesh.n_nodes();
        let variants = [
            (
                "rigid motion",
                Variant {
                    rotation: Rotation3::from_euler_angles(0.3, -1.1, 2.0),
                    translation: [3.0, -2.0, 5.0],
                    ..Variant::identity()
                },
                false,
            ),
            (
                "axes taken to each other",
                Variant {
                    rotation: axes,
                    ..Variant::identity()
                },
                true,
            ),
            (
                "renumbering",
                Variant {
                    perm: Some(permutation(n, 7)),
                    ..Variant::identity()
                },
                true,
            ),
            (
                "units",
                Variant {
                    length_scale: 1e3,
                    modulus_scale: 2.5e6,
                    ..Variant::identity()
                },
                true,
            ),
        ];
        for (what, v, tangents) in variants {
            let got = run(&p, &v, ContactOptions::default()).unwrap();
            let d = difference(&base, &got, tangents);
            eprintln!(
                "{}, {what}: worst relative difference {d:.1e}",
                formulation.name()
            );
            assert!(d <= 1e-9, "{what}: {d}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Bad input

mod bad_input {
    use hycon::contact::faces::FaceGeometry;
    use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair};
    use hycon::solid::contact_meshes::{BlockOnFlat, ContactMesh};
    use hycon::solid::geometry::FACES;
    use hycon::solid::model::SolidModel;
    use hycon::solid::{BrickFormulation, Isotropic};

    /// A block of `3 x 3` bricks on a flat of `3 x 3` (unit cubes, the block above).
    fn stack() -> ContactMesh {
        BlockOnFlat {
            size: [1.0; 3],
            cells: [3, 3, 1],
            flat: [1.0; 3],
            flat_cells: [3, 3, 1],
            angle: 0.0,
        }
        .build()
        .unwrap()
    }

    /// The message of `ContactAnalysis::solid` refusing the pair `(a, b)` on the stack's mesh
    /// (with positions moved by `change`).
    fn refused(
        c: &ContactMesh,
        a: Vec<[usize; 4]>,
        b: Vec<[usize; 4]>,
        change: impl Fn(&mut Vec<[f64; 3]>),
    ) -> String {
        let mut mesh = c.mesh.clone();
        change(&mut mesh.nodes);
        let m = Isotropic::new(1.0, 0.3).unwrap();
        let mut model = SolidModel::new(mesh, vec![m, m], BrickFormulation::Hybrid18).unwrap();
        model.prescribe(&c.a_top, &[0, 1, 2]).unwrap();
        model.prescribe(&c.b_bottom, &[0, 1, 2]).unwrap();
        let pair = FacePair {
            a,
            b,
            friction: 0.0,
        };
        ContactAnalysis::solid(model, vec![pair], &[], ContactOptions::default())
            .unwrap_err()
            .to_string()
    }

    /// Brick `e`'s local face `f` as node ids.
    fn face(c: &ContactMesh, e: usize, f: usize) -> [usize; 4] {
        FACES[f].map(|k| c.mesh.elements[e][k])
    }

    /// Each bad input of issue #43 is refused when the analysis is made, with a message that
    /// names the pair and what is wrong: nodes that are no face of the body, an inverted face,
    /// a warped face, a side that is not one connected surface, both sides on one body, sides
    /// that never face each other (turned the same way; back to back and too far apart for the
    /// orientation check within the search distance).
    #[test]
    fn each_bad_input_is_named() {
        let c = stack();
        let (a, b) = (c.a_faces.clone(), c.b_faces.clone());
        let none = |_: &mut Vec<[f64; 3]>| {};
        let check = |what: &str, message: String, expected: &str| {
            eprintln!("{what}: {message}");
            assert!(
                message.contains("contact pair 0") && message.contains(expected),
                "{what}: {message}"
            );
        };
        // 4 nodes of the first brick that are no face: its bottom with a top corner
        let mut not_a_face = a.clone();
        let bottom = face(&c, 0, 4);
        not_a_face[0] = [bottom[0], bottom[1], bottom[2], c.mesh.elements[0][7]];
        let message = refused(&c, not_a_face, b.clone(), none);
        assert!(message.contains("A face 0"), "{message}");
        check("no face", message, "not a face of any brick");
        // inverted: a B face listed clockwise
        let mut inverted = b.clone();
        inverted[4].reverse();
        let message = refused(&c, a.clone(), inverted, none);
        assert!(message.contains("B face 4"), "{message}");
        check("inverted", message, "listed clockwise");
        // warped: the corner of A's bottom at (-1/2, -1/2) raised by a brick's width, 1/3
        // (its brick stays valid; the halves of its bottom face on either side of the diagonal
        // through that corner have normals (1, 0, 1) and (0, 1, 1): 60 degrees apart)
        let corner = (0..c.a_nodes)
            .find(|&k| c.mesh.nodes[k] == [-0.5, -0.5, 0.0])
            .unwrap();
        let warped = refused(&c, a.clone(), b.clone(), |x| x[corner][2] = 1.0 / 3.0);
        check("warped", warped, "warped by 60.0 degrees");
        // not one surface: two of A's corner faces
        let apart = vec![a[0], a[a.len() - 1]];
        check(
            "two pieces",
            refused(&c, apart, b.clone(), none),
            "contact side A is not one connected surface: its 2 faces form 2 pieces",
        );
        // both sides on one body: the block's bottom against its top
        let block_top: Vec<[usize; 4]> = (0..9).map(|e| face(&c, e, 5)).collect();
        check(
            "one body",
            refused(&c, a.clone(), block_top.clone(), none),
            "both sides are on one body",
        );
        // never facing: B the flat's bottom (turned the same way as A, 1 below it)
        let flat_bottom: Vec<[usize; 4]> = (9..18).map(|e| face(&c, e, 4)).collect();
        check(
            "same way",
            refused(&c, a.clone(), flat_bottom.clone(), none),
            "the sides never face each other",
        );
        // never facing: A the block's top against the flat's bottom, back to back 2 apart
        // (beyond the search distance of 4 mean A faces, 1.33, where the orientation check
        // within it judges no node)
        check(
            "back to back",
            refused(&c, block_top, flat_bottom, none),
            "the sides never face each other",
        );
    }

    /// The same checks on the geometry alone (as a host's pair gets them): a side in two
    /// pieces, sides that never face each other.
    #[test]
    fn the_geometry_refuses_pieces_and_sides_that_never_face() {
        let c = stack();
        let x = c.mesh.nodes.as_flattened();
        let new = |a: Vec<[usize; 4]>, b: Vec<[usize; 4]>| {
            FaceGeometry::new(a, b, x, None, &[])
                .map(drop)
                .map_err(|e| e.to_string())
        };
        new(c.a_faces.clone(), c.b_faces.clone()).unwrap();
        let apart = vec![c.b_faces[0], c.b_faces[8]];
        let err = new(c.a_faces.clone(), apart).unwrap_err();
        assert!(
            err.contains("contact side B is not one connected surface"),
            "{err}"
        );
        let flat_bottom: Vec<[usize; 4]> = (9..18).map(|e| face(&c, e, 4)).collect();
        let err = new(c.a_faces.clone(), flat_bottom).unwrap_err();
        assert!(err.contains("never face each other"), "{err}");
    }
}
