//! Scene files over Gmsh meshes: the reader (normalisation, chains, rejected elements, a fuzz
//! of truncated and corrupted files), the dry run, a run checked against linearity and
//! equilibrium, and one test per set-up mistake of the table in docs/scene-files.md.

use hycon_lab::gmsh;
use hycon_lab::scenefile::{self, SceneError};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// A fresh folder holding `press.msh` (and the other fixtures) and the scene `text`.
fn scene_dir(tag: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("hycon-scenes-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for m in ["press.msh", "press_cw.msh", "press_tri.msh"] {
        std::fs::copy(data(m), dir.join(m)).unwrap();
    }
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    path
}

fn press_text() -> String {
    std::fs::read_to_string(data("press.toml")).unwrap()
}

/// Load the press scene after replacing `from` by `to` (which must occur).
fn load_edited(tag: &str, from: &str, to: &str) -> Result<scenefile::Scene, SceneError> {
    let text = press_text();
    assert!(text.contains(from), "{from:?} not in press.toml");
    scenefile::load(&scene_dir(tag, &text.replacen(from, to, 1)))
}

/// The error of a scene, with every `needles` in its message.
fn expect_error(result: Result<scenefile::Scene, SceneError>, needles: &[&str]) {
    let e = result.expect_err("the scene should be rejected");
    let text = e.to_string();
    for n in needles {
        assert!(text.contains(n), "{n:?} not in the error: {text}");
    }
    assert!(
        text.contains(".toml") || text.contains(".msh"),
        "no file: {text}"
    );
}

fn signed_area(q: &[usize; 4], x: &[[f64; 2]]) -> f64 {
    (0..4)
        .map(|i| {
            let (p, r) = (x[q[i]], x[q[(i + 1) % 4]]);
            p[0] * r[1] - r[0] * p[1]
        })
        .sum::<f64>()
        / 2.0
}

#[test]
fn reader_groups_names_and_counter_clockwise_quads() {
    for file in ["press.msh", "press_cw.msh"] {
        let m = gmsh::read(&data(file)).unwrap();
        assert_eq!(m.nodes.len(), 135);
        let base = &m.groups["base"];
        assert_eq!((base.dim, base.quads.len()), (2, 64));
        assert_eq!(m.groups["punch"].quads.len(), 36);
        assert_eq!(m.groups["base_top"].lines.len(), 16);
        assert_eq!(m.groups["punch_corner"].points.len(), 1);
        // every quad counter-clockwise, areas summing to the bodies' 4 and 2
        for (g, area) in [("base", 4.0), ("punch", 2.0)] {
            let total: f64 = m.groups[g]
                .quads
                .iter()
                .map(|q| {
                    let a = signed_area(q, &m.nodes);
                    assert!(a > 0.0, "{file}: clockwise quad in {g}");
                    a
                })
                .sum();
            assert!((total - area).abs() < 1e-12, "{file} {g}: {total}");
        }
    }
}

#[test]
fn chains_run_with_the_body_on_the_left_whatever_the_curve_direction() {
    // press_cw.msh writes the quads clockwise and the contact curves reversed
    for file in ["press.msh", "press_cw.msh"] {
        let s = scenefile::load(&scene_dir(
            &format!("chain-{file}"),
            &press_text().replace("press.msh", file),
        ))
        .unwrap();
        let pair = &s.pairs[0].pair;
        let x = &s.model.mesh.nodes;
        // the punch's bottom (body above) runs left to right, the base's top right to left
        assert!(x[pair.a[0]][0] < x[pair.a[pair.a.len() - 1]][0], "{file}");
        assert!(x[pair.b[0]][0] > x[pair.b[pair.b.len() - 1]][0], "{file}");
        pair.check_on(&s.model.mesh).unwrap();
        assert_eq!(s.pairs[0].facing.touching, 10, "{file}");
    }
}

#[test]
fn triangles_are_rejected_with_how_to_recombine() {
    let e = gmsh::read(&data("press_tri.msh")).unwrap_err();
    let text = e.to_string();
    assert!(text.contains("press_tri.msh:"), "{text}");
    assert!(text.contains("3-node triangle"), "{text}");
    assert!(text.contains("Recombine"), "{text}");
    assert!(e.line > 0);
}

#[test]
fn second_order_and_old_versions_are_rejected() {
    let text = std::fs::read_to_string(data("press.msh")).unwrap();
    let p = Path::new("x.msh");
    // the base's quads as 9-node quadrilaterals (type 10)
    let q9 = text.replacen("2 1 3 64", "2 1 10 64", 1);
    let e = gmsh::parse(&q9, p).unwrap_err();
    assert!(e.message.contains("second order") && e.message.contains("ElementOrder"));
    let v2 = text.replacen("4.1 0 8", "2.2 0 8", 1);
    let e = gmsh::parse(&v2, p).unwrap_err();
    assert_eq!(e.line, 2);
    assert!(e.message.contains("4.1"), "{}", e.message);
}

/// Every truncation at a line and at a byte inside a line, and every line replaced by junk or
/// a token changed: an error naming a line in the file, never a panic (the fuzz of the
/// reader).
#[test]
fn reader_fuzz_truncated_and_corrupted_files() {
    let text = std::fs::read_to_string(data("press.msh")).unwrap();
    let p = Path::new("fuzz.msh");
    let lines: Vec<&str> = text.lines().collect();
    let n = lines.len();
    let mut errors = 0;
    for cut in 0..n {
        let t = lines[..cut].join("\n");
        let e = gmsh::parse(&t, p).unwrap_err();
        assert!(e.line <= n, "line {} of {n}", e.line);
        errors += 1;
        // and cut inside the line
        let partial = format!("{t}\n{}", &lines[cut][..lines[cut].len() / 2]);
        let _ = gmsh::parse(&partial, p);
    }
    let junk = [
        "",
        "x",
        "-1",
        "99999999999999999999",
        "1e400",
        "nan",
        "$End",
        "\"",
        "0 0 0 0",
    ];
    for k in 0..n {
        for (j, bad) in junk.iter().enumerate() {
            let mut v = lines.clone();
            v[k] = bad;
            if let Err(e) = gmsh::parse(&v.join("\n"), p) {
                assert!(e.line <= n + 1, "{}", e);
                errors += 1;
            }
            // change one token of the line instead
            let mut tokens: Vec<&str> = lines[k].split_whitespace().collect();
            if !tokens.is_empty() {
                let i = (k + j) % tokens.len();
                tokens[i] = bad;
                let changed = tokens.join(" ");
                let mut v = lines.clone();
                v[k] = &changed;
                let _ = gmsh::parse(&v.join("\n"), p);
            }
        }
    }
    assert!(errors > n, "{errors}");
}

#[test]
fn dry_run_says_what_hycon_understood() {
    let text = scenefile::dry_run(&scene_dir("dry", &press_text())).unwrap();
    for needle in [
        "base         group \"base\": 64 elements, 85 nodes, E = 200000, nu = 0.3",
        "punch        group \"punch\": 36 elements, 50 nodes, E = 70000, nu = 0.33",
        "\"punch_top\": 10 nodes, ux = 0, uy = -0.001 (curve press)",
        "A \"punch_bottom\" (body punch, 10 nodes, length 2.0000e0) on B \"base_top\"",
        "10 of 10 A nodes find B",
        "the sides face each other",
        "1: press = 0.5",
        "cutback depth 4",
        "verdict: ready to run",
    ] {
        assert!(text.contains(needle), "{needle:?} not in\n{text}");
    }
}

/// The press run: small kinematics and a flat punch in full contact from the start, so the
/// response is linear: step 2 (factor 1) has twice step 1's force and peak; the contact force
/// balances the punch-top reaction (in the summary: the force on A equals the load pushing
/// the punch), and the whole punch bottom (length 2) is in contact.
#[test]
fn run_the_press_linear_in_the_load_with_every_file() {
    let path = scene_dir("run", &press_text());
    let scene = scenefile::load(&path).unwrap();
    let mut log = Vec::new();
    let s = scenefile::run(&scene, &mut log).unwrap();
    let log = String::from_utf8(log).unwrap();
    assert!(s.error.is_none(), "{log}");
    assert_eq!(s.steps.len(), 2);
    let (p1, p2) = (&s.steps[0].pairs[0], &s.steps[1].pairs[0]);
    assert!(
        (p1.contact_length - 2.0).abs() < 1e-12,
        "{}",
        p1.contact_length
    );
    assert!(p1.total_force[1] > 0.0);
    let ratio = p2.total_force[1] / p1.total_force[1];
    assert!((ratio - 2.0).abs() < 1e-6, "{ratio}");
    assert!((p2.peak_pressure / p1.peak_pressure - 2.0).abs() < 1e-6);
    // symmetric about x = 2: no net tangential force
    assert!(p2.total_force[0].abs() < 1e-9 * p2.total_force[1]);
    // the mean pressure is the force over the punch width; the peak (at the corners) above it
    assert!(p2.peak_pressure > p2.total_force[1] / 2.0);
    for f in ["scene-01.vtu", "scene-02.vtu"] {
        assert!(s.files.iter().any(|p| p.ends_with(f)), "{f}: {:?}", s.files);
    }
    let dir = scene.output_dir();
    let csv = std::fs::read_to_string(dir.join("scene-contact.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 2 * 10);
    let svg = std::fs::read_to_string(dir.join("scene-pair1.svg")).unwrap();
    assert!(svg.starts_with("<svg"));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("scene-summary.json")).unwrap())
            .unwrap();
    assert_eq!(json["steps"].as_array().unwrap().len(), 2);
    assert!(log.contains("wrote"), "{log}");
}

/// Equilibrium of the press: the contact force on the punch equals the reaction at its top.
#[test]
fn press_contact_force_balances_the_support_reaction() {
    use hycon::contact::iteration::ContactAnalysis;
    let scene = scenefile::load(&scene_dir("equil", &press_text())).unwrap();
    let mut a = ContactAnalysis::new(
        scene.model.clone(),
        vec![scene.pairs[0].pair.clone()],
        scene.options,
    )
    .unwrap();
    let (f, qp) = scene.step_loads(1);
    a.increment(&f, &qp).unwrap();
    let rows = a.node_results(0).unwrap();
    let contact: f64 = rows.iter().map(|r| r.force[1]).sum();
    let q = a.displacement().unwrap().to_vec();
    let internal = scene.model.internal_forces(&q).unwrap();
    let top = &scene.model.mesh;
    let reaction: f64 = (0..top.n_nodes())
        .filter(|&n| top.nodes[n][1] > 1.0 - 1e-12)
        .map(|n| internal[2 * n + 1])
        .sum();
    assert!(
        (contact + reaction).abs() < 1e-6 * contact.abs()
            || (contact - reaction).abs() < 1e-6 * contact.abs(),
        "contact {contact}, reaction {reaction}"
    );
}

// ---- one test per set-up mistake (the table in docs/scene-files.md) ----

#[test]
fn mistake_unknown_group() {
    expect_error(
        load_edited("unknown", "group = \"punch\"", "group = \"punsh\""),
        &[
            "body \"punsh\"",
            "unknown physical group \"punsh\"",
            "\"punch\" (2D)",
        ],
    );
}

#[test]
fn mistake_group_of_the_wrong_dimension() {
    expect_error(
        load_edited("dim", "group = \"punch\"", "group = \"punch_top\""),
        &["group \"punch_top\" is 1D (lines), this needs 2D (surfaces)"],
    );
    expect_error(
        load_edited("dim2", "a = \"punch_bottom\"", "a = \"punch\""),
        &["contact pair 1", "group \"punch\" is 2D"],
    );
}

#[test]
fn mistake_body_with_no_elements() {
    // a named 2D physical group that holds no elements (a surface that was not meshed)
    let text = std::fs::read_to_string(data("press.msh"))
        .unwrap()
        .replacen(
            "$PhysicalNames\n8\n",
            "$PhysicalNames\n9\n2 9 \"empty\"\n",
            1,
        );
    let path = scene_dir(
        "empty",
        &press_text().replacen("group = \"punch\"", "group = \"empty\"", 1),
    );
    std::fs::write(path.with_file_name("press.msh"), text).unwrap();
    expect_error(
        scenefile::load(&path),
        &["body \"empty\" (line 10): group \"empty\" has no elements"],
    );
}

#[test]
fn mistake_body_not_held_against_rigid_motion() {
    // the punch held only in y: free to translate in x
    expect_error(
        load_edited("free-x", "x = 0.0\ny = -1e-3", "y = -1e-3"),
        &[
            "body \"punch\" is not held against rigid motion",
            "translation in x",
        ],
    );
    // the punch held at one point only (its corner): free to rotate about it
    let text = press_text().replacen(
        "group = \"punch_top\"\nx = 0.0\ny = -1e-3",
        "group = \"punch_corner\"\nx = 0.0\ny = -1e-3",
        1,
    );
    expect_error(
        scenefile::load(&scene_dir("free-rot", &text)),
        &["body \"punch\"", "rotation"],
    );
}

#[test]
fn mistake_pair_on_one_body() {
    expect_error(
        load_edited("one-body", "b = \"base_top\"", "b = \"punch_top\""),
        &["contact pair 1", "both sides are on body \"punch\""],
    );
}

#[test]
fn mistake_pair_whose_sides_never_face() {
    // A = the base's bottom, B = the punch's top: back to back, facing away
    let text = press_text()
        .replacen("a = \"punch_bottom\"", "a = \"base_bottom\"", 1)
        .replacen("b = \"base_top\"", "b = \"punch_top\"", 1)
        .replacen(
            "group = \"base_bottom\"\nx = 0.0\ny = 0.0",
            "group = \"base_top\"\nx = 0.0\ny = 0.0",
            1,
        )
        .replace("[options]", "[options]\nsearch_distance = 40.0");
    expect_error(
        scenefile::load(&scene_dir("away", &text)),
        &["contact pair 1", "never face each other"],
    );
}

#[test]
fn mistake_overlapping_pairs() {
    let text = press_text().replacen(
        "[[step]]",
        "[[contact]]\na = \"punch_bottom\"\nb = \"base_top\"\n\n[[step]]",
        1,
    );
    expect_error(
        scenefile::load(&scene_dir("overlap", &text)),
        &["contact pair 2", "overlaps contact pair 1"],
    );
}

#[test]
fn mistake_boundary_group_not_a_chain() {
    // the punch's left side and bottom as one group is a chain; its top and bottom is not:
    // make the mesh's punch_left curve carry the punch_top physical group too
    let msh = std::fs::read_to_string(data("press.msh")).unwrap();
    // curve entity 5 (punch_left, physical 7) -> physical 6 (punch_top): two pieces
    let msh = msh.replacen("5 0 0 0 1 1 0 1 7 0", "5 0 0 0 1 1 0 1 5 0", 1);
    let path = scene_dir("chain", &press_text());
    std::fs::write(path.with_file_name("press.msh"), msh).unwrap();
    // punch_bottom now also holds the left side: still one chain (left side down, bottom)
    scenefile::load(&path).unwrap();
    let msh = std::fs::read_to_string(data("press.msh"))
        .unwrap()
        .replacen("4 0 0 0 1 1 0 1 6 0", "4 0 0 0 1 1 0 2 6 5 0", 1);
    std::fs::write(path.with_file_name("press.msh"), msh).unwrap();
    expect_error(
        scenefile::load(&path),
        &[
            "group \"punch_bottom\" is not a boundary chain",
            "2 separate pieces",
        ],
    );
}

#[test]
fn mistake_missing_material() {
    expect_error(
        load_edited(
            "no-material",
            "material = { E = 70e3, nu = 0.33, thickness = 1.0 }",
            "",
        ),
        &["body \"punch\" (line 10): no material"],
    );
    // a misspelt key is not ignored
    expect_error(
        load_edited("typo", "E = 70e3", "e = 70e3"),
        &["unknown field `e`", "line"],
    );
}

#[test]
fn mistake_out_of_range_values() {
    expect_error(
        load_edited("nu", "nu = 0.33", "nu = 0.5"),
        &["body \"punch\" (line 10): material", "oisson"],
    );
    expect_error(
        load_edited("E", "E = 70e3", "E = -70e3"),
        &["body \"punch\" (line 10): material"],
    );
    expect_error(
        load_edited("mu", "friction = 0.0", "friction = -0.1"),
        &["contact pair 1", "friction -0.1"],
    );
    expect_error(
        load_edited("cut", "cutback_depth = 4", "cutback_depth = 99"),
        &["options:", "cutback_depth"],
    );
    expect_error(
        load_edited(
            "axi",
            "analysis = \"plane_strain\"",
            "analysis = \"axisymetric\"",
        ),
        &["analysis = \"axisymetric\""],
    );
}

#[test]
fn mistake_step_table_with_no_steps() {
    let text = press_text().replacen("[[step]]\npress = 0.5\n\n[[step]]\npress = 1.0\n", "", 1);
    expect_error(
        scenefile::load(&scene_dir("nosteps", &text)),
        &["no [[step]]"],
    );
    expect_error(
        load_edited("badcurve", "press = 0.5", "pres = 0.5"),
        &["step 1: curve \"pres\" is not used"],
    );
}

#[test]
fn likely_unit_mistake_is_a_warning_in_the_dry_run() {
    // the punch pushed down by 0.5 (half its height): strains far beyond small strain
    let s = load_edited("units", "y = -1e-3", "y = -0.5").unwrap();
    let text = s.describe();
    assert!(
        text.contains("warning: a prescribed displacement"),
        "{text}"
    );
    assert!(text.contains("units?"), "{text}");
    // a pressure of the order of E
    let text = press_text().replacen(
        "[[contact]]",
        "[[load]]\ngroup = \"punch_left\"\npressure = 70e3\ncurve = \"press\"\n\n[[contact]]",
        1,
    );
    let s = scenefile::load(&scene_dir("units-p", &text)).unwrap();
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("load on \"punch_left\"")),
        "{:?}",
        s.warnings
    );
}

/// The dry run solves step 1 linearly without contact: E in the wrong units (70 where the
/// pressure of 100 is in the units of E = 70e3) strains the punch far beyond small strain and
/// the warning names it; the right E gives no such warning.
#[test]
fn first_linear_solve_names_a_unit_mistake() {
    let with_load = |e: &str| {
        press_text()
            .replacen(
                "[[contact]]",
                "[[load]]\ngroup = \"punch_left\"\npressure = 100.0\ncurve = \"press\"\n\n[[contact]]",
                1,
            )
            .replacen("E = 70e3", e, 1)
    };
    let text = with_load("E = 70e3");
    assert!(text.contains("pressure = 100.0"));
    let mut right = scenefile::load(&scene_dir("units-right", &text)).unwrap();
    let (strain, body) = right.check_first_solve().expect("the linear solve");
    assert!(strain > 1e-4 && strain < 0.05, "{strain}");
    assert_eq!(right.bodies[body].group, "punch");
    assert!(right.warnings.is_empty(), "{:?}", right.warnings);
    let text = with_load("E = 70.0");
    let mut wrong = scenefile::load(&scene_dir("units-wrong", &text)).unwrap();
    let (strain, body) = wrong.check_first_solve().expect("the linear solve");
    assert!(strain > scenefile::STRAIN_WARNING, "{strain}");
    assert_eq!(wrong.bodies[body].group, "punch");
    let dry = wrong.describe();
    assert!(
        dry.contains("warning: step 1 solved linearly without contact: largest strain")
            && dry.contains("\"punch\"")
            && dry.contains("units?"),
        "{dry}"
    );
    // through the dry run's entry point too
    let path = scene_dir("units-wrong-dry", &text);
    let dry = scenefile::dry_run(&path).unwrap();
    assert!(dry.contains("step 1 solved linearly"), "{dry}");
}

#[test]
fn mesh_errors_name_the_mesh_file_and_line() {
    let msh = std::fs::read_to_string(data("press.msh")).unwrap();
    let path = scene_dir("mesh-line", &press_text());
    let broken = msh.replacen("\n17\n", "\nseventeen\n", 1);
    std::fs::write(path.with_file_name("press.msh"), broken).unwrap();
    expect_error(scenefile::load(&path), &["press.msh", "line ", "seventeen"]);
}

/// The example scenes shipped in examples/scenes: each checks and runs (in a copy, so the
/// repository stays clean).
#[test]
fn example_scenes_run() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes");
    let mut ran = 0;
    for entry in std::fs::read_dir(&root).unwrap() {
        let src = entry.unwrap().path();
        let dir = std::env::temp_dir().join(format!(
            "hycon-example-{}-{}",
            std::process::id(),
            src.file_name().unwrap().to_string_lossy()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        for f in std::fs::read_dir(&src).unwrap() {
            let f = f.unwrap().path();
            if f.is_file() {
                std::fs::copy(&f, dir.join(f.file_name().unwrap())).unwrap();
            }
        }
        for f in std::fs::read_dir(&dir).unwrap() {
            let f = f.unwrap().path();
            if f.extension().is_some_and(|e| e == "toml") {
                let mut scene = scenefile::load(&f).unwrap();
                scene.check_first_solve();
                let dry = scene.describe();
                assert!(dry.contains("verdict: ready to run"), "{dry}");
                assert!(
                    !dry.contains("warning"),
                    "{}: a warning on an example: {dry}",
                    f.display()
                );
                let s = scenefile::run(&scene, &mut std::io::sink()).unwrap();
                assert!(s.error.is_none(), "{}: {:?}", f.display(), s.error);
                ran += 1;
            }
        }
    }
    assert!(ran >= 1);
}

/// The press as an axisymmetric scene (x = r: a ring punch on a disk): it runs, linear in the
/// load as in plane strain; a body held only radially is free along the axis; a thickness
/// other than 1 is rejected (the measure is 2 pi r).
#[test]
fn axisymmetric_scene() {
    let s = load_edited(
        "axi",
        "analysis = \"plane_strain\"",
        "analysis = \"axisymmetric\"",
    )
    .unwrap();
    assert!(s.describe().contains("axisymmetric"), "{}", s.describe());
    let r = scenefile::run(&s, &mut std::io::sink()).unwrap();
    assert!(r.error.is_none(), "{:?}", r.error);
    let (p1, p2) = (&r.steps[0].pairs[0], &r.steps[1].pairs[0]);
    assert!((p2.total_force[1] / p1.total_force[1] - 2.0).abs() < 1e-6);
    let text = press_text()
        .replacen(
            "analysis = \"plane_strain\"",
            "analysis = \"axisymmetric\"",
            1,
        )
        .replacen("x = 0.0\ny = 0.0", "x = 0.0", 1);
    expect_error(
        scenefile::load(&scene_dir("axi-free", &text)),
        &["body \"base\"", "translation in y (z, along the axis)"],
    );
    let text = press_text()
        .replacen(
            "analysis = \"plane_strain\"",
            "analysis = \"axisymmetric\"",
            1,
        )
        .replacen("thickness = 1.0 }", "thickness = 2.0 }", 1);
    expect_error(
        scenefile::load(&scene_dir("axi-t", &text)),
        &["body \"base\" (line 6): material", "2 pi r"],
    );
}

/// Two pairs may share their B side (two punches on one base), not an A side.
#[test]
fn two_pairs_share_a_b_side() {
    let msh = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/scenes/two_punches/two_punches.toml");
    let s = scenefile::load(&msh).unwrap();
    assert_eq!(s.pairs.len(), 2);
    assert_eq!(s.pairs[0].pair.b, s.pairs[1].pair.b);
}

/// The Hertz cylinder as a scene: the lab's disk-on-block mesh (4-node quadrilaterals only,
/// 16 elements per target half-width) written as MSH by `gmsh::write`, read back through a
/// scene file, pressed by a prescribed approach of the disk's top; p0 and a (from the second
/// moment of the multiplier pressure) within 1% of the closed form at the measured load.
#[test]
fn hertz_scene_matches_the_closed_form() {
    use hycon::mesh::generate::Transition;
    use hycon_lab::gmsh::WriteGroup;
    use hycon_lab::scene::{DiskOnBlock, compare_with_hertz};
    let lab = DiskOnBlock {
        transition: Transition::Quads,
        radius_over_half_width: 16,
        band_layers: 8,
        ..DiskOnBlock::default()
    }
    .build()
    .unwrap();
    let m = &lab.model.mesh;
    let msh = hycon_lab::gmsh::write(
        m,
        &[
            WriteGroup::Surface("block".into(), 0),
            WriteGroup::Surface("disk".into(), 1),
            WriteGroup::Curve("block_top".into(), lab.pair.a.clone()),
            WriteGroup::Curve("disk_arc".into(), lab.pair.b.clone()),
            WriteGroup::Points("block_bottom".into(), m.node_sets["block.bottom"].clone()),
            WriteGroup::Points("disk_top".into(), lab.top.clone()),
        ],
    )
    .unwrap();
    // in 2D the load is nearly linear in the approach and a grows as its square root: 3.1
    // times the trial approach a^2 / R reaches about the target half-width
    let approach = 3.1 * lab.half_width.powi(2) / lab.radius;
    let text = format!(
        "# The Hertz cylinder: a half disk (R = 1) pressed onto a block, both E = 1, nu = 0.3,\n\
         # plane strain; the mesh is the lab's disk-on-block scene (4-node quads, R / a = 16)\n\
         # written by lab/tests/scenes.rs (HYCON_WRITE_EXAMPLES=1 rewrites it).\n\
         mesh = \"hertz.msh\"\n\
         [[body]]\ngroup = \"block\"\nmaterial = {{ E = 1.0, nu = 0.3 }}\n\
         [[body]]\ngroup = \"disk\"\nmaterial = {{ E = 1.0, nu = 0.3 }}\n\
         [[support]]\ngroup = \"block_bottom\"\nx = 0.0\ny = 0.0\n\
         [[support]]\ngroup = \"disk_top\"\nx = 0.0\ny = {}\n\
         [[contact]]\na = \"block_top\"\nb = \"disk_arc\"\n\
         [[step]]\nload = 1.0\n\
         [output]\nvtu = false\nsvg = false\n",
        -approach
    );
    let path = scene_dir("hertz", &text);
    std::fs::write(path.with_file_name("hertz.msh"), &msh).unwrap();
    // the example shipped in examples/scenes/hertz is this scene
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/hertz");
    if std::env::var_os("HYCON_WRITE_EXAMPLES").is_some() {
        std::fs::create_dir_all(&shipped).unwrap();
        std::fs::write(shipped.join("hertz.msh"), &msh).unwrap();
        std::fs::write(
            shipped.join("hertz.toml"),
            text.replace("vtu = false\n", "dir = \"out\"\n"),
        )
        .unwrap();
    }
    assert!(
        std::fs::read_to_string(shipped.join("hertz.msh")).unwrap() == msh,
        "examples/scenes/hertz/hertz.msh is stale: rerun with HYCON_WRITE_EXAMPLES=1"
    );
    let scene = scenefile::load(&path).unwrap();
    eprintln!("{} elements", scene.model.mesh.n_elements());
    let mut a = hycon::contact::iteration::ContactAnalysis::new(
        scene.model.clone(),
        vec![scene.pairs[0].pair.clone()],
        scene.options,
    )
    .unwrap();
    let (f, qp) = scene.step_loads(0);
    a.increment(&f, &qp).unwrap();
    let mut rows = a.node_results(0).unwrap();
    for r in &mut rows {
        r.position = scene.model.mesh.nodes[r.node].into();
    }
    let c = compare_with_hertz(&rows, lab.radius, lab.e_star).unwrap();
    let per_half_width = c.hertz.half_width / (lab.half_width / 16.0);
    eprintln!(
        "a {} vs {}, p0 {} vs {}, {per_half_width} elements per half-width",
        c.half_width, c.hertz.half_width, c.peak, c.hertz.peak
    );
    assert!(per_half_width >= 16.0 * 0.95, "{per_half_width}");
    assert!((c.half_width / c.hertz.half_width - 1.0).abs() < 0.01);
    assert!((c.peak / c.hertz.peak - 1.0).abs() < 0.01);
    // and through `run`: the same load
    let r = scenefile::run(&scene, &mut std::io::sink()).unwrap();
    let fy = r.steps[0].pairs[0].total_force[1].abs();
    assert!((fy / c.load - 1.0).abs() < 1e-6, "{fy} vs {}", c.load);
}

/// A rigid plate on the punch's top, pushed by a force in y and held in x: the contact force
/// on the punch balances the plate force at every step.
#[test]
fn rigid_plate_force_control_balances_the_contact_force() {
    let text = press_text().replacen(
        "[[support]]\ngroup = \"punch_top\"\nx = 0.0\ny = -1e-3\ncurve = \"press\"",
        "[plate]\ngroup = \"punch_top\"\nx = \"displacement\"\ny = \"force\"\nvalue = [0.0, \
         -100.0]\ncurve = \"press\"",
        1,
    );
    let s = scenefile::load(&scene_dir("plate", &text)).unwrap();
    assert!(
        s.describe()
            .contains("on a rigid plate, x by displacement 0, y by force -100")
    );
    let r = scenefile::run(&s, &mut std::io::sink()).unwrap();
    assert!(r.error.is_none(), "{:?}", r.error);
    for (step, load) in r.steps.iter().zip([50.0, 100.0]) {
        let fy = step.pairs[0].total_force[1];
        assert!((fy - load).abs() < 1e-6 * load, "{fy} vs {load}");
    }
    expect_error(
        scenefile::load(&scene_dir(
            "plate-bad",
            &text.replacen("y = \"force\"", "y = \"push\"", 1),
        )),
        &["plate on \"punch_top\" (line ", "control \"push\""],
    );
}

/// The frictional sliding example (examples/scenes/press_slide): pressed, then slid until the
/// whole contact slips; then the tangential force is mu = 0.3 times the normal force (Coulomb
/// at every node of a flat contact), and in the first, pressing-only step it is zero.
#[test]
fn sliding_scene_reaches_coulomb() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/press_slide");
    let text = std::fs::read_to_string(src.join("press_slide.toml")).unwrap();
    let scene = scenefile::load(&scene_dir("slide", &text)).unwrap();
    let r = scenefile::run(&scene, &mut std::io::sink()).unwrap();
    assert!(r.error.is_none(), "{:?}", r.error);
    let first = &r.steps[0].pairs[0];
    assert!(first.total_force[0].abs() < 1e-9 * first.total_force[1]);
    let last = &r.steps.last().unwrap().pairs[0];
    assert_eq!((last.active, last.slip), (10, 10));
    let ratio = -last.total_force[0] / last.total_force[1];
    assert!((ratio - 0.3).abs() < 1e-6, "{ratio}");
}

/// The flat punch with rounded corners (examples/scenes/rounded_punch): the dry run sees the
/// roundings as initial gaps up to their radius 0.3; under a plate force the contact force
/// balances it at every step and the contact spreads onto the roundings as it grows.
#[test]
fn rounded_punch_spreads_and_balances() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/rounded_punch");
    let dir = scene_dir(
        "rounded",
        &std::fs::read_to_string(src.join("rounded_punch.toml")).unwrap(),
    );
    std::fs::copy(
        src.join("rounded_punch.msh"),
        dir.with_file_name("rounded_punch.msh"),
    )
    .unwrap();
    let scene = scenefile::load(&dir).unwrap();
    let (lo, hi) = scene.pairs[0].gap_range.unwrap();
    assert!(lo.abs() < 1e-12 && (hi - 0.3).abs() < 1e-12, "{lo} {hi}");
    let r = scenefile::run(&scene, &mut std::io::sink()).unwrap();
    assert!(r.error.is_none(), "{:?}", r.error);
    let mut last = 0.0;
    for (step, load) in r.steps.iter().zip([100.0, 1000.0, 4000.0]) {
        let p = &step.pairs[0];
        assert!((p.total_force[1] - load).abs() < 1e-6 * load, "{p:?}");
        assert!(p.contact_length >= last);
        last = p.contact_length;
    }
    assert!(last > 1.4, "{last}: the flat part is 1.4 long");
}

/// A body group of two separate pieces, one of them without supports: named with the piece.
#[test]
fn mistake_body_piece_not_held() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/two_punches");
    // both punches in the physical group "left_punch" (the right one's surface entity gets the
    // left one's physical tag 2)
    let msh = std::fs::read_to_string(src.join("two_punches.msh"))
        .unwrap()
        .replacen("3 0 0 0 1 1 0 1 3 0", "3 0 0 0 1 1 0 1 2 0", 1);
    let text = "mesh = \"two_punches.msh\"\n\
        [[body]]\ngroup = \"base\"\nmaterial = { E = 1.0, nu = 0.3 }\n\
        [[body]]\ngroup = \"left_punch\"\nmaterial = { E = 1.0, nu = 0.3 }\n\
        [[support]]\ngroup = \"base_bottom\"\nx = 0.0\ny = 0.0\n\
        [[support]]\ngroup = \"left_top\"\nx = 0.0\ny = -1e-3\n\
        [[contact]]\na = \"left_bottom\"\nb = \"base_top\"\n\
        [[step]]\nload = 1.0\n";
    let path = scene_dir("pieces", text);
    std::fs::write(path.with_file_name("two_punches.msh"), msh).unwrap();
    expect_error(
        scenefile::load(&path),
        &[
            "body \"left_punch\" (its piece of 14 elements",
            "2 separate pieces",
            "translation in x",
        ],
    );
}

/// The paper's frictional sliding example as a scene (examples/scenes/disk_slide): the lab's
/// disk-on-block mesh (4-node quadrilaterals, 8 elements per target half-width a, the block
/// long enough for the travel) written as MSH by `gmsh::write`; the disk's top pressed down
/// (curve `press`), then moved 2 a sideways (curve `slide`) with mu = 0.3 under finite
/// kinematics. The shipped files are current, the scene runs, and once the disk slides every
/// contact node slips and the tangential force is mu times the normal force, less the tilt of
/// the deformed interface.
#[test]
fn disk_slide_scene_is_the_papers_sliding_example() {
    use hycon::mesh::generate::Transition;
    use hycon_lab::gmsh::WriteGroup;
    use hycon_lab::scene::DiskOnBlock;
    let lab = DiskOnBlock {
        transition: Transition::Quads,
        elements_per_half_width: 8,
        radius_over_half_width: 16,
        band_layers: 8,
        friction: 0.3,
        travel: 2.5,
        ..DiskOnBlock::default()
    }
    .build()
    .unwrap();
    let m = &lab.model.mesh;
    let msh = hycon_lab::gmsh::write(
        m,
        &[
            WriteGroup::Surface("block".into(), 0),
            WriteGroup::Surface("disk".into(), 1),
            WriteGroup::Curve("block_top".into(), lab.pair.a.clone()),
            WriteGroup::Curve("disk_arc".into(), lab.pair.b.clone()),
            WriteGroup::Points("block_bottom".into(), m.node_sets["block.bottom"].clone()),
            WriteGroup::Points("disk_top".into(), lab.top.clone()),
        ],
    )
    .unwrap();
    let approach = 3.1 * lab.half_width.powi(2) / lab.radius;
    let travel = 2.0 * lab.half_width;
    let text = format!(
        "# The paper's frictional sliding example: a half disk (R = 1) pressed onto a block (both\n\
         # E = 1, nu = 0.3, plane strain) to a contact half-width a of about R / 16, then its top\n\
         # moved 2 a sideways with mu = 0.3 (finite kinematics: the disk slides over many\n\
         # elements). The mesh is the lab's disk-on-block scene (4-node quads, 8 elements per a)\n\
         # written by lab/tests/scenes.rs (HYCON_WRITE_EXAMPLES=1 rewrites it; see README.md).\n\
         mesh = \"disk_slide.msh\"\n\n\
         [[body]]\ngroup = \"block\"\nmaterial = {{ E = 1.0, nu = 0.3 }}\n\n\
         [[body]]\ngroup = \"disk\"\nmaterial = {{ E = 1.0, nu = 0.3 }}\n\n\
         [[support]]\ngroup = \"block_bottom\"\nx = 0.0\ny = 0.0\n\n\
         # the disk's top: pressed down on `press`, moved sideways on `slide`\n\
         [[support]]\ngroup = \"disk_top\"\ny = {:e}\ncurve = \"press\"\n\n\
         [[support]]\ngroup = \"disk_top\"\nx = {travel:e}\ncurve = \"slide\"\n\n\
         [[contact]]\na = \"block_top\"\nb = \"disk_arc\"\nfriction = 0.3\n\n\
         [[step]]\npress = 1.0\nslide = 0.0\n\n\
         [[step]]\npress = 1.0\nslide = 0.25\n\n\
         [[step]]\npress = 1.0\nslide = 0.5\n\n\
         [[step]]\npress = 1.0\nslide = 0.75\n\n\
         [[step]]\npress = 1.0\nslide = 1.0\n\n\
         [options]\nkinematics = \"finite\"\n\n\
         [output]\ndir = \"out\"\n",
        -approach
    );
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/disk_slide");
    if std::env::var_os("HYCON_WRITE_EXAMPLES").is_some() {
        std::fs::create_dir_all(&shipped).unwrap();
        std::fs::write(shipped.join("disk_slide.msh"), &msh).unwrap();
        std::fs::write(shipped.join("disk_slide.toml"), &text).unwrap();
    }
    assert!(
        std::fs::read_to_string(shipped.join("disk_slide.msh")).unwrap() == msh
            && std::fs::read_to_string(shipped.join("disk_slide.toml")).unwrap() == text,
        "examples/scenes/disk_slide is stale: rerun with HYCON_WRITE_EXAMPLES=1"
    );
    let dir = std::env::temp_dir().join(format!("hycon-scenes-{}-disk-slide", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("disk_slide.msh"), &msh).unwrap();
    std::fs::write(
        dir.join("disk_slide.toml"),
        text.replace(
            "[output]\ndir = \"out\"\n",
            "[output]\nvtu = false\nsvg = false\n",
        ),
    )
    .unwrap();
    let scene = scenefile::load(&dir.join("disk_slide.toml")).unwrap();
    let r = scenefile::run(&scene, &mut std::io::sink()).unwrap();
    assert!(r.error.is_none(), "{:?}", r.error);
    for s in &r.steps {
        let p = &s.pairs[0];
        eprintln!(
            "step {}: active {} slip {} Q/P {}",
            s.step,
            p.active,
            p.slip,
            p.total_force[0].abs() / p.total_force[1].abs()
        );
    }
    // gross sliding: every active node slips and Q / P is mu less the interface tilt of
    // finite kinematics (lab/tests/contact_sliding.rs: mu - Q/P = (1 - 2 nu)(1 + nu) / E mu
    // 8 p0 / (3 pi), about 2e-3 here; measured 2.8e-3)
    let last = &r.steps.last().unwrap().pairs[0];
    assert!(last.active > 0 && last.slip == last.active, "{last:?}");
    let [fx, fy] = last.total_force;
    let deficit = 0.3 - fx.abs() / fy.abs();
    assert!(
        deficit > 0.0 && deficit < 0.01,
        "Q / P = {} at the end of the slide",
        fx.abs() / fy.abs()
    );
}
