//! FCLIB's local problem files (feature `fclib`): the round trip through libfclib (write, read
//! back bit for bit, solve with hycon's solvers, same reactions), libfclib's merit function
//! against hycon's residual, damaged and foreign files refused with clear errors, and the
//! `hycon fclib` commands.

use hdf5::Values;
use hycon::contact::local::LocalProblem;
use hycon_lab::fclib::{self, Error, Metadata};
use hycon_lab::local_problems;
use nalgebra::DMatrix;
use std::ffi::{CString, c_char, c_int, c_uint};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A scratch directory of this test (removed on drop).
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("hycon-fclib-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create the scratch directory");
        Scratch(dir)
    }
    fn file(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A reproducible sequence in [0, 1) (xorshift64*).
struct Sequence(u64);

impl Sequence {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// A 3D problem of `n` contacts with a known solution `r*`: `W` symmetric positive definite
/// and block-banded (contacts coupled to their neighbours only, so its CSC has exact zeros
/// to drop), the contacts in turn open (`r = 0`, `u_N > 0`), sticking (`r` inside the cone,
/// `u = 0`) and slipping (`r` on the cone, `u_N = 0`, `u_T` against `r_T`), and
/// `q = u* - W r*`. `W`'s diagonal dominates, so the solution is unique for these `mu`.
fn known_problem(n: usize, seed: u64) -> (LocalProblem, Vec<f64>) {
    let mut s = Sequence(seed);
    let m = 3 * n;
    let mut w = DMatrix::zeros(m, m);
    for i in 0..m {
        for j in 0..=i {
            if i / 3 <= j / 3 + 1 {
                let v = s.between(-0.2, 0.2);
                w[(i, j)] = v;
                w[(j, i)] = v;
            }
        }
        w[(i, i)] = s.between(2.0, 3.0);
    }
    let (mut r, mut u, mut mu) = (vec![0.0; m], vec![0.0; m], Vec::new());
    for c in 0..n {
        let f = s.between(0.1, 0.4);
        mu.push(f);
        let angle = s.between(0.0, std::f64::consts::TAU);
        let (cos, sin) = (angle.cos(), angle.sin());
        let k = 3 * c;
        match c % 3 {
            0 => u[k..k + 3].copy_from_slice(&[s.between(0.1, 1.0), s.next(), -s.next()]),
            1 => {
                let (rn, t) = (s.between(0.5, 2.0), s.between(0.0, 0.9));
                r[k..k + 3].copy_from_slice(&[rn, t * f * rn * cos, t * f * rn * sin]);
            }
            _ => {
                let (rn, slip) = (s.between(0.5, 2.0), s.between(0.1, 1.0));
                r[k..k + 3].copy_from_slice(&[rn, f * rn * cos, f * rn * sin]);
                u[k..k + 3].copy_from_slice(&[0.0, -slip * cos, -slip * sin]);
            }
        }
    }
    let wr = &w * nalgebra::DVector::from_column_slice(&r);
    let q = (0..m).map(|i| u[i] - wr[i]).collect();
    (LocalProblem::new(3, w, q, mu).expect("a valid problem"), r)
}

fn metadata(title: &str) -> Metadata {
    Metadata {
        title: title.into(),
        description: "a hycon test problem with a known solution".into(),
        math_info: "W symmetric positive definite".into(),
    }
}

fn largest_difference(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = a
        .iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    diff / scale
}

#[test]
fn the_known_problem_is_solved_by_its_reactions() {
    // the construction itself: r* meets the conditions exactly (up to round-off of q)
    let (problem, r) = known_problem(9, 7);
    assert!(problem.natural_map_residual(&r) < 1e-14);
    let perturbed: Vec<f64> = r.iter().map(|v| v * 1.01).collect();
    assert!(problem.natural_map_residual(&perturbed) > 1e-4);
}

#[test]
fn round_trip_is_bit_identical_and_solves_to_the_stored_reactions() {
    let dir = Scratch::new("round-trip");
    let (problem, r) = known_problem(12, 3);
    let path = dir.file("known.hdf5");
    fclib::write_local(&path, &problem, Some(&r), &metadata("known 12")).unwrap();
    let (back, solution, info) = fclib::read_local_with_info(&path).unwrap();
    assert_eq!(back, problem, "W, q, mu and dim read back bit for bit");
    assert_eq!(
        solution.as_deref(),
        Some(r.as_slice()),
        "the stored r, bit for bit"
    );
    assert_eq!(info, metadata("known 12"));
    // hycon's Newton method on the problem read back finds the stored reactions
    let solve = back.solve_newton();
    assert!(solve.settled, "residual {:.3e}", solve.residual);
    assert!(solve.residual < 1e-12, "residual {:.3e}", solve.residual);
    let diff = largest_difference(&solve.r, &r);
    assert!(diff < 1e-10, "largest difference {diff:.3e} of max |r|");
}

#[test]
fn a_3d_increment_round_trips_and_solves_to_the_analysis_reactions() {
    // the half cap pulled to Q / (mu P) = 0.5: sticking inside, slipping around (mu = 0.3)
    let dir = Scratch::new("mindlin3d");
    let named = local_problems::mindlin3d(3)
        .unwrap()
        .pop()
        .expect("the pull");
    let r = named.solution.expect("an analysis' reactions");
    let path = dir.file("pull.hdf5");
    fclib::write_local(&path, &named.problem, Some(&r), &metadata(&named.name)).unwrap();
    let (back, solution) = fclib::read_local(&path).unwrap();
    assert_eq!(
        back, named.problem,
        "W, q, mu and dim read back bit for bit"
    );
    assert_eq!(solution.as_deref(), Some(r.as_slice()));
    let stored = back.natural_map_residual(&r);
    let solve = back.solve_newton();
    assert!(solve.settled, "residual {:.3e}", solve.residual);
    assert!(
        solve.residual <= stored.max(1e-12),
        "{:.3e} > {stored:.3e}",
        solve.residual
    );
    let diff = largest_difference(&solve.r, &r);
    assert!(diff < 1e-9, "largest difference {diff:.3e} of max |r|");
    let slipping = (0..back.contacts()).filter(|&c| {
        let rc = &r[3 * c..3 * c + 3];
        rc[0] > 0.0 && (rc[1].hypot(rc[2]) - back.mu()[c] * rc[0]).abs() < 1e-9 * rc[0]
    });
    assert!(slipping.count() > 0, "the pull has slipping contacts");
}

#[test]
fn writing_again_replaces_the_file_and_a_solution_is_optional() {
    let dir = Scratch::new("replace");
    let path = dir.file("p.hdf5");
    let (first, r) = known_problem(3, 11);
    fclib::write_local(&path, &first, Some(&r), &metadata("first")).unwrap();
    let (second, _) = known_problem(4, 12);
    fclib::write_local(&path, &second, None, &metadata("second")).unwrap();
    let (back, solution, info) = fclib::read_local_with_info(&path).unwrap();
    assert_eq!(
        (back, solution, info.title),
        (second, None, "second".into())
    );
}

#[test]
fn a_solution_of_the_wrong_length_is_refused() {
    let dir = Scratch::new("short-solution");
    let (problem, r) = known_problem(3, 5);
    let err = fclib::write_local(&dir.file("p.hdf5"), &problem, Some(&r[1..]), &metadata("p"))
        .unwrap_err();
    assert!(
        err.to_string()
            .contains("the solution has 8 entries, W has 9 rows"),
        "{err}"
    );
}

#[test]
fn fclib_merit_agrees_with_hycons_residual_up_to_the_normalisation() {
    // libfclib 3.1: sqrt(sum |r_i - P_K(r_i - û_i)|^2) / (1 + sqrt(|q|)); hycon (Siconos'
    // fc3d_compute_error): the same sum's root over |q|
    let (problem, r) = known_problem(10, 21);
    let off: Vec<f64> = r
        .iter()
        .enumerate()
        .map(|(i, v)| v + 0.01 * (i % 5) as f64)
        .collect();
    let norm_q = problem.q().iter().map(|v| v * v).sum::<f64>().sqrt();
    let merit = fclib::merit(&problem, &off).expect("3D");
    let hycon = problem.natural_map_residual(&off);
    assert!(hycon > 1e-4, "the perturbation shows: {hycon:.3e}");
    let expected = hycon * norm_q / (1.0 + norm_q.sqrt());
    assert!(
        (merit - expected).abs() <= 1e-12 * expected,
        "fclib {merit:.15e} against {expected:.15e}"
    );
    assert!(fclib::merit(&problem, &r).expect("3D") < 1e-14);
}

#[test]
fn fclib_has_no_merit_in_2d() {
    let problem = LocalProblem::new(2, DMatrix::identity(2, 2), vec![-1.0, 0.5], vec![0.3]);
    assert_eq!(fclib::merit(&problem.unwrap(), &[1.0, 0.0]), None);
}

#[test]
fn a_plane_problem_round_trips() {
    let dir = Scratch::new("plane");
    let w = DMatrix::from_row_slice(
        4,
        4,
        &[
            2.0, 0.5, 0.25, 0.0, //
            0.5, 1.5, 0.0, 0.125, //
            0.25, 0.0, 2.5, -0.5, //
            0.0, 0.125, -0.5, 1.0,
        ],
    );
    let problem = LocalProblem::new(2, w, vec![-1.0, 0.3, 0.2, -0.1], vec![0.2, 0.5]).unwrap();
    let solve = problem.solve_newton();
    assert!(solve.residual < 1e-12);
    let path = dir.file("plane.hdf5");
    fclib::write_local(&path, &problem, Some(&solve.r), &metadata("plane")).unwrap();
    let (back, solution) = fclib::read_local(&path).unwrap();
    assert_eq!(back, problem);
    assert_eq!(solution, Some(solve.r));
}

#[test]
fn missing_and_foreign_files_are_refused() {
    let dir = Scratch::new("foreign");
    let missing = fclib::read_local(&dir.file("nothing.hdf5")).unwrap_err();
    assert!(matches!(missing, Error::Io(..)), "{missing}");
    assert!(missing.to_string().contains("cannot open it"), "{missing}");
    let text = dir.file("text.hdf5");
    std::fs::write(&text, "u = W r + q\n").unwrap();
    let foreign = fclib::read_local(&text).unwrap_err();
    assert!(matches!(foreign, Error::Format(..)), "{foreign}");
    assert!(
        foreign.to_string().contains("not an HDF5 file"),
        "{foreign}"
    );
}

/// The HDF5 calls that damage a valid file (hdf5_serial is linked through hycon-lab).
mod hdf5 {
    use super::{CString, Path, c_char, c_int, c_uint};

    type Hid = i64;
    unsafe extern "C" {
        fn H5Fopen(name: *const c_char, flags: c_uint, fapl: Hid) -> Hid;
        fn H5Fclose(id: Hid) -> c_int;
        fn H5Ldelete(loc: Hid, name: *const c_char, lapl: Hid) -> c_int;
        fn H5LTmake_dataset_double(
            loc: Hid,
            name: *const c_char,
            rank: c_int,
            dims: *const u64,
            data: *const f64,
        ) -> c_int;
        fn H5LTmake_dataset_int(
            loc: Hid,
            name: *const c_char,
            rank: c_int,
            dims: *const u64,
            data: *const c_int,
        ) -> c_int;
    }

    /// The values of a replaced dataset.
    #[derive(Clone, Copy)]
    pub enum Values<'a> {
        Doubles(&'a [f64]),
        Ints(&'a [c_int]),
    }

    /// Deletes `dataset` from the HDF5 file at `path`, and writes `values` in its place.
    pub fn replace(path: &Path, dataset: &str, values: Option<Values>) {
        let (file, name) = (
            CString::new(path.to_str().unwrap()).unwrap(),
            CString::new(dataset).unwrap(),
        );
        // SAFETY: NUL-terminated names, buffers of the lengths given.
        unsafe {
            let id = H5Fopen(file.as_ptr(), 1, 0);
            assert!(id >= 0, "open {}", path.display());
            assert!(H5Ldelete(id, name.as_ptr(), 0) >= 0, "delete {dataset}");
            let written = match values {
                Some(Values::Doubles(v)) => {
                    H5LTmake_dataset_double(id, name.as_ptr(), 1, &(v.len() as u64), v.as_ptr())
                }
                Some(Values::Ints(v)) => {
                    H5LTmake_dataset_int(id, name.as_ptr(), 1, &(v.len() as u64), v.as_ptr())
                }
                None => 0,
            };
            assert!(written >= 0, "write {dataset}");
            assert!(H5Fclose(id) >= 0);
        }
    }
}

/// A valid file of a 2-contact problem, then `dataset` replaced by `values` (deleted if none):
/// the error it reads with.
fn damaged(name: &str, dataset: &str, values: Option<Values>) -> Error {
    let dir = Scratch::new(name);
    let path = dir.file("p.hdf5");
    let (problem, r) = known_problem(2, 9);
    fclib::write_local(&path, &problem, Some(&r), &metadata(name)).unwrap();
    hdf5::replace(&path, dataset, values);
    fclib::read_local(&path).unwrap_err()
}

#[test]
fn damaged_files_are_refused_with_what_is_wrong() {
    let cases = [
        ("/fclib_local", None, "no /fclib_local group"),
        (
            "/fclib_local/vectors/mu",
            None,
            "no dataset /fclib_local/vectors/mu",
        ),
        (
            "/fclib_local/vectors/q",
            Some(Values::Doubles(&[1.0; 5])),
            "/fclib_local/vectors/q has 5 entries, 6 expected",
        ),
        (
            "/solution/r",
            Some(Values::Doubles(&[1.0; 4])),
            "/solution/r has 4 entries, 6 expected",
        ),
        (
            "/fclib_local/W/nz",
            Some(Values::Ints(&[-3])),
            "nz = -3 (nzmax 36) is no FCLIB storage",
        ),
        (
            "/fclib_local/spacedim",
            Some(Values::Ints(&[4])),
            "spacedim is 4, not 2 or 3",
        ),
    ];
    for (k, (dataset, values, message)) in cases.into_iter().enumerate() {
        let err = damaged(&format!("damaged-{k}"), dataset, values);
        assert!(matches!(err, Error::Format(..)), "{dataset}: {err}");
        assert!(err.to_string().contains(message), "{dataset}: {err}");
    }
}

#[test]
fn bad_indices_and_an_unsymmetric_w_are_refused() {
    // the 2-contact W is full (36 entries, CSC): row index 6 is out of range
    let mut rows: Vec<c_int> = (0..6).cycle().take(36).collect();
    rows[7] = 6;
    let err = damaged("index", "/fclib_local/W/i", Some(Values::Ints(&rows)));
    assert!(
        err.to_string().contains("W: row index 6 out of range 0..6"),
        "{err}"
    );
    // W's entry (1, 0) changed, not (0, 1): LocalProblem::new's message
    let (problem, _) = known_problem(2, 9);
    let mut x: Vec<f64> = problem.w().iter().copied().collect();
    x[1] += 0.5;
    let err = damaged("unsymmetric", "/fclib_local/W/x", Some(Values::Doubles(&x)));
    assert!(matches!(err, Error::Problem(..)), "{err}");
    assert!(err.to_string().contains("W is not symmetric"), "{err}");
}

fn hycon(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hycon"))
        .args(args)
        .output()
        .expect("run hycon")
}

/// The line of `name` in a command's output, split in cells.
fn cells<'a>(stdout: &'a str, name: &str) -> Vec<&'a str> {
    let line = stdout.lines().find(|l| l.starts_with(name));
    let line = line.unwrap_or_else(|| panic!("no line {name}: {stdout}"));
    line.split_whitespace().collect()
}

#[test]
fn the_commands_write_and_solve_the_problem_sets() {
    let dir = Scratch::new("cli");
    let out = dir.0.to_str().expect("utf-8 temp dir");
    let args = [
        "fclib",
        "write",
        "--class",
        "plane,random",
        "--contacts",
        "5,20",
        "--out",
        out,
    ];
    let run = hycon(&args);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    // name, contacts, dim
    let problems = [
        ("plane-disk-press", "19", 2),
        ("plane-disk-slide", "19", 2),
        ("random-d3-n5-s1", "5", 3),
        ("random-d3-n20-s1", "20", 3),
    ];
    for (name, contacts, _) in problems {
        let line = cells(&stdout, name);
        assert_eq!(line[1], contacts, "{line:?}");
        let residual: f64 = line[3].parse().unwrap();
        assert!(residual < 1e-10, "the stored solution's residual: {line:?}");
    }
    let files: Vec<String> = problems
        .iter()
        .map(|p| format!("{out}/{}.hdf5", p.0))
        .collect();
    for solver in ["newton", "rules"] {
        let mut args = vec!["fclib", "solve", "--solver", solver];
        args.extend(files.iter().map(String::as_str));
        let run = hycon(&args);
        let stdout = String::from_utf8_lossy(&run.stdout);
        assert!(
            run.status.success(),
            "{stdout}{}",
            String::from_utf8_lossy(&run.stderr)
        );
        for (name, contacts, dim) in problems {
            let line = cells(&stdout, name);
            assert_eq!((line[1], line[3]), (contacts, solver), "{line:?}");
            // libfclib's merit function is 3D only
            assert_eq!(line[9] == "-", dim == 2, "{line:?}");
            // (whether the rules settle is the local problem's tests' business)
            if solver == "newton" {
                assert_eq!(line[4], "yes", "{line:?}");
                let versus: f64 = line[11].parse().unwrap();
                assert!(versus < 1e-9, "{line:?}");
            }
        }
    }
}

#[test]
fn solve_reports_a_bad_file_and_solves_the_others() {
    let dir = Scratch::new("cli-bad");
    let (problem, r) = known_problem(4, 2);
    let good = dir.file("good.hdf5");
    fclib::write_local(&good, &problem, Some(&r), &metadata("good")).unwrap();
    let text = dir.file("text.hdf5");
    std::fs::write(&text, "not hdf5").unwrap();
    let run = hycon(&[
        "fclib",
        "solve",
        good.to_str().unwrap(),
        text.to_str().unwrap(),
    ]);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr),
    );
    assert!(!run.status.success());
    assert!(
        stdout.lines().any(|l| l.starts_with("good.hdf5")),
        "{stdout}"
    );
    assert!(
        stderr.contains("text.hdf5: not an FCLIB local problem hycon reads: not an HDF5 file"),
        "{stderr}"
    );
    assert!(
        stderr.contains("1 of 2 files could not be read"),
        "{stderr}"
    );
}
