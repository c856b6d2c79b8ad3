//! A 3D press for the invariance tests (`contact3d_validation`, `contact_properties`): a block
//! (body 0, side A its bottom) on a flat (body 1, side B its top), [`BlockOnFlat`]'s meshes, the
//! block lifted by a gap; every node of the block's top moved by a prescribed total per
//! increment (pressed and slid), the flat's bottom held. The same problem rigidly moved,
//! renumbered or in other units is a [`Variant`]; [`run`] reports the results mapped back to
//! the problem's own numbering, frame and units, so that a variant's must equal the problem's.

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair};
use hycon::solid::contact_meshes::BlockOnFlat;
use hycon::solid::mesh::SolidMesh;
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use hycon::{Error, Result};
use nalgebra::{Rotation3, Vector3};

/// One press.
#[derive(Debug, Clone)]
pub struct Press {
    /// The block (A) and the flat (B).
    pub meshes: BlockOnFlat,
    /// The block lifted by this much above the flat.
    pub gap: f64,
    /// Young's moduli of the block and the flat.
    pub moduli: [f64; 2],
    /// Poisson's ratios of the block and the flat.
    pub poisson: [f64; 2],
    /// Coulomb's coefficient between them.
    pub friction: f64,
    /// Both bodies' bricks.
    pub formulation: BrickFormulation,
    /// The total motion of the block's top after each increment.
    pub steps: Vec<[f64; 3]>,
}

/// The press in other coordinates `x' = Q (s_l x) + t`, moduli times `s_e`, node `i` renumbered
/// `perm[i]` with the bricks and each side's faces listed in another order and each face from
/// another corner; or with every coordinate moved by a pseudo-random amount up to `noise`
/// (what round-off of that size does to the results).
#[derive(Debug, Clone)]
pub struct Variant {
    /// `Q`.
    pub rotation: Rotation3<f64>,
    /// `t`.
    pub translation: [f64; 3],
    /// `s_l`.
    pub length_scale: f64,
    /// `s_e`.
    pub modulus_scale: f64,
    /// `perm[old] = new`; `None` keeps the numbering and the lists' orders.
    pub perm: Option<Vec<usize>>,
    /// The largest change of a coordinate (after the transformation).
    pub noise: f64,
}

impl Variant {
    /// The press itself.
    pub fn identity() -> Self {
        Variant {
            rotation: Rotation3::identity(),
            translation: [0.0; 3],
            length_scale: 1.0,
            modulus_scale: 1.0,
            perm: None,
            noise: 0.0,
        }
    }

    fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        let w = self.rotation * Vector3::from(v) * self.length_scale;
        [w[0], w[1], w[2]]
    }

    fn point(&self, x: [f64; 3]) -> [f64; 3] {
        let w = self.vector(x);
        std::array::from_fn(|i| w[i] + self.translation[i])
    }

    /// A vector of the variant back in the press's frame, divided by `scale`.
    fn back(&self, v: &[f64], scale: f64) -> [f64; 3] {
        let w = self.rotation.inverse() * Vector3::new(v[0], v[1], v[2]) / scale;
        [w[0], w[1], w[2]]
    }

    fn node(&self, i: usize) -> usize {
        self.perm.as_ref().map_or(i, |p| p[i])
    }
}

/// An A node's results in the press's numbering, frame and units.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeView {
    /// The node (the press's id).
    pub node: usize,
    /// Open, stick, slip or frictionless.
    pub state: &'static str,
    /// The normal traction.
    pub tn: f64,
    /// The tangential traction as a vector.
    pub ts: [f64; 3],
    /// The normal and the two tangents.
    pub frame: [[f64; 3]; 3],
    /// The nodal force on A.
    pub force: [f64; 3],
    /// The weight (an area).
    pub weight: f64,
}

/// A converged increment: the A nodes by the press's id, every node's displacement.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// The A nodes, by increasing id of the press.
    pub nodes: Vec<NodeView>,
    /// Every node's displacement, by the press's id.
    pub displacement: Vec<[f64; 3]>,
}

/// The press's model (its moved and held nodes prescribed), pair and moved nodes in variant
/// `v`.
fn model(p: &Press, v: &Variant) -> Result<(SolidModel, FacePair, Vec<usize>)> {
    let mut c = p.meshes.build()?;
    for x in &mut c.mesh.nodes[..c.a_nodes] {
        x[2] += p.gap;
    }
    let n = c.mesh.n_nodes();
    let mut mesh = SolidMesh {
        nodes: vec![[0.0; 3]; n],
        ..SolidMesh::default()
    };
    let mut state: u64 = 0x6879_636f_6e33;
    let mut noise = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        v.noise * ((state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0)
    };
    for (i, x) in c.mesh.nodes.iter().enumerate() {
        mesh.nodes[v.node(i)] = v.point(*x).map(|c| c + noise());
    }
    let mut bricks: Vec<_> = c
        .mesh
        .elements
        .iter()
        .zip(&c.mesh.element_material)
        .collect();
    let faces = |faces: &[[usize; 4]]| -> Vec<[usize; 4]> {
        let turn = |i: usize| if v.perm.is_some() { i % 4 } else { 0 };
        let mut out: Vec<[usize; 4]> = (faces.iter().enumerate())
            .map(|(i, f)| std::array::from_fn(|k| v.node(f[(k + turn(i)) % 4])))
            .collect();
        if v.perm.is_some() {
            out.reverse();
        }
        out
    };
    if v.perm.is_some() {
        bricks.reverse();
    }
    mesh.elements = bricks.iter().map(|(e, _)| e.map(|k| v.node(k))).collect();
    mesh.element_material = bricks.iter().map(|(_, m)| **m).collect();
    let materials = (0..2)
        .map(|i| Isotropic::new(p.moduli[i] * v.modulus_scale, p.poisson[i]))
        .collect::<Result<Vec<_>>>()?;
    let mut model = SolidModel::new(mesh, materials, p.formulation)?;
    let (top, bottom): (Vec<usize>, Vec<usize>) = (
        c.a_top.iter().map(|&k| v.node(k)).collect(),
        c.b_bottom.iter().map(|&k| v.node(k)).collect(),
    );
    model.prescribe(&top, &[0, 1, 2])?;
    model.prescribe(&bottom, &[0, 1, 2])?;
    let pair = FacePair {
        a: faces(&c.a_faces),
        b: faces(&c.b_faces),
        friction: p.friction,
    };
    Ok((model, pair, top))
}

/// The error's kind (`contact NotConverged`, `InvalidInput`): the same in every variant of a
/// problem that fails alike.
fn kind(e: &Error) -> String {
    let name = |debug: String| {
        (debug.split(|c: char| !c.is_alphanumeric()))
            .next()
            .unwrap_or_default()
            .to_string()
    };
    match e {
        Error::Contact(c) => format!("contact {}", name(format!("{c:?}"))),
        other => name(format!("{other:?}")),
    }
}

/// Run the press in variant `v` under `options`: the results of each increment in the press's
/// numbering, frame and units, or the error's kind.
pub fn run(
    p: &Press,
    v: &Variant,
    options: ContactOptions,
) -> std::result::Result<Vec<Snapshot>, String> {
    let (model, pair, top) = model(p, v).map_err(|e| kind(&e))?;
    let n = model.mesh.n_nodes();
    let mut analysis =
        ContactAnalysis::solid(model, vec![pair], &[], options).map_err(|e| kind(&e))?;
    let inverse: Vec<usize> = {
        let mut inv = vec![0; n];
        for i in 0..n {
            inv[v.node(i)] = i;
        }
        inv
    };
    let (s_l, s_e) = (v.length_scale, v.modulus_scale);
    let mut out = Vec::new();
    for step in &p.steps {
        let mut qp = vec![0.0; 3 * n];
        let u = v.vector(*step);
        for &k in &top {
            qp[3 * k..3 * k + 3].copy_from_slice(&u);
        }
        analysis
            .increment(&vec![0.0; 3 * n], &qp)
            .map_err(|e| kind(&e))?;
        let mut nodes: Vec<NodeView> = (analysis.node_results(0).map_err(|e| kind(&e))?)
            .iter()
            .map(|r| {
                let f = &r.frame;
                let ts = f.vector(0.0, r.ts);
                NodeView {
                    node: inverse[r.node],
                    state: r.state.name(),
                    tn: r.tn / s_e,
                    ts: v.back(ts.components(), s_e),
                    frame: [
                        v.back(f.normal().components(), 1.0),
                        v.back(f.tangent(0).components(), 1.0),
                        v.back(f.tangent(1).components(), 1.0),
                    ],
                    force: v.back(r.force.components(), s_e * s_l * s_l),
                    weight: r.weight / (s_l * s_l),
                }
            })
            .collect();
        nodes.sort_by_key(|r| r.node);
        let q = analysis.displacement().map_err(|e| kind(&e))?;
        let displacement = (0..n)
            .map(|i| {
                let k = v.node(i);
                v.back(&q[3 * k..3 * k + 3], s_l)
            })
            .collect();
        out.push(Snapshot {
            nodes,
            displacement,
        });
    }
    Ok(out)
}

/// The largest difference between `want` and `got` relative to the largest `|tn|` (tractions),
/// the largest displacement (displacements) and 1 (frames, weights relative to each node's);
/// the frames' tangents only if `tangents`. Infinite if the node sets or states differ.
pub fn difference(want: &[Snapshot], got: &[Snapshot], tangents: bool) -> f64 {
    let dist =
        |a: &[f64; 3], b: &[f64; 3]| (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
    let mut worst: f64 = 0.0;
    if want.len() != got.len() {
        return f64::INFINITY;
    }
    for (w, g) in want.iter().zip(got) {
        let peak = w
            .nodes
            .iter()
            .fold(0.0f64, |m, r| m.max(r.tn.abs()))
            .max(f64::MIN_POSITIVE);
        let umax = (w.displacement.iter())
            .fold(0.0f64, |m, u| m.max(dist(u, &[0.0; 3])))
            .max(f64::MIN_POSITIVE);
        if w.nodes.len() != g.nodes.len() {
            return f64::INFINITY;
        }
        for (a, b) in w.nodes.iter().zip(&g.nodes) {
            if a.node != b.node || a.state != b.state {
                return f64::INFINITY;
            }
            let frames = if tangents { 3 } else { 1 };
            let force_scale = peak * a.weight;
            let errs = [
                (a.tn - b.tn).abs() / peak,
                dist(&a.ts, &b.ts) / peak,
                dist(&a.force, &b.force) / force_scale.max(f64::MIN_POSITIVE),
                (a.weight - b.weight).abs() / a.weight,
            ];
            let frame = (0..frames).map(|i| dist(&a.frame[i], &b.frame[i]));
            worst = errs.into_iter().chain(frame).fold(worst, f64::max);
        }
        for (a, b) in w.displacement.iter().zip(&g.displacement) {
            worst = worst.max(dist(a, b) / umax);
        }
    }
    worst
}
