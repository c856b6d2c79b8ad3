//! Helpers shared by the integration test modules of the product (the lab's own live in
//! `lab/tests/common`; these tests cannot use the lab, which depends on the product).

use hycon::mesh::Mesh;

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
