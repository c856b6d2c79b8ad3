//! The loops over a mesh's elements that the plane and the solid models share: the assembly of
//! the stiffness and the element forces, written once over [`ElementSet`], which
//! says what differs between the two (the element kernel, the nodes of an element, the dofs per
//! node).
//!
//! With `A_e` the map from the global dofs to the element's (the rows of the identity at the
//! element's global dofs, in element dof order: [`DofMap::element_dofs`]):
//! * the stiffness is `K = sum_e A_e^T K_e A_e`, of which [`assemble`] keeps the free-free block
//!   `K_ff` (lower triangle);
//! * the element forces of a displacement `q` over all dofs are `f = K q = sum_e A_e^T K_e q_e`,
//!   `q_e = A_e q` ([`internal_forces`]): at the prescribed dofs minus the external forces they
//!   are the reactions, and of the prescribed motion alone they give the load `-K_fp q_p` of a
//!   solve (`docs/method.md`, "The mixed system with K factored once").

use super::{DofMap, SparsePattern, element_dofs};
use crate::error::{Error, Result};
use nalgebra::SMatrix;

/// Element stiffness storage for at most `ND` dofs (the leading `n x n` block used).
pub type Stiffness<const ND: usize> = SMatrix<f64, ND, ND>;

/// The elements of a mesh with their materials and formulation, as the loops of this module see
/// them. `ND` is the largest number of dofs of one element (the storage size): 12 in the plane,
/// 24 for bricks.
pub trait ElementSet<const ND: usize> {
    /// Dofs per node: 2 in the plane, 3 in a solid.
    const PER_NODE: usize;

    /// Number of elements.
    fn n_elements(&self) -> usize;

    /// The nodes of element `e`, in element order (at most `ND / PER_NODE`).
    fn nodes(&self, e: usize) -> &[usize];

    /// The stiffness `K_e` of element `e` into the leading block of `ke`; returns its number of
    /// dofs. An error (a bad shape, an unknown material) names the element.
    fn stiffness_into(&self, e: usize, ke: &mut Stiffness<ND>) -> Result<usize>;
}

/// The material `materials[index]` of element `e`, or an error naming the element (`what`:
/// "element", "brick") and the index.
pub fn element_material<'a, M>(
    materials: &'a [M],
    index: usize,
    what: &str,
    e: usize,
) -> Result<&'a M> {
    materials.get(index).ok_or_else(|| {
        Error::InvalidInput(format!(
            "{what} {e} uses material {index} but only {} are defined",
            materials.len()
        ))
    })
}

/// Compute in turn the stiffness of every element whose global dofs `wanted` accepts (the
/// others' is not computed, nor checked) and hand it to `visit(element, global dofs, n_dof,
/// K_e)`, the global dofs in element dof order in the leading `n_dof` entries. Stops at the first
/// bad element.
pub fn for_each_selected<const ND: usize, S: ElementSet<ND>>(
    set: &S,
    ke: &mut Stiffness<ND>,
    mut wanted: impl FnMut(&[usize]) -> bool,
    mut visit: impl FnMut(usize, &[usize; ND], usize, &Stiffness<ND>),
) -> Result<()> {
    let mut gd = [0; ND];
    for e in 0..set.n_elements() {
        let n_dof = element_dofs(S::PER_NODE, set.nodes(e), &mut gd);
        if !wanted(&gd[..n_dof]) {
            continue;
        }
        let nd = set.stiffness_into(e, ke)?;
        visit(e, &gd, nd, ke);
    }
    Ok(())
}

/// Refill the values of `pattern` with `K_ff`, the free-free block of
/// `K = sum_e A_e^T K_e A_e` (elements in order), and hand every element's global dofs and
/// `K_e` to `also` after adding it.
pub fn assemble<const ND: usize, S: ElementSet<ND>>(
    set: &S,
    pattern: &mut SparsePattern,
    dofs: &DofMap,
    mut also: impl FnMut(&[usize], &Stiffness<ND>),
) -> Result<()> {
    pattern.clear();
    let mut ke = Stiffness::<ND>::zeros();
    for_each_selected(
        set,
        &mut ke,
        |_| true,
        |_, gd, nd, ke| {
            pattern.add(dofs, &gd[..nd], |b, a| ke[(b, a)]);
            also(&gd[..nd], ke);
        },
    )
}

/// Element forces `f = K q = sum_e A_e^T K_e q_e` over all dofs (the length of `q`). An element
/// whose displacements `q_e` are all zero adds nothing and is skipped (the prescribed motion
/// alone touches only the elements at moved supports).
pub fn internal_forces<const ND: usize, S: ElementSet<ND>>(set: &S, q: &[f64]) -> Result<Vec<f64>> {
    let mut r = vec![0.0; q.len()];
    let mut ke = Stiffness::<ND>::zeros();
    for_each_selected(
        set,
        &mut ke,
        |gd| gd.iter().any(|&d| q[d] != 0.0),
        |_, gd, nd, ke| {
            for a in 0..nd {
                r[gd[a]] += (0..nd).map(|b| ke[(a, b)] * q[gd[b]]).sum::<f64>();
            }
        },
    )?;
    Ok(r)
}

/// The element displacements `q_e = A_e q` of the element with nodes `nodes` (`per_node` dofs
/// each) from `q` over all dofs, into `out`; returns their number.
pub fn gather(per_node: usize, nodes: &[usize], q: &[f64], out: &mut [f64]) -> usize {
    for (i, &node) in nodes.iter().enumerate() {
        out[per_node * i..per_node * (i + 1)]
            .copy_from_slice(&q[per_node * node..per_node * (node + 1)]);
    }
    per_node * nodes.len()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::Formulation;
    use crate::material::{Analysis, Material};
    use crate::mesh::generate::{Grading, graded_rectangle};
    use crate::model::Model;
    use crate::solid::mesh::SolidMesh;
    use crate::solid::model::SolidModel;
    use crate::solid::{BrickFormulation, Isotropic};

    /// `K q` from the assembled lower triangle of `K` (no dof prescribed, so `K_ff = K`).
    fn assembled_times<const ND: usize>(
        set: &impl ElementSet<ND>,
        dofs: &DofMap,
        q: &[f64],
    ) -> Vec<f64> {
        let n_nodes = dofs.n_dofs() / dofs.per_node();
        let nodes = (0..set.n_elements()).map(|e| set.nodes(e));
        let mut pattern = SparsePattern::from_elements(n_nodes, nodes, dofs);
        assemble(set, &mut pattern, dofs, |_, _| ()).unwrap();
        let k = pattern.matrix();
        let mut kq = vec![0.0; q.len()];
        for col in 0..k.ncols() {
            for (row, v) in k.row_idx_of_col(col).zip(k.val_of_col(col)) {
                kq[row] += v * q[col];
                if row != col {
                    kq[col] += v * q[row];
                }
            }
        }
        kq
    }

    /// `max |a - b| / max |b|`.
    fn relative_gap(a: &[f64], b: &[f64]) -> f64 {
        let scale = b.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let gap = a
            .iter()
            .zip(b)
            .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
        gap / scale
    }

    /// A displacement with every component different, over `n` dofs.
    fn displacement(n: usize) -> Vec<f64> {
        (0..n)
            .map(|d| ((d * 7 + 3) % 11) as f64 * 0.01 - 0.05)
            .collect()
    }

    #[test]
    fn element_forces_are_the_assembled_stiffness_times_q() {
        // plane: a graded mesh with 5- and 6-node transition elements
        let grading = Grading::toward_point([0.0, 1.0], 0.1, 1);
        let mesh = graded_rectangle(0.0, 0.0, 2.0, 1.0, 4, 2, &grading);
        let material = Material::new(1000.0, 0.3, 0.5, Analysis::PlaneStrain).unwrap();
        let plane = Model::new(mesh, vec![material], Formulation::Hybrid);
        assert!((0..plane.mesh.n_elements()).any(|e| plane.mesh.element(e).len() > 4));
        let dofs = DofMap::new(plane.mesh.n_nodes(), 2, []).unwrap();
        let q = displacement(dofs.n_dofs());
        let f = plane.internal_forces(&q).unwrap();
        assert!(relative_gap(&f, &assembled_times(&plane.elements(), &dofs, &q)) < 1e-13);

        let mesh = SolidMesh::uniform([2.0, 1.0, 1.0], [2, 1, 2]);
        let iso = Isotropic::new(200.0, 0.25).unwrap();
        let solid = SolidModel::new(mesh, vec![iso], BrickFormulation::Hybrid18).unwrap();
        let dofs = solid.dof_map().unwrap();
        let q = displacement(dofs.n_dofs());
        let f = solid.internal_forces(&q).unwrap();
        assert!(relative_gap(&f, &assembled_times(&solid.elements(), &dofs, &q)) < 1e-13);
    }

    #[test]
    fn an_element_without_its_material_is_named() {
        let mesh = graded_rectangle(
            0.0,
            0.0,
            2.0,
            1.0,
            2,
            1,
            &Grading::toward_point([0.0; 2], 1.0, 1),
        );
        let material = Material::new(1000.0, 0.3, 1.0, Analysis::PlaneStress).unwrap();
        let mut plane = Model::new(mesh, vec![material], Formulation::Q4);
        plane.mesh.element_material[1] = 1;
        let q = vec![1.0; 2 * plane.mesh.n_nodes()];
        let message = plane.internal_forces(&q).unwrap_err().to_string();
        assert!(
            message.contains("element 1 uses material 1 but only 1 are defined"),
            "{message}"
        );

        let mut mesh = SolidMesh::uniform([1.0; 3], [2, 1, 1]);
        mesh.element_material[1] = 3;
        let materials = vec![Isotropic::new(1.0, 0.0).unwrap()];
        let refused = SolidModel::new(mesh.clone(), materials.clone(), BrickFormulation::H8)
            .unwrap_err()
            .to_string();
        let named = "brick 1 uses material 3 but only 1 are defined";
        assert!(refused.contains(named), "{refused}");
        // a model changed after its checks: the loop names the brick too
        mesh.element_material[1] = 0;
        let mut solid = SolidModel::new(mesh, materials, BrickFormulation::H8).unwrap();
        solid.mesh.element_material[1] = 3;
        let q = vec![1.0; 3 * solid.mesh.n_nodes()];
        let message = solid.internal_forces(&q).unwrap_err().to_string();
        assert!(message.contains(named), "{message}");
    }

    #[test]
    fn gather_reads_the_element_dofs_in_element_order() {
        let q: Vec<f64> = (0..12).map(|d| d as f64).collect();
        let mut out = [0.0; 6];
        assert_eq!(gather(3, &[3, 1], &q, &mut out), 6);
        assert_eq!(out, [9.0, 10.0, 11.0, 3.0, 4.0, 5.0]);
    }
}
