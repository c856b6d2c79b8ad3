//! Results of a contact analysis: tractions three ways (multipliers at the A nodes, nodal
//! forces and pressures on the B side, element stresses of body A), and the contact-element
//! matrices for hosts that assemble the mixed system themselves.

use super::surfaces::PairNodes;
use super::{BNodeResult, ContactAnalysis, NodeResult};
use crate::contact::geometry::ContactSurface;
use crate::contact::space::{self, Vector, node};
use crate::error::{Error, Result};

/// The constraint matrix `Kc` of one pair in compressed sparse row form: rows `D k` (normal,
/// `n_k . sum_j c_kj u_j`) and `D k + i` (tangential, `s_ki . sum_j c_kj u_j`, one per frame
/// tangent `s_ki`, `i = 1 .. D - 1`; empty for a tangent dropped by symmetry) for the A nodes
/// `k`, `D` the dimension (in the plane and in axisymmetry rows `2k` and `2k + 1`), columns
/// over the field (model dofs or host equations; a host's fixed dofs are dropped).
#[derive(Debug, Clone, PartialEq)]
pub struct ConstraintRows {
    /// `D n_A + 1` row starts.
    pub row_ptr: Vec<usize>,
    /// Column (field index) of each entry.
    pub columns: Vec<usize>,
    /// Value of each entry.
    pub values: Vec<f64>,
}

impl ContactAnalysis {
    /// Node counts of the A and B sides of pair `p` (polylines in the plane, face sets in 3D).
    pub fn pair_size(&self, p: usize) -> Result<(usize, usize)> {
        self.pair(p).map(|pair| (pair.a.len(), pair.b.len()))
    }

    /// Check a pair index.
    fn pair(&self, p: usize) -> Result<&PairNodes> {
        self.surfaces.pairs.get(p).ok_or_else(|| {
            Error::InvalidInput(format!(
                "contact pair {p} does not exist ({} pairs)",
                self.surfaces.pairs.len()
            ))
        })
    }

    /// The contact quantities of pair `p` at the converged state (the reference one before
    /// the first increment), iteration numbering: kept from the iteration, not evaluated
    /// again.
    fn converged_surface(&self, p: usize) -> Result<&ContactSurface> {
        self.pair(p)?;
        Ok(&self.surfaces.current[p])
    }

    /// The contact-element quantities of pair `p` at the converged state, node ids in the
    /// caller's numbering: per A node the weight, frame, weighted gap `R_C` and the coupling
    /// row `c_kj` (`+F^A_kj` at A nodes, `-F^B_kj` at B nodes). Under small kinematics the
    /// pairing, frames, weights and coupling are those of the reference configuration and
    /// the gaps are linearized; under finite kinematics all are evaluated at the converged
    /// positions.
    pub fn surface(&self, p: usize) -> Result<ContactSurface> {
        let mut surface = self.converged_surface(p)?.clone();
        for node in &mut surface.nodes {
            node.node = self.bodies.external(node.node);
            for entry in &mut node.coupling {
                entry.0 = self.bodies.external(entry.0);
            }
        }
        Ok(surface)
    }

    /// The constraint matrix `Kc` of pair `p` in the converged configuration (see
    /// [`ConstraintRows`]).
    pub fn constraint_rows(&self, p: usize) -> Result<ConstraintRows> {
        let surface = self.converged_surface(p)?;
        let mut rows = ConstraintRows {
            row_ptr: vec![0],
            columns: Vec::new(),
            values: Vec::new(),
        };
        for node in &surface.nodes {
            let tangents = node.frame.tangents().iter().copied();
            for direction in std::iter::once(node.frame.normal()).chain(tangents) {
                for &(j, c) in &node.coupling {
                    for (d, component) in direction.components().iter().enumerate() {
                        let field = self.bodies.field_index(self.dim() * j + d);
                        if let Some(i) = field.filter(|_| *component != 0.0) {
                            rows.columns.push(i);
                            rows.values.push(c * component);
                        }
                    }
                }
                rows.row_ptr.push(rows.columns.len());
            }
        }
        Ok(rows)
    }

    /// Contact tractions at the A nodes of pair `p` from the element stresses of body A (the
    /// paper's way (a)): at each node, `t = sigma n` of the element owning each adjacent A
    /// segment, evaluated at the node and averaged over the (one or two) segments, returned as
    /// `(tn, ts)` in the nodal frame. Needs the full field (one solve if not yet recovered):
    /// an error for a host that handed over its condensed operator, whose displacement hycon
    /// cannot recover.
    pub fn stress_tractions(&self, p: usize) -> Result<Vec<(f64, f64)>> {
        let frames = self.node_results(p)?;
        let missing = || {
            Error::InvalidInput(
                "tractions from element stresses need the elements of body A: a host hands them \
                 over with hycon_host_set_elements (HostSystem::elements in Rust)"
                    .into(),
            )
        };
        if !self.bodies.has_elements() {
            return Err(missing());
        }
        self.bodies.check_solver().map_err(|_| {
            Error::InvalidInput(
                "tractions from element stresses need the displacement of the elements' nodes, \
                 and a host that handed over its condensed operator recovers it itself (hycon \
                 has no solver of its K): take the multipliers (node_results, \
                 hycon_contact_node_results) or the host's own stresses"
                    .into(),
            )
        })?;
        let field = self.displacement()?.to_vec();
        let (model, q, local) = self.bodies.elements(&field).ok_or_else(missing)?;
        let a = self.surfaces.pairs[p]
            .a
            .iter()
            .map(|&n| {
                local(n).ok_or_else(|| {
                    Error::InvalidInput(format!(
                        "A node {} belongs to none of the elements handed over",
                        self.bodies.external(n)
                    ))
                })
            })
            .collect::<Result<Vec<usize>>>()?;
        let edges = model.mesh.directed_edges();
        let solution = crate::model::Solution { q };
        let mut sums = vec![([0.0; 2], 0.0); a.len()];
        for (k, w) in a.windows(2).enumerate() {
            let &(e, edge) = edges.get(&(w[0], w[1])).ok_or_else(|| {
                let pair = &self.surfaces.pairs[p].a;
                Error::InvalidInput(format!(
                    "A segment {} -> {} is not an element edge with its body on the left",
                    self.bodies.external(pair[k]),
                    self.bodies.external(pair[k + 1])
                ))
            })?;
            let field = solution.stress_field(model, e)?;
            for (node, at) in [(k, 0.0), (k + 1, 1.0)] {
                let t = field.edge_traction(edge, at);
                sums[node].0[0] += t[0];
                sums[node].0[1] += t[1];
                sums[node].1 += 1.0;
            }
        }
        let tractions: Vec<(f64, f64)> = sums
            .iter()
            .zip(&frames)
            .map(|((t, count), r)| {
                let t = [t[0] / count, t[1] / count];
                (
                    t[0] * r.frame.normal()[0] + t[1] * r.frame.normal()[1],
                    t[0] * r.frame.tangent(0)[0] + t[1] * r.frame.tangent(0)[1],
                )
            })
            .collect();
        match tractions
            .iter()
            .position(|t| !(t.0.is_finite() && t.1.is_finite()))
        {
            None => Ok(tractions),
            Some(k) => Err(Error::Solver(format!(
                "the element stresses at A node {} overflow (the displacements are finite, but                  stiffness times displacement over a tiny element is not): choose other units",
                self.bodies.external(self.surfaces.pairs[p].a[k])
            ))),
        }
    }

    /// Contact results on the B side of pair `p`, per B node: the equivalent nodal force on B `f_j = -sum_k F^B_kj t_k` (the traction on B is
    /// `-t`), its weight over the projected overlap `w_j = sum_k F^B_kj = integral over the
    /// overlap of L^B_j ds`, and the pressure `p_j = -f_j . n_j / w_j` (`n_j` B's outward nodal
    /// normal, the average of its segments'). Nodes outside the overlap have weight 0 and
    /// pressure 0.
    pub fn b_node_results(&self, p: usize) -> Result<Vec<BNodeResult>> {
        let a_nodes = self.node_results(p)?;
        let surface = self.converged_surface(p)?;
        let x = self.positions(&self.boundary.qc);
        let xg = self.geometry_positions(&x);
        let dim = self.dim();
        let pair = &self.surfaces.pairs[p];
        let index = |j: usize| pair.b.iter().position(|&b| b == j);
        let mut weight = vec![0.0; pair.b.len()];
        let mut force = vec![Vector::zero(dim); pair.b.len()];
        for (node, r) in surface.nodes.iter().zip(&a_nodes) {
            let t = r.frame.vector(r.tn, r.ts);
            for &(j, c) in &node.coupling {
                if let Some(i) = index(j) {
                    // the coupling holds -F^B at B nodes
                    weight[i] -= c;
                    force[i] = force[i].add_scaled(c, &t);
                }
            }
        }
        Ok(pair
            .b
            .iter()
            .enumerate()
            .map(|(i, &j)| {
                let n = self.surfaces.geometries[p].b_node_normal(i, xg);
                let pressure = if weight[i] > 0.0 {
                    -force[i].dot(&n) / weight[i]
                } else {
                    0.0
                };
                BNodeResult {
                    node: self.bodies.external(j),
                    weight: weight[i],
                    force: force[i],
                    pressure,
                    position: node(&x, dim, j),
                }
            })
            .collect())
    }

    /// Converged results at the A nodes of pair `p`: states, tractions (multipliers),
    /// equivalent nodal forces, frames, weights and gaps in the converged configuration.
    pub fn node_results(&self, p: usize) -> Result<Vec<NodeResult>> {
        let surface = self.converged_surface(p)?;
        let x = self.positions(&self.boundary.qc);
        let dim = self.dim();
        let pair = &self.surfaces.pairs[p];
        let data = &self.nodes[p];
        // equivalent nodal force on A: f_j = sum_k F^A_kj t_k
        let mut force = vec![Vector::zero(dim); pair.a.len()];
        for (k, node) in surface.nodes.iter().enumerate() {
            let traction = &data[k].traction;
            let t = node.frame.vector(traction.normal, traction.tangential);
            for &(j, c) in &node.coupling {
                if let Some(i) = pair.a.iter().position(|&a| a == j) {
                    force[i] = force[i].add_scaled(c, &t);
                }
            }
        }
        Ok(surface
            .nodes
            .iter()
            .enumerate()
            .map(|(k, node)| NodeResult {
                node: self.bodies.external(node.node),
                state: data[k].state,
                tn: data[k].traction.normal,
                ts: data[k].traction.tangential,
                frame: node.frame,
                position: space::node(&x, dim, node.node),
                weight: node.weight,
                gap: node.normal_gap,
                force: force[k],
            })
            .collect())
    }
}
