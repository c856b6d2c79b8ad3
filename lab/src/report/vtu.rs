//! VTK XML unstructured grid (`.vtu`) of a model and a displacement field.
//!
//! Written by hand rather than with the `vtkio` crate: its only maintained line is a release
//! candidate (0.7.0-rc2; the last stable 0.6.3 pulls outdated parser dependencies), its XML
//! support goes through serde plus quick-xml and, by default, three compression libraries, and
//! the file needed here is a few dozen lines of ASCII XML. The tests parse the output back.
//!
//! Contents: the points are the reference node coordinates (z = 0); point data `displacement`
//! (3 components, z = 0); cell data `sx`, `sy`, `txy` (recovered stress at the element centre),
//! `von_mises` (with `sz = nu (sx + sy)` in plane strain, 0 in plane stress) and `body` (the
//! material index: 0 = block, 1 = disk in the contact scene). 4-node elements are `VTK_QUAD` (9),
//! 5- and 6-node transition elements `VTK_POLYGON` (7), nodes counter-clockwise in boundary order.

use super::{Result, write_file};
use hycon::model::{Model, Solution};
use std::fmt::Write as _;
use std::path::Path;

/// `VTK_POLYGON`.
pub const VTK_POLYGON: u8 = 7;
/// `VTK_QUAD`.
pub const VTK_QUAD: u8 = 9;

/// Von Mises stress from the in-plane stress and `sz`.
pub fn von_mises(s: [f64; 3], sz: f64) -> f64 {
    let [sx, sy, txy] = s;
    (0.5 * ((sx - sy).powi(2) + (sy - sz).powi(2) + (sz - sx).powi(2)) + 3.0 * txy * txy).sqrt()
}

/// The `.vtu` text of `model` with displacement `q` (over all dofs).
pub fn to_string(model: &Model, q: &[f64]) -> Result<String> {
    let mesh = &model.mesh;
    let (n_points, n_cells) = (mesh.n_nodes(), mesh.n_elements());
    if q.len() != 2 * n_points {
        return Err(hycon::Error::InvalidInput(format!(
            "displacement has {} values, the mesh {} dofs",
            q.len(),
            2 * n_points
        ))
        .into());
    }
    let solution = Solution { q: q.to_vec() };
    let mut stress = Vec::with_capacity(n_cells);
    for e in 0..n_cells {
        // the out-of-plane normal stress: nu (sx + sy), 0, or the hoop stress
        let [sx, sy, txy, sz] = solution.stress_field(model, e)?.at_centre_full();
        let s = [sx, sy, txy];
        stress.push((s, von_mises(s, sz)));
    }
    let mut x = String::with_capacity(64 * (n_points + n_cells));
    // `write!` to a String cannot fail
    let _ = writeln!(x, "<?xml version=\"1.0\"?>");
    let _ = writeln!(
        x,
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" \
         header_type=\"UInt64\">"
    );
    let _ = writeln!(x, "  <UnstructuredGrid>");
    let _ = writeln!(
        x,
        "    <Piece NumberOfPoints=\"{n_points}\" NumberOfCells=\"{n_cells}\">"
    );
    let _ = writeln!(x, "      <PointData Vectors=\"displacement\">");
    array(&mut x, "Float64", "displacement", 3, |x| {
        for p in q.chunks(2) {
            let _ = writeln!(x, "{:e} {:e} 0", p[0], p[1]);
        }
    });
    let _ = writeln!(x, "      </PointData>");
    let _ = writeln!(x, "      <CellData Scalars=\"von_mises\">");
    for (name, i) in [("sx", 0), ("sy", 1), ("txy", 2)] {
        array(&mut x, "Float64", name, 1, |x| {
            for (s, _) in &stress {
                let _ = writeln!(x, "{:e}", s[i]);
            }
        });
    }
    array(&mut x, "Float64", "von_mises", 1, |x| {
        for (_, vm) in &stress {
            let _ = writeln!(x, "{vm:e}");
        }
    });
    array(&mut x, "Int32", "body", 1, |x| {
        for m in &mesh.element_material {
            let _ = writeln!(x, "{m}");
        }
    });
    let _ = writeln!(x, "      </CellData>");
    let _ = writeln!(x, "      <Points>");
    array(&mut x, "Float64", "Points", 3, |x| {
        for p in &mesh.nodes {
            let _ = writeln!(x, "{:e} {:e} 0", p[0], p[1]);
        }
    });
    let _ = writeln!(x, "      </Points>");
    let _ = writeln!(x, "      <Cells>");
    array(&mut x, "Int64", "connectivity", 1, |x| {
        for e in 0..n_cells {
            let nodes: Vec<String> = mesh.element(e).iter().map(|n| n.to_string()).collect();
            let _ = writeln!(x, "{}", nodes.join(" "));
        }
    });
    array(&mut x, "Int64", "offsets", 1, |x| {
        let mut offset = 0;
        for e in 0..n_cells {
            offset += mesh.element(e).len();
            let _ = writeln!(x, "{offset}");
        }
    });
    array(&mut x, "UInt8", "types", 1, |x| {
        for e in 0..n_cells {
            let t = if mesh.element(e).len() == 4 {
                VTK_QUAD
            } else {
                VTK_POLYGON
            };
            let _ = writeln!(x, "{t}");
        }
    });
    let _ = writeln!(x, "      </Cells>");
    let _ = writeln!(x, "    </Piece>");
    let _ = writeln!(x, "  </UnstructuredGrid>");
    let _ = writeln!(x, "</VTKFile>");
    Ok(x)
}

fn array(x: &mut String, ty: &str, name: &str, components: usize, body: impl FnOnce(&mut String)) {
    let _ = writeln!(
        x,
        "        <DataArray type=\"{ty}\" Name=\"{name}\" NumberOfComponents=\"{components}\" \
         format=\"ascii\">"
    );
    body(x);
    let _ = writeln!(x, "        </DataArray>");
}

/// Write the `.vtu` of `model` with displacement `q` to `path`.
pub fn write(path: &Path, model: &Model, q: &[f64]) -> Result<()> {
    write_file(path, to_string(model, q)?.as_bytes())
}

/// File stem of run `run` of `example`: the example's name, plus the run's tag when it has one.
pub fn stem(example: &crate::examples::Example, run: usize) -> String {
    let tag = &example.runs[run].tag;
    if tag.is_empty() {
        example.name.clone()
    } else {
        format!("{}-{tag}", example.name)
    }
}

/// Write the fields of every run of `example` into `dir`: `STEM.vtu` (final increment) and,
/// with `every_increment` (and a field kept for every increment), `STEM-KK.vtu` per increment
/// plus a ParaView collection `STEM.pvd` over them (time = increment number). Runs without
/// fields are skipped. Returns the files written.
pub fn write_example(
    dir: &Path,
    example: &crate::examples::Example,
    every_increment: bool,
) -> Result<Vec<std::path::PathBuf>> {
    let mut written = Vec::new();
    for (r, run) in example.runs.iter().enumerate() {
        let stem = stem(example, r);
        let Some(last) = run.increments.last().filter(|i| !i.displacement.is_empty()) else {
            continue;
        };
        let path = dir.join(format!("{stem}.vtu"));
        write(&path, &run.model, &last.displacement)?;
        written.push(path);
        let every = run.increments.iter().all(|i| !i.displacement.is_empty());
        if every_increment && every {
            let mut pvd = String::from(
                "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  \
                 <Collection>\n",
            );
            for inc in &run.increments {
                let name = format!("{stem}-{:02}.vtu", inc.number);
                let path = dir.join(&name);
                write(&path, &run.model, &inc.displacement)?;
                let _ = writeln!(
                    pvd,
                    "    <DataSet timestep=\"{}\" part=\"0\" file=\"{name}\"/>",
                    inc.number
                );
                written.push(path);
            }
            pvd.push_str("  </Collection>\n</VTKFile>\n");
            let path = dir.join(format!("{stem}.pvd"));
            write_file(&path, pvd.as_bytes())?;
            written.push(path);
        }
    }
    Ok(written)
}
