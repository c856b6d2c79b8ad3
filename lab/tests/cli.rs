//! The command-line program: the contact subcommands on small cases, their JSON, SVG and VTU
//! output, and error handling.

use hycon::contact::iteration::Kinematics;
use hycon_lab::bench::SweepScene;
use hycon_lab::scene::DiskOnBlock;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn hycon(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hycon"))
        .args(args)
        .output()
        .expect("run hycon")
}

/// A fresh scratch directory (removed on drop).
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("hycon-cli-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        Scratch(dir)
    }
    fn path(&self) -> &Path {
        &self.0
    }
    fn arg(&self) -> &str {
        self.0.to_str().expect("utf-8 temp dir")
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn finite(v: &Value, what: &str) -> f64 {
    let x = v
        .as_f64()
        .unwrap_or_else(|| panic!("{what} is not a number: {v}"));
    assert!(x.is_finite(), "{what} = {x}");
    x
}

#[test]
fn hertz_json_has_the_fields_and_finite_numbers() {
    let dir = Scratch::new("hertz");
    let out = hycon(&["hertz", "--n", "4", "--json", "--out", dir.arg()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("stdout is JSON");
    assert_eq!(json["name"], "hertz");
    let runs = json["runs"].as_array().expect("runs");
    assert_eq!(runs.len(), 3, "modulus ratios 1, 1e-2, 1e-4");
    for run in runs {
        let setup = &run["setup"];
        assert_eq!(setup["elements_per_half_width"], 4);
        assert!(finite(&setup["e_star"], "E*") > 0.0);
        assert!(finite(&run["calibration"]["approach"], "approach") > 0.0);
        let increments = run["increments"].as_array().expect("increments");
        assert_eq!(increments.len(), 3);
        for inc in increments {
            assert!(inc["iterations"].as_u64().expect("iterations") >= 1);
            assert!(inc["active"].as_u64().expect("active") >= 1);
            assert!(finite(&inc["load"], "P") > 0.0);
            for key in [
                "half_width",
                "peak",
                "centre",
                "measured_half_width",
                "measured_peak",
                "half_width_error",
                "peak_error",
                "l2_error",
                "l2_error_forces",
            ] {
                finite(&inc["hertz"][key], key);
            }
            assert!(finite(&inc["hertz"]["l2_error"], "L2") < 0.5);
            let nodes = inc["nodes"].as_array().expect("nodes");
            assert!(!nodes.is_empty());
            for node in nodes {
                for key in ["x", "p", "p_forces", "q", "p_exact", "q_exact"] {
                    finite(&node[key], key);
                }
                assert!(
                    ["open", "stick", "slip", "frictionless"]
                        .contains(&node["state"].as_str().unwrap())
                );
            }
        }
        let t = &run["timings"];
        for key in [
            "assembly",
            "factorization",
            "flexibility",
            "load_solves",
            "iterations",
            "recovery",
            "linear",
        ] {
            assert!(finite(&t[key], key) >= 0.0);
        }
        assert!(finite(&t["total"], "total") > 0.0);
    }
}

/// Minimal XML reading for the test: every element's name and attributes, and the text of
/// each `DataArray` split into numbers; checks that tags nest.
struct Xml {
    elements: Vec<(String, Attributes)>,
    arrays: Vec<(Attributes, Vec<f64>)>,
}

type Attributes = Vec<(String, String)>;

fn parse_xml(text: &str) -> Xml {
    let mut stack: Vec<String> = Vec::new();
    let mut elements = Vec::new();
    let mut arrays = Vec::new();
    let mut rest = text;
    let mut open_array: Option<Vec<(String, String)>> = None;
    while let Some(start) = rest.find('<') {
        let body = &rest[..start];
        if let Some(attrs) = &open_array {
            if !body.trim().is_empty() {
                let values = body
                    .split_whitespace()
                    .map(|v| v.parse::<f64>().expect("number in DataArray"))
                    .collect();
                arrays.push((attrs.clone(), values));
            }
        } else {
            assert!(body.trim().is_empty(), "stray text {body:?}");
        }
        let end = rest[start..].find('>').expect("unclosed tag") + start;
        let tag = &rest[start + 1..end];
        rest = &rest[end + 1..];
        if tag.starts_with('?') {
            continue;
        }
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name.trim()), "tags nest");
            if name.trim() == "DataArray" {
                open_array = None;
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let tag = tag.trim_end_matches('/');
        let mut parts = tag.splitn(2, char::is_whitespace);
        let name = parts.next().expect("tag name").to_string();
        let mut attrs = Vec::new();
        let mut a = parts.next().unwrap_or("").trim();
        while !a.is_empty() {
            let eq = a.find('=').expect("attribute =");
            let key = a[..eq].trim().to_string();
            let after = &a[eq + 1..];
            assert!(after.starts_with('"'), "quoted attribute");
            let close = after[1..].find('"').expect("closing quote") + 1;
            attrs.push((key, after[1..close].to_string()));
            a = after[close + 1..].trim();
        }
        if name == "DataArray" && !self_closing {
            open_array = Some(attrs.clone());
        }
        elements.push((name.clone(), attrs));
        if !self_closing {
            stack.push(name);
        }
    }
    assert!(rest.trim().is_empty());
    assert!(stack.is_empty(), "unclosed elements {stack:?}");
    Xml { elements, arrays }
}

fn attr<'a>(attrs: &'a [(String, String)], key: &str) -> &'a str {
    attrs
        .iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .unwrap_or_else(|| panic!("no attribute {key}"))
}

#[test]
fn slide_writes_an_svg_and_a_vtu_that_parses_back() {
    let dir = Scratch::new("slide");
    let out = hycon(&["slide", "--n", "4", "--increments", "2", "--out", dir.arg()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("slide-frictionless"), "{stdout}");
    assert!(stdout.contains("written to"), "{stdout}");

    let svg = std::fs::read_to_string(dir.path().join("slide-frictionless.svg")).expect("svg");
    assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"));
    assert!(
        svg.contains("x / a") && svg.contains("p / p0"),
        "axes labelled"
    );

    let scene = DiskOnBlock {
        elements_per_half_width: 4,
        travel: 2.5,
        ..Default::default()
    }
    .build()
    .unwrap();
    let mesh = &scene.model.mesh;
    let (n_points, n_cells) = (mesh.n_nodes(), mesh.n_elements());

    let text = std::fs::read_to_string(dir.path().join("slide-frictionless.vtu")).expect("vtu");
    let xml = parse_xml(&text);
    let root = &xml.elements[0];
    assert_eq!(root.0, "VTKFile");
    assert_eq!(attr(&root.1, "type"), "UnstructuredGrid");
    let piece = xml.elements.iter().find(|e| e.0 == "Piece").expect("Piece");
    assert_eq!(attr(&piece.1, "NumberOfPoints"), n_points.to_string());
    assert_eq!(attr(&piece.1, "NumberOfCells"), n_cells.to_string());
    let array = |name: &str| {
        xml.arrays
            .iter()
            .find(|(a, _)| attr(a, "Name") == name)
            .map(|(_, v)| v)
            .unwrap_or_else(|| panic!("no DataArray {name}"))
    };
    assert_eq!(array("Points").len(), 3 * n_points);
    assert_eq!(array("displacement").len(), 3 * n_points);
    for name in ["sx", "sy", "txy", "von_mises", "body", "offsets", "types"] {
        assert_eq!(array(name).len(), n_cells, "{name}");
    }
    assert!(array("displacement").iter().all(|v| v.is_finite()));
    assert!(
        array("von_mises")
            .iter()
            .all(|v| v.is_finite() && *v >= 0.0)
    );
    let connectivity = array("connectivity");
    assert_eq!(
        *array("offsets").last().unwrap() as usize,
        connectivity.len()
    );
    assert!(connectivity.iter().all(|&i| (i as usize) < n_points));
    for (e, t) in array("types").iter().enumerate() {
        let expected = if mesh.element(e).len() == 4 { 9.0 } else { 7.0 };
        assert_eq!(*t, expected, "cell type of element {e}");
    }
    let bodies = array("body");
    assert!(
        bodies.contains(&0.0) && bodies.contains(&1.0),
        "both bodies"
    );
    // the disk was pushed down: its top moved by -approach
    let top = scene.top[0];
    assert!(array("displacement")[3 * top + 1] < 0.0);
}

/// `hycon sphere` (the main job's axisymmetric example) prints its table and writes the
/// pressure plot and the meridian section: every node and element of the sphere scene, the
/// hoop stress as `sz` in the von Mises stress, the sphere's top moved down.
#[test]
fn sphere_writes_an_svg_and_a_vtu_of_the_meridian_section() {
    let dir = Scratch::new("sphere");
    let out = hycon(&[
        "sphere",
        "--n",
        "4",
        "--increments",
        "2",
        "--out",
        dir.arg(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("== sphere") && stdout.contains("no calibration"),
        "{stdout}"
    );
    let svg = std::fs::read_to_string(dir.path().join("sphere.svg")).expect("svg");
    assert!(
        svg.contains("x / a") && svg.contains("p / p0"),
        "axes labelled"
    );
    let scene = hycon_lab::axisymmetric::SphereOnBlock {
        elements_per_radius: 4,
        radius_over_contact: 32.0,
        modulus_ratio: 1.0,
    }
    .build()
    .unwrap();
    let mesh = &scene.model.mesh;
    let text = std::fs::read_to_string(dir.path().join("sphere-ratio-1e0.vtu")).expect("vtu");
    let xml = parse_xml(&text);
    let piece = xml.elements.iter().find(|e| e.0 == "Piece").expect("Piece");
    assert_eq!(attr(&piece.1, "NumberOfPoints"), mesh.n_nodes().to_string());
    assert_eq!(
        attr(&piece.1, "NumberOfCells"),
        mesh.n_elements().to_string()
    );
    let array = |name: &str| {
        xml.arrays
            .iter()
            .find(|(a, _)| attr(a, "Name") == name)
            .map(|(_, v)| v)
            .unwrap_or_else(|| panic!("no DataArray {name}"))
    };
    assert!(
        array("von_mises")
            .iter()
            .all(|v| v.is_finite() && *v >= 0.0)
    );
    assert!(array("displacement")[3 * scene.top[0] + 1] < 0.0);
}

#[test]
fn no_files_writes_nothing() {
    let dir = Scratch::new("nofiles");
    let out = hycon(&["cattaneo", "--n", "4", "--no-files", "--out", dir.arg()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("Q/muP"), "{stdout}");
    assert!(!dir.path().exists());
}

#[test]
fn bad_options_fail_with_a_readable_message() {
    let out = hycon(&["slide", "--bogus"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--bogus"), "{stderr}");

    let out = hycon(&["hertz", "--n", "3", "--no-files"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("hycon:") && stderr.contains("power of two"),
        "{stderr}"
    );

    let out = hycon(&["cattaneo", "--n", "4", "--friction", "0", "--no-files"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("friction"));
}

#[test]
fn bench_sweep_runs_at_tiny_sizes_and_writes_the_csv_and_plots() {
    let dir = Scratch::new("sweep");
    let out = hycon(&[
        "bench",
        "sweep",
        "--min",
        "2",
        "--max",
        "4",
        "--configs",
        "hybrid/transition,pian-sumihara/quads",
        "--refactor-n",
        "2",
        "--out",
        dir.arg(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = std::fs::read_to_string(dir.path().join("sweep.csv")).expect("sweep.csv");
    let runs = hycon_lab::bench::parse_sweep_csv(&csv).expect("the CSV parses back");
    let plain: Vec<_> = runs.iter().filter(|r| !r.case.refactor).collect();
    let sphere = |r: &hycon_lab::bench::SweepRun| r.case.scene == SweepScene::Sphere;
    assert_eq!(
        plain.len(),
        6,
        "(2 configurations + the sphere) x n = 2, 4:\n{csv}"
    );
    assert_eq!(plain.iter().filter(|r| sphere(r)).count(), 2, "{csv}");
    assert!(
        runs.iter()
            .filter(|r| sphere(r))
            .all(|r| r.case.radius_over_half_width == 32 && !r.case.refactor),
        "{csv}"
    );
    for r in &runs {
        assert!(
            r.dofs > 0 && r.contact_dofs > 0 && r.iterations > 0,
            "{csv}"
        );
        assert!(
            r.total > 0.0 && r.l2_error.is_finite() && r.l2_error > 0.0,
            "{csv}"
        );
        if !r.case.refactor {
            // (with re-factoring, the split counts the re-factorizations twice: in the
            // factorization and in the iterations)
            assert!(r.total >= r.timings.total() - 1e-9, "{csv}");
        }
    }
    for name in [
        "sweep_error_time.svg",
        "sweep_time_dofs.svg",
        "sweep_summary.md",
    ] {
        let text = std::fs::read_to_string(dir.path().join(name)).expect(name);
        assert!(!text.is_empty(), "{name}");
    }
    // re-plotting from the CSV runs nothing and gives the same summary
    let again = hycon(&[
        "bench",
        "sweep",
        "--from-csv",
        dir.path().join("sweep.csv").to_str().expect("utf-8"),
        "--out",
        dir.arg(),
    ]);
    assert!(again.status.success());
}

#[test]
fn bench_sweep_rejects_a_transition_mesh_for_q4() {
    let dir = Scratch::new("sweep-bad");
    let out = hycon(&[
        "bench",
        "sweep",
        "--min",
        "2",
        "--max",
        "2",
        "--configs",
        "q4/transition",
        "--refactor-n",
        "2",
        "--out",
        dir.arg(),
    ]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("4-node quadrilaterals only") && stderr.contains("2 sweep runs failed"),
        "{stderr}"
    );
}

#[test]
fn bench_contact_scale_writes_the_csv_and_the_fit() {
    let dir = Scratch::new("contact-scale");
    let out = hycon(&[
        "bench",
        "contact-scale",
        "--n",
        "2",
        "--levels",
        "1,2,3",
        "--out",
        dir.arg(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = std::fs::read_to_string(dir.path().join("contact_scale.csv")).expect("csv");
    let runs = hycon_lab::bench::parse_sweep_csv(&csv).expect("the CSV parses back");
    assert_eq!(runs.len(), 3);
    // a smaller cap never gives fewer dofs
    assert!(runs.windows(2).all(|w| w[1].dofs >= w[0].dofs), "{csv}");
    assert!(runs.iter().all(|r| r.case.max_element_size.is_some()));
    let md = std::fs::read_to_string(dir.path().join("contact_scale.md")).expect("md");
    assert!(md.contains("| faer | 2 |"), "{md}");
}

#[test]
fn bench_sweep_one_takes_the_scene_options() {
    let out = hycon(&[
        "bench",
        "sweep-one",
        "--element",
        "q4",
        "--mesh",
        "quads",
        "--n",
        "4",
        "--r-over-a",
        "128",
        "--header",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let runs = hycon_lab::bench::parse_sweep_csv(&text).expect("header and one row");
    assert_eq!(runs.len(), 1);
    let r = &runs[0];
    assert_eq!(r.case.radius_over_half_width, 128);
    assert_eq!(r.case.config(), "q4/quads");
    assert_eq!(r.case.kinematics, Kinematics::Small, "the default");
    assert!(r.peak_rss >= r.start_rss, "{text}");
    let bad = hycon(&["bench", "sweep-one", "--r-over-a", "100"]);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("power of two"));
}

/// `hycon bench skip` prints its six rows with finite, positive times (timings are printed,
/// never compared).
#[test]
fn bench_skip_prints_the_table() {
    let out = hycon(&["bench", "skip", "--n", "4", "--repeats", "1"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| skipped"))
        .collect();
    assert_eq!(rows.len(), 6, "{text}");
    for row in rows {
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        for cell in &cells[2..4] {
            let t: f64 = cell.parse().unwrap_or_else(|_| panic!("{row}"));
            assert!(t.is_finite() && t > 0.0, "{row}");
        }
    }
}

/// The committed sweeps parse back with their kinematics: the 0.3 sweep's `kinematics` column
/// says small, and the 0.2 files, written before the column existed, read as finite; the
/// current one holds the sphere's rows (0.7.0), the 0.2 files only the disk's.
#[test]
fn committed_sweeps_parse_with_their_kinematics() {
    let read = |path: &str| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path);
        let text = std::fs::read_to_string(path).expect("committed sweep CSV");
        hycon_lab::bench::parse_sweep_csv(&text).expect("it parses")
    };
    let current = read("docs/bench/sweep.csv");
    let old = read("docs/bench/finite-kinematics/sweep.csv");
    assert!(!current.is_empty() && !old.is_empty());
    assert!(
        current
            .iter()
            .all(|r| r.case.kinematics == Kinematics::Small)
    );
    assert!(old.iter().all(|r| r.case.kinematics == Kinematics::Finite));
    assert!(current.iter().any(|r| r.case.scene == SweepScene::Sphere));
    assert!(current.iter().any(|r| r.case.scene == SweepScene::Disk));
    assert!(old.iter().all(|r| r.case.scene == SweepScene::Disk));
}

/// `bench presses` accounts for every press (converged or failed by kind and class), only
/// presses with friction can fail with a node locked in slip, and no failure is one that the
/// reference run in sub-increments settles; `--press` runs the chosen presses of the draw.
#[test]
fn bench_presses_accounts_for_every_press() {
    let out = hycon(&["bench", "presses", "--count", "200", "--seed", "7"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let number = |s: &str| s.trim().parse::<usize>().expect("a count");
    let first = text.lines().next().expect("a summary line");
    let converged = number(
        first
            .rsplit(": ")
            .next()
            .unwrap()
            .trim_end_matches(" converged"),
    );
    let failed: usize = text
        .lines()
        .filter(|l| l.trim_start().starts_with("failed, "))
        .map(|l| number(l.rsplit(": ").next().unwrap()))
        .sum();
    assert_eq!(converged + failed, 200, "{text}");
    assert!(converged > 190, "{text}");
    assert!(!text.contains("SlipReversal, frictionless"), "{text}");
    assert!(!text.contains("the reference settles"), "{text}");
    assert!(text.contains("the paper's rules alone"), "{text}");
    // chosen presses of the same draw
    let out = hycon(&[
        "bench", "presses", "--count", "200", "--seed", "7", "--press", "3,150",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.starts_with("2 random two-block presses"), "{text}");
}

/// `hycon run --dry-run` prints the verdict and solves nothing; `hycon run` prints the step
/// table and writes the files; a set-up mistake fails with the scene file and the group on
/// stderr.
#[test]
fn run_scene_dry_run_run_and_a_mistake() {
    let scratch = Scratch::new("run-scene");
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/press");
    std::fs::create_dir_all(scratch.path()).unwrap();
    for f in ["press.msh", "press.toml"] {
        std::fs::copy(src.join(f), scratch.path().join(f)).unwrap();
    }
    let scene = scratch.path().join("press.toml");
    let scene_arg = scene.to_str().unwrap();
    let dry = hycon(&["run", "--dry-run", scene_arg]);
    assert!(dry.status.success());
    let text = String::from_utf8_lossy(&dry.stdout);
    assert!(text.contains("verdict: ready to run"), "{text}");
    assert!(
        !scratch.path().join("out").exists(),
        "the dry run wrote files"
    );
    let run = hycon(&["run", scene_arg]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(
        text.contains("contact len") && text.contains("wrote"),
        "{text}"
    );
    assert!(scratch.path().join("out/press-summary.json").exists());
    // the global --out replaces the scene's [output] dir
    let elsewhere = scratch.path().join("elsewhere");
    let run = hycon(&["run", scene_arg, "--out", elsewhere.to_str().unwrap()]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(elsewhere.join("press-summary.json").exists());
    assert!(elsewhere.join("press-contact.csv").exists());
    let bad = std::fs::read_to_string(&scene).unwrap().replacen(
        "group = \"punch\"",
        "group = \"punsh\"",
        1,
    );
    std::fs::write(&scene, bad).unwrap();
    let out = hycon(&["run", "--dry-run", scene_arg]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("press.toml") && err.contains("\"punsh\""),
        "{err}"
    );
}

/// `hycon bench brick` prints the convergence table (the hybrid brick ahead of the H8 on every
/// mesh, its regular-mesh error falling by about 4 per halving) and writes the SVG plot.
#[test]
fn bench_brick_prints_the_table_and_writes_the_plot() {
    let dir = Scratch::new("brick");
    let out = hycon(&["bench", "brick", "--k", "1,2", "--out", dir.arg()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| l.starts_with("| regular") || l.starts_with("| distorted"))
        .map(|l| {
            l.split('|')
                .map(str::trim)
                .skip(2)
                .take(3)
                .map(|c| c.parse().unwrap_or_else(|_| panic!("{l}")))
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), 4, "{text}");
    for r in &rows {
        assert!(r[1] > 0.0 && r[1] < r[2], "hybrid ahead of the H8: {text}");
    }
    assert!(
        rows[0][1] / rows[1][1] > 3.5,
        "h^2 on regular meshes: {text}"
    );
    let svg = std::fs::read_to_string(dir.path().join("brick_convergence.svg")).expect("the SVG");
    assert!(svg.starts_with("<svg") && svg.contains("hybrid18, distorted meshes"));
    let bad = hycon(&["bench", "brick", "--k", "0"]);
    assert!(!bad.status.success());
}

/// `hycon bench hertz3d` prints one row per a/h, then the time split: the 3D Hertz
/// comparison of `hycon_lab::hertz3d` (the numbers themselves are checked in
/// `contact_hertz3d`).
#[test]
fn bench_hertz3d_prints_the_comparison() {
    let out = hycon(&[
        "bench",
        "hertz3d",
        "--a-over-h",
        "4",
        "--modulus-ratio",
        "1",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let row: Vec<&str> = text
        .lines()
        .find(|l| l.trim_start().starts_with("4 "))
        .unwrap_or_else(|| panic!("{text}"))
        .split_whitespace()
        .collect();
    assert_eq!(row.len(), 13, "{text}");
    assert_eq!(row[2], "15", "active A nodes: {text}");
    let radius: f64 = row[4].parse().unwrap();
    assert!((radius + 1.0).abs() < 0.01, "{text}");
    assert!(
        text.contains("x a linear analysis of the same model"),
        "{text}"
    );
    let bad = hycon(&[
        "bench",
        "hertz3d",
        "--a-over-h",
        "4",
        "--modulus-ratio",
        "-1",
    ]);
    assert!(!bad.status.success());
}

/// `hycon sphere3d` (the main job's 3D examples, at the main job's `a/h = 4`): the JSON array
/// of the two examples in the plane examples' structure, the quarter cap's `a` and `p0`
/// within the tolerances `contact_hertz3d` asserts at `a/h = 4` (and equal to
/// `hycon_lab::hertz3d::QuarterCap`'s own, so the shared scene builder builds its model), the
/// half cap pulled to `Q / (mu P) = 0.5` with its stick radius within a node spacing of
/// Mindlin's (`contact_mindlin3d`'s tolerance), and a VTU of both bodies per example that
/// parses back: every brick a `VTK_HEXAHEDRON`, the contact pressure at the contact nodes
/// (its largest value the centre node's), the cap's top moved by the last increment's motion.
#[test]
fn sphere3d_writes_the_json_the_plots_and_the_bricks() {
    let dir = Scratch::new("sphere3d");
    let out = hycon(&["sphere3d", "--json", "--out", dir.arg()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    let examples = json.as_array().expect("an array of examples");
    let names: Vec<&str> = examples
        .iter()
        .map(|e| e["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["hertz3d", "cattaneo-mindlin3d"]);

    let press = &examples[0]["runs"][0]["increments"][0];
    let hertz = &press["hertz"];
    let [radius, peak] = ["half_width_error", "peak_error"].map(|k| finite(&hertz[k], k));
    assert!(radius.abs() < 0.03 && peak.abs() < 0.02, "{hertz}");
    let mut cap = hycon_lab::hertz3d::QuarterCap::new(4, Default::default()).unwrap();
    let own = cap.press().unwrap().errors();
    assert!(
        (radius - own[0]).abs() < 1e-12 && (peak - own[1]).abs() < 1e-12,
        "{own:?}"
    );
    for k in ["l2_error", "l2_error_forces"] {
        let e = finite(&hertz[k], k);
        assert!(e > 0.0 && e < 0.5, "{k} {e}");
    }

    let run = &examples[1]["runs"][0];
    let h = finite(&run["setup"]["element_size"], "h");
    let pulled = run["increments"].as_array().unwrap().last().unwrap();
    let ratio = finite(&pulled["q_over_mu_p"], "Q/(mu P)");
    assert!((ratio - 0.5).abs() <= 0.005, "{ratio}");
    let zone = &pulled["stick_zone"];
    let miss = finite(&zone["measured"], "c") - finite(&zone["predicted"], "c_M");
    assert!(miss.abs() <= h, "{zone}, h = {h}");

    for (example, stem) in examples.iter().zip(["hertz3d", "cattaneo-mindlin3d"]) {
        let svg = std::fs::read_to_string(dir.path().join(format!("{stem}.svg"))).expect("svg");
        assert!(svg.contains("p / p0"), "{stem}: pressure axis");
        let setup = &example["runs"][0]["setup"];
        let n_points = setup["nodes"].as_u64().unwrap() as usize;
        let n_cells = setup["elements"].as_u64().unwrap() as usize;
        let text = std::fs::read_to_string(dir.path().join(format!("{stem}.vtu"))).expect("vtu");
        let xml = parse_xml(&text);
        let piece = xml.elements.iter().find(|e| e.0 == "Piece").expect("Piece");
        assert_eq!(attr(&piece.1, "NumberOfPoints"), n_points.to_string());
        assert_eq!(attr(&piece.1, "NumberOfCells"), n_cells.to_string());
        let array = |name: &str| {
            xml.arrays
                .iter()
                .find(|(a, _)| attr(a, "Name") == name)
                .map(|(_, v)| v)
                .unwrap_or_else(|| panic!("{stem}: no DataArray {name}"))
        };
        for (name, len) in [
            ("Points", 3 * n_points),
            ("displacement", 3 * n_points),
            ("contact_pressure", n_points),
            ("contact_traction", 3 * n_points),
            ("connectivity", 8 * n_cells),
        ] {
            assert_eq!(array(name).len(), len, "{stem}: {name}");
        }
        for name in [
            "sx",
            "sy",
            "sz",
            "txy",
            "tyz",
            "tzx",
            "von_mises",
            "body",
            "types",
        ] {
            assert_eq!(array(name).len(), n_cells, "{stem}: {name}");
        }
        assert!(
            array("types").iter().all(|&t| t == 12.0),
            "{stem}: hexahedra"
        );
        assert_eq!(*array("offsets").last().unwrap() as usize, 8 * n_cells);
        assert!(
            array("connectivity")
                .iter()
                .all(|&i| (i as usize) < n_points)
        );
        assert!(
            array("von_mises")
                .iter()
                .all(|v| v.is_finite() && *v >= 0.0)
        );
        let bodies = array("body");
        assert!(
            bodies.contains(&0.0) && bodies.contains(&1.0),
            "{stem}: both bodies"
        );
        let inc = example["runs"][0]["increments"]
            .as_array()
            .unwrap()
            .last()
            .unwrap();
        let pressure = array("contact_pressure");
        let loaded = pressure.iter().filter(|&&p| p > 0.0).count();
        assert!(loaded >= inc["active"].as_u64().unwrap() as usize, "{stem}");
        let largest = pressure.iter().copied().fold(0.0, f64::max);
        assert_eq!(
            largest,
            finite(&inc["hertz"]["measured_peak"], "p0"),
            "{stem}"
        );
        // the cap's top (the highest points) moved by the increment's motion: down by the
        // approach; the half cap's also along x by the slide and not along y (the quarter's
        // top is free to move sideways)
        let slide = finite(&inc["slide"], "slide");
        let motion = [slide, 0.0, -finite(&inc["approach"], "d")];
        let held = if slide > 0.0 { 0..3 } else { 2..3 };
        let points = array("Points");
        let top = points.chunks(3).map(|p| p[2]).fold(f64::MIN, f64::max);
        let moved: Vec<&[f64]> = (array("displacement").chunks(3))
            .zip(points.chunks(3))
            .filter(|(_, p)| p[2] == top)
            .map(|(u, _)| u)
            .collect();
        assert!(moved.len() > 1, "{stem}");
        for u in moved {
            for d in held.clone() {
                assert!(
                    (u[d] - motion[d]).abs() <= 1e-12 * motion[2].abs(),
                    "{stem}: {u:?} {motion:?}"
                );
            }
        }
    }
}
