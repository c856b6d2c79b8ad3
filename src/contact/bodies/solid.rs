//! hycon's own 3D brick model ([`SolidModel`]) as the bodies of a contact analysis: the field is
//! all `3 n_nodes` dofs, node ids are the mesh's, and `K_ff` is assembled and factored here, with
//! the contact dofs last (eager) or with `F` built lazily within their reach, as for the plane
//! [`ModelBodies`](super::ModelBodies). What the 3D contact iteration plugs in.

use super::SetupSeconds;
use super::model::{OwnBodies, OwnModel};
use crate::assembly::DofMap;
use crate::error::Result;
use crate::solid::model::{SolidModel, SolidSystem};
use crate::solver::{Backend, SparseCholesky};

/// hycon's 3D brick model and its `K_ff` as contact bodies: 3 equations per node, node ids the
/// mesh's, the field all `3 n_nodes` dofs (`f` external forces, `qp` prescribed values).
pub type SolidBodies = OwnBodies<SolidModel>;

impl OwnModel for SolidModel {
    type System = SolidSystem;
    const DIM: usize = 3;

    fn positions(&self) -> &[f64] {
        self.mesh.nodes.as_flattened()
    }

    fn factored(&self, trailing: &[usize], backend: Backend) -> Result<SolidSystem> {
        SolidSystem::with_trailing_on(self, trailing, backend)
    }

    fn dofs(system: &SolidSystem) -> &DofMap {
        system.dofs()
    }

    fn cholesky(system: &mut SolidSystem) -> &SparseCholesky {
        system.cholesky()
    }

    fn refactorize(&self, system: &mut SolidSystem) -> Result<()> {
        system.refactorize(self)
    }

    fn solve(&self, system: &mut SolidSystem, f: &[f64], qp: &[f64]) -> Result<Vec<f64>> {
        system.solve_for(self, f, qp)
    }

    fn setup_seconds(system: &SolidSystem) -> SetupSeconds {
        let [assembly, factorization] = system.setup_seconds();
        SetupSeconds {
            assembly,
            factorization,
        }
    }

    fn internal_forces(&self, q: &[f64]) -> Result<Vec<f64>> {
        SolidModel::internal_forces(self, q)
    }

    /// The largest `E` of the materials times the mesh's largest extent along an axis.
    fn stiffness_scale(&self) -> f64 {
        let nodes = &self.mesh.nodes;
        let extent = (0..3)
            .map(|d| {
                let (lo, hi) = (nodes.iter())
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                        (lo.min(p[d]), hi.max(p[d]))
                    });
                hi - lo
            })
            .fold(0.0, f64::max);
        let youngs = (self.materials.iter())
            .map(|m| m.youngs)
            .fold(0.0, f64::max);
        youngs * extent
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::bodies::Bodies;
    use crate::solid::mesh::SolidMesh;
    use crate::solid::{BrickFormulation, Isotropic};
    use nalgebra::DMatrix;

    /// A bar of 3 x 1 x 1 distorted bricks clamped at `x = 0`, one node of the free end moved
    /// by a prescribed `w`, and its "contact" dofs: every dof of the free end `x = 3` and one
    /// clamped dof (a fixed dof among the contact dofs, as the iteration has them).
    fn bar() -> (SolidModel, Vec<usize>) {
        let mesh = SolidMesh::uniform([3.0, 1.0, 1.0], [3, 1, 1])
            .map(|[x, y, z]| [x + 0.1 * y * z, y + 0.05 * x * z, z + 0.08 * x * y]);
        let material = Isotropic::new(1000.0, 0.3).unwrap();
        let mut model = SolidModel::new(mesh, vec![material], BrickFormulation::Hybrid18).unwrap();
        let clamped = model.mesh.nodes_where(|p| p[0] == 0.0);
        for &n in &clamped {
            for d in 0..3 {
                model.fix(n, d, 0.0);
            }
        }
        let end = model.mesh.nodes_where(|p| p[0] > 2.9);
        model.fix(end[0], 2, 0.01);
        let mut contact: Vec<usize> = end
            .iter()
            .flat_map(|&n| [3 * n, 3 * n + 1, 3 * n + 2])
            .collect();
        contact.push(3 * clamped[0]);
        contact.sort_unstable();
        (model, contact)
    }

    /// `F` by plain solves with a unit load at each contact dof (zero at fixed dofs).
    fn solved_flexibility(bodies: &dyn Bodies, dofs: &[usize]) -> DMatrix<f64> {
        let n = bodies.field_len();
        let zero = vec![0.0; n];
        let mut f = DMatrix::zeros(dofs.len(), dofs.len());
        for (j, &dj) in dofs.iter().enumerate() {
            if !bodies.is_free(dj) {
                continue;
            }
            let mut unit = zero.clone();
            unit[dj] = 1.0;
            let u = bodies.solve(&unit, &zero).unwrap();
            for (i, &di) in dofs.iter().enumerate() {
                if bodies.is_free(di) {
                    f[(i, j)] = u[di];
                }
            }
        }
        f
    }

    /// Through the trait, eager and lazy: 3 equations per node, flat positions, `F` against
    /// plain solves with unit loads, `F V` against `F` times `V`, and (lazy) the images with
    /// their back substitution against `F`; the prescribed motion in a solve.
    #[test]
    fn solid_bodies_give_the_flexibility_of_plain_solves() {
        let (model, dofs) = bar();
        let n_nodes = model.mesh.n_nodes();
        let fixed = dofs
            .iter()
            .position(|&d| model.mesh.nodes[d / 3][0] == 0.0)
            .expect("a clamped contact dof");
        let vectors = vec![
            vec![(0, 1.0), (3, -2.0)],
            vec![(fixed, 5.0), (dofs.len() - 1, 0.5)],
        ];
        for lazy in [false, true] {
            let mut bodies =
                SolidBodies::new(model.clone(), &dofs, Backend::Faer, lazy, 1).unwrap();
            assert_eq!(bodies.dim(), 3);
            assert_eq!(bodies.positions().len(), 3 * n_nodes);
            assert_eq!(bodies.positions()[3 * 5..3 * 6], model.mesh.nodes[5]);
            assert_eq!(bodies.lazy_flexibility(), lazy);
            assert!(!bodies.is_free(dofs[fixed]));
            let reference = solved_flexibility(&bodies, &dofs);
            let scale = reference.amax();
            assert!(scale > 0.0);
            let f = bodies.flexibility(&dofs).unwrap();
            assert!((&f - &reference).amax() < 1e-12 * scale, "lazy {lazy}");
            assert!(f.row(fixed).amax() == 0.0 && f.column(fixed).amax() == 0.0);
            let times = bodies.flexibility_times(&dofs, &vectors).unwrap();
            let mut v = DMatrix::zeros(dofs.len(), vectors.len());
            for (c, column) in vectors.iter().enumerate() {
                for &(j, w) in column {
                    if bodies.is_free(dofs[j]) {
                        v[(j, c)] = w;
                    }
                }
            }
            let expected = &reference * &v;
            assert!(
                (&times - &expected).amax() < 1e-12 * scale * 5.0,
                "lazy {lazy}"
            );
            assert_eq!(bodies.has_images(), lazy);
            if lazy {
                let images = bodies
                    .images(&dofs, std::slice::from_ref(&vectors))
                    .unwrap()
                    .unwrap();
                let w = images[0].values.as_ref();
                let gram = w.transpose() * w;
                let vfv = v.transpose() * &expected;
                for (i, j) in [(0, 0), (0, 1), (1, 1)] {
                    assert!((gram[(i, j)] - vfv[(i, j)]).abs() < 1e-12 * scale * 25.0);
                }
                let c = [0.5, -1.0];
                let back = bodies.back_substitute(&dofs, &[(&images[0], &c)]).unwrap();
                for (i, b) in back.iter().enumerate() {
                    let e = expected[(i, 0)] * c[0] + expected[(i, 1)] * c[1];
                    assert!((b - e).abs() < 1e-12 * scale * 5.0);
                }
            } else {
                assert!(
                    bodies
                        .images(&dofs, std::slice::from_ref(&vectors))
                        .unwrap()
                        .is_none()
                );
            }
            // the prescribed motion (through element forces) as the model's own solve has it
            // (through the assembled correction), the prescribed values met exactly
            let (f, qp) = (vec![0.0; 3 * n_nodes], model.prescribed_values());
            let u = bodies.solve(&f, &qp).unwrap();
            let plain = model.solve().unwrap().displacements;
            let worst = u
                .iter()
                .zip(&plain)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(worst < 1e-12 * 0.01, "{worst:e}");
            for (d, v) in model.prescribed() {
                assert_eq!(u[d], v);
            }
            assert_eq!(bodies.factorizations(), 1);
            bodies.refactorize().unwrap();
            assert_eq!(bodies.factorizations(), 2);
            let f = bodies.flexibility(&dofs).unwrap();
            assert!(
                (&f - &reference).amax() < 1e-12 * scale,
                "refactored, lazy {lazy}"
            );
        }
    }
}
