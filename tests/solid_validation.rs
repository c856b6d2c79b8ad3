//! Validation of the bricks against published reference values (MacNeal and Harder, FEAD 1
//! (1985) 3-20, with their sources in docs/validation.md; docs/elements.md has the table):
//! the straight cantilever (regular, trapezoidal and parallelogram elements; extension, in-plane
//! and out-of-plane shear, twist), the twisted beam, the thick-walled cylinder (Lamé) at
//! nu = 0.3, 0.49, 0.4999 as a 3D slice with `u_z = 0`, and the 3D patch test on their mesh of
//! seven irregular bricks (with the shape policy it needs).
//!
//! `cargo test -p hycon --test integration solid_validation:: -- --nocapture` prints the table of
//! normalised results (the table of docs/elements.md).

use hycon::solid::mesh::{SolidMesh, graded};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic, ShapePolicy, check_shape};
use hycon::{Error, ShapeError, ShapeWarning};

const HYBRID: BrickFormulation = BrickFormulation::Hybrid18;
const H8: BrickFormulation = BrickFormulation::H8;

/// MacNeal-Harder straight cantilever shapes: regular, trapezoidal, parallelogram.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Shape {
    Regular,
    Trapezoidal,
    Parallelogram,
}

/// The straight cantilever: `[0, 6] x [0, 0.2] x [0, 0.1]`, 6 x 1 x 1 bricks. The trapezoidal
/// and parallelogram meshes slant the 5 interior interfaces at 45 degrees in the `x-y` plane
/// (the in-plane direction; `x += s (y - 0.1)`), alternately (`s = +1, -1, ...`) or all alike;
/// the end faces stay square, every brick keeps the volume 0.02.
fn straight_beam(shape: Shape) -> SolidMesh {
    SolidMesh::uniform([6.0, 0.2, 0.1], [6, 1, 1]).map(|[x, y, z]| {
        let i = x.round() as i32;
        let s = match shape {
            Shape::Regular => 0.0,
            _ if i == 0 || i == 6 => 0.0,
            Shape::Trapezoidal => {
                if i % 2 == 1 {
                    1.0
                } else {
                    -1.0
                }
            }
            Shape::Parallelogram => 1.0,
        };
        [x + s * (y - 0.1), y, z]
    })
}

/// The straight cantilever's load cases: the reference tip value and the tip measure.
#[derive(Debug, Clone, Copy)]
enum Load {
    Extension,
    InPlane,
    OutOfPlane,
    Twist,
}

const STRAIGHT: [(Load, f64); 4] = [
    (Load::Extension, 3.0e-5),
    (Load::InPlane, 0.1081),
    (Load::OutOfPlane, 0.4321),
    (Load::Twist, 0.03208),
];

/// Solve the cantilever clamped at `x = 0` with a unit tip load spread equally over the 4 tip
/// nodes (the twist: a unit torque as 4 forces normal to the corner radii), and return the tip
/// value: mean displacement along the load, or the mean rotation `(y u_z - z u_y) / r^2` about
/// the beam's axis.
fn cantilever(shape: Shape, load: Load, f: BrickFormulation) -> f64 {
    let mesh = straight_beam(shape);
    let m = Isotropic::new(1e7, 0.3).unwrap();
    let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
    for n in mesh.nodes_where(|p| p[0] == 0.0) {
        for d in 0..3 {
            model.fix(n, d, 0.0);
        }
    }
    let tip = mesh.nodes_where(|p| p[0] == 6.0);
    assert_eq!(tip.len(), 4);
    let arm = |n: usize| (mesh.nodes[n][1] - 0.1, mesh.nodes[n][2] - 0.05);
    for &n in &tip {
        let (y, z) = arm(n);
        let r2 = y * y + z * z;
        let force = match load {
            Load::Extension => [0.25, 0.0, 0.0],
            Load::InPlane => [0.0, 0.25, 0.0],
            Load::OutOfPlane => [0.0, 0.0, 0.25],
            Load::Twist => [0.0, -z / (4.0 * r2), y / (4.0 * r2)],
        };
        model.load(n, force);
    }
    let sol = model.solve().unwrap();
    let mean = |g: &dyn Fn(usize) -> f64| tip.iter().map(|&n| g(n)).sum::<f64>() / 4.0;
    match load {
        Load::Extension => mean(&|n| sol.at(n)[0]),
        Load::InPlane => mean(&|n| sol.at(n)[1]),
        Load::OutOfPlane => mean(&|n| sol.at(n)[2]),
        Load::Twist => mean(&|n| {
            let (y, z) = arm(n);
            let u = sol.at(n);
            (y * u[2] - z * u[1]) / (y * y + z * z)
        }),
    }
}

/// MacNeal and Harder's HEX8 column (OptiStruct's, normalised; docs/validation.md, "MacNeal and Harder's 3D problems") for the three
/// bending loads and extension: a brick with incompatible modes, to which Pian and Tong's
/// 18-beta field is the hybrid counterpart.
const PUBLISHED_HEX8: [(Shape, [f64; 3]); 3] = [
    (Shape::Regular, [0.988, 0.978, 0.973]),
    (Shape::Trapezoidal, [1.010, 0.047, 0.030]),
    (Shape::Parallelogram, [1.012, 0.624, 0.529]),
];

/// The hybrid brick against MacNeal and Harder's reference values, with the displacement brick
/// beside it. Checked: within 2.5% of the reference in extension and bending on regular bricks;
/// within 0.07 of the published HEX8 (incompatible modes) on every shape for extension and
/// bending (the trapezoidal mesh locks every 8-node brick that passes the patch test, as MacNeal
/// showed; the hybrid brick does not escape it); never below the H8; twist within 12% (one
/// brick over the section cannot carry the warping of Saint-Venant's torsion).
#[test]
fn macneal_harder_straight_cantilever() {
    println!("| shape | load | hybrid18 | h8 |");
    println!("|---|---|---|---|");
    let table = std::env::var_os("HYCON_TABLE").is_some();
    for (shape, published) in PUBLISHED_HEX8 {
        for (i, (load, reference)) in STRAIGHT.into_iter().enumerate() {
            let hy = cantilever(shape, load, HYBRID) / reference;
            let h8 = cantilever(shape, load, H8) / reference;
            println!("| {shape:?} | {load:?} | {hy:.3} | {h8:.3} |");
            if table {
                continue;
            }
            assert!(hy >= h8 - 1e-9, "{shape:?} {load:?}: {hy} below h8 {h8}");
            match load {
                Load::Twist => assert!((hy - 1.0).abs() < 0.12, "{shape:?} twist: {hy}"),
                _ => {
                    let p = published[i];
                    assert!((hy - p).abs() < 0.07, "{shape:?} {load:?}: {hy} vs {p}");
                    if shape == Shape::Regular {
                        assert!((hy - 1.0).abs() < 0.025, "{shape:?} {load:?}: {hy}");
                    }
                }
            }
            if shape == Shape::Regular && matches!(load, Load::InPlane | Load::OutOfPlane) {
                assert!(h8 < 0.1, "{shape:?} {load:?}: h8 {h8} should lock");
            }
        }
    }
}

/// The twisted beam: `L = 12`, width 1.1, depth 0.32, 90 degrees of twist, E = 29e6,
/// nu = 0.22, 12 x 2 x 1 bricks, clamped at the root, a unit tip load spread consistently over
/// the tip face (uniform traction). Tip deflection along the load, mean over the tip nodes.
fn twisted_beam(dir: usize, f: BrickFormulation) -> f64 {
    let mesh = SolidMesh::block(
        &graded(0.0, 12.0, 12, 1.0),
        &graded(-0.55, 0.55, 2, 1.0),
        &graded(-0.16, 0.16, 1, 1.0),
    )
    .map(|[x, y, z]| {
        let a = std::f64::consts::FRAC_PI_2 * x / 12.0;
        [x, y * a.cos() - z * a.sin(), y * a.sin() + z * a.cos()]
    });
    let m = Isotropic::new(29e6, 0.22).unwrap();
    let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
    for n in mesh.nodes_where(|p| p[0] == 0.0) {
        for d in 0..3 {
            model.fix(n, d, 0.0);
        }
    }
    let tip_faces = mesh.faces_where(|p| (p[0] - 12.0).abs() < 1e-9);
    assert_eq!(tip_faces.len(), 2);
    let area = 1.1 * 0.32;
    let mut t = [0.0; 3];
    t[dir] = 1.0 / area;
    model.load_faces(&tip_faces, |_, _| t);
    let sol = model.solve().unwrap();
    let tip = mesh.nodes_where(|p| (p[0] - 12.0).abs() < 1e-9);
    tip.iter().map(|&n| sol.at(n)[dir]).sum::<f64>() / tip.len() as f64
}

/// Twisted beam: the load along the tip's width (`z` at the tip) is MacNeal and Harder's
/// in-plane case (5.424e-3), along the tip's depth (`y`) the out-of-plane case (1.754e-3).
#[test]
fn macneal_harder_twisted_beam() {
    println!("| twisted beam | hybrid18 | h8 |");
    println!("|---|---|---|");
    for (dir, name, reference) in [(2, "in-plane", 5.424e-3), (1, "out-of-plane", 1.754e-3)] {
        let hy = twisted_beam(dir, HYBRID) / reference;
        let h8 = twisted_beam(dir, H8) / reference;
        println!("| {name} | {hy:.3} | {h8:.3} |");
        assert!((hy - 1.0).abs() < 0.05, "{name}: hybrid {hy}");
        assert!(h8 < hy, "{name}: h8 {h8} vs hybrid {hy}");
    }
}

/// The curved beam: a 90 degree arc, radii 4.12 and 4.32, depth 0.1, E = 1e7, nu = 0.25, 6 x 1
/// x 1 bricks, `(theta, r, z) -> (r sin theta, r cos theta, z)`, clamped at `theta = 0`
/// (`x = 0`), a unit load at the free end (`theta = 90` degrees: `y = 0`, the axis along `-y`)
/// spread equally over the 4 tip nodes: in-plane along the radius (`x`), out-of-plane along `z`.
/// Tip deflection along the load, mean over the tip nodes.
fn curved_beam(dir: usize, f: BrickFormulation) -> f64 {
    let mesh = SolidMesh::block(
        &graded(0.0, std::f64::consts::FRAC_PI_2, 6, 1.0),
        &[4.12, 4.32],
        &[0.0, 0.1],
    )
    .map(|[t, r, z]| [r * t.sin(), r * t.cos(), z]);
    let m = Isotropic::new(1e7, 0.25).unwrap();
    let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
    let tip = mesh.nodes_where(|p| p[1].abs() < 1e-9);
    for n in mesh.nodes_where(|p| p[0].abs() < 1e-9) {
        for d in 0..3 {
            model.fix(n, d, 0.0);
        }
    }
    assert_eq!(tip.len(), 4);
    for &n in &tip {
        let mut force = [0.0; 3];
        force[dir] = 0.25;
        model.load(n, force);
    }
    let sol = model.solve().unwrap();
    tip.iter().map(|&n| sol.at(n)[dir]).sum::<f64>() / 4.0
}

/// Curved beam against MacNeal and Harder's references (in-plane 0.08734, out-of-plane 0.5022):
/// with one brick through a section 20 times thinner than the radius and elements 6 times longer
/// than deep, the hybrid brick reaches 0.880 and 0.835, within 0.03 of the published HEX8
/// (0.880, 0.820: incompatible modes, its counterpart); the H8 locks (0.073, 0.231).
#[test]
fn macneal_harder_curved_beam() {
    println!("| curved beam | hybrid18 | h8 |");
    println!("|---|---|---|");
    for (dir, name, reference, published) in [
        (0, "in-plane", 0.08734, 0.880),
        (2, "out-of-plane", 0.5022, 0.820),
    ] {
        let hy = curved_beam(dir, HYBRID) / reference;
        let h8 = curved_beam(dir, H8) / reference;
        println!("| {name} | {hy:.3} | {h8:.3} |");
        if std::env::var_os("HYCON_TABLE").is_some() {
            continue;
        }
        assert!(
            (hy - published).abs() < 0.03,
            "{name}: hybrid {hy} vs {published}"
        );
        assert!(h8 < 0.3 * hy, "{name}: h8 {h8} vs hybrid {hy}");
    }
}

/// The thick-walled cylinder, `a = 3`, `b = 9`, `E = 1000`, internal pressure 1, plane strain as
/// a 3D slice (quarter, 5 bricks through the wall, 12 round, 1 thick, `u_z = 0` everywhere;
/// symmetry on the cut planes). Inner radial displacement against Lamé's `u_r(a)`.
fn thick_cylinder(nu: f64, f: BrickFormulation) -> f64 {
    let (a, b) = (3.0, 9.0);
    let mesh = SolidMesh::block(
        &graded(a, b, 5, 1.0),
        &graded(0.0, std::f64::consts::FRAC_PI_2, 12, 1.0),
        &[0.0, 1.0],
    )
    .map(|[r, t, z]| [r * t.cos(), r * t.sin(), z]);
    let m = Isotropic::new(1000.0, nu).unwrap();
    let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
    for (n, p) in mesh.nodes.iter().enumerate() {
        model.fix(n, 2, 0.0);
        if p[1].abs() < 1e-9 {
            model.fix(n, 1, 0.0);
        }
        if p[0].abs() < 1e-9 {
            model.fix(n, 0, 0.0);
        }
    }
    let radius = |p: [f64; 3]| (p[0] * p[0] + p[1] * p[1]).sqrt();
    let inner = mesh.faces_where(|p| (radius(p) - a).abs() < 1e-9);
    assert_eq!(inner.len(), 12);
    model.load_faces(&inner, |_, n| [-n[0], -n[1], -n[2]]);
    let sol = model.solve().unwrap();
    let nodes = mesh.nodes_where(|p| (radius(p) - a).abs() < 1e-9);
    nodes
        .iter()
        .map(|&n| {
            let (p, u) = (mesh.nodes[n], sol.at(n));
            (p[0] * u[0] + p[1] * u[1]) / a
        })
        .sum::<f64>()
        / nodes.len() as f64
}

/// Lamé's `u_r(a)` (the VALIDATION table's values, checked here from the formula first), and the
/// hybrid brick within 3% at every `nu` (the error of 5 bricks through the wall, which the H8
/// shares at nu = 0.3) and unchanged to 1% as `nu -> 0.5`, while the H8 locks.
#[test]
fn thick_cylinder_near_incompressibility() {
    let lame = |nu: f64| {
        let (a, b, p, e) = (3.0f64, 9.0f64, 1.0, 1000.0);
        let bb = p * a * a * b * b / (b * b - a * a);
        let aa = bb / (b * b);
        let (sr, st) = (aa - bb / (a * a), aa + bb / (a * a));
        a * (1.0 + nu) / e * ((1.0 - nu) * st - nu * sr)
    };
    for (nu, published) in [(0.3, 4.58250e-3), (0.49, 5.03992e-3), (0.4999, 5.06227e-3)] {
        assert!((lame(nu) / published - 1.0).abs() < 1e-5, "Lamé at nu {nu}");
    }
    println!("| nu | hybrid18 | h8 |");
    println!("|---|---|---|");
    let at_03 = thick_cylinder(0.3, HYBRID) / lame(0.3);
    for nu in [0.3, 0.49, 0.4999] {
        let hy = thick_cylinder(nu, HYBRID) / lame(nu);
        let h8 = thick_cylinder(nu, H8) / lame(nu);
        println!("| {nu} | {hy:.4} | {h8:.4} |");
        if std::env::var_os("HYCON_TABLE").is_some() {
            continue;
        }
        assert!((hy - 1.0).abs() < 0.03, "nu {nu}: hybrid {hy}");
        assert!(
            (hy - at_03).abs() < 0.01,
            "nu {nu}: hybrid {hy} vs {at_03} at nu = 0.3"
        );
        if nu > 0.49 {
            assert!(h8 < 0.1, "nu {nu}: h8 {h8} should lock");
        }
    }
}

/// Saint-Venant's end-loaded cantilever with `nu = 0` (Timoshenko and Goodier, section 21),
/// where the plane solution is exact in 3D with `w = 0`: beam `[0, L] x [-c, c] x [-b/2, b/2]`,
/// `L = 10`, `c = 0.5`, `b = 1`, E = 1000, end shear P = 1 at the free end `x = 0`, the exact
/// displacements held on the root face `x = L`:
///
/// ```text
/// sx = -P x y / I,  txy = -P (c^2 - y^2) / (2 I),  sy = sz = tyz = tzx = 0
/// u  = -P x^2 y / (2 E I) + P y^3 / (6 I G) + (P L^2 / (2 E I) - P c^2 / (2 I G)) y
/// v  =  P x^3 / (6 E I) - P L^2 x / (2 E I) + P L^3 / (3 E I),  w = 0
/// ```
fn saint_venant(p: [f64; 3]) -> ([f64; 3], [f64; 6]) {
    let (l, c, b, e): (f64, f64, f64, f64) = (10.0, 0.5, 1.0, 1000.0);
    let g = e / 2.0;
    let i = b * (2.0 * c).powi(3) / 12.0;
    let [x, y, _] = p;
    let u = -x * x * y / (2.0 * e * i)
        + y.powi(3) / (6.0 * i * g)
        + (l * l / (2.0 * e * i) - c * c / (2.0 * i * g)) * y;
    let v = x.powi(3) / (6.0 * e * i) - l * l * x / (2.0 * e * i) + l.powi(3) / (3.0 * e * i);
    let s = [-x * y / i, 0.0, 0.0, -(c * c - y * y) / (2.0 * i), 0.0, 0.0];
    ([u, v, 0.0], s)
}

/// Largest nodal displacement error over the largest displacement, for a mesh of
/// `4k x k x k` bricks (distorted: interior nodes moved by up to 20% of their shortest edge).
fn saint_venant_error(k: usize, distorted: bool, f: BrickFormulation) -> (usize, f64) {
    let mut mesh = SolidMesh::block(
        &graded(0.0, 10.0, 4 * k, 1.0),
        &graded(-0.5, 0.5, k, 1.0),
        &graded(-0.5, 0.5, k, 1.0),
    );
    if distorted {
        mesh = mesh.distort(0.2, 11, |p| {
            p[0] > 1e-9 && p[0] < 10.0 - 1e-9 && p[1].abs() < 0.5 - 1e-9 && p[2].abs() < 0.5 - 1e-9
        });
    }
    let m = Isotropic::new(1000.0, 0.0).unwrap();
    let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
    for n in mesh.nodes_where(|p| (p[0] - 10.0).abs() < 1e-12) {
        let (u, _) = saint_venant(mesh.nodes[n]);
        for (d, ud) in u.into_iter().enumerate() {
            model.fix(n, d, ud);
        }
    }
    let free_end = mesh.faces_where(|p| p[0].abs() < 1e-12);
    model.load_faces(&free_end, |x, n| {
        let (_, s) = saint_venant(x);
        let s = nalgebra::SVector::<f64, 6>::from(s);
        hycon::solid::traction(&s, n)
    });
    let sol = model.solve().unwrap();
    let (mut err, mut max): (f64, f64) = (0.0, 0.0);
    for (n, &p) in mesh.nodes.iter().enumerate() {
        for (got, want) in sol.at(n).into_iter().zip(saint_venant(p).0) {
            err = err.max((got - want).abs());
            max = max.max(want.abs());
        }
    }
    (sol.n_free, err / max)
}

/// Convergence on Saint-Venant's beam: the exact field first checked against its own stresses
/// (strain of the displacements = `S sigma`, by central differences), then the error against
/// dofs for both bricks on regular and distorted meshes. The hybrid brick is below 2% on the
/// coarsest mesh, more accurate than the H8 on every mesh, its error falls with each refinement
/// (on regular meshes as `h^2`: by 4 per halving; on meshes distorted at random by 20% at every
/// level, slowly: 1.6%, 1.4%, 1.1%); the H8 starts locked (76%).
#[test]
fn saint_venant_convergence() {
    let h = 1e-4;
    for p in [[3.0, 0.2, 0.1], [7.5, -0.4, -0.3]] {
        let (_, s) = saint_venant(p);
        let du = |a: usize, d: usize| {
            let (mut q, mut r) = (p, p);
            q[a] += h;
            r[a] -= h;
            (saint_venant(q).0[d] - saint_venant(r).0[d]) / (2.0 * h)
        };
        let strain = [du(0, 0), du(1, 1), du(2, 2), du(1, 0) + du(0, 1)];
        let (e, g) = (1000.0, 500.0);
        let expect = [s[0] / e, 0.0, 0.0, s[3] / g];
        for i in 0..4 {
            assert!(
                (strain[i] - expect[i]).abs() < 1e-8,
                "exact field: strain {i}"
            );
        }
    }
    println!("| mesh | dofs | hybrid18 | h8 |");
    println!("|---|---|---|---|");
    for distorted in [false, true] {
        let mut last = f64::INFINITY;
        for k in [1, 2, 4] {
            let (dofs, hy) = saint_venant_error(k, distorted, HYBRID);
            let (_, h8) = saint_venant_error(k, distorted, H8);
            let name = if distorted { "distorted" } else { "regular" };
            println!(
                "| {name} {}x{k}x{k} | {dofs} | {hy:.2e} | {h8:.2e} |",
                4 * k
            );
            assert!(hy < h8, "{name} k {k}: hybrid {hy} vs h8 {h8}");
            assert!(hy < last, "{name} k {k}: {hy} after {last}");
            assert!(hy < 0.02, "{name} k {k}: {hy}");
            if !distorted && k > 1 {
                assert!(last / hy > 3.5, "regular k {k}: rate {}", last / hy);
            }
            last = hy;
            if k == 1 {
                assert!(h8 > 0.3, "{name}: h8 {h8} should lock on the coarse mesh");
            }
        }
    }
}

/// MacNeal and Harder's 3D patch test mesh: the unit cube (nodes 0-7, in the brick order) around
/// an irregular inner brick (nodes 8-15, node `8 + i` near corner `i`), joined by six bricks, one
/// per face of the cube: centre, bottom, top, front (`y = 0`), back, left (`x = 0`), right.
fn macneal_harder_patch() -> SolidMesh {
    let nodes = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
        [0.249, 0.342, 0.192],
        [0.826, 0.288, 0.288],
        [0.850, 0.649, 0.263],
        [0.273, 0.750, 0.230],
        [0.320, 0.186, 0.643],
        [0.677, 0.305, 0.683],
        [0.788, 0.693, 0.644],
        [0.165, 0.745, 0.702],
    ];
    let elements = vec![
        [8, 9, 10, 11, 12, 13, 14, 15],
        [0, 1, 2, 3, 8, 9, 10, 11],
        [12, 13, 14, 15, 4, 5, 6, 7],
        [0, 1, 9, 8, 4, 5, 13, 12],
        [11, 10, 2, 3, 15, 14, 6, 7],
        [0, 8, 11, 3, 4, 12, 15, 7],
        [9, 1, 2, 10, 13, 5, 6, 14],
    ];
    let element_material = vec![0; elements.len()];
    SolidMesh {
        nodes,
        elements,
        element_material,
        ..Default::default()
    }
}

/// The patch test's displacement field, `1e-3 (2x + y + z, x + 2y + z, x + y + 2z) / 2`: with
/// `E = 1e6`, `nu = 0.25` the stress `sigma_x = sigma_y = sigma_z = 2000`, every shear 400.
fn patch_field([x, y, z]: [f64; 3]) -> [f64; 3] {
    [
        1e-3 * (2.0 * x + y + z) / 2.0,
        1e-3 * (x + 2.0 * y + z) / 2.0,
        1e-3 * (x + y + 2.0 * z) / 2.0,
    ]
}

/// MacNeal-Harder's 3D patch test at its full distortion, which the strict policy (0.8's check)
/// rejects: the front brick has `det J = -0.0016` at its corner node 7 (positive at every
/// integration point, at least 0.0063) and the face it shares with the left brick is warped by 48
/// degrees (35 on the other diagonal). The default policy runs it with those three warnings and
/// both bricks are exact: the interior displacements to 1e-13 of the field, every brick's stress
/// at its centre and corners to 1e-10 of 2000.
#[test]
fn macneal_harder_patch_test() {
    let mesh = macneal_harder_patch();
    // the measures the policies judge
    let front = check_shape(&mesh.element_coords(3), ShapePolicy::default()).unwrap();
    assert!((front.corner_jacobian + 0.00158).abs() < 5e-6, "{front:?}");
    assert!(
        (front.integration_jacobian - 0.00634).abs() < 5e-6,
        "{front:?}"
    );
    let warnings = mesh.check(ShapePolicy::default()).unwrap();
    let [
        (3, ShapeWarning::CornerJacobian { node: 7, relative }),
        (
            3,
            ShapeWarning::WarpedFace {
                face: 0,
                degrees: a,
            },
        ),
        (
            5,
            ShapeWarning::WarpedFace {
                face: 2,
                degrees: b,
            },
        ),
    ] = warnings[..]
    else {
        panic!("{warnings:?}");
    };
    assert_eq!(relative, front.corner_jacobian);
    assert!((a - 48.0).abs() < 0.05 && a == b, "{a} {b}");
    // strict: 0.8's errors and messages
    assert_eq!(
        mesh.check(ShapePolicy::Strict),
        Err(Error::at_element(ShapeError::InvertedCorner { node: 7 }, 3))
    );
    let left = check_shape(&mesh.element_coords(5), ShapePolicy::Strict);
    assert_eq!(left, Err(ShapeError::WarpedFace { face: 2 }));
    assert_eq!(
        left.unwrap_err().to_string(),
        "face 2 is warped beyond the limit (see the face numbering of the brick)"
    );

    let m = Isotropic::new(1e6, 0.25).unwrap();
    let exact = [2000.0, 2000.0, 2000.0, 400.0, 400.0, 400.0];
    for f in BrickFormulation::ALL {
        let mut model = SolidModel::new(mesh.clone(), vec![m], f).unwrap();
        for n in 0..8 {
            for (d, u) in patch_field(mesh.nodes[n]).into_iter().enumerate() {
                model.fix(n, d, u);
            }
        }
        let sol = model.solve().unwrap();
        let mut u_err: f64 = 0.0;
        for n in 8..16 {
            for (got, want) in sol.at(n).into_iter().zip(patch_field(mesh.nodes[n])) {
                u_err = u_err.max((got - want).abs() / 2e-3);
            }
        }
        let mut s_err: f64 = 0.0;
        for e in 0..mesh.n_elements() {
            let field = model.element_stress(&sol, e).unwrap();
            let mut points = vec![[0.0; 3]];
            points.extend(hycon::solid::geometry::NODE_XI);
            for xi in points {
                let s = field.at_natural(xi);
                for (got, want) in s.iter().zip(exact) {
                    s_err = s_err.max((got - want).abs() / 2000.0);
                }
            }
        }
        println!(
            "MacNeal-Harder 3D patch, {}: displacement error {u_err:.1e}, stress error {s_err:.1e}",
            f.name()
        );
        assert!(u_err < 1e-13, "{f:?}: displacement error {u_err:e}");
        assert!(s_err < 1e-10, "{f:?}: stress error {s_err:e}");
    }
}
