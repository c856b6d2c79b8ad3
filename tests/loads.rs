//! The load and check routines against closed forms: consistent nodal forces of pressures and
//! tractions on plane, axisymmetric and brick boundaries (the classical splits, exact moments,
//! a pressure on a curved face summing to the projected area, Lamé's bore load solved through
//! the model APIs), element volumes, the scaled Jacobian, and stress at natural coordinates.

use crate::common::{annulus_node, inner_arc_error, quarter_annulus};
use hycon::element::geometry::Bilinear;
use hycon::element::loads::{EdgeLoad, edge_load};
use hycon::element::{self, Formulation, quality};
use hycon::mesh::Mesh;
use hycon::model::Model;
use hycon::solid::geometry::{FACES, NODE_XI, Trilinear};
use hycon::solid::loads::{FaceLoad, face_load};
use hycon::solid::mesh::{SolidMesh, graded};
use hycon::solid::model::SolidModel;
use hycon::solid::{self, BrickFormulation, Isotropic};
use hycon::{Analysis, Error, Material, ShapeError};
use std::f64::consts::{FRAC_PI_2, PI};

fn plane(t: f64) -> Material {
    Material::new(1000.0, 0.3, t, Analysis::PlaneStrain).unwrap()
}

fn axi(nu: f64) -> Material {
    Material::new(1000.0, nu, 1.0, Analysis::Axisymmetric).unwrap()
}

/// `|a - b| <= tol * scale`, with a message.
fn assert_close(a: f64, b: f64, tol: f64, scale: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * scale,
        "{what}: {a} vs {b} (difference {:e}, allowed {:e})",
        (a - b).abs(),
        tol * scale
    );
}

// ------------------------------------------------------------------------------------------
// Plane and axisymmetric edges

/// A quad with one inclined edge (edge 1, from node 1 to node 2), and the same outline as a
/// 6-node hybrid element (mid-side nodes on edges 0 and 2).
const QUAD: [[f64; 2]; 4] = [[0.0, 0.0], [3.0, 0.5], [2.0, 2.5], [-0.5, 2.0]];

/// A linearly varying pressure `p0 -> p1` on a straight edge of length `L`: the classical
/// split `t L (2 p0 + p1) / 6`, `t L (p0 + 2 p1) / 6` along the inward normal (1/2-1/2 when
/// uniform), so the resultant is `t L (p0 + p1) / 2` and the moment about the start node
/// `t L^2 (p0 + 2 p1) / 6`, exactly; every element kind, every edge, nothing at the other
/// nodes.
#[test]
fn edge_pressure_gives_the_classical_split_and_exact_moments() {
    let t = 0.7;
    let m = plane(t);
    let six = [
        QUAD[0],
        [1.5, 0.25],
        QUAD[1],
        QUAD[2],
        [0.75, 2.25],
        QUAD[3],
    ];
    let cases: [(Formulation, &[[f64; 2]]); 4] = [
        (Formulation::Q4, &QUAD),
        (Formulation::PianSumihara, &QUAD),
        (Formulation::Hybrid, &QUAD),
        (Formulation::Hybrid, &six),
    ];
    for (f, coords) in cases {
        let n = coords.len();
        for edge in 0..n {
            for (p0, p1) in [(2.0, 2.0), (1.0, 4.0), (-3.0, 5.0)] {
                let load = EdgeLoad {
                    pressure: [p0, p1],
                    ..Default::default()
                };
                let out = edge_load(f, coords, &m, edge, &load).unwrap();
                let (a, b) = (edge, (edge + 1) % n);
                let (xa, xb) = (coords[a], coords[b]);
                let d = [xb[0] - xa[0], xb[1] - xa[1]];
                let len = d[0].hypot(d[1]);
                let inward = [-d[1] / len, d[0] / len];
                let scale = t * len * (p0.abs() + p1.abs());
                let want = [
                    t * len * (2.0 * p0 + p1) / 6.0,
                    t * len * (p0 + 2.0 * p1) / 6.0,
                ];
                for (node, w) in [(a, want[0]), (b, want[1])] {
                    for dir in 0..2 {
                        let what = format!("{f:?} n={n} edge {edge} node {node} dir {dir}");
                        assert_close(out[2 * node + dir], w * inward[dir], 1e-14, scale, &what);
                    }
                }
                for k in (0..n).filter(|&k| k != a && k != b) {
                    assert_eq!([out[2 * k], out[2 * k + 1]], [0.0, 0.0]);
                }
                // the moment about the start node (z component of sum (x_k - x_a) x f_k)
                let moment = d[0] * out[2 * b + 1] - d[1] * out[2 * b];
                let exact = t * len * len * (p0 + 2.0 * p1) / 6.0;
                assert_close(moment, exact, 1e-14, scale * len, "moment");
            }
        }
    }
}

/// A traction vector and a pressure on the same edge add; the model's own line loads
/// (`Model::external_forces`) share the integral.
#[test]
fn traction_and_pressure_add_and_match_the_model_line_loads() {
    let m = plane(2.0);
    let traction = EdgeLoad {
        traction: [[1.0, -2.0], [3.0, 0.5]],
        ..Default::default()
    };
    let pressure = EdgeLoad {
        pressure: [4.0, -1.0],
        ..Default::default()
    };
    let both = EdgeLoad {
        pressure: pressure.pressure,
        traction: traction.traction,
    };
    let f = |l: &EdgeLoad| edge_load(Formulation::Q4, &QUAD, &m, 1, l).unwrap();
    let sum = f(&traction) + f(&pressure);
    assert!((f(&both) - sum).amax() <= 1e-14 * sum.amax());
    let mut mesh = Mesh::new();
    for p in QUAD {
        mesh.push_node(p);
    }
    mesh.push_element(&[0, 1, 2, 3], 0);
    let mut model = Model::new(mesh, vec![m], Formulation::Q4);
    model.line_loads.push(hycon::model::LineLoad {
        nodes: [1, 2],
        load: traction.traction,
    });
    let ext = model.external_forces();
    let direct = f(&traction);
    for (k, v) in ext.iter().enumerate() {
        assert_close(*v, direct[k], 1e-15, direct.amax(), "line load");
    }
}

/// Axisymmetry, full circle: a uniform pressure `p` on the top of a ring `r in [r1, r2]`
/// pushes down with `p pi (r2^2 - r1^2)`, split as `2 pi p L (2 r_a + r_b) / 6` (the measure
/// `2 pi r` is linear along the edge); a uniform radial traction `t` on the bore `r = r1`,
/// height `h`, gives `2 pi r1 h t / 2` per node.
#[test]
fn axisymmetric_edges_integrate_over_the_circle() {
    let (r1, r2, h, p) = (0.5, 2.0, 0.75, 3.0);
    let ring = [[r1, 0.0], [r2, 0.0], [r2, h], [r1, h]];
    for f in [Formulation::Hybrid, Formulation::Q4] {
        // edge 2: top, from (r2, h) to (r1, h)
        let out = edge_load(f, &ring, &axi(0.3), 2, &EdgeLoad::pressure(p)).unwrap();
        let total = out[5] + out[7];
        let exact = -p * PI * (r2 * r2 - r1 * r1);
        assert_close(total, exact, 1e-14, exact.abs(), "axial total");
        let len = r2 - r1;
        assert_close(
            out[5],
            -2.0 * PI * p * len * (2.0 * r2 + r1) / 6.0,
            1e-14,
            exact.abs(),
            "node 2",
        );
        assert_close(
            out[7],
            -2.0 * PI * p * len * (2.0 * r1 + r2) / 6.0,
            1e-14,
            exact.abs(),
            "node 3",
        );
        assert!(out[4] == 0.0 && out[6] == 0.0);
        // edge 3: the bore, from (r1, h) to (r1, 0), a traction (t, 0) = a pressure t there
        let t = 5.0;
        let bore = edge_load(f, &ring, &axi(0.3), 3, &EdgeLoad::traction([t, 0.0])).unwrap();
        let want = PI * r1 * h * t;
        assert_close(bore[6], want, 1e-14, want, "bore node 3");
        assert_close(bore[0], want, 1e-14, want, "bore node 0");
        let as_pressure = edge_load(f, &ring, &axi(0.3), 3, &EdgeLoad::pressure(t)).unwrap();
        assert!((as_pressure - bore).amax() <= 1e-14 * want);
    }
}

/// Lamé's `u_r(r)` of a thick cylinder under internal pressure `p` in plane strain (also the
/// axisymmetric cylinder with both ends held): `u_r = r (1 + nu) / E ((1 - nu) sigma_theta -
/// nu sigma_r)`, `sigma_r = A - B / r^2`, `sigma_theta = A + B / r^2`,
/// `B = p a^2 b^2 / (b^2 - a^2)`, `A = B / b^2`.
fn lame_u_r(r: f64, [a, b]: [f64; 2], youngs: f64, nu: f64, p: f64) -> f64 {
    let bb = p * a * a * b * b / (b * b - a * a);
    let aa = bb / (b * b);
    let (sr, st) = (aa - bb / (r * r), aa + bb / (r * r));
    r * (1.0 + nu) / youngs * ((1.0 - nu) * st - nu * sr)
}

/// MacNeal and Harder's thick cylinder: `a = 3`, `b = 9`, `E = 1000`, `p = 1`.
const RADII: [f64; 2] = [3.0, 9.0];

/// Lamé's bore load, axisymmetric: the cylinder meshed with `n` equal hybrid elements through
/// the wall (one layer, `u_z = 0` everywhere), the bore pressure applied through `edge_load` on
/// the first element's edge 3 and added to the model as nodal forces. On such a mesh the
/// hybrid element is nodally exact under this load (`tests/axisymmetric.rs` shows it through
/// the model's own line loads), so `u_r(a)` must match Lamé to the solver's round-off: 1e-6
/// relative leaves room for the conditioning at `nu = 0.4999` and would catch any error in the
/// load (a missing `2 pi`, a wrong split or sign is a factor, not a part in a million).
#[test]
fn lame_bore_load_axisymmetric() {
    let [a, b] = RADII;
    for nu in [0.3, 0.4999] {
        for n in [5, 20] {
            let h = (b - a) / n as f64;
            let mut mesh = Mesh::new();
            for i in 0..=n {
                let r = a + (b - a) * i as f64 / n as f64;
                mesh.push_node([r, 0.0]);
                mesh.push_node([r, h]);
            }
            for i in 0..n {
                let (l, r) = (2 * i, 2 * i + 2);
                mesh.push_element(&[l, r, r + 1, l + 1], 0);
            }
            let m = axi(nu);
            let first = [mesh.nodes[0], mesh.nodes[2], mesh.nodes[3], mesh.nodes[1]];
            let f =
                edge_load(Formulation::Hybrid, &first, &m, 3, &EdgeLoad::pressure(1.0)).unwrap();
            let mut model = Model::new(mesh, vec![m], Formulation::Hybrid);
            let all: Vec<usize> = (0..2 * (n + 1)).collect();
            model.fix_dir(&all, 1, 0.0).unwrap();
            for (local, node) in [(0, 0), (3, 1)] {
                model
                    .nodal_forces
                    .push((node, [f[2 * local], f[2 * local + 1]]));
            }
            let u = model.solve().unwrap().displacement(0)[0];
            let exact = lame_u_r(a, RADII, 1000.0, nu, 1.0);
            assert_close(u, exact, 1e-6, exact, &format!("nu = {nu}, {n} elements"));
        }
    }
}

/// Largest relative error of `u_r` over the bore nodes of a quarter ring (plane strain, hybrid
/// elements, `nr x nt` in polar coordinates, symmetry supports), its polygonal bore loaded by a
/// unit pressure through `edge_load`, element by element, assembled by the test.
fn ring_bore_error(nu: f64, [nr, nt]: [usize; 2]) -> f64 {
    let a = RADII[0];
    let id = |i, j| annulus_node(nr, i, j);
    let mesh = quarter_annulus(RADII, [nr, nt]);
    let m = plane(1.0);
    let m = Material::new(1000.0, nu, 1.0, m.analysis).unwrap();
    let mut model = Model::new(mesh.clone(), vec![m], Formulation::Hybrid);
    for j in 0..nt {
        let nodes = [id(0, j), id(1, j), id(1, j + 1), id(0, j + 1)];
        let coords = nodes.map(|k| mesh.nodes[k]);
        let f = edge_load(
            Formulation::Hybrid,
            &coords,
            &m,
            3,
            &EdgeLoad::pressure(1.0),
        )
        .unwrap();
        for (local, node) in [(3, nodes[3]), (0, nodes[0])] {
            model
                .nodal_forces
                .push((node, [f[2 * local], f[2 * local + 1]]));
        }
    }
    let bottom: Vec<usize> = (0..=nr).map(|i| id(i, 0)).collect();
    let left: Vec<usize> = (0..=nr).map(|i| id(i, nt)).collect();
    model.fix_dir(&bottom, 1, 0.0).unwrap();
    model.fix_dir(&left, 0, 0.0).unwrap();
    let solution = model.solve().unwrap();
    let exact = lame_u_r(a, RADII, 1000.0, nu, 1.0);
    inner_arc_error(&mesh, &solution, [nr, nt], a, exact)
}

/// Lamé's bore load in plane strain: a quarter ring whose bore is a polygon, loaded through
/// `edge_load`. The polygon's chords lie inside the circle by `a (1 - cos(dtheta / 2))`, an
/// `O(h^2)` geometric error, so the bore displacement converges at second order: the error must
/// fall by at least 3 per halving of the mesh (measured 3.6 and 3.9 at `nu = 0.3`, 3.3 and 3.8
/// at 0.4999) and stay below 0.6% on the finest (measured 0.20% and 0.47%; `--nocapture`
/// prints them). A wrong split or a missing factor would not converge to Lamé at all.
#[test]
fn lame_bore_load_plane_strain_ring() {
    for nu in [0.3, 0.4999] {
        let e: Vec<f64> = [[4, 8], [8, 16], [16, 32]]
            .iter()
            .map(|&m| ring_bore_error(nu, m))
            .collect();
        println!("plane-strain ring, nu = {nu}: max |u_r / Lame - 1| on the bore {e:?}");
        assert!(e[0] / e[1] > 3.0 && e[1] / e[2] > 3.0, "nu = {nu}: {e:?}");
        assert!(e[2] < 6e-3, "nu = {nu}: {e:?}");
    }
}

// ------------------------------------------------------------------------------------------
// Brick faces

/// A quarter of a thick cylinder, `a = 3`, `b = 9`, height 2, as bricks (`nr x nt x nz`),
/// optionally with the bore's interior nodes moved (radially and along the axis) so that its
/// faces are warped; the bore's 4 boundary curves are kept.
fn cylinder(nr: usize, nt: usize, nz: usize, warp: f64) -> SolidMesh {
    let [a, b] = RADII;
    let mesh = SolidMesh::block(
        &graded(a, b, nr, 1.0),
        &graded(0.0, FRAC_PI_2, nt, 1.0),
        &graded(0.0, 2.0, nz, 1.0),
    );
    let (dt, dz) = (FRAC_PI_2 / nt as f64, 2.0 / nz as f64);
    mesh.map(|[r, t, z]| {
        let inner = (r - a).abs() < 1e-12 && t > 1e-12 && t < FRAC_PI_2 - 1e-12;
        let (dr, dzz) = if inner && z > 1e-12 && z < 2.0 - 1e-12 {
            // a deterministic pseudo-random number in [-0.5, 0.5) per node
            let s = (((t + 1.3 * z) * 12.9898).sin() * 43_758.545_3)
                .fract()
                .abs()
                - 0.5;
            (warp * s * a * dt, -warp * s * dz)
        } else {
            (0.0, 0.0)
        };
        [(r + dr) * t.cos(), (r + dr) * t.sin(), z + dzz]
    })
}

/// The bore faces `(brick, face)` of [`cylinder`] (face 0, `xi = -1`, at `r = a`).
fn bore_faces(mesh: &SolidMesh, nr: usize) -> Vec<(usize, usize)> {
    (0..mesh.n_elements())
        .filter(|e| e % nr == 0)
        .map(|e| (e, 0))
        .collect()
}

/// A uniform pressure `p` on the curved bore of a quarter cylinder (radius `a`, height `H`,
/// faceted, and again with every interior bore node moved so that the faces warp): the nodal
/// forces sum to `p` times the projected area in each direction, `(p a H, p a H, 0)` (the
/// vector area of a surface depends only on its boundary, and 2 x 2 Gauss integrates the
/// pressure exactly on bilinear faces), to round-off.
#[test]
fn pressure_on_a_curved_face_sums_to_the_projected_area() {
    let (p, a, height) = (2.5, RADII[0], 2.0);
    for warp in [0.0, 0.3] {
        let mesh = cylinder(2, 6, 3, warp);
        let mut total = [0.0; 3];
        for (e, face) in bore_faces(&mesh, 2) {
            let f = face_load(&mesh.element_coords(e), face, &FaceLoad::pressure(p)).unwrap();
            for k in 0..8 {
                for i in 0..3 {
                    total[i] += f[3 * k + i];
                }
            }
        }
        let want = [p * a * height, p * a * height, 0.0];
        for i in 0..3 {
            assert_close(
                total[i],
                want[i],
                1e-13,
                want[0],
                &format!("warp {warp}, dir {i}"),
            );
        }
    }
}

/// A pressure linear in `x` on a plane rectangular face, `p = p0 + g x` over
/// `x in [0, L]`, `y in [0, W]` (face 4 of a box, `z = 0`, outward normal `-z`): the resultant
/// `W (p0 L + g L^2 / 2)` along `+z` and its moments about the origin
/// (`M_y = -W (p0 L^2 / 2 + g L^3 / 3)`, `M_x = W^2 / 2 (p0 L + g L^2 / 2)`), exactly (the
/// bilinear interpolation of a linear pressure is exact, and so is the integral). A uniform
/// traction on a plane trapezoidal face sums to the traction times the face's area.
#[test]
fn linear_face_pressure_gives_exact_moments_and_tractions_their_area() {
    let (l, w, h) = (3.0, 1.5, 0.8);
    let boxed = NODE_XI.map(|[x, y, z]| {
        [
            l * (x + 1.0) / 2.0,
            w * (y + 1.0) / 2.0,
            h * (z + 1.0) / 2.0,
        ]
    });
    let (p0, g) = (2.0, -1.5);
    let face = 4;
    let load = FaceLoad {
        pressure: FACES[face].map(|k| p0 + g * boxed[k][0]),
        ..Default::default()
    };
    let f = face_load(&boxed, face, &load).unwrap();
    let (mut force, mut moment) = ([0.0; 3], [0.0; 3]);
    for (k, x) in boxed.iter().enumerate() {
        let fk = [f[3 * k], f[3 * k + 1], f[3 * k + 2]];
        for i in 0..3 {
            force[i] += fk[i];
        }
        moment[0] += x[1] * fk[2] - x[2] * fk[1];
        moment[1] += x[2] * fk[0] - x[0] * fk[2];
        moment[2] += x[0] * fk[1] - x[1] * fk[0];
    }
    let resultant = w * (p0 * l + g * l * l / 2.0);
    let scale = w * l * (p0.abs() + g.abs() * l);
    assert_close(force[2], resultant, 1e-14, scale, "resultant");
    assert_close(force[0], 0.0, 1e-14, scale, "fx");
    assert_close(force[1], 0.0, 1e-14, scale, "fy");
    assert_close(moment[0], w * resultant / 2.0, 1e-14, scale * l, "M_x");
    assert_close(
        moment[1],
        -w * (p0 * l * l / 2.0 + g * l.powi(3) / 3.0),
        1e-14,
        scale * l,
        "M_y",
    );
    assert_close(moment[2], 0.0, 1e-14, scale * l, "M_z");
    // a plane trapezoidal face (face 5 at z = h; the brick a prism tapered in x): sum = t area
    let mut tapered = boxed;
    tapered[6][0] = 2.0;
    tapered[2][0] = 2.0;
    let area = w * (l + 2.0) / 2.0;
    let t = [1.0, -2.0, 0.5];
    let f = face_load(&tapered, 5, &FaceLoad::traction(t)).unwrap();
    for i in 0..3 {
        let sum: f64 = (0..8).map(|k| f[3 * k + i]).sum();
        assert_close(sum, t[i] * area, 1e-14, 2.0 * area, "traction");
    }
}

/// The model's face loads (`SolidModel::load_faces`) and `face_load` are one integral; through
/// the 3D model, Lamé's bore load on the quarter cylinder (a plane-strain slice, `w = 0`) gives
/// the bore displacement of the existing validation (5 hybrid bricks through the wall: within
/// 3%, `tests/solid_validation.rs`).
#[test]
fn lame_bore_load_on_bricks() {
    let (nr, nt) = (5, 12);
    let mesh = cylinder(nr, nt, 1, 0.0);
    let m = Isotropic::new(1000.0, 0.3).unwrap();
    let mut model = SolidModel::new(mesh.clone(), vec![m], BrickFormulation::Hybrid18).unwrap();
    let mut reference = model.clone();
    for (n, p) in mesh.nodes.iter().enumerate() {
        for m in [&mut model, &mut reference] {
            m.fix(n, 2, 0.0);
            if p[1].abs() < 1e-9 {
                m.fix(n, 1, 0.0);
            }
            if p[0].abs() < 1e-9 {
                m.fix(n, 0, 0.0);
            }
        }
    }
    let faces = bore_faces(&mesh, nr);
    for &(e, face) in &faces {
        let f = face_load(&mesh.element_coords(e), face, &FaceLoad::pressure(1.0)).unwrap();
        for (k, &node) in mesh.elements[e].iter().enumerate() {
            model.load(node, [f[3 * k], f[3 * k + 1], f[3 * k + 2]]);
        }
    }
    reference.load_faces(&faces, |_, n| [-n[0], -n[1], -n[2]]);
    let (u, u_ref) = (model.solve().unwrap(), reference.solve().unwrap());
    let a = RADII[0];
    let bore = mesh.nodes_where(|p| ((p[0] * p[0] + p[1] * p[1]).sqrt() - a).abs() < 1e-9);
    let exact = lame_u_r(a, RADII, 1000.0, 0.3, 1.0);
    let mut mean = 0.0;
    for &n in &bore {
        let (p, d, r) = (mesh.nodes[n], u.at(n), u_ref.at(n));
        for i in 0..3 {
            assert_close(d[i], r[i], 1e-10, exact, "against load_faces");
        }
        mean += (p[0] * d[0] + p[1] * d[1]) / a / bore.len() as f64;
    }
    assert_close(mean, exact, 0.03, exact, "Lamé on bricks");
}

#[test]
fn bad_faces_and_loads_are_rejected() {
    let x = NODE_XI;
    assert!(matches!(
        face_load(&x, 6, &FaceLoad::pressure(1.0)),
        Err(Error::InvalidInput(s)) if s.contains("face 6")
    ));
    assert!(matches!(
        face_load(&x, 0, &FaceLoad::traction([0.0, f64::INFINITY, 0.0])),
        Err(Error::InvalidInput(s)) if s.contains("not finite")
    ));
    let mut inverted = x;
    inverted.swap(0, 4);
    inverted.swap(1, 5);
    inverted.swap(2, 6);
    inverted.swap(3, 7);
    assert!(matches!(
        face_load(&inverted, 0, &FaceLoad::pressure(1.0)),
        Err(Error::Element { .. })
    ));
}

// ------------------------------------------------------------------------------------------
// Volume and quality

/// Volumes against independent closed forms: a square frustum brick
/// `h (A1 + sqrt(A1 A2) + A2) / 3`, an affine image of the cube `8 |det A|`, a warped brick
/// against a 4 x 4 x 4 Gauss integral of `det J` (a different rule; `det J` has degree 2 in each
/// coordinate, so both are exact); a ring whose section is a trapezoid touching the axis, the
/// cone frustum `pi h (R^2 + R r + r^2) / 3`; plane elements `A t`.
#[test]
fn volumes_match_closed_forms() {
    let (bottom, top, h) = (2.0, 0.8, 1.3);
    let frustum = NODE_XI.map(|[x, y, z]| {
        let s = if z < 0.0 { bottom } else { top };
        [s * x / 2.0, s * y / 2.0, h * (z + 1.0) / 2.0]
    });
    let v = solid::quality::volume(&frustum).unwrap();
    let exact = h * (bottom * bottom + bottom * top + top * top) / 3.0;
    assert_close(v, exact, 1e-14, exact, "frustum");
    let a = [[1.2, 0.3, -0.2], [0.1, 0.9, 0.4], [-0.3, 0.2, 1.1]];
    let affine =
        NODE_XI.map(|x| std::array::from_fn(|i| (0..3).map(|j| a[i][j] * x[j]).sum::<f64>() + 5.0));
    let det = nalgebra::Matrix3::from_fn(|i, j| a[i][j]).determinant();
    assert_close(
        solid::quality::volume(&affine).unwrap(),
        8.0 * det,
        1e-14,
        8.0,
        "affine",
    );
    let warped = crate::common::distorted_brick();
    let map = Trilinear::new(&warped);
    let g4 = [
        (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
        (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    ];
    let mut exact = 0.0;
    for (x, wx) in g4 {
        for (y, wy) in g4 {
            for (z, wz) in g4 {
                exact += wx * wy * wz * map.jacobian([x, y, z]).determinant();
            }
        }
    }
    assert_close(
        solid::quality::volume(&warped).unwrap(),
        exact,
        1e-14,
        exact,
        "warped",
    );
    // axisymmetric: the section (0, 0), (R, 0), (r, h), (0, h) swept round the axis
    let (big, small, h) = (2.0, 0.5, 1.5);
    let section = [[0.0, 0.0], [big, 0.0], [small, h], [0.0, h]];
    for f in [Formulation::Hybrid, Formulation::Q4] {
        let v = quality::volume(f, &section, &axi(0.3)).unwrap();
        let cone = PI * h * (big * big + big * small + small * small) / 3.0;
        assert_close(v, cone, 1e-14, cone, "cone frustum");
        let v = quality::volume(f, &QUAD, &plane(0.4)).unwrap();
        // QUAD's area by the shoelace formula written out
        let area = 0.5 * ((3.0 * 2.5 - 2.0 * 0.5) + (2.0 * 2.0 - (-0.5) * 2.5));
        assert_close(v, 0.4 * area, 1e-14, area, "plane");
    }
}

/// The scaled Jacobian: 1 for rectangles and boxes, `sin(theta)` for a rhombus and a sheared
/// box, unchanged by scale, translation and rotation, mid-side nodes skipped; a near-degenerate
/// element (a corner of 179.8 degrees, a brick sheared to corners of 0.3 degrees) falls below 0.01, so a host's
/// threshold flags it; an invalid element is an error, not a number.
#[test]
fn quality_is_the_scaled_jacobian() {
    let rect = [[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 1.0]];
    let six = [
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [2.0, 1.0],
        [0.0, 1.0],
    ];
    assert_eq!(
        quality::scaled_jacobian(Formulation::Q4, &rect).unwrap(),
        1.0
    );
    assert_eq!(
        quality::scaled_jacobian(Formulation::Hybrid, &six).unwrap(),
        1.0
    );
    let theta: f64 = 0.6;
    let rhombus = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0 + theta.cos(), theta.sin()],
        [theta.cos(), theta.sin()],
    ];
    let q = quality::scaled_jacobian(Formulation::PianSumihara, &rhombus).unwrap();
    assert_close(q, theta.sin(), 1e-15, 1.0, "rhombus");
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    let moved = rhombus.map(|[x, y]| [1e3 * (c * x - s * y) + 7.0, 1e3 * (s * x + c * y) - 2.0]);
    let qm = quality::scaled_jacobian(Formulation::Q4, &moved).unwrap();
    assert_close(qm, q, 1e-13, 1.0, "rotated and scaled");
    // a corner of 179.8 degrees at node 1: valid (above the check's 1e-6), flagged
    let e = (0.1f64).to_radians().tan();
    let kite = [[0.0, 0.0], [1.0, -e], [2.0, 0.0], [1.0, 1.0]];
    assert_eq!(element::check_shape(Formulation::Q4, &kite), Ok(()));
    let qk = quality::scaled_jacobian(Formulation::Q4, &kite).unwrap();
    assert!(qk > 0.0 && qk < 0.01, "{qk}");
    let mut cw = rect;
    cw.reverse();
    assert_eq!(
        quality::scaled_jacobian(Formulation::Q4, &cw),
        Err(ShapeError::Inverted)
    );

    let unit = NODE_XI;
    assert_close(
        solid::quality::scaled_jacobian(&unit).unwrap(),
        1.0,
        1e-15,
        1.0,
        "cube",
    );
    let sheared = NODE_XI.map(|[x, y, z]| [x + theta.cos() / theta.sin() * z, y, z]);
    let qs = solid::quality::scaled_jacobian(&sheared).unwrap();
    // the edges along zeta lean by (90 deg - theta): the corner's sine is sin(theta)
    assert_close(qs, theta.sin(), 1e-14, 1.0, "sheared box");
    // sheared until its corners are nearly flat (0.3 degrees): valid, flagged
    let angle: f64 = 0.3f64.to_radians();
    let flat = NODE_XI.map(|[x, y, z]| [x + z / angle.tan(), y, z]);
    solid::check_shape(&flat, solid::ShapePolicy::Strict).unwrap();
    let qf = solid::quality::scaled_jacobian(&flat).unwrap();
    assert!(qf > 0.0 && qf < 0.01, "{qf}");
}

// ------------------------------------------------------------------------------------------
// Stress at natural coordinates

/// Deterministic pseudo-random displacements.
fn dofs(n: usize, seed: u64) -> Vec<f64> {
    let mut state = seed;
    (0..n)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            1e-3 * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
        })
        .collect()
}

const NATURAL: [[f64; 2]; 5] = [
    [0.0, 0.0],
    [-1.0, -1.0],
    [0.577, -0.3],
    [1.0, 0.25],
    [-0.8, 1.0],
];

/// The stress at natural coordinates equals the stress at the mapped physical point, for every
/// plane and axisymmetric element kind and for the 6-node hybrid element (its map runs through
/// its corners, here listed from a mid-side node); coordinates outside `[-1, 1]` are errors.
#[test]
fn stress_at_natural_coordinates_is_the_stress_at_the_mapped_point() {
    let six = [
        [1.5, 0.25],
        QUAD[1],
        QUAD[2],
        [0.75, 2.25],
        QUAD[3],
        QUAD[0],
    ];
    let ring = [[0.0, 0.0], [2.0, 0.3], [2.4, 1.9], [0.0, 1.5]];
    let cases: [(Formulation, &[[f64; 2]], Material); 6] = [
        (Formulation::Q4, &QUAD, plane(1.0)),
        (Formulation::PianSumihara, &QUAD, plane(1.0)),
        (Formulation::Hybrid, &QUAD, plane(1.0)),
        (Formulation::Hybrid, &six, plane(1.0)),
        (Formulation::Hybrid, &ring, axi(0.3)),
        (Formulation::Q4, &ring, axi(0.3)),
    ];
    for (k, (f, coords, m)) in cases.into_iter().enumerate() {
        let q = dofs(2 * coords.len(), 7 + k as u64);
        let field = element::recover_stress(f, coords, &m, &q).unwrap();
        let corners: Vec<[f64; 2]> = if coords.len() == 6 {
            vec![QUAD[1], QUAD[2], QUAD[3], QUAD[0]]
        } else {
            coords.to_vec()
        };
        let map = Bilinear::new(&corners);
        for [xi, eta] in NATURAL {
            let at_natural = field.at_natural_point(xi, eta).unwrap();
            let at_point = field.at_full(map.point(xi, eta));
            let scale = at_point.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for c in 0..4 {
                let what = format!(
                    "{f:?} {} nodes at ({xi}, {eta}), component {c}",
                    coords.len()
                );
                assert_close(at_natural[c], at_point[c], 1e-10, scale, &what);
            }
        }
        assert!(matches!(
            field.at_natural_point(1.0 + 1e-12, 0.0),
            Err(Error::InvalidInput(_))
        ));
        assert!(matches!(
            field.at_natural_point(0.0, f64::NAN),
            Err(Error::InvalidInput(_))
        ));
    }
    // a 5-node element with 3 true corners has no bilinear map
    let triangle = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0], [0.5, 0.5]];
    let field =
        element::recover_stress(Formulation::Hybrid, &triangle, &plane(1.0), &dofs(10, 1)).unwrap();
    assert!(
        matches!(field.at_natural_point(0.0, 0.0), Err(Error::InvalidInput(s)) if s.contains("3 true corners"))
    );
}

/// Bricks: the stress at natural coordinates equals the stress at the mapped point.
#[test]
fn brick_stress_at_natural_coordinates() {
    let warped = crate::common::distorted_brick();
    let m = Isotropic::new(1000.0, 0.3).unwrap();
    let map = Trilinear::new(&warped);
    for f in BrickFormulation::ALL {
        let field = solid::recover_stress(f, &warped, &m, &dofs(24, 3)).unwrap();
        for xi in [[0.0, 0.0, 0.0], [-1.0, 1.0, -1.0], [0.3, -0.7, 0.9]] {
            let a = field.at_natural_point(xi).unwrap();
            let b = field.at(map.point(xi));
            assert!(
                (a - b).amax() <= 1e-10 * b.amax(),
                "{f:?} {xi:?}: {a} vs {b}"
            );
        }
        assert!(field.at_natural_point([0.0, -1.5, 0.0]).is_err());
    }
}
