//! The 8-node bricks: rank, rigid-body modes, invariance under node renumbering and rotation,
//! the constant-stress patch test on an irregular mesh, stress recovery and face tractions, the
//! shape check, and the 3D model's assembly with its analysis reused.

use hycon::assembly::DofMap;
use hycon::solid::geometry::{FACES, NODE_XI};
use hycon::solid::mesh::{SolidMesh, graded};
use hycon::solid::model::{SolidModel, SolidSystem};
use hycon::solid::{
    self, BrickFormulation, BrickMatrix, Isotropic, N_DOF, ShapePolicy, ShapeReport,
    recover_stress, stiffness_into,
};
use hycon::{ShapeError, ShapeWarning};

const STRICT: ShapePolicy = ShapePolicy::Strict;

/// The shape check under the default policy (integration points).
fn check_shape(x: &[[f64; 3]]) -> Result<ShapeReport, ShapeError> {
    solid::check_shape(x, ShapePolicy::default())
}

/// The shape check under the strict policy (0.8's), without the report.
fn check_strict(x: &[[f64; 3]]) -> Result<(), ShapeError> {
    solid::check_shape(x, STRICT).map(|_| ())
}
use hycon::solver::Backend;
use nalgebra::{DMatrix, Matrix3, SymmetricEigen};

const UNIT: [[f64; 3]; 8] = NODE_XI;

use crate::common::distorted_brick as distorted;

fn steel() -> Isotropic {
    Isotropic::new(210e3, 0.3).unwrap()
}

fn stiffness(f: BrickFormulation, x: &[[f64; 3]; 8], m: &Isotropic) -> BrickMatrix {
    let mut k = BrickMatrix::zeros();
    stiffness_into(f, x, m, &mut k).unwrap();
    k
}

fn eigenvalues(k: &BrickMatrix) -> Vec<f64> {
    let mut ev: Vec<f64> = SymmetricEigen::new(DMatrix::from_column_slice(24, 24, k.as_slice()))
        .eigenvalues
        .iter()
        .copied()
        .collect();
    ev.sort_by(f64::total_cmp);
    ev
}

/// Exactly six zero eigenvalues (the rigid motions, at round-off: below `1e-13` of the largest),
/// the seventh clear of them, on the unit cube, a distorted brick and a thin one (3 x 0.5 x 0.1);
/// for both formulations and near incompressibility (where the largest eigenvalue, a
/// volumetric one, is `1e4` times a shear one, and the thin brick's bending mode is far smaller).
#[test]
fn six_zero_modes_on_distorted_bricks() {
    let thin = UNIT.map(|[x, y, z]| [3.0 * x, 0.5 * y + 0.1 * x, 0.1 * z + 0.02 * x * y]);
    for f in BrickFormulation::ALL {
        for nu in [0.3, 0.4999] {
            let m = Isotropic::new(1.0, nu).unwrap();
            for x in [UNIT, distorted(), thin] {
                let ev = eigenvalues(&stiffness(f, &x, &m));
                let max = ev[23];
                let zero = ev.iter().filter(|e| e.abs() < 1e-13 * max).count();
                assert_eq!(zero, 6, "{f:?} nu {nu}: {ev:?}");
                assert!(
                    ev[6] > 1e-10 * max,
                    "{f:?} nu {nu}: seventh {:e}",
                    ev[6] / max
                );
            }
        }
    }
}

/// The six rigid motions (3 translations, 3 small rotations) as element dof vectors at `x`.
fn rigid_modes(x: &[[f64; 3]; 8]) -> [nalgebra::SVector<f64, 24>; 6] {
    let mut out = [nalgebra::SVector::<f64, 24>::zeros(); 6];
    for (k, p) in x.iter().enumerate() {
        for d in 0..3 {
            out[d][3 * k + d] = 1.0;
        }
        // rotation about x: (0, -z, y); about y: (z, 0, -x); about z: (-y, x, 0)
        let rot = [[0.0, -p[2], p[1]], [p[2], 0.0, -p[0]], [-p[1], p[0], 0.0]];
        for r in 0..3 {
            for d in 0..3 {
                out[3 + r][3 * k + d] = rot[r][d];
            }
        }
    }
    out
}

#[test]
fn rigid_motions_are_free_of_force() {
    let x = distorted();
    for f in BrickFormulation::ALL {
        let k = stiffness(f, &x, &steel());
        let scale = k.abs().max() * 3.0;
        for (i, mode) in rigid_modes(&x).iter().enumerate() {
            let force = (k * mode).abs().max();
            assert!(force < 1e-12 * scale, "{f:?} mode {i}: |K r| = {force:e}");
        }
    }
}

/// The 24 rotations of the cube as signed axis permutations `R` (det +1).
fn cube_rotations() -> Vec<Matrix3<f64>> {
    let mut out = Vec::new();
    for p in [
        [0, 1, 2],
        [1, 2, 0],
        [2, 0, 1],
        [0, 2, 1],
        [2, 1, 0],
        [1, 0, 2],
    ] {
        for signs in 0..8 {
            let mut r = Matrix3::zeros();
            for (row, &col) in p.iter().enumerate() {
                r[(row, col)] = if signs >> row & 1 == 1 { -1.0 } else { 1.0 };
            }
            if r.determinant() > 0.0 {
                out.push(r);
            }
        }
    }
    assert_eq!(out.len(), 24);
    out
}

/// Renumbering the nodes by any of the 24 orientation-preserving symmetries of the cube
/// permutes `K` and nothing else: new node `k` is the old node at `R xi_k`.
#[test]
fn invariant_under_node_renumbering() {
    let x = distorted();
    for f in BrickFormulation::ALL {
        let k = stiffness(f, &x, &steel());
        let scale = k.abs().max();
        for r in cube_rotations() {
            let old: [usize; 8] = std::array::from_fn(|k| {
                let c = r * nalgebra::Vector3::from(NODE_XI[k]);
                NODE_XI
                    .iter()
                    .position(|n| (0..3).all(|i| n[i] == c[i]))
                    .unwrap()
            });
            let y = old.map(|o| x[o]);
            let k2 = stiffness(f, &y, &steel());
            let mut err: f64 = 0.0;
            for a in 0..24 {
                for b in 0..24 {
                    let (oa, ob) = (3 * old[a / 3] + a % 3, 3 * old[b / 3] + b % 3);
                    err = err.max((k2[(a, b)] - k[(oa, ob)]).abs());
                }
            }
            assert!(err < 1e-12 * scale, "{f:?} renumbering {old:?}: {err:e}");
        }
    }
}

/// Rotating the brick rotates `K`: `K(Q x) = T K(x) T^T`, `T` = diag(Q, ..., Q).
#[test]
fn invariant_under_rotation() {
    let x = distorted();
    let q = nalgebra::Rotation3::from_euler_angles(0.3, -1.1, 2.0).into_inner();
    let y = x.map(|p| {
        let v = q * nalgebra::Vector3::from(p) + nalgebra::Vector3::new(5.0, -3.0, 1.0);
        [v[0], v[1], v[2]]
    });
    let mut t = BrickMatrix::zeros();
    for k in 0..8 {
        t.fixed_view_mut::<3, 3>(3 * k, 3 * k).copy_from(&q);
    }
    for f in BrickFormulation::ALL {
        let k = stiffness(f, &x, &steel());
        let k2 = stiffness(f, &y, &steel());
        let err = (k2 - t * k * t.transpose()).abs().max();
        assert!(err < 1e-12 * k.abs().max(), "{f:?}: {err:e}");
    }
}

/// A linear displacement field `u = A x + c` and its constant stress.
fn linear_field() -> (Matrix3<f64>, [f64; 3]) {
    (
        Matrix3::new(1.0, 0.4, -0.3, 0.2, -0.7, 0.5, 0.6, 0.1, 0.9) * 1e-3,
        [1e-3, -2e-3, 3e-3],
    )
}

fn linear_u(p: [f64; 3]) -> [f64; 3] {
    let (a, c) = linear_field();
    let v = a * nalgebra::Vector3::from(p);
    [v[0] + c[0], v[1] + c[1], v[2] + c[2]]
}

fn exact_stress(m: &Isotropic) -> solid::Voigt {
    let (a, _) = linear_field();
    let e = nalgebra::SVector::<f64, 6>::from([
        a[(0, 0)],
        a[(1, 1)],
        a[(2, 2)],
        a[(0, 1)] + a[(1, 0)],
        a[(1, 2)] + a[(2, 1)],
        a[(2, 0)] + a[(0, 2)],
    ]);
    m.elasticity() * e
}

/// The constant-stress patch test on an irregular 3 x 3 x 3 mesh (every interior node moved by
/// up to a quarter of its shortest edge), boundary displacements from a linear field: the
/// interior nodes and every brick's stress are exact to round-off, for both formulations and at
/// nu = 0.4999.
#[test]
fn patch_test_on_an_irregular_mesh_is_exact() {
    let mesh = SolidMesh::block(
        &graded(0.0, 2.0, 3, 2.0),
        &graded(0.0, 1.0, 3, 0.5),
        &graded(0.0, 1.5, 3, 1.0),
    )
    .distort(0.25, 7, |p| {
        p.iter()
            .zip([2.0, 1.0, 1.5])
            .all(|(&v, l)| v > 1e-9 && v < l - 1e-9)
    });
    let boundary = |p: [f64; 3]| {
        p.iter()
            .zip([2.0, 1.0, 1.5])
            .any(|(&v, l)| v.abs() < 1e-9 || (v - l).abs() < 1e-9)
    };
    for f in BrickFormulation::ALL {
        for nu in [0.3, 0.4999] {
            let m = Isotropic::new(1000.0, nu).unwrap();
            let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
            for n in mesh.nodes_where(boundary) {
                for (d, u) in linear_u(mesh.nodes[n]).into_iter().enumerate() {
                    model.fix(n, d, u);
                }
            }
            let sol = model.solve().unwrap();
            let mut err: f64 = 0.0;
            for (n, &p) in mesh.nodes.iter().enumerate() {
                for (got, want) in sol.at(n).into_iter().zip(linear_u(p)) {
                    err = err.max((got - want).abs());
                }
            }
            assert!(err < 1e-14, "{f:?} nu {nu}: displacement error {err:e}");
            let s0 = exact_stress(&m);
            let scale = s0.abs().max();
            for e in 0..mesh.n_elements() {
                let field = model.element_stress(&sol, e).unwrap();
                for xi in [[0.0; 3], [0.9, -0.7, 0.3], [-1.0, 1.0, -1.0]] {
                    let s = field.at_natural(xi);
                    let err = (s - s0).abs().max();
                    assert!(err < 1e-10 * scale, "{f:?} nu {nu} brick {e}: {err:e}");
                }
            }
        }
    }
}

/// Stress recovery: a linear displacement field gives its constant stress at any point, the
/// hybrid `beta_1..6` equal that stress (and the higher `beta` vanish), and every face traction
/// is `sigma n`.
#[test]
fn stress_and_face_traction_recovery() {
    let x = distorted();
    let m = steel();
    let mut q = [0.0; N_DOF];
    for (k, p) in x.iter().enumerate() {
        q[3 * k..3 * k + 3].copy_from_slice(&linear_u(*p));
    }
    let s0 = exact_stress(&m);
    let scale = s0.abs().max();
    for f in BrickFormulation::ALL {
        let field = recover_stress(f, &x, &m, &q).unwrap();
        let centroid = [1.1, 0.9, 0.7];
        assert!((field.at(centroid) - s0).abs().max() < 1e-10 * scale);
        if f == BrickFormulation::Hybrid18 {
            let beta = field.beta();
            assert_eq!(beta.len(), 18);
            for i in 0..6 {
                assert!((beta[i] - s0[i]).abs() < 1e-10 * scale, "beta {i}");
            }
            assert!(beta[6..].iter().all(|b| b.abs() < 1e-10 * scale));
        } else {
            assert!(field.beta().is_empty());
        }
        for (face, nodes) in FACES.iter().enumerate() {
            let [a, b, _, d] = nodes.map(|k| nalgebra::Vector3::from(x[k]));
            let t = field.face_traction(face, -1.0, -1.0);
            // at the face's first corner the normal is (b - a) x (d - a)
            let n = (b - a).cross(&(d - a)).normalize();
            let expect = solid::traction(&s0, [n[0], n[1], n[2]]);
            for i in 0..3 {
                assert!(
                    (t[i] - expect[i]).abs() < 1e-10 * scale,
                    "{f:?} face {face}"
                );
            }
        }
        // outward: face 1 (xi = +1) of the unit cube has normal +x
        let cube = recover_stress(f, &UNIT, &m, &[0.0; 24]).unwrap();
        let _ = cube.face_traction(1, 0.0, 0.0);
    }
    let n = hycon::solid::geometry::face_normal(
        &hycon::solid::geometry::Trilinear::new(&UNIT),
        1,
        0.3,
        -0.2,
    );
    assert!((n[0] - 1.0).abs() < 1e-15);
}

/// The errors of both policies, and the strict policy's (0.8's check, its messages) where the
/// default one warns.
#[test]
fn shape_check_names_the_defect() {
    for check in [check_strict, |x: &[[f64; 3]]| check_shape(x).map(|_| ())] {
        assert_eq!(check(&UNIT), Ok(()));
        assert_eq!(check(&distorted()), Ok(()));
        assert_eq!(
            check(&UNIT[..7]),
            Err(ShapeError::NodeCount {
                got: 7,
                expected: "8"
            })
        );
        let mut nan = UNIT;
        nan[3][1] = f64::NAN;
        assert_eq!(check(&nan), Err(ShapeError::NonFinite));
        // top and bottom swapped: negative volume
        let swapped = [4, 5, 6, 7, 0, 1, 2, 3].map(|k| UNIT[k]);
        assert_eq!(check(&swapped), Err(ShapeError::Inverted));
        // flat: zero volume
        let flat = UNIT.map(|[x, y, _]| [x, y, 0.0]);
        assert_eq!(check(&flat), Err(ShapeError::Degenerate));
        let mut same = UNIT;
        same[6] = same[5];
        assert_eq!(check(&same), Err(ShapeError::Degenerate));
        // a small twist (7.5 degrees, as in the MacNeal-Harder twisted beam) is accepted
        assert_eq!(check(&small_twist()), Ok(()));
    }
    assert_eq!(check_shape(&small_twist()).unwrap().warnings().count(), 0);
    // node 6 pushed through the brick towards node 0: re-entrant at node 6, where det J is
    // -0.121 h^3 at the corner and -0.039 h^3 at the nearest integration point: an error under
    // both policies, each naming it its own way
    let mut dent = UNIT;
    dent[6] = [-0.5, -0.5, -0.5];
    assert_eq!(
        check_strict(&dent),
        Err(ShapeError::InvertedCorner { node: 6 })
    );
    let got = check_shape(&dent);
    assert_eq!(got, Err(ShapeError::InvertedIntegrationPoint { node: 6 }));
    assert!(
        got.unwrap_err()
            .to_string()
            .starts_with("Jacobian not positive at the integration point nearest local node 6")
    );
    // top face twisted by 90 degrees: the side faces warp by 97.9 degrees, det J stays positive
    // (0.016 h^3 at the corners, 0.011 at the integration points): strict rejects the first
    // face, as 0.8 did; the default warns about the worst one (the four side faces tie)
    let twisted = UNIT.map(|[x, y, z]| if z > 0.0 { [-y, x, z + 3.0] } else { [x, y, z] });
    assert_eq!(
        check_strict(&twisted),
        Err(ShapeError::WarpedFace { face: 0 })
    );
    let report = check_shape(&twisted).unwrap();
    assert!((report.warp_degrees - 97.9).abs() < 0.05, "{report:?}");
    assert!(report.corner_jacobian > 0.0 && report.integration_jacobian > 0.0);
    assert!(report.face < 4, "{report:?}");
    assert_eq!(
        report.warnings().collect::<Vec<_>>(),
        vec![ShapeWarning::WarpedFace {
            face: report.face,
            degrees: report.warp_degrees
        }]
    );
    // a roof-folded top face (node 6 raised by 3 over a side of 2): warped by 72.1 degrees, a
    // readable warning by default, an error when strict
    let mut folded = UNIT;
    folded[6][2] += 3.0;
    assert_eq!(
        check_strict(&folded),
        Err(ShapeError::WarpedFace { face: 5 })
    );
    let warnings: Vec<_> = check_shape(&folded).unwrap().warnings().collect();
    assert_eq!(warnings.len(), 1);
    let text = warnings[0].to_string();
    assert!(
        text.starts_with("face 5 is warped by 72.1 degrees") && text.contains("limit is 45"),
        "{text}"
    );
}

/// A 7.5 degree twist of the top face.
fn small_twist() -> [[f64; 3]; 8] {
    let a = 7.5f64.to_radians();
    UNIT.map(|[x, y, z]| {
        if z > 0.0 {
            [x * a.cos() - y * a.sin(), x * a.sin() + y * a.cos(), z]
        } else {
            [x, y, z]
        }
    })
}

/// The report is unchanged by the units (Jacobians relative to the longest edge cubed) and by a
/// rigid rotation.
#[test]
fn shape_report_is_scale_free() {
    let mut folded = UNIT;
    folded[6][2] += 3.0;
    let base = check_shape(&folded).unwrap();
    let (c, s) = (0.6, 0.8);
    for scale in [1e-6, 1e6] {
        let moved =
            folded.map(|[x, y, z]| [scale * (c * x - s * y), scale * (s * x + c * y), scale * z]);
        let r = check_shape(&moved).unwrap();
        assert!((r.integration_jacobian / base.integration_jacobian - 1.0).abs() < 1e-12);
        assert!((r.corner_jacobian / base.corner_jacobian - 1.0).abs() < 1e-12);
        assert!((r.warp_degrees - base.warp_degrees).abs() < 1e-9);
        assert_eq!((r.corner, r.face), (base.corner, base.face));
    }
}

#[test]
fn material_is_checked() {
    assert!(Isotropic::new(0.0, 0.3).is_err());
    assert!(Isotropic::new(1.0, 0.5).is_err());
    assert!(Isotropic::new(f64::NAN, 0.3).is_err());
    let m = steel();
    let err = (m.compliance() * m.elasticity() - nalgebra::SMatrix::<f64, 6, 6>::identity())
        .abs()
        .max();
    assert!(err < 1e-14);
}

/// The dof map and the system: the analysis is done once and reused by every refactorization
/// (another material, another formulation), and the 3D pattern has 81 entries per interior
/// node column block (27 neighbours x 3 dofs).
#[test]
fn system_reuses_its_analysis() {
    let mesh = SolidMesh::uniform([1.0, 1.0, 1.0], [4, 4, 4]);
    let clamped: Vec<usize> = mesh
        .nodes_where(|p| p[0] == 0.0)
        .into_iter()
        .flat_map(|n| [3 * n, 3 * n + 1, 3 * n + 2])
        .collect();
    let dofs = DofMap::new(mesh.n_nodes(), 3, clamped.iter().copied()).unwrap();
    assert_eq!(dofs.n_free(), 3 * (125 - 25));
    let mut system = SolidSystem::new(&mesh, dofs, Backend::Faer).unwrap();
    for f in BrickFormulation::ALL {
        for e in [1.0, 7.0] {
            let m = Isotropic::new(e, 0.3).unwrap();
            system.assemble_and_factor(&mesh, &[m], f, &[]).unwrap();
        }
    }
    assert_eq!(system.cholesky().factorizations(), 4);
    assert!(DofMap::new(2, 3, [6]).is_err());
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// On random bricks (every corner of a 2 x 1 x 0.5 box moved by up to 30% of the shortest
    /// side, any that fail the shape check skipped): `K` symmetric to round-off and exactly six
    /// zero eigenvalues, for both formulations.
    #[test]
    fn random_bricks_have_six_zero_modes(
        moves in proptest::collection::vec(-0.15f64..0.15, 24),
        nu in 0.0f64..0.4999,
    ) {
        let mut x: [[f64; 3]; 8] =
            UNIT.map(|[a, b, c]| [1.0 + a, 0.5 + 0.5 * b, 0.25 + 0.25 * c]);
        for (k, p) in x.iter_mut().enumerate() {
            for i in 0..3 {
                p[i] += moves[3 * k + i];
            }
        }
        if check_shape(&x).is_err() {
            return Ok(());
        }
        let m = Isotropic::new(1.0, nu).unwrap();
        for f in BrickFormulation::ALL {
            let k = stiffness(f, &x, &m);
            let asym = (k - k.transpose()).abs().max();
            proptest::prop_assert!(asym < 1e-13 * k.abs().max(), "{:?}: asymmetry {:e}", f, asym);
            let ev = eigenvalues(&k);
            let zero = ev.iter().filter(|e| e.abs() < 1e-13 * ev[23]).count();
            proptest::prop_assert_eq!(zero, 6, "{:?} nu {}: {:?}", f, nu, ev);
        }
    }
}

/// A cantilever of distorted bricks (interior nodes moved), clamped at `x = 0`, one node of
/// the free end moved by a prescribed `v = 1e-3` and the end loaded in `-z`: what the trailing
/// and condensed solves are checked on. Also the contact body's test subject
/// (`contact::bodies::solid`).
fn distorted_cantilever() -> SolidModel {
    let mesh = SolidMesh::uniform([2.0, 1.0, 1.0], [4, 2, 2])
        .distort(0.2, 11, |p| p[0] > 0.0 && p[0] < 2.0);
    let mut model = SolidModel::new(mesh, vec![steel()], BrickFormulation::Hybrid18).unwrap();
    for n in model.mesh.nodes_where(|p| p[0] == 0.0) {
        for d in 0..3 {
            model.fix(n, d, 0.0);
        }
    }
    let end = model.mesh.nodes_where(|p| p[0] == 2.0);
    model.fix(end[0], 1, 1e-3);
    for &n in &end {
        model.load(n, [0.0, 0.0, -100.0]);
    }
    model
}

/// The dofs of the top face `z = 1`, sorted: those at `x = 0` are clamped (skipped by the
/// trailing unknowns).
fn top_dofs(model: &SolidModel) -> Vec<usize> {
    let mut dofs: Vec<usize> = model
        .mesh
        .nodes_where(|p| p[2] == 1.0)
        .into_iter()
        .flat_map(|n| [3 * n, 3 * n + 1, 3 * n + 2])
        .collect();
    dofs.sort_unstable();
    dofs
}

/// The solid system with trailing unknowns solves as the plain one does (the prescribed motion
/// through `K_fp u_p` from element forces, against the plain solve's assembled correction), and
/// the flexibility read off its factor's trailing block is `K^-1` between those dofs: each
/// column equals a plain solve with a unit load, to round-off of the flexibility's scale.
#[test]
fn trailing_and_condensed_solves_match_the_plain_solve() {
    let model = distorted_cantilever();
    let plain = model.solve().unwrap().displacements;
    let trailing = top_dofs(&model);
    assert!(
        trailing
            .iter()
            .any(|&d| model.prescribed().any(|(p, _)| p == d))
    );
    let mut system = SolidSystem::with_trailing_on(&model, &trailing, Backend::Faer).unwrap();
    let (f, qp) = (model.external_forces().to_vec(), model.prescribed_values());
    let u = system.solve_for(&model, &f, &qp).unwrap();
    let scale = plain.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = u
        .iter()
        .zip(&plain)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        scale > 1e-4 && worst < 1e-12 * scale,
        "{worst:e} of {scale:e}"
    );

    let free: Vec<usize> = trailing
        .iter()
        .copied()
        .filter(|&d| system.dofs().equation(d).is_some())
        .collect();
    let flexibility = system.condensed_flexibility().unwrap();
    assert_eq!(
        (flexibility.nrows(), flexibility.ncols()),
        (free.len(), free.len())
    );
    let mut reference = SolidSystem::with_trailing_on(&model, &[], Backend::Faer).unwrap();
    let zero = vec![0.0; f.len()];
    let largest = (0..free.len()).fold(0.0f64, |m, i| m.max(flexibility[(i, i)].abs()));
    for (j, &dj) in free.iter().enumerate() {
        let mut unit = zero.clone();
        unit[dj] = 1.0;
        let column = reference.solve_for(&model, &unit, &zero).unwrap();
        for (i, &di) in free.iter().enumerate() {
            let d = (flexibility[(i, j)] - column[di]).abs();
            assert!(d < 1e-12 * largest, "F[{i}][{j}]: {d:e} of {largest:e}");
        }
    }
    assert_eq!(reference.cholesky().factorizations(), 1);
}
