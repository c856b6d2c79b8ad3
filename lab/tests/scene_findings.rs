//! Scene files a new user gets right the first time: one test per finding of issue 44 on a
//! mesh made outside the lab's generators, a half disk (R = 1, its flat cut on top, its arc
//! below) resting on a block, meshed in unstructured-looking quadrilaterals and written as
//! Gmsh MSH 4.1 ASCII with node tags that are not the model's node ids.

use hycon_lab::scenefile::{self, SceneError};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The mesh's node tag of node `i` (never `i` or `i + 1`, so a message naming a model id
/// instead of a tag is caught).
fn tag(i: usize) -> usize {
    1000 + 7 * i
}

/// Whether `n` is one of [`tag`]'s values.
fn is_tag(n: usize) -> bool {
    n >= 1000 && (n - 1000).is_multiple_of(7)
}

/// A body of the test mesh: its nodes and counter-clockwise quads.
#[derive(Default)]
struct Body {
    nodes: Vec<[f64; 2]>,
    quads: Vec<[usize; 4]>,
    index: HashMap<(i64, i64), usize>,
}

impl Body {
    /// The node at `p`, merged with an earlier one at the same place.
    fn node(&mut self, p: [f64; 2]) -> usize {
        let key = ((p[0] * 1e9).round() as i64, (p[1] * 1e9).round() as i64);
        *self.index.entry(key).or_insert_with(|| {
            self.nodes.push(p);
            self.nodes.len() - 1
        })
    }

    /// A patch lofted between the curves `inner(t)` and `outer(t)`, `t` in [0, 1]:
    /// `n` divisions along them, `k` across.
    fn loft(
        &mut self,
        inner: impl Fn(f64) -> [f64; 2],
        outer: impl Fn(f64) -> [f64; 2],
        n: usize,
        k: usize,
    ) {
        let mut ids = vec![vec![0; n + 1]; k + 1];
        for (j, row) in ids.iter_mut().enumerate() {
            let s = j as f64 / k as f64;
            for (i, id) in row.iter_mut().enumerate() {
                let t = i as f64 / n as f64;
                let (p, q) = (inner(t), outer(t));
                *id = self.node([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]);
            }
        }
        for j in 0..k {
            for i in 0..n {
                let q = [ids[j][i], ids[j][i + 1], ids[j + 1][i + 1], ids[j + 1][i]];
                // counter-clockwise whichever way the curves run
                let x = &self.nodes;
                let area: f64 = (0..4)
                    .map(|m| {
                        let (a, b) = (x[q[m]], x[q[(m + 1) % 4]]);
                        a[0] * b[1] - b[0] * a[1]
                    })
                    .sum();
                self.quads.push(if area > 0.0 {
                    q
                } else {
                    [q[0], q[3], q[2], q[1]]
                });
            }
        }
    }

    /// Move every node for which `inside` holds by a deterministic pseudo-random offset of up
    /// to `amount` in each direction (unstructured-looking quads).
    fn jitter(&mut self, amount: f64, inside: impl Fn([f64; 2]) -> bool) {
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % 2001) as f64 / 1000.0 - 1.0
        };
        for p in &mut self.nodes {
            let (dx, dy) = (next(), next());
            if inside(*p) {
                p[0] += amount * dx;
                p[1] += amount * dy;
            }
        }
    }

    /// The nodes for which `on` holds, ordered by `key`.
    fn curve(&self, on: impl Fn([f64; 2]) -> bool, key: impl Fn([f64; 2]) -> f64) -> Vec<usize> {
        let mut ids: Vec<usize> = (0..self.nodes.len())
            .filter(|&i| on(self.nodes[i]))
            .collect();
        ids.sort_by(|&a, &b| key(self.nodes[a]).total_cmp(&key(self.nodes[b])));
        ids
    }
}

/// The half disk of radius 1 with its flat cut at y = `lift` + 1 (arc down, lowest point at
/// y = `lift`) over the block [-w, w] x [-1, 0]; MSH 4.1 ASCII with the physical groups
/// `disk`, `block` (surfaces), `disk_cut`, `disk_arc` (the whole arc: its end nodes are the
/// cut's), `block_top`, `block_bottom` (curves).
fn half_disk_on_block(lift: f64, w: f64) -> String {
    let pi = std::f64::consts::PI;
    let (c, r) = ([0.0, 1.0 + lift], 1.0);
    let on_circle = |a: f64| [c[0] + r * a.cos(), c[1] + r * a.sin()];
    let mut disk = Body::default();
    // a butterfly: an inner rectangle [-1/2, 1/2] x [c - 1/2, c] and three patches to the arc
    let corner = |x: f64, y: f64| [x, c[1] - 0.5 * y];
    let (n_side, n_bottom, k) = (3, 12, 3);
    disk.loft(
        |t| corner(-0.5 + t, 1.0),
        |t| corner(-0.5 + t, 0.0),
        n_bottom,
        n_side,
    );
    disk.loft(
        |t| corner(-0.5, t),
        |t| on_circle(pi + 0.25 * pi * t),
        n_side,
        k,
    );
    disk.loft(
        |t| corner(-0.5 + t, 1.0),
        |t| on_circle(1.25 * pi + 0.5 * pi * t),
        n_bottom,
        k,
    );
    disk.loft(
        |t| corner(0.5, 1.0 - t),
        |t| on_circle(1.75 * pi + 0.25 * pi * t),
        n_side,
        k,
    );
    let near = |a: f64, b: f64| (a - b).abs() < 1e-9;
    let on_arc = |p: [f64; 2]| near((p[0] - c[0]).hypot(p[1] - c[1]), r) && p[1] <= c[1] + 1e-9;
    let on_cut = |p: [f64; 2]| near(p[1], c[1]);
    disk.jitter(0.012, |p| !on_arc(p) && !on_cut(p));
    let arc = disk.curve(on_arc, |p| p[0]);
    let cut = disk.curve(on_cut, |p| p[0]);

    let mut block = Body::default();
    let (nx, ny) = ((16.0 * w) as usize, 4);
    block.loft(
        |t| [-w + 2.0 * w * t, -1.0],
        |t| [-w + 2.0 * w * t, 0.0],
        nx,
        ny,
    );
    let h = 2.0 * w / nx as f64;
    block.jitter(0.12 * h, |p| {
        !near(p[1], 0.0) && !near(p[1], -1.0) && !near(p[0].abs(), w)
    });
    let top = block.curve(|p| near(p[1], 0.0), |p| p[0]);
    let bottom = block.curve(|p| near(p[1], -1.0), |p| p[0]);

    // one numbering: the block's nodes after the disk's
    let offset = disk.nodes.len();
    let nodes: Vec<[f64; 2]> = disk.nodes.iter().chain(&block.nodes).copied().collect();
    let shift = |ids: &[usize]| ids.iter().map(|&i| i + offset).collect::<Vec<_>>();
    let quads = |b: &Body, o: usize| -> Vec<Vec<usize>> {
        b.quads
            .iter()
            .map(|q| q.iter().map(|&i| i + o).collect())
            .collect()
    };
    let lines =
        |ids: &[usize]| -> Vec<Vec<usize>> { ids.windows(2).map(<[usize]>::to_vec).collect() };
    let groups: Vec<(usize, &str, Vec<Vec<usize>>)> = vec![
        (2, "disk", quads(&disk, 0)),
        (2, "block", quads(&block, offset)),
        (1, "disk_cut", lines(&cut)),
        (1, "disk_arc", lines(&arc)),
        (1, "block_top", lines(&shift(&top))),
        (1, "block_bottom", lines(&shift(&bottom))),
    ];
    msh(&nodes, &groups)
}

/// MSH 4.1 ASCII text: the nodes (tagged by [`tag`]) and one entity per physical group
/// `(dim, name, elements)`.
fn msh(nodes: &[[f64; 2]], groups: &[(usize, &str, Vec<Vec<usize>>)]) -> String {
    let mut s = String::from("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n");
    let _ = writeln!(s, "{}", groups.len());
    for (k, (d, name, _)) in groups.iter().enumerate() {
        let _ = writeln!(s, "{d} {} \"{name}\"", k + 1);
    }
    s.push_str("$EndPhysicalNames\n$Entities\n");
    let count = |d: usize| groups.iter().filter(|g| g.0 == d).count();
    let _ = writeln!(s, "0 {} {} 0", count(1), count(2));
    for d in [1, 2] {
        for (k, _) in groups.iter().enumerate().filter(|(_, g)| g.0 == d) {
            let _ = writeln!(s, "{} 0 0 0 0 0 0 1 {} 0", k + 1, k + 1);
        }
    }
    let n = nodes.len();
    let _ = writeln!(s, "$EndEntities\n$Nodes\n1 {n} {} {}", tag(0), tag(n - 1));
    let _ = writeln!(s, "2 0 0 {n}");
    for i in 0..n {
        let _ = writeln!(s, "{}", tag(i));
    }
    for p in nodes {
        let _ = writeln!(s, "{:e} {:e} 0", p[0], p[1]);
    }
    let total: usize = groups.iter().map(|g| g.2.len()).sum();
    let _ = writeln!(
        s,
        "$EndNodes\n$Elements\n{} {total} 1 {total}",
        groups.len()
    );
    let mut e = 1;
    for (k, (d, _, els)) in groups.iter().enumerate() {
        let kind = if *d == 2 { 3 } else { 1 };
        let _ = writeln!(s, "{d} {} {kind} {}", k + 1, els.len());
        for el in els {
            let _ = write!(s, "{e}");
            for &i in el {
                let _ = write!(s, " {}", tag(i));
            }
            s.push('\n');
            e += 1;
        }
    }
    s.push_str("$EndElements\n");
    s
}

/// A fresh folder with the half disk's mesh `disk.msh` and the scene `text`.
fn scene_at(name: &str, text: &str, msh: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("hycon-findings-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("disk.msh"), msh).unwrap();
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// The half disk pressed onto the block by a rigid plate on its cut (force -`force` in y,
/// held in x), `a` the multiplier side; both E = `e`, nu = 0.3.
fn plate_scene(a: &str, b: &str, e: f64, force: f64) -> String {
    format!(
        "mesh = \"disk.msh\"\n\n\
         [[body]]\ngroup = \"block\"\nmaterial = {{ E = {e:e}, nu = 0.3 }}\n\n\
         [[body]]\ngroup = \"disk\"\nmaterial = {{ E = {e:e}, nu = 0.3 }}\n\n\
         [[support]]\ngroup = \"block_bottom\"\nx = 0.0\ny = 0.0\n\n\
         [plate]\ngroup = \"disk_cut\"\nx = \"displacement\"\ny = \"force\"\n\
         value = [0.0, {:e}]\n\n\
         [[contact]]\na = \"{a}\"\nb = \"{b}\"\n\n\
         [[step]]\nload = 0.5\n\n[[step]]\nload = 1.0\n\n\
         [output]\nvtu = false\nsvg = false\n",
        -force
    )
}

/// The run of `path`, every step converged.
fn run_ok(path: &Path) -> (scenefile::Scene, scenefile::RunSummary) {
    let scene = scenefile::load(path).unwrap_or_else(|e| panic!("{e}"));
    let r = scenefile::run(&scene, &mut std::io::sink()).unwrap();
    assert!(r.error.is_none(), "{:?}", r.error);
    (scene, r)
}

fn error_text(result: Result<scenefile::Scene, SceneError>) -> String {
    result
        .expect_err("the scene should be rejected")
        .to_string()
}

/// The half disk held by a support on its cut (x = 0, y = `uy` at factor 1), `a` the
/// multiplier side; both E = 1, nu = 0.3.
fn support_scene(a: &str, b: &str, uy: f64) -> String {
    format!(
        "mesh = \"disk.msh\"\n\n\
         [[body]]\ngroup = \"block\"\nmaterial = {{ E = 1.0, nu = 0.3 }}\n\n\
         [[body]]\ngroup = \"disk\"\nmaterial = {{ E = 1.0, nu = 0.3 }}\n\n\
         [[support]]\ngroup = \"block_bottom\"\nx = 0.0\ny = 0.0\n\n\
         [[support]]\ngroup = \"disk_cut\"\nx = 0.0\ny = {uy:e}\n\n\
         [[contact]]\na = \"{a}\"\nb = \"{b}\"\n\n\
         [[step]]\nload = 0.5\n\n[[step]]\nload = 1.0\n\n\
         [output]\nvtu = false\nsvg = false\n"
    )
}

/// `hycon ARGS`: the exit status's success, stdout and stderr.
fn hycon(args: &[&str]) -> (bool, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_hycon"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Finding: a plate on the disk's flat cut passed the dry run and then failed, the cut's end
/// nodes being the arc's, with an internal node number. Now the dry run says that the arc's
/// end nodes are left to the plate (naming both groups), and the run converges with the
/// contact force balancing the plate's at every step.
#[test]
fn plate_on_a_cut_that_ends_the_contact_arc() {
    let msh = half_disk_on_block(0.0, 2.0);
    let path = scene_at(
        "plate-arc",
        &plate_scene("block_top", "disk_arc", 1.0, 0.05),
        &msh,
    );
    let dry = scenefile::dry_run(&path).unwrap();
    assert!(
        dry.contains("note: contact pair 1")
            && dry.contains("of group \"disk_arc\" are also on the plate's group \"disk_cut\""),
        "{dry}"
    );
    let (_, r) = run_ok(&path);
    for (step, load) in r.steps.iter().zip([0.025, 0.05]) {
        // the force on A (the block's top) is the disk's push, down
        let fy = step.pairs[0].total_force[1];
        assert!((fy + load).abs() < 1e-6 * load, "{fy} vs -{load}");
    }
    assert!(r.steps[1].pairs[0].active >= 3, "{:?}", r.steps[1]);
    // a plate on the arc itself: the contact side lies on the plate, said before any solve
    let text = plate_scene("block_top", "disk_arc", 1.0, 0.05).replace(
        "group = \"disk_cut\"\nx = \"displacement\"",
        "group = \"disk_arc\"\nx = \"displacement\"",
    );
    let e = error_text(scenefile::load(&scene_at("plate-on-arc", &text, &msh)));
    assert!(
        e.contains("contact pair 1") && e.contains("\"disk_arc\" lies on the plate's group"),
        "{e}"
    );
}

/// Finding: without a plate there was no force control (a traction alone leaves the body "not
/// held against rigid motion"). Now that message points to the plate, and a traction on the
/// cut, with the plate holding the disk (x by displacement, y by a force of 0), goes into the
/// contact whole.
#[test]
fn force_load_on_an_edge_where_the_scene_holds_the_body_otherwise() {
    let msh = half_disk_on_block(0.0, 2.0);
    // the cut is 2 long: a traction of 0.025 down is a load of 0.05
    let text = plate_scene("block_top", "disk_arc", 1.0, 0.0).replace(
        "[[contact]]",
        "[[load]]\ngroup = \"disk_cut\"\ntraction = [0.0, -0.025]\n\n[[contact]]",
    );
    let (_, r) = run_ok(&scene_at("traction-plate", &text, &msh));
    for (step, load) in r.steps.iter().zip([0.025, 0.05]) {
        let fy = step.pairs[0].total_force[1];
        assert!((fy + load).abs() < 1e-6 * load, "{fy} vs -{load}");
    }
    // the traction alone: not held, and the message says how to control by force
    let start = text.find("[plate]").unwrap();
    let end = text.find("[[load]]").unwrap();
    let alone = format!("{}{}", &text[..start], &text[end..]);
    let e = error_text(scenefile::load(&scene_at("traction-alone", &alone, &msh)));
    assert!(
        e.contains("body \"disk\"")
            && e.contains("not held against rigid motion")
            && e.contains("[plate]")
            && e.contains("y = \"force\""),
        "{e}"
    );
}

/// Finding: with the multiplier side on the arc (the sides swapped), the run failed at one
/// search distance with "extend the B polyline" for a B side far longer than the contact: an
/// arc node far from the contact, whose support the search window cut, closed. The cause was
/// its gap under small kinematics: `R_C` over the covered part of its support moved by `F^A`
/// over the whole support, and divided by the covered weight, so the disk's approach closed
/// it by the approach times weight / covered weight. With `F^A` over the covered part the
/// swapped scene runs at every search distance, with the same results.
#[test]
fn swapped_sides_run_at_every_search_distance() {
    let msh = half_disk_on_block(0.0, 2.0);
    let scene = |distance: f64| {
        support_scene("disk_arc", "block_top", -0.02).replace(
            "[output]",
            &format!("[options]\nsearch_distance = {distance:?}\n\n[output]"),
        )
    };
    let (_, base) = run_ok(&scene_at("swapped-4", &scene(4.0), &msh));
    // the force on A (the disk's arc) is the block's push, up
    let push = base.steps[1].pairs[0].total_force[1];
    assert!(push > 0.0, "{:?}", base.steps[1]);
    // 0.10.0 failed at 0.5 and 3 (the window cut the support of an arc node that closed)
    for distance in [0.5, 1.0, 2.0, 3.0, 5.0, 8.0] {
        let (_, r) = run_ok(&scene_at(
            &format!("swapped-{distance}"),
            &scene(distance),
            &msh,
        ));
        for (step, first) in r.steps.iter().zip(&base.steps) {
            let (p, q) = (&step.pairs[0], &first.pairs[0]);
            assert_eq!(
                (step.iterations, p.active, p.slip),
                (first.iterations, q.active, q.slip),
                "search distance {distance}"
            );
            let force =
                (p.total_force[0] - q.total_force[0]).hypot(p.total_force[1] - q.total_force[1]);
            assert!(
                force <= 1e-12 * push,
                "search distance {distance}: {p:?} vs {q:?}"
            );
        }
    }
    // the swapped sides under the plate: beyond small kinematics at this load (strains of
    // 0.1, the disk's arc sliding on the block), and the advice to use finite kinematics holds
    let text = plate_scene("disk_arc", "block_top", 1.0, 0.05);
    let s = scenefile::load(&scene_at("swapped-plate", &text, &msh)).unwrap();
    let small = scenefile::run(&s, &mut std::io::sink())
        .unwrap()
        .error
        .expect("beyond small kinematics");
    assert!(small.contains("use finite kinematics"), "{small}");
    let finite = text.replace("[output]", "[options]\nkinematics = \"finite\"\n\n[output]");
    let (_, r) = run_ok(&scene_at("swapped-finite", &finite, &msh));
    for (step, load) in r.steps.iter().zip([0.025, 0.05]) {
        let fy = step.pairs[0].total_force[1];
        assert!((fy - load).abs() < 1e-6 * load, "{fy} vs {load}");
    }
}

/// Finding: a binary MSH file gave "line  cannot read the mesh: stream did not contain valid
/// UTF-8" (a blank line number, no how-to); a missing or empty mesh path a blank file name.
/// Now each names the file, the line where there is one, and how to get an ASCII mesh.
#[test]
fn binary_missing_and_empty_mesh_paths_say_what_and_where() {
    let text = support_scene("block_top", "disk_arc", -0.02);
    // binary: Gmsh's header, then raw bytes from the third line on
    let mut binary = b"$MeshFormat\n4.1 1 8\n".to_vec();
    binary.extend_from_slice(&[1, 0, 0, 0, 0xff, 0xfe, 0x80, b'\n']);
    binary.extend_from_slice(b"$EndMeshFormat\n");
    let path = scene_at("binary", &text, "");
    std::fs::write(path.with_file_name("disk.msh"), &binary).unwrap();
    let e = error_text(scenefile::load(&path));
    assert!(
        e.contains("disk.msh: line 3: binary MSH")
            && e.contains("Mesh.Binary = 0")
            && e.contains("-format msh41"),
        "{e}"
    );
    // a missing file: its path, the scene's line that names it and the how-to
    let missing = text.replace("mesh = \"disk.msh\"", "mesh = \"other.msh\"");
    let path = scene_at("missing", &missing, "");
    let e = error_text(scenefile::load(&path));
    assert!(
        e.contains(&path.with_file_name("other.msh").display().to_string())
            && e.contains("cannot read the mesh")
            && e.contains("mesh = \"other.msh\" in ")
            && e.contains("(line 1)")
            && e.contains("relative to the scene file's folder")
            && !e.contains("line  "),
        "{e}"
    );
    // no mesh key
    let none = text.replace("mesh = \"disk.msh\"", "");
    let path = scene_at("no-mesh", &none, "");
    let e = error_text(scenefile::load(&path));
    assert!(
        e.starts_with(&path.display().to_string())
            && e.contains("missing field `mesh`: add mesh = \"model.msh\" at the top"),
        "{e}"
    );
    // an empty path
    let empty = text.replace("mesh = \"disk.msh\"", "mesh = \"\"");
    let path = scene_at("empty", &empty, "");
    let e = error_text(scenefile::load(&path));
    assert!(
        e.starts_with(&path.display().to_string())
            && e.contains("mesh = \"\" (line 1): give the Gmsh mesh"),
        "{e}"
    );
}

/// Finding: the unit check missed force-controlled plates (E = 210e9 with a load of 1 gave a
/// contact one node wide, E = 1e-4 the advice "use finite kinematics"). Now the dry run
/// checks the plate's mean strain both ways, and the run flags a contact zone narrower than
/// two elements.
#[test]
fn unit_check_covers_force_controlled_plates() {
    let msh = half_disk_on_block(0.0, 2.0);
    let soft = scene_at(
        "soft",
        &plate_scene("block_top", "disk_arc", 1e-4, 0.05),
        &msh,
    );
    let dry = scenefile::dry_run(&soft).unwrap();
    assert!(
        dry.contains("warning: plate on \"disk_cut\"") && dry.contains("far beyond small strain"),
        "{dry}"
    );
    let stiff = scene_at(
        "stiff",
        &plate_scene("block_top", "disk_arc", 210e9, 1.0),
        &msh,
    );
    let dry = scenefile::dry_run(&stiff).unwrap();
    assert!(
        dry.contains("warning: plate on \"disk_cut\"") && dry.contains("implausibly small"),
        "{dry}"
    );
    let (ok, out, err) = hycon(&["run", stiff.to_str().unwrap()]);
    assert!(ok, "{out}{err}");
    assert!(
        out.contains(
            "warning: contact pair 1 (\"block_top\" on \"disk_arc\"): at step 2 the \
                      contact zone is"
        ) && out.contains("narrower than two elements"),
        "{out}"
    );
    // the well-scaled press: neither warning
    let fine = scene_at(
        "fine",
        &plate_scene("block_top", "disk_arc", 1.0, 0.05),
        &msh,
    );
    let (ok, out, err) = hycon(&["run", fine.to_str().unwrap()]);
    assert!(ok && !out.contains("warning"), "{out}{err}");
}

/// Finding: node numbers in errors and in the tractions CSV were internal indices, and the CSV
/// gave deformed positions only. Now both use the mesh's node tags, and the CSV gives the
/// reference position beside the deformed one.
#[test]
fn errors_and_the_csv_name_the_mesh_node_tags() {
    let msh = half_disk_on_block(0.0, 2.0);
    let text = support_scene("block_top", "disk_arc", -0.05)
        .replace("svg = false\n", "svg = false\ndir = \"out\"\n");
    let path = scene_at("tags", &text, &msh);
    let (scene, _) = run_ok(&path);
    let csv = std::fs::read_to_string(scene.output_dir().join("scene-contact.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| {
        head.iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name} in {head:?}"))
    };
    let (node, x0, y0, y) = (col("node"), col("x0"), col("y0"), col("y"));
    let mut moved = 0;
    for l in lines {
        let v: Vec<&str> = l.split(',').collect();
        let n: usize = v[node].parse().unwrap();
        assert!(is_tag(n), "node {n} is not a mesh tag: {l}");
        // A is the block's top, at y = 0 in the reference configuration
        let (ref_y, cur_y): (f64, f64) = (v[y0].parse().unwrap(), v[y].parse().unwrap());
        assert!(
            ref_y.abs() < 1e-12 && v[x0].parse::<f64>().unwrap().abs() <= 2.0,
            "{l}"
        );
        if cur_y < -1e-6 {
            moved += 1;
        }
    }
    assert!(moved >= 3, "the pressed nodes move down: {csv}");
    // an error naming a node: the disk slid sideways under small kinematics
    let text = support_scene("block_top", "disk_arc", -0.05)
        .replace("x = 0.0\ny = -5e-2", "x = 0.6\ny = -5e-2");
    let scene = scenefile::load(&scene_at("tags-error", &text, &msh)).unwrap();
    let r = scenefile::run(&scene, &mut std::io::sink()).unwrap();
    let e = r.error.expect("the slide breaks small kinematics");
    let n: usize = e
        .split("node ")
        .nth(1)
        .and_then(|t| t.split(|c: char| !c.is_ascii_digit()).next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no node in {e}"));
    assert!(is_tag(n), "node {n} is not a mesh tag: {e}");
}

/// Finding: a pair that never closes (a pull instead of a push) ended with exit code 0 and no
/// note, and an open pair's contact length printed as "-0.0000e0". Now the run's summary
/// warns, `--strict` fails, and the length prints as 0.
#[test]
fn a_pair_that_never_closes_is_a_warning_and_fails_strict() {
    let msh = half_disk_on_block(0.0, 2.0);
    let path = scene_at("pull", &support_scene("block_top", "disk_arc", 0.02), &msh);
    let (ok, out, err) = hycon(&["run", path.to_str().unwrap()]);
    assert!(ok, "{out}{err}");
    assert!(
        out.contains(
            "warning: contact pair 1 (\"block_top\" on \"disk_arc\") never closed in 2 steps"
        ),
        "{out}"
    );
    assert!(
        !out.contains("-0.0000e0") && out.contains(" 0.0000e0"),
        "{out}"
    );
    let (ok, out, err) = hycon(&["run", "--strict", path.to_str().unwrap()]);
    assert!(
        !ok && err.contains("--strict: 1 warning above"),
        "{out}{err}"
    );
    // the push: no warning, and --strict passes
    let push = scene_at("push", &support_scene("block_top", "disk_arc", -0.05), &msh);
    let (ok, out, err) = hycon(&["run", "--strict", push.to_str().unwrap()]);
    assert!(ok && !out.contains("warning"), "{out}{err}");
}

/// Finding: a pair between the wrong groups, back to back and apart, said "widen
/// search_distance"; a pair of one group with itself "group block_top overlaps contact pair 1
/// (block_top on block_top)". Now the first is named as never facing, the second as one group.
#[test]
fn back_to_back_and_one_group_pairs_are_named() {
    let msh = half_disk_on_block(0.0, 2.0);
    // the block's bottom against the disk's cut: 2 apart, back to back
    let text = support_scene("block_bottom", "disk_cut", -0.02);
    let e = error_text(scenefile::load(&scene_at("back", &text, &msh)));
    assert!(
        e.contains("contact pair 1 (\"block_bottom\" on \"disk_cut\")")
            && e.contains("these sides never face each other")
            && !e.contains("search_distance"),
        "{e}"
    );
    let text = support_scene("block_top", "block_top", -0.02);
    let e = error_text(scenefile::load(&scene_at("same", &text, &msh)));
    assert!(
        e.contains("a and b are both group \"block_top\"") && !e.contains("overlaps"),
        "{e}"
    );
}
