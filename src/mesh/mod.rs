//! Meshes: node coordinates, element connectivity (counter-clockwise boundary nodes, 4 to 6 per
//! element), per-element material index, and named node and edge sets for boundary conditions.
//!
//! [`generate`] builds the benchmark geometries with graded 2:1 refinement, where hanging nodes
//! become the 5- and 6-node transition elements; [`quality`] reports element shape measures.

pub mod generate;
pub mod quality;

use crate::element::MAX_NODES;
use crate::error::{Error, Result, ShapeError};
use std::collections::BTreeMap;

/// A 2D mesh in compressed connectivity storage.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// Node coordinates `[x, y]`.
    pub nodes: Vec<[f64; 2]>,
    /// `element_nodes[element_offsets[e]..element_offsets[e + 1]]` are element `e`'s nodes.
    pub element_offsets: Vec<usize>,
    /// Concatenated element connectivity (counter-clockwise, corners and mid-side nodes in
    /// boundary order).
    pub element_nodes: Vec<usize>,
    /// Material index of each element.
    pub element_material: Vec<usize>,
    /// Named node sets (for example `"left"`, `"contact"`), each sorted along its boundary where
    /// that makes sense.
    pub node_sets: BTreeMap<String, Vec<usize>>,
    /// Named boundary edge sets: pairs of nodes `[a, b]` with the body on the left of `a -> b`
    /// (so `b - a` rotated clockwise is the outward normal), listed along the boundary.
    pub edge_sets: BTreeMap<String, Vec<[usize; 2]>>,
}

impl Mesh {
    /// An empty mesh.
    pub fn new() -> Self {
        Mesh {
            element_offsets: vec![0],
            ..Default::default()
        }
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Number of elements.
    pub fn n_elements(&self) -> usize {
        self.element_offsets.len().saturating_sub(1)
    }

    /// Node indices of element `e`.
    pub fn element(&self, e: usize) -> &[usize] {
        &self.element_nodes[self.element_offsets[e]..self.element_offsets[e + 1]]
    }

    /// Every element edge in its element's counter-clockwise order, `(from, to)` node ids
    /// mapped to `(element, local edge)` (edge `i` runs from local node `i` to `i + 1`): the
    /// element lies on the left of `from -> to`.
    pub fn directed_edges(&self) -> std::collections::HashMap<(usize, usize), (usize, usize)> {
        let mut edges = std::collections::HashMap::new();
        for e in 0..self.n_elements() {
            let nodes = self.element(e);
            for i in 0..nodes.len() {
                edges.insert((nodes[i], nodes[(i + 1) % nodes.len()]), (e, i));
            }
        }
        edges
    }

    /// Append a node, returning its index.
    pub fn push_node(&mut self, xy: [f64; 2]) -> usize {
        self.nodes.push(xy);
        self.nodes.len() - 1
    }

    /// Append an element with material `material`, returning its index.
    pub fn push_element(&mut self, nodes: &[usize], material: usize) -> usize {
        if self.element_offsets.is_empty() {
            self.element_offsets.push(0);
        }
        self.element_nodes.extend_from_slice(nodes);
        self.element_offsets.push(self.element_nodes.len());
        self.element_material.push(material);
        self.element_material.len() - 1
    }

    /// Coordinates of element `e`'s nodes, copied into a fixed buffer; returns the node count.
    pub fn element_coords(&self, e: usize, out: &mut [[f64; 2]; MAX_NODES]) -> usize {
        let nodes = self.element(e);
        for (o, &n) in out.iter_mut().zip(nodes) {
            *o = self.nodes[n];
        }
        nodes.len()
    }

    /// Check the connectivity: offsets monotone, 4 to 6 distinct in-range nodes per element,
    /// finite coordinates, one material per element, set members in range.
    pub fn validate(&self) -> Result<()> {
        if self.element_offsets.first() != Some(&0)
            || self.element_offsets.last() != Some(&self.element_nodes.len())
        {
            return Err(Error::InvalidInput(
                "element_offsets must start at 0 and end at element_nodes.len()".into(),
            ));
        }
        if self.element_material.len() != self.n_elements() {
            return Err(Error::InvalidInput(format!(
                "{} elements but {} material indices",
                self.n_elements(),
                self.element_material.len()
            )));
        }
        if let Some(i) = self
            .nodes
            .iter()
            .position(|p| !(p[0].is_finite() && p[1].is_finite()))
        {
            return Err(Error::InvalidInput(format!(
                "node {i} has a non-finite coordinate"
            )));
        }
        for e in 0..self.n_elements() {
            let (lo, hi) = (self.element_offsets[e], self.element_offsets[e + 1]);
            if hi < lo || !(4..=MAX_NODES).contains(&(hi - lo)) {
                const _: () = assert!(MAX_NODES == 6, "update the message below");
                let kind = ShapeError::NodeCount {
                    got: hi.saturating_sub(lo),
                    expected: "4 to 6",
                };
                return Err(Error::at_element(kind, e));
            }
            let nodes = self.element(e);
            if let Some(&n) = nodes.iter().find(|&&n| n >= self.n_nodes()) {
                return Err(Error::InvalidInput(format!(
                    "element {e} refers to unknown node {n} (mesh has {} nodes)",
                    self.n_nodes()
                )));
            }
            for (i, a) in nodes.iter().enumerate() {
                if nodes[i + 1..].contains(a) {
                    // the same node twice: two coincident corners
                    return Err(Error::at_element(ShapeError::Degenerate, e));
                }
            }
        }
        let n = self.n_nodes();
        for (name, set) in &self.node_sets {
            if let Some(&bad) = set.iter().find(|&&i| i >= n) {
                return Err(Error::InvalidInput(format!(
                    "node set {name:?} refers to unknown node {bad}"
                )));
            }
        }
        for (name, set) in &self.edge_sets {
            if let Some(bad) = set.iter().find(|e| e[0] >= n || e[1] >= n) {
                return Err(Error::InvalidInput(format!(
                    "edge set {name:?} refers to unknown node in {bad:?}"
                )));
            }
        }
        Ok(())
    }

    /// Bounding box `[xmin, ymin, xmax, ymax]` of the nodes.
    pub fn bounding_box(&self) -> [f64; 4] {
        self.nodes.iter().fold(
            [
                f64::INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NEG_INFINITY,
            ],
            |b, p| {
                [
                    b[0].min(p[0]),
                    b[1].min(p[1]),
                    b[2].max(p[0]),
                    b[3].max(p[1]),
                ]
            },
        )
    }

    /// Append `other` (nodes, elements, sets) to this mesh, shifting its node indices and material
    /// indices by `material_offset`; sets of `other` are renamed `prefix + name`. Returns the node
    /// offset applied.
    pub fn append(&mut self, other: &Mesh, material_offset: usize, prefix: &str) -> usize {
        let off = self.nodes.len();
        self.nodes.extend_from_slice(&other.nodes);
        for e in 0..other.n_elements() {
            let shifted: Vec<usize> = other.element(e).iter().map(|&n| n + off).collect();
            self.push_element(&shifted, other.element_material[e] + material_offset);
        }
        for (name, set) in &other.node_sets {
            self.node_sets.insert(
                format!("{prefix}{name}"),
                set.iter().map(|&n| n + off).collect(),
            );
        }
        for (name, set) in &other.edge_sets {
            self.edge_sets.insert(
                format!("{prefix}{name}"),
                set.iter().map(|e| [e[0] + off, e[1] + off]).collect(),
            );
        }
        off
    }
}
