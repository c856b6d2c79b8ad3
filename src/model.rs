//! A linear static problem on a mesh: prescribed displacements (zero or not), nodal forces and
//! line loads, solved with the sparse Cholesky factorization of the free-free stiffness.
//!
//! With `q_p` the prescribed values, the free displacements solve
//! `K_ff q_f = f_f - K_fp q_p`. [`LinearSystem`] keeps the dof map, the assembled pattern and the
//! factorization, so one factorization serves any number of load cases (and, in the contact
//! method, every contact iteration). Reactions and element stresses are computed only when
//! asked for.

use crate::assembly::elements::{self, ElementSet, element_material, gather};
use crate::assembly::{DofMap, FactoredSystem, SparsePattern, dof, scatter};
use crate::element::{self, ElementMatrix, Formulation, MAX_DOF, MAX_NODES, StressField};
use crate::error::{Error, Result};
use crate::material::{Analysis, Material};
use crate::mesh::Mesh;
use crate::solver::{Backend, OrderingRule, SparseCholesky};
use faer::Mat;

/// A prescribed displacement component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prescribed {
    /// Node index.
    pub node: usize,
    /// 0 = x, 1 = y.
    pub dir: usize,
    /// Prescribed displacement.
    pub value: f64,
}

/// A distributed load on a boundary edge `[a, b]`, linear along it: a traction (force per unit
/// area), given as global `[fx, fy]` at `a` and at `b`. Its nodal forces are integrated with the
/// measure of the edge's material ([`Material::measure`]): `t ds` in plane analyses, `2 pi r ds`
/// in axisymmetry (full-circle forces).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineLoad {
    /// The edge's end nodes.
    pub nodes: [usize; 2],
    /// Traction (force per unit area) at the two ends.
    pub load: [[f64; 2]; 2],
}

/// Mesh, materials, formulation, boundary conditions and loads of a linear static problem.
#[derive(Debug, Clone)]
pub struct Model {
    /// The mesh (material indices refer to `materials`).
    pub mesh: Mesh,
    /// Materials, indexed by `mesh.element_material`.
    pub materials: Vec<Material>,
    /// Element formulation used for every element.
    pub formulation: Formulation,
    /// Prescribed displacement components.
    pub prescribed: Vec<Prescribed>,
    /// Nodal forces `(node, [fx, fy])`.
    pub nodal_forces: Vec<(usize, [f64; 2])>,
    /// Line loads on boundary edges.
    pub line_loads: Vec<LineLoad>,
}

impl Model {
    /// A model with no boundary conditions or loads yet.
    pub fn new(mesh: Mesh, materials: Vec<Material>, formulation: Formulation) -> Self {
        Model {
            mesh,
            materials,
            formulation,
            prescribed: Vec::new(),
            nodal_forces: Vec::new(),
            line_loads: Vec::new(),
        }
    }

    /// Prescribe both displacement components of every node in `nodes` to `value`.
    ///
    /// Checked here, atomically (on an error nothing is added): every node exists, `value` is
    /// finite, and no component is prescribed twice (within `nodes` or by an earlier call).
    pub fn fix(&mut self, nodes: &[usize], value: [f64; 2]) -> Result<()> {
        self.prescribe(nodes, &[(0, value[0]), (1, value[1])])
    }

    /// Prescribe displacement component `dir` (0 = x, 1 = y) of every node in `nodes` to
    /// `value`, checked like [`Model::fix`].
    pub fn fix_dir(&mut self, nodes: &[usize], dir: usize, value: f64) -> Result<()> {
        if dir > 1 {
            return Err(Error::InvalidInput(format!(
                "direction {dir} (0 = x, 1 = y)"
            )));
        }
        self.prescribe(nodes, &[(dir, value)])
    }

    /// Append `(node, dir, value)` for every node and every `(dir, value)` after checking them
    /// all against the mesh and the components already prescribed.
    fn prescribe(&mut self, nodes: &[usize], components: &[(usize, f64)]) -> Result<()> {
        let n = self.mesh.n_nodes();
        let mut taken = vec![false; 2 * n];
        for p in &self.prescribed {
            if p.node < n && p.dir < 2 {
                taken[dof(p.node, p.dir)] = true;
            }
        }
        if let Some(&node) = nodes.iter().find(|&&node| node >= n) {
            return Err(Error::InvalidInput(format!(
                "unknown node {node} (the model has {n} nodes)"
            )));
        }
        if let Some(&(_, value)) = components.iter().find(|(_, v)| !v.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "prescribed value {value} is not finite"
            )));
        }
        for &node in nodes {
            for &(dir, _) in components {
                if std::mem::replace(&mut taken[dof(node, dir)], true) {
                    return Err(Error::InvalidInput(format!(
                        "node {node} direction {} is prescribed twice",
                        ["x", "y"][dir]
                    )));
                }
            }
        }
        for &node in nodes {
            self.prescribed
                .extend(
                    components
                        .iter()
                        .map(|&(dir, value)| Prescribed { node, dir, value }),
                );
        }
        Ok(())
    }

    /// A uniform traction (force per unit area; see [`LineLoad`]) on every edge of `edges`.
    pub fn load_edges(&mut self, edges: &[[usize; 2]], load: [f64; 2]) {
        self.line_loads.extend(edges.iter().map(|&nodes| LineLoad {
            nodes,
            load: [load, load],
        }));
    }

    /// The analysis kind of the model's materials (plane strain if it has none). A model does
    /// not mix kinds ([`Model::validate`]).
    pub fn analysis(&self) -> Analysis {
        self.materials
            .first()
            .map_or(Analysis::PlaneStrain, |m| m.analysis)
    }

    /// Check materials (one analysis kind for all), mesh, element shapes (for their material's
    /// kind), boundary conditions and loads.
    pub fn validate(&self) -> Result<()> {
        for m in &self.materials {
            m.validate()?;
        }
        let kind = self.analysis();
        if let Some((i, m)) = self
            .materials
            .iter()
            .enumerate()
            .find(|(_, m)| m.analysis != kind)
        {
            return Err(Error::Material(format!(
                "material {i} is {} but material 0 is {}: one model takes one analysis kind",
                m.analysis.name(),
                kind.name()
            )));
        }
        self.mesh.validate()?;
        let n = self.mesh.n_nodes();
        let mut coords = [[0.0; 2]; MAX_NODES];
        for e in 0..self.mesh.n_elements() {
            let k = self.mesh.element_coords(e, &mut coords);
            let material = self.materials.get(self.mesh.element_material[e]);
            match material {
                Some(m) => element::check_element(self.formulation, &coords[..k], m),
                None => element::check_shape(self.formulation, &coords[..k]),
            }
            .map_err(|kind| Error::at_element(kind, e))?;
        }
        let mut seen = vec![false; 2 * n];
        for p in &self.prescribed {
            if p.node >= n || p.dir > 1 || !p.value.is_finite() {
                return Err(Error::InvalidInput(format!(
                    "bad prescribed displacement {p:?} (mesh has {n} nodes)"
                )));
            }
            let d = dof(p.node, p.dir);
            if std::mem::replace(&mut seen[d], true) {
                return Err(Error::InvalidInput(format!(
                    "node {} direction {} is prescribed twice",
                    p.node, p.dir
                )));
            }
        }
        for (node, f) in &self.nodal_forces {
            if *node >= n || !(f[0].is_finite() && f[1].is_finite()) {
                return Err(Error::InvalidInput(format!(
                    "bad nodal force on node {node}: {f:?}"
                )));
            }
        }
        for l in &self.line_loads {
            let finite = l.load.iter().flatten().all(|v| v.is_finite());
            if l.nodes.iter().any(|&a| a >= n) || l.nodes[0] == l.nodes[1] || !finite {
                return Err(Error::InvalidInput(format!("bad line load {l:?}")));
            }
        }
        Ok(())
    }

    /// External force vector over all dofs: nodal forces plus the consistent forces of the
    /// line loads, `f_a = integral of N_a q m ds` with `N_a` the linear shape function of end
    /// `a`, `q` the linear traction and `m` the measure: in plane analyses `m = t` and
    /// `f_a = t L (2 q_a + q_b) / 6`, `f_b = t L (q_a + 2 q_b) / 6`; in axisymmetry `m = 2 pi r`
    /// is linear too and two-point Gauss integrates the cubic integrand exactly
    /// ([`element::loads::segment_forces`]).
    pub fn external_forces(&self) -> Vec<f64> {
        let mut f = vec![0.0; 2 * self.mesh.n_nodes()];
        for &(node, force) in &self.nodal_forces {
            f[dof(node, 0)] += force[0];
            f[dof(node, 1)] += force[1];
        }
        // the measure depends on the material through t only: look for the edge's element only
        // when the thicknesses differ
        let uniform = self
            .materials
            .windows(2)
            .all(|w| w[0].thickness == w[1].thickness);
        for l in &self.line_loads {
            let [a, b] = l.nodes;
            let (pa, pb) = (self.mesh.nodes[a], self.mesh.nodes[b]);
            let material = if uniform {
                self.materials.first()
            } else {
                self.edge_material(a, b)
            };
            let Some(material) = material else {
                continue; // a node outside every element: `validate` reports the model
            };
            let [fa, fb] = element::loads::segment_forces(pa, pb, material, l.load);
            for dir in 0..2 {
                f[dof(a, dir)] += fa[dir];
                f[dof(b, dir)] += fb[dir];
            }
        }
        f
    }

    /// The material of an element with `a` and `b` as consecutive nodes (the element the edge
    /// bounds), else of an element holding `a`; `None` if `a` is in no element or its material
    /// index is out of range.
    fn edge_material(&self, a: usize, b: usize) -> Option<&Material> {
        let mesh = &self.mesh;
        let has_edge = |e: usize| {
            let nodes = mesh.element(e);
            let n = nodes.len();
            (0..n).any(|i| {
                let (p, q) = (nodes[i], nodes[(i + 1) % n]);
                (p, q) == (a, b) || (p, q) == (b, a)
            })
        };
        let element = (0..mesh.n_elements())
            .find(|&e| has_edge(e))
            .or_else(|| (0..mesh.n_elements()).find(|&e| mesh.element(e).contains(&a)))?;
        self.materials.get(mesh.element_material[element])
    }

    /// Prescribed displacement values over all dofs (zero where free).
    pub fn prescribed_values(&self) -> Vec<f64> {
        let values = self
            .prescribed
            .iter()
            .map(|p| (dof(p.node, p.dir), p.value));
        scatter(2 * self.mesh.n_nodes(), values)
    }

    /// Assemble, factor and solve in one call.
    pub fn solve(&self) -> Result<Solution> {
        let mut system = LinearSystem::new(self)?;
        system.solve(self)
    }

    /// The free dofs numbered (the prescribed ones left out) and `K_ff` assembled over them
    /// (lower triangle): the stiffness a host with its own solver factors; [`LinearSystem`]
    /// factors it with hycon's.
    pub fn assemble_free(&self) -> Result<(DofMap, SparsePattern)> {
        let dofs = DofMap::new(
            self.mesh.n_nodes(),
            2,
            self.prescribed.iter().map(|p| dof(p.node, p.dir)),
        )?;
        let mut pattern = SparsePattern::new(&self.mesh, &dofs);
        pattern.assemble(&self.mesh, &self.materials, self.formulation, &dofs)?;
        Ok((dofs, pattern))
    }

    /// Element forces `K q = sum_e A_e^T K_e q_e` over all dofs (length `2 n_nodes`,
    /// [`elements::internal_forces`]): the equivalent nodal forces the elements exert; at
    /// prescribed dofs minus external forces this is the reaction. An element whose
    /// displacements `q_e` are all zero adds nothing and is skipped (the prescribed motion alone,
    /// `K_fp q_p`, touches only the elements at moved supports).
    pub fn internal_forces(&self, q: &[f64]) -> Result<Vec<f64>> {
        elements::internal_forces(&self.elements(), q)
    }

    /// The model's elements with their materials and formulation, for the element loops.
    pub fn elements(&self) -> PlaneElements<'_> {
        PlaneElements::new(&self.mesh, &self.materials, self.formulation)
    }
}

/// The elements of a plane mesh with their materials and one formulation: the plane case of the
/// element loops ([`ElementSet`]; 2 dofs per node, at most [`MAX_DOF`] per element).
#[derive(Debug, Clone, Copy)]
pub struct PlaneElements<'a> {
    /// The mesh.
    pub mesh: &'a Mesh,
    /// Materials, indexed by `mesh.element_material`.
    pub materials: &'a [Material],
    /// The formulation of every element.
    pub formulation: Formulation,
}

impl ElementSet<MAX_DOF> for PlaneElements<'_> {
    const PER_NODE: usize = 2;

    fn n_elements(&self) -> usize {
        self.mesh.n_elements()
    }

    fn nodes(&self, e: usize) -> &[usize] {
        self.mesh.element(e)
    }

    fn stiffness_into(&self, e: usize, ke: &mut ElementMatrix) -> Result<usize> {
        let mut coords = [[0.0; 2]; MAX_NODES];
        let n = self.mesh.element_coords(e, &mut coords);
        let material = self.material(e)?;
        element::stiffness_into(self.formulation, &coords[..n], material, ke)
            .map_err(|kind| Error::at_element(kind, e))
    }
}

impl<'a> PlaneElements<'a> {
    /// The elements of `mesh`, with `materials` and `formulation`.
    pub fn new(mesh: &'a Mesh, materials: &'a [Material], formulation: Formulation) -> Self {
        PlaneElements {
            mesh,
            materials,
            formulation,
        }
    }

    /// The material of element `e`, or an error naming it.
    pub fn material(&self, e: usize) -> Result<&'a Material> {
        let index = self.mesh.element_material[e];
        element_material(self.materials, index, "element", e)
    }
}

/// The factored free-free stiffness of a model, reusable for many right-hand sides.
#[derive(Debug)]
pub struct LinearSystem {
    system: FactoredSystem,
    seconds: [f64; 2],
}

impl LinearSystem {
    /// Validate, number the dofs, check every body is held against rigid motion, assemble and
    /// factor `K_ff`.
    pub fn new(model: &Model) -> Result<Self> {
        Self::with_trailing(model, &[])
    }

    /// As [`LinearSystem::new`], with the free ones among the global dofs `trailing` eliminated
    /// last, so that [`LinearSystem::condensed_flexibility`] can read their flexibility off the
    /// factor.
    pub fn with_trailing(model: &Model, trailing: &[usize]) -> Result<Self> {
        Self::with_trailing_on(model, trailing, Backend::Faer)
    }

    /// As [`LinearSystem::with_trailing`], factoring with the given sparse Cholesky
    /// [`Backend`] (an unavailable one is an error before any work is done).
    pub fn with_trailing_on(model: &Model, trailing: &[usize], backend: Backend) -> Result<Self> {
        backend.check_available()?;
        model.validate()?;
        check_rigid_body_support(model)?;
        let clock = std::time::Instant::now();
        let (dofs, pattern) = model.assemble_free()?;
        let assembly = clock.elapsed().as_secs_f64();
        let mut system =
            FactoredSystem::analyze(dofs, pattern, backend, trailing, OrderingRule::Auto)?;
        system.factor()?;
        Ok(LinearSystem {
            system,
            seconds: [assembly, clock.elapsed().as_secs_f64() - assembly],
        })
    }

    /// Assemble and factor `K_ff` again, reusing the pattern and the symbolic analysis (what a
    /// design that does not keep its factor pays per solve; the contact benchmark's
    /// refactor-every-iteration variant).
    pub fn refactorize(&mut self, model: &Model) -> Result<()> {
        self.system.refactor(&model.elements())
    }

    /// The flexibility `(K^-1)` between the free dofs among the `trailing` dofs given to
    /// [`LinearSystem::with_trailing`] (in that order, prescribed ones skipped), read off the
    /// factor: no solves.
    pub fn condensed_flexibility(&self) -> Result<Mat<f64>> {
        self.system.condensed_flexibility()
    }

    /// Wall-clock seconds of `[assembly, analysis + factorization]` when the system was built.
    pub fn setup_seconds(&self) -> [f64; 2] {
        self.seconds
    }

    /// The free-dof numbering.
    pub fn dofs(&self) -> &DofMap {
        self.system.dofs()
    }

    /// Number of stored entries of the lower triangle of `K_ff` and of its factor `L`.
    pub fn nnz(&self) -> (usize, usize) {
        (
            self.system.pattern().nnz(),
            self.system.factorization().nnz_l(),
        )
    }

    /// The factorization (for batched solves on free dofs).
    pub fn cholesky(&mut self) -> &mut SparseCholesky {
        self.system.cholesky()
    }

    /// Solve for the model's loads and prescribed displacements (the model must be the one this
    /// system was built from, up to load and prescribed *values*).
    pub fn solve(&mut self, model: &Model) -> Result<Solution> {
        let (f, qp) = (model.external_forces(), model.prescribed_values());
        self.solve_for(model, &f, &qp)
    }

    /// Solve `K_ff q_f = f_f - K_fp q_p` for external forces `f` and prescribed values `qp`, both
    /// over all dofs (`qp` is read at the prescribed dofs only). One solve with the kept factor.
    pub fn solve_for(&mut self, model: &Model, f: &[f64], qp: &[f64]) -> Result<Solution> {
        let q = self.system.solve_for(f, qp, |q| model.internal_forces(q))?;
        Ok(Solution { q })
    }
}

/// Displacements of a solved model; reactions and stresses are derived on demand.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Displacements over all dofs, `[u0, v0, u1, v1, ...]`.
    pub q: Vec<f64>,
}

impl Solution {
    /// Displacement `[u, v]` of a node.
    pub fn displacement(&self, node: usize) -> [f64; 2] {
        [self.q[dof(node, 0)], self.q[dof(node, 1)]]
    }

    /// Reactions: `K q - f` over all dofs (non-zero only at prescribed dofs, up to round-off).
    pub fn reactions(&self, model: &Model) -> Result<Vec<f64>> {
        let mut r = model.internal_forces(&self.q)?;
        for (ri, fi) in r.iter_mut().zip(model.external_forces()) {
            *ri -= fi;
        }
        Ok(r)
    }

    /// The recovered stress field of element `e`.
    pub fn stress_field(&self, model: &Model, e: usize) -> Result<StressField> {
        let mut coords = [[0.0; 2]; MAX_NODES];
        let n = model.mesh.element_coords(e, &mut coords);
        let mut qe = [0.0; MAX_DOF];
        let n_dof = gather(2, model.mesh.element(e), &self.q, &mut qe);
        let material = model.elements().material(e)?;
        element::recover_stress(model.formulation, &coords[..n], material, &qe[..n_dof])
            .map_err(|kind| Error::at_element(kind, e))
    }
}

/// Every connected body must be held against its rigid-body motions by prescribed
/// displacements: in plane analyses the rigid modes `(1, 0)`, `(0, 1)`, `(-(y - yc), x - xc) / L`
/// restricted to the body's prescribed dofs must have rank 3; in axisymmetry the only rigid
/// motion is the axial translation `(0, 1)` (a radial translation strains the hoop), so some
/// axial displacement of the body must be prescribed. Also rejects nodes that belong to no
/// element and are not fully prescribed.
fn check_rigid_body_support(model: &Model) -> Result<()> {
    let mesh = &model.mesh;
    let body = connected_bodies(mesh);
    let n_bodies = body.iter().filter_map(|b| *b).max().map_or(0, |m| m + 1);
    let mut prescribed = vec![[false; 2]; mesh.n_nodes()];
    for p in &model.prescribed {
        prescribed[p.node][p.dir] = true;
    }
    if let Some(node) =
        (0..mesh.n_nodes()).find(|&i| body[i].is_none() && prescribed[i] != [true; 2])
    {
        return Err(Error::Singular(format!(
            "node {node} belongs to no element and is not fully prescribed"
        )));
    }
    let axisymmetric = model.analysis() == Analysis::Axisymmetric;
    for b in 0..n_bodies {
        let nodes: Vec<usize> = (0..mesh.n_nodes())
            .filter(|&i| body[i] == Some(b))
            .collect();
        let first = nodes.first().copied().unwrap_or(0);
        if axisymmetric {
            if !nodes.iter().any(|&i| prescribed[i][1]) {
                return Err(Error::Singular(format!(
                    "body {b} (the {} nodes connected to node {first}) is not held against its \
                     axial translation: prescribe the axial (y = z) displacement of one of its \
                     nodes",
                    nodes.len()
                )));
            }
            continue;
        }
        let rank = rigid_mode_rank(mesh, &nodes, &prescribed);
        if rank < 3 {
            return Err(Error::Singular(format!(
                "body {b} (the {} nodes connected to node {first}) is not held against rigid \
                 motion: its prescribed displacements fix only {rank} of its 3 rigid-body modes",
                nodes.len()
            )));
        }
    }
    Ok(())
}

/// Rank of the rigid-body modes of `nodes` restricted to their prescribed dofs.
fn rigid_mode_rank(mesh: &Mesh, nodes: &[usize], prescribed: &[[bool; 2]]) -> usize {
    let count = nodes.len().max(1) as f64;
    let (xc, yc) = nodes.iter().fold((0.0, 0.0), |(x, y), &i| {
        (x + mesh.nodes[i][0] / count, y + mesh.nodes[i][1] / count)
    });
    let scale = nodes
        .iter()
        .map(|&i| (mesh.nodes[i][0] - xc).hypot(mesh.nodes[i][1] - yc))
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut gram = nalgebra::Matrix3::<f64>::zeros();
    for &i in nodes {
        let (x, y) = (
            (mesh.nodes[i][0] - xc) / scale,
            (mesh.nodes[i][1] - yc) / scale,
        );
        for (dir, row) in [[1.0, 0.0, -y], [0.0, 1.0, x]].iter().enumerate() {
            if prescribed[i][dir] {
                let r = nalgebra::Vector3::from_row_slice(row);
                gram += r * r.transpose();
            }
        }
    }
    let eig = gram.symmetric_eigenvalues();
    let max = eig.max();
    eig.iter()
        .filter(|&&l| l > 1e-10 * max.max(1e-300) && max > 0.0)
        .count()
}

/// Connected body index of every node (through shared elements); `None` for orphan nodes.
fn connected_bodies(mesh: &Mesh) -> Vec<Option<usize>> {
    let mut parent: Vec<usize> = (0..mesh.n_nodes()).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut used = vec![false; mesh.n_nodes()];
    for e in 0..mesh.n_elements() {
        let nodes = mesh.element(e);
        for &n in nodes {
            used[n] = true;
            let (a, b) = (find(&mut parent, nodes[0]), find(&mut parent, n));
            parent[a] = b;
        }
    }
    let mut label = vec![usize::MAX; mesh.n_nodes()];
    let mut next = 0;
    (0..mesh.n_nodes())
        .map(|i| {
            if !used[i] {
                return None;
            }
            let root = find(&mut parent, i);
            if label[root] == usize::MAX {
                label[root] = next;
                next += 1;
            }
            Some(label[root])
        })
        .collect()
}
