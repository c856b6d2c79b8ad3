//! Validation of the bricks against published reference values (MacNeal and Harder, FEAD 1
//! (1985) 3-20, as collected for the project; the README's brick section has the table):
//! the straight cantilever (regular, trapezoidal and parallelogram elements; extension, in-plane
//! and out-of-plane shear, twist), the twisted beam, and the thick-walled cylinder (Lamé) at
//! nu = 0.3, 0.49, 0.4999 as a 3D slice with `u_z = 0`.
//!
//! `cargo test -p hycon --test solid_validation -- --nocapture` prints the table of
//! normalised results (the README's table).

use hycon::solid::mesh::{SolidMesh, graded};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};

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

/// MacNeal and Harder's HEX8 column (OptiStruct's, normalised; VALIDATION.md) for the three
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
