//! Helpers shared by the integration test modules of the product (the lab's own live in
//! `lab/tests/common`; these tests cannot use the lab, which depends on the product).

use hycon::ffi::hycon_last_error_message;
use hycon::mesh::Mesh;
use hycon::solid::contact_meshes::{BlockOnFlat, ContactMesh};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use std::ffi::CStr;

pub mod press3d;

/// This thread's last error message of the C ABI, read with the size-query protocol.
pub fn last_error() -> String {
    // SAFETY: (NULL, 0) is the documented size query.
    let needed = unsafe { hycon_last_error_message(std::ptr::null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; needed];
    // SAFETY: `buf` holds `needed` writable bytes.
    let again = unsafe { hycon_last_error_message(buf.as_mut_ptr(), buf.len()) };
    assert_eq!(again, needed);
    // SAFETY: the function NUL-terminated the buffer.
    unsafe { CStr::from_ptr(buf.as_ptr()) }
        .to_str()
        .unwrap()
        .to_owned()
}

/// A block of 2 x 2 x 1 bricks (1 x 1 x 0.5) turned 30 degrees about the normal on a flat of
/// 3 x 3 x 1 bricks (3 x 3 x 1): every overlap of their faces a general polygon.
pub fn turned_block_on_flat() -> ContactMesh {
    BlockOnFlat {
        size: [1.0, 1.0, 0.5],
        cells: [2, 2, 1],
        flat: [3.0, 3.0, 1.0],
        flat_cells: [3, 3, 1],
        angle: 30.0,
    }
    .build()
    .unwrap()
}

/// A block-on-flat mesh `c` as a solid model (`E = 1`, `nu = 0.3`, hybrid bricks): the flat's
/// bottom held, the block's top prescribed in the directions `top`.
pub fn block_on_flat_model(c: &ContactMesh, top: &[usize]) -> SolidModel {
    let material = Isotropic::new(1.0, 0.3).unwrap();
    let mut model = SolidModel::new(
        c.mesh.clone(),
        vec![material; 2],
        BrickFormulation::Hybrid18,
    )
    .unwrap();
    model.prescribe(&c.b_bottom, &[0, 1, 2]).unwrap();
    model.prescribe(&c.a_top, top).unwrap();
    model
}

/// A permutation of `0..n` from `seed` (Fisher-Yates with a small LCG).
pub fn permutation(n: usize, seed: u64) -> Vec<usize> {
    let mut perm: Vec<usize> = (0..n).collect();
    let mut state = seed | 1;
    for i in (1..n).rev() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        perm.swap(i, (state >> 33) as usize % (i + 1));
    }
    perm
}

/// A grid block from `origin` of `size` in `cells` quads of material `material` into `mesh`;
/// its node ids row by row.
pub fn block(
    mesh: &mut Mesh,
    origin: [f64; 2],
    size: [f64; 2],
    cells: [usize; 2],
    material: usize,
) -> Vec<usize> {
    let mut ids = Vec::new();
    for j in 0..=cells[1] {
        for i in 0..=cells[0] {
            ids.push(mesh.push_node([
                origin[0] + size[0] * i as f64 / cells[0] as f64,
                origin[1] + size[1] * j as f64 / cells[1] as f64,
            ]));
        }
    }
    let at = |i: usize, j: usize| ids[j * (cells[0] + 1) + i];
    for j in 0..cells[1] {
        for i in 0..cells[0] {
            mesh.push_element(
                &[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)],
                material,
            );
        }
    }
    ids
}

/// A clearly distorted brick (no two faces parallel, no face planar).
pub fn distorted_brick() -> [[f64; 3]; 8] {
    [
        [0.0, 0.0, 0.0],
        [2.1, 0.2, -0.1],
        [2.4, 1.9, 0.2],
        [-0.2, 1.5, 0.1],
        [0.3, -0.1, 1.2],
        [2.0, 0.1, 1.4],
        [2.2, 2.2, 1.7],
        [0.1, 1.7, 1.1],
    ]
}

/// A quarter annulus `radii[0] <= r <= radii[1]` in the first quadrant, meshed `nr x nt` in
/// polar coordinates: node `(i, j)` (outward `i`, `j` from the x axis to the y axis, the last
/// row exactly on the y axis) is `annulus_node(nr, i, j)`; quads in row order, material 0.
pub fn quarter_annulus(radii: [f64; 2], [nr, nt]: [usize; 2]) -> Mesh {
    let id = |i, j| annulus_node(nr, i, j);
    let mut mesh = Mesh::new();
    for j in 0..=nt {
        let t = std::f64::consts::FRAC_PI_2 * j as f64 / nt as f64;
        for i in 0..=nr {
            let r = radii[0] + (radii[1] - radii[0]) * i as f64 / nr as f64;
            let x = if j == nt { 0.0 } else { r * t.cos() };
            mesh.push_node([x, r * t.sin()]);
        }
    }
    for j in 0..nt {
        for i in 0..nr {
            mesh.push_element(&[id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)], 0);
        }
    }
    mesh
}

/// The id of node `(i, j)` of [`quarter_annulus`] with `nr` elements through the wall.
pub fn annulus_node(nr: usize, i: usize, j: usize) -> usize {
    j * (nr + 1) + i
}

/// The largest `|u_r / exact - 1|` over the inner arc's nodes (radius `a`) of a solved
/// [`quarter_annulus`], `u_r = u . x / a`.
pub fn inner_arc_error(
    mesh: &Mesh,
    solution: &hycon::model::Solution,
    [nr, nt]: [usize; 2],
    a: f64,
    exact: f64,
) -> f64 {
    (0..=nt)
        .map(|j| {
            let k = annulus_node(nr, 0, j);
            let (p, u) = (mesh.nodes[k], solution.displacement(k));
            ((u[0] * p[0] + u[1] * p[1]) / a / exact - 1.0).abs()
        })
        .fold(0.0, f64::max)
}
