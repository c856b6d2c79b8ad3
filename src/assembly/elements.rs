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

    /// Number of nodes of the mesh.
    fn n_nodes(&self) -> usize;

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
