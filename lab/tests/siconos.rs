//! Siconos side by side (feature `siconos`, never in the default test run): the hand-written
//! declarations of `hycon_lab::siconos::ffi` against the installed 4.4.0 headers, Siconos'
//! residual against hycon's, and Siconos' and hycon's reactions on small problems.
//! `cargo test -p hycon-lab --features siconos --test lab siconos::`

use hycon::contact::local::LocalProblem;
use hycon_lab::siconos::ffi::{FrictionContactProblem, NumericsMatrix, SolverOptions};
use hycon_lab::siconos::{SiconosProblem, SiconosSolver};
use std::mem::{offset_of, size_of};
use std::process::Command;

/// `sizeof` and `offsetof` of every declared struct and field, as the C compiler lays them
/// out from Siconos' headers: lines `name value`.
fn c_layout() -> String {
    let dir = std::env::temp_dir().join(format!("hycon-siconos-layout-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fields: [(&str, &[&str]); 3] = [
        (
            "NumericsMatrix",
            &[
                "storageType",
                "size0",
                "size1",
                "matrix0",
                "matrix1",
                "matrix2",
                "internalData",
                "version",
                "destructible",
            ],
        ),
        (
            "FrictionContactProblem",
            &["dimension", "numberOfContacts", "M", "q", "mu"],
        ),
        (
            "SolverOptions",
            &[
                "solverId",
                "isSet",
                "iSize",
                "iparam",
                "dSize",
                "dparam",
                "filterOn",
                "dWorkSize",
                "dWork",
                "iWorkSize",
                "iWork",
                "numberOfInternalSolvers",
                "internalSolvers",
                "callback",
                "solverParameters",
                "solverData",
            ],
        ),
    ];
    let mut c = String::from(
        "#include <stdio.h>\n#include <stddef.h>\n#include \"NumericsMatrix.h\"\n\
         #include \"FrictionContactProblem.h\"\n#include \"SolverOptions.h\"\n\
         #include \"Friction_cst.h\"\nint main(void) {\n",
    );
    for (s, fs) in fields {
        c += &format!("printf(\"{s} %zu\\n\", sizeof(struct {s}));\n");
        for f in fs {
            c += &format!("printf(\"{s}.{f} %zu\\n\", offsetof(struct {s}, {f}));\n");
        }
    }
    for k in [
        "NM_DENSE",
        "SICONOS_FRICTION_3D_NSGS",
        "SICONOS_FRICTION_3D_NSN_AC",
        "SICONOS_IPARAM_MAX_ITER",
        "SICONOS_IPARAM_ITER_DONE",
        "SICONOS_DPARAM_TOL",
        "SICONOS_DPARAM_RESIDU",
        "SICONOS_FRICTION_3D_NSN_LINESEARCH",
        "SICONOS_FRICTION_3D_NSN_LINESEARCH_NO",
        "SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY",
        "SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN",
    ] {
        c += &format!("printf(\"{k} %d\\n\", (int){k});\n");
    }
    c += "return 0;\n}\n";
    let (src, exe) = (dir.join("layout.c"), dir.join("layout"));
    std::fs::write(&src, c).unwrap();
    let built = Command::new("cc")
        .args([
            "-I/usr/include/siconos/numerics",
            "-I/usr/include/siconos",
            "-o",
        ])
        .arg(&exe)
        .arg(&src)
        .output()
        .expect("a C compiler `cc`");
    assert!(
        built.status.success(),
        "{}",
        String::from_utf8_lossy(&built.stderr)
    );
    let run = Command::new(&exe).output().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    String::from_utf8(run.stdout).unwrap()
}

#[test]
fn the_declarations_match_the_installed_headers() {
    use hycon_lab::siconos::ffi;
    let rust: Vec<(&str, usize)> = vec![
        ("NumericsMatrix", size_of::<NumericsMatrix>()),
        (
            "NumericsMatrix.storageType",
            offset_of!(NumericsMatrix, storage_type),
        ),
        ("NumericsMatrix.size0", offset_of!(NumericsMatrix, size0)),
        ("NumericsMatrix.size1", offset_of!(NumericsMatrix, size1)),
        (
            "NumericsMatrix.matrix0",
            offset_of!(NumericsMatrix, matrix0),
        ),
        (
            "NumericsMatrix.matrix1",
            offset_of!(NumericsMatrix, matrix1),
        ),
        (
            "NumericsMatrix.matrix2",
            offset_of!(NumericsMatrix, matrix2),
        ),
        (
            "NumericsMatrix.internalData",
            offset_of!(NumericsMatrix, internal_data),
        ),
        (
            "NumericsMatrix.version",
            offset_of!(NumericsMatrix, version),
        ),
        (
            "NumericsMatrix.destructible",
            offset_of!(NumericsMatrix, destructible),
        ),
        (
            "FrictionContactProblem",
            size_of::<FrictionContactProblem>(),
        ),
        (
            "FrictionContactProblem.dimension",
            offset_of!(FrictionContactProblem, dimension),
        ),
        (
            "FrictionContactProblem.numberOfContacts",
            offset_of!(FrictionContactProblem, number_of_contacts),
        ),
        (
            "FrictionContactProblem.M",
            offset_of!(FrictionContactProblem, m),
        ),
        (
            "FrictionContactProblem.q",
            offset_of!(FrictionContactProblem, q),
        ),
        (
            "FrictionContactProblem.mu",
            offset_of!(FrictionContactProblem, mu),
        ),
        ("SolverOptions", size_of::<SolverOptions>()),
        (
            "SolverOptions.solverId",
            offset_of!(SolverOptions, solver_id),
        ),
        ("SolverOptions.isSet", offset_of!(SolverOptions, is_set)),
        ("SolverOptions.iSize", offset_of!(SolverOptions, i_size)),
        ("SolverOptions.iparam", offset_of!(SolverOptions, iparam)),
        ("SolverOptions.dSize", offset_of!(SolverOptions, d_size)),
        ("SolverOptions.dparam", offset_of!(SolverOptions, dparam)),
        (
            "SolverOptions.filterOn",
            offset_of!(SolverOptions, filter_on),
        ),
        (
            "SolverOptions.dWorkSize",
            offset_of!(SolverOptions, d_work_size),
        ),
        ("SolverOptions.dWork", offset_of!(SolverOptions, d_work)),
        (
            "SolverOptions.iWorkSize",
            offset_of!(SolverOptions, i_work_size),
        ),
        ("SolverOptions.iWork", offset_of!(SolverOptions, i_work)),
        (
            "SolverOptions.numberOfInternalSolvers",
            offset_of!(SolverOptions, number_of_internal_solvers),
        ),
        (
            "SolverOptions.internalSolvers",
            offset_of!(SolverOptions, internal_solvers),
        ),
        (
            "SolverOptions.callback",
            offset_of!(SolverOptions, callback),
        ),
        (
            "SolverOptions.solverParameters",
            offset_of!(SolverOptions, solver_parameters),
        ),
        (
            "SolverOptions.solverData",
            offset_of!(SolverOptions, solver_data),
        ),
    ];
    let constants: Vec<(&str, i64)> = vec![
        ("NM_DENSE", ffi::NM_DENSE.into()),
        (
            "SICONOS_FRICTION_3D_NSGS",
            ffi::SICONOS_FRICTION_3D_NSGS.into(),
        ),
        (
            "SICONOS_FRICTION_3D_NSN_AC",
            ffi::SICONOS_FRICTION_3D_NSN_AC.into(),
        ),
        (
            "SICONOS_IPARAM_MAX_ITER",
            ffi::SICONOS_IPARAM_MAX_ITER as i64,
        ),
        (
            "SICONOS_IPARAM_ITER_DONE",
            ffi::SICONOS_IPARAM_ITER_DONE as i64,
        ),
        ("SICONOS_DPARAM_TOL", ffi::SICONOS_DPARAM_TOL as i64),
        ("SICONOS_DPARAM_RESIDU", ffi::SICONOS_DPARAM_RESIDU as i64),
        (
            "SICONOS_FRICTION_3D_NSN_LINESEARCH",
            ffi::SICONOS_FRICTION_3D_NSN_LINESEARCH as i64,
        ),
        (
            "SICONOS_FRICTION_3D_NSN_LINESEARCH_NO",
            ffi::SICONOS_FRICTION_3D_NSN_LINESEARCH_NO.into(),
        ),
        (
            "SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY",
            ffi::SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY as i64,
        ),
        (
            "SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN",
            ffi::SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN.into(),
        ),
    ];
    let expected: String = rust
        .iter()
        .map(|(k, v)| format!("{k} {v}\n"))
        .chain(constants.iter().map(|(k, v)| format!("{k} {v}\n")))
        .collect();
    let mut c: Vec<&str> = Vec::new();
    let layout = c_layout();
    c.extend(layout.lines());
    let mut e: Vec<&str> = expected.lines().collect();
    c.sort_unstable();
    e.sort_unstable();
    assert_eq!(c, e);
}

/// The lab's random well-posed problem of `contacts` contacts (`local_problems::random`):
/// open, sticking and slipping contacts, some frictionless.
fn random_problem(contacts: usize, seed: u64) -> LocalProblem {
    hycon_lab::local_problems::random(contacts, 3, seed).problem
}

#[test]
fn siconos_residual_is_hycons_on_another_scale() {
    // e = hycon's residual * |q| = Siconos' * max(|q|, |r|, |u|), away from the solution
    let problem = random_problem(6, 3);
    let siconos = SiconosProblem::new(&problem).unwrap();
    let solution = problem.solve_newton().r;
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let norm_q = norm(problem.q());
    for r in [
        solution.iter().map(|v| v * 1.01).collect::<Vec<_>>(),
        solution.iter().map(|v| v * 3.0 + 0.1).collect(),
        solution.iter().map(|v| v * 0.5).collect(),
    ] {
        let scale = norm_q.max(norm(&r)).max(norm(&problem.velocity(&r)));
        let hycon = problem.natural_map_residual(&r) * norm_q;
        let theirs = siconos.compute_error(&r) * scale;
        // away from the solution: not a comparison of two roundoffs
        assert!(problem.natural_map_residual(&r) > 1e-3, "{hycon}");
        assert!((hycon - theirs).abs() <= 1e-13 * hycon, "{hycon} {theirs}");
    }
}

#[test]
fn siconos_and_hycon_find_the_same_reactions() {
    const TOLERANCE: f64 = 1e-12;
    for (contacts, seed) in [(1, 1), (4, 2), (10, 3), (20, 4)] {
        let problem = random_problem(contacts, seed);
        let hycon = problem.solve_newton();
        assert!(
            hycon.settled && hycon.residual < TOLERANCE,
            "{}",
            hycon.residual
        );
        let largest = hycon.r.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let siconos = SiconosProblem::new(&problem).unwrap();
        for solver in SiconosSolver::ALL {
            let theirs = siconos.solve(solver, TOLERANCE, 10_000);
            assert_eq!(theirs.info, 0, "{} on {contacts} contacts", solver.name());
            let difference =
                (theirs.r.iter().zip(&hycon.r)).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
            assert!(
                difference <= 1e-8 * largest,
                "{} on {contacts} contacts: {difference:e} of {largest:e}",
                solver.name()
            );
        }
    }
}

/// The cone of `mu = 0` is the half-line `r_T = 0, r_N >= 0`: a trial point below it with no
/// tangential part projects to zero (Siconos' `projectionOnCone` tests the polar cone first).
#[test]
fn an_open_frictionless_contact_has_no_residual() {
    // one frictionless contact, open at r = 0 (u = q = (1, 0, 0)): r = 0 solves it, and
    // r - P_K(r - û) = 0 - P_K((-1, 0, 0)) = 0 with the cone of mu = 0 the half-line r_T = 0,
    // r_N >= 0
    let problem = LocalProblem::new(
        3,
        nalgebra::DMatrix::identity(3, 3),
        vec![1.0, 0.0, 0.0],
        vec![0.0],
    )
    .unwrap();
    let siconos = SiconosProblem::new(&problem).unwrap();
    let r = [0.0; 3];
    assert_eq!(siconos.compute_error(&r), 0.0);
    assert_eq!(problem.natural_map_residual(&r), 0.0);
}
