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
//!
//! A brick model ([`solid_to_string`]): the points are the reference node coordinates; point
//! data `displacement` and, at the contact's multiplier side A, `contact_pressure` (`-tn`) and
//! `contact_traction` (the traction on A, global components; both zero elsewhere); cell data
//! the stress at the brick's centre `sx`, `sy`, `sz`, `txy`, `tyz`, `tzx`, `von_mises` and
//! `body`; every brick `VTK_HEXAHEDRON` (12), whose node order is hycon's.

use super::{Result, write_file};
use crate::examples::{Bodies, ContactPoint, Example, Increment};
use hycon::model::{Model, Solution};
use hycon::solid::model::SolidModel;
use hycon::solid::recover_stress;
use std::fmt::Write as _;
use std::path::Path;

/// `VTK_POLYGON`.
pub const VTK_POLYGON: u8 = 7;
/// `VTK_QUAD`.
pub const VTK_QUAD: u8 = 9;
/// `VTK_HEXAHEDRON`.
pub const VTK_HEXAHEDRON: u8 = 12;

/// Von Mises stress from the in-plane stress and `sz`.
pub fn von_mises(s: [f64; 3], sz: f64) -> f64 {
    let [sx, sy, txy] = s;
    (0.5 * ((sx - sy).powi(2) + (sy - sz).powi(2) + (sz - sx).powi(2)) + 3.0 * txy * txy).sqrt()
}

/// Von Mises stress of a Voigt stress `[sx, sy, sz, txy, tyz, tzx]`.
pub fn von_mises_solid(s: [f64; 6]) -> f64 {
    let [sx, sy, sz, txy, tyz, tzx] = s;
    let normal = (sx - sy).powi(2) + (sy - sz).powi(2) + (sz - sx).powi(2);
    (0.5 * normal + 3.0 * (txy * txy + tyz * tyz + tzx * tzx)).sqrt()
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
    let mut x = head(n_points, n_cells);
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
    tail(&mut x);
    Ok(x)
}

/// The file's start, up to the `Piece` element.
fn head(n_points: usize, n_cells: usize) -> String {
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
    x
}

/// The file's end, from the cells' closing tag.
fn tail(x: &mut String) {
    let _ = writeln!(x, "      </Cells>");
    let _ = writeln!(x, "    </Piece>");
    let _ = writeln!(x, "  </UnstructuredGrid>");
    let _ = writeln!(x, "</VTKFile>");
}

/// The `.vtu` text of the brick model `model` with displacement `q` (over all `3 n_nodes`
/// dofs) and the contact tractions `contact` (module docs).
pub fn solid_to_string(model: &SolidModel, q: &[f64], contact: &[ContactPoint]) -> Result<String> {
    let mesh = &model.mesh;
    let (n_points, n_cells) = (mesh.n_nodes(), mesh.n_elements());
    if q.len() != 3 * n_points {
        return Err(hycon::Error::InvalidInput(format!(
            "displacement has {} values, the mesh {} dofs",
            q.len(),
            3 * n_points
        ))
        .into());
    }
    let bricks = model.elements();
    let mut stress = Vec::with_capacity(n_cells);
    for (e, nodes) in mesh.elements.iter().enumerate() {
        let qe: Vec<f64> = nodes
            .iter()
            .flat_map(|&n| q[3 * n..3 * n + 3].to_vec())
            .collect();
        let s = recover_stress(
            model.formulation,
            &mesh.element_coords(e),
            bricks.material(e)?,
            &qe,
        )
        .map_err(|kind| hycon::Error::at_element(kind, e))?
        .at_natural([0.0; 3]);
        stress.push(std::array::from_fn::<f64, 6, _>(|i| s[i]));
    }
    let mut pressure = vec![0.0; n_points];
    let mut traction = vec![[0.0; 3]; n_points];
    for c in contact {
        pressure[c.node] = c.pressure;
        traction[c.node] = c.traction;
    }
    let mut x = head(n_points, n_cells);
    let _ = writeln!(
        x,
        "      <PointData Vectors=\"displacement\" Scalars=\"contact_pressure\">"
    );
    array(&mut x, "Float64", "displacement", 3, |x| {
        for p in q.chunks(3) {
            let _ = writeln!(x, "{:e} {:e} {:e}", p[0], p[1], p[2]);
        }
    });
    array(&mut x, "Float64", "contact_pressure", 1, |x| {
        for p in &pressure {
            let _ = writeln!(x, "{p:e}");
        }
    });
    array(&mut x, "Float64", "contact_traction", 3, |x| {
        for t in &traction {
            let _ = writeln!(x, "{:e} {:e} {:e}", t[0], t[1], t[2]);
        }
    });
    let _ = writeln!(x, "      </PointData>");
    let _ = writeln!(x, "      <CellData Scalars=\"von_mises\">");
    for (i, name) in ["sx", "sy", "sz", "txy", "tyz", "tzx"].iter().enumerate() {
        array(&mut x, "Float64", name, 1, |x| {
            for s in &stress {
                let _ = writeln!(x, "{:e}", s[i]);
            }
        });
    }
    array(&mut x, "Float64", "von_mises", 1, |x| {
        for s in &stress {
            let _ = writeln!(x, "{:e}", von_mises_solid(*s));
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
            let _ = writeln!(x, "{:e} {:e} {:e}", p[0], p[1], p[2]);
        }
    });
    let _ = writeln!(x, "      </Points>");
    let _ = writeln!(x, "      <Cells>");
    array(&mut x, "Int64", "connectivity", 1, |x| {
        for nodes in &mesh.elements {
            let nodes: Vec<String> = nodes.iter().map(|n| n.to_string()).collect();
            let _ = writeln!(x, "{}", nodes.join(" "));
        }
    });
    array(&mut x, "Int64", "offsets", 1, |x| {
        for e in 1..=n_cells {
            let _ = writeln!(x, "{}", 8 * e);
        }
    });
    array(&mut x, "UInt8", "types", 1, |x| {
        for _ in 0..n_cells {
            let _ = writeln!(x, "{VTK_HEXAHEDRON}");
        }
    });
    tail(&mut x);
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

/// Write the `.vtu` of a run's bodies at `increment` to `path`: [`to_string`] of a plane
/// model, [`solid_to_string`] (with the increment's contact tractions) of a brick model.
fn write_increment(path: &Path, bodies: &Bodies, increment: &Increment) -> Result<()> {
    let q = &increment.displacement;
    let text = match bodies {
        Bodies::Plane(model) => to_string(model, q)?,
        Bodies::Solid(model) => solid_to_string(model, q, &increment.contact)?,
    };
    write_file(path, text.as_bytes())
}

/// File stem of run `run` of `example`: the example's name, plus the run's tag when it has one.
pub fn stem(example: &Example, run: usize) -> String {
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
    example: &Example,
    every_increment: bool,
) -> Result<Vec<std::path::PathBuf>> {
    let mut written = Vec::new();
    for (r, run) in example.runs.iter().enumerate() {
        let stem = stem(example, r);
        let Some(last) = run.increments.last().filter(|i| !i.displacement.is_empty()) else {
            continue;
        };
        let path = dir.join(format!("{stem}.vtu"));
        write_increment(&path, &run.model, last)?;
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
                write_increment(&path, &run.model, inc)?;
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
