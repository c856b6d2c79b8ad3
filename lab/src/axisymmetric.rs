//! Axisymmetric contact scenes (`x = r`, `y = z`, full-circle measure `2 pi r`) with closed
//! forms: the shrink fit of two thick tubes (and pushing it out), and two solid cylinders
//! pressed end to end (a contact zone centred on the axis).
//!
//! # Initial overlap (a shrink fit's interference)
//! A host prescribes an interference as a **geometric overlap in the reference configuration**:
//! the inner tube's outer radius is `b + delta`, the outer tube's bore `b`, so the contact
//! polylines start interpenetrating by `delta`. Under small kinematics (the default) the
//! contact geometry is evaluated once in that configuration: the weighted gap is
//! `g0 = -delta` (linear in the displacements afterwards), and the first increment (no load,
//! nothing prescribed but the supports) closes it. Nothing else is needed: no initial stress,
//! no special load. The reference positions differ from the drawing by `delta`, so the exact
//! solution to compare with is Lamé's for the radii actually modelled ([`ShrinkFitExact`]);
//! for `delta / b -> 0` it tends to the textbook formula ([`shrink_fit_pressure`]).

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, ContactPair, NodeResult};
use hycon::element::Formulation;
use hycon::error::Result;
use hycon::material::{Analysis, Material};
use hycon::mesh::{Mesh, generate};
use hycon::model::Model;

/// Nodes of an edge chain (body on the left), in order.
pub fn chain(edges: &[[usize; 2]]) -> Vec<usize> {
    let mut nodes = vec![edges[0][0]];
    for e in edges {
        nodes.push(e[1]);
    }
    nodes
}

/// A tube `r0 <= r <= r1`, `0 <= z <= length`, with `nr x nz` elements (sets of
/// [`generate::beam`]: `"left"` the bore running down, `"right"` the outside running up).
fn tube(r0: f64, r1: f64, length: f64, nr: usize, nz: usize) -> Mesh {
    let mut m = generate::beam(r1 - r0, length, nr, nz, 0.0);
    for p in &mut m.nodes {
        *p = [p[0] + r0, p[1] + 0.5 * length];
    }
    m
}

/// Nodes of `mesh` with `first <= id < last` at `z = 0` or `z = length` (to round-off).
fn ends(mesh: &Mesh, first: usize, last: usize, length: f64) -> Vec<usize> {
    (first..last)
        .filter(|&i| {
            let z = mesh.nodes[i][1];
            z.abs() < 1e-12 * length || (z - length).abs() < 1e-12 * length
        })
        .collect()
}

/// The textbook interface pressure of a shrink fit of two tubes of one material, plane strain,
/// radial interference `delta` (small): `p = E delta (b^2 - a^2)(c^2 - b^2) / (2 b^3 (1 - nu^2)
/// (c^2 - a^2))`.
pub fn shrink_fit_pressure(a: f64, b: f64, c: f64, youngs: f64, poisson: f64, delta: f64) -> f64 {
    youngs * delta * (b * b - a * a) * (c * c - b * b)
        / (2.0 * b.powi(3) * (1.0 - poisson * poisson) * (c * c - a * a))
}

/// Lamé's plane-strain solution of the shrink fit for the radii modelled: inner tube
/// `a <= r <= d = b + delta`, outer tube `b <= r <= c`, linearized (small kinematics): the
/// interface closes, `u_outer(b) - u_inner(d) = delta`, and the contact force balances over
/// the full circle, `p_outer b = p_inner d` (the multipliers live on A, the outer tube's bore).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShrinkFitExact {
    /// Pressure on the outer tube's bore (`r = b`), the multiplier side.
    pub outer: f64,
    /// Pressure on the inner tube's outside (`r = d`).
    pub inner: f64,
    a: f64,
    b: f64,
    c: f64,
    d: f64,
}

impl ShrinkFitExact {
    /// The solution for radii `a, b, c`, interference `delta`, one material `(E, nu)`.
    pub fn new(a: f64, b: f64, c: f64, delta: f64, youngs: f64, poisson: f64) -> Self {
        let d = b + delta;
        let u = |r: f64, s_r: f64, s_t: f64| {
            r * (1.0 + poisson) / youngs * ((1.0 - poisson) * s_t - poisson * s_r)
        };
        // outer tube, unit internal pressure: sigma_r(b) = -1, sigma_theta(b) = (b^2 + c^2) /
        // (c^2 - b^2); inner tube, unit external pressure at d
        let u_outer = u(b, -1.0, (b * b + c * c) / (c * c - b * b));
        let u_inner = u(d, -1.0, -(d * d + a * a) / (d * d - a * a));
        let outer = delta / (u_outer - u_inner * b / d);
        ShrinkFitExact {
            outer,
            inner: outer * b / d,
            a,
            b,
            c,
            d,
        }
    }

    /// Hoop stress at radius `r` of the outer (`outer = true`) or the inner tube.
    pub fn hoop(&self, r: f64, outer: bool) -> f64 {
        if outer {
            let k = self.outer * self.b * self.b / (self.c * self.c - self.b * self.b);
            k * (1.0 + self.c * self.c / (r * r))
        } else {
            let k = -self.inner * self.d * self.d / (self.d * self.d - self.a * self.a);
            k * (1.0 + self.a * self.a / (r * r))
        }
    }
}

/// The shrink fit of two thick tubes of one material, their ends held axially (`u_z = 0` at
/// `z = 0` and `z = length`), so that Lamé's plane-strain solution is exact in the
/// axisymmetric model. Contact pair: A = the outer tube's bore (multipliers), B = the inner
/// tube's outside; meshes of `nr` elements through each wall and `nz_outer`, `nz_inner` along
/// the axis (different: node-to-internode).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShrinkFit {
    /// Inner tube's bore `a`.
    pub a: f64,
    /// Interface radius `b` (the outer tube's bore).
    pub b: f64,
    /// Outer tube's outside `c`.
    pub c: f64,
    /// Radial interference `delta`: the inner tube's outside is at `b + delta`.
    pub interference: f64,
    /// Tube length.
    pub length: f64,
    /// Young's modulus and Poisson's ratio of both tubes.
    pub youngs: f64,
    /// Poisson's ratio.
    pub poisson: f64,
    /// Elements through each wall.
    pub nr: usize,
    /// Elements along the outer tube.
    pub nz_outer: usize,
    /// Elements along the inner tube.
    pub nz_inner: usize,
    /// Coulomb friction coefficient.
    pub friction: f64,
    /// Element formulation.
    pub formulation: Formulation,
}

impl Default for ShrinkFit {
    /// The data of docs/validation.md ("Shrink fit of two tubes"): `a = 0.5, b = 1, c = 2, E = 1, nu = 0.3, delta = 1e-3`; length 0.5,
    /// 8 elements through each wall, 4 and 3 along the tubes, frictionless, hybrid.
    fn default() -> Self {
        ShrinkFit {
            a: 0.5,
            b: 1.0,
            c: 2.0,
            interference: 1e-3,
            length: 0.5,
            youngs: 1.0,
            poisson: 0.3,
            nr: 8,
            nz_outer: 4,
            nz_inner: 3,
            friction: 0.0,
            formulation: Formulation::Hybrid,
        }
    }
}

/// A built shrink fit.
#[derive(Debug, Clone)]
pub struct ShrinkFitScene {
    /// Both tubes (outer first).
    pub model: Model,
    /// Outer bore (A) against the inner tube's outside (B).
    pub pair: ContactPair,
    /// The outer tube's elements are `0..outer_elements`.
    pub outer_elements: usize,
    /// End nodes (z = 0 and z = length) of the inner tube (held axially, or moved to push it
    /// out).
    pub inner_ends: Vec<usize>,
    /// Lamé's solution for the radii modelled.
    pub exact: ShrinkFitExact,
}

impl ShrinkFit {
    /// Build the meshes, the material, the axial supports and the pair.
    pub fn build(&self) -> Result<ShrinkFitScene> {
        let material = Material::new(self.youngs, self.poisson, 1.0, Analysis::Axisymmetric)?;
        let d = self.b + self.interference;
        let outer = tube(self.b, self.c, self.length, self.nr, self.nz_outer);
        let inner = tube(self.a, d, self.length, self.nr, self.nz_inner);
        let mut mesh = Mesh::new();
        mesh.append(&outer, 0, "outer.");
        let first_inner = mesh.append(&inner, 0, "inner.");
        let outer_elements = outer.n_elements();
        let pair = ContactPair {
            a: chain(&mesh.edge_sets["outer.left"]),
            b: chain(&mesh.edge_sets["inner.right"]),
            friction: self.friction,
        };
        let outer_ends = ends(&mesh, 0, first_inner, self.length);
        let inner_ends = ends(&mesh, first_inner, mesh.n_nodes(), self.length);
        let mut model = Model::new(mesh, vec![material], self.formulation);
        model.fix_dir(&outer_ends, 1, 0.0)?;
        model.fix_dir(&inner_ends, 1, 0.0)?;
        Ok(ShrinkFitScene {
            model,
            pair,
            outer_elements,
            inner_ends,
            exact: ShrinkFitExact::new(
                self.a,
                self.b,
                self.c,
                self.interference,
                self.youngs,
                self.poisson,
            ),
        })
    }
}

impl ShrinkFitScene {
    /// The contact analysis (small kinematics unless `options` say otherwise).
    pub fn analysis(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        ContactAnalysis::new(self.model.clone(), vec![self.pair.clone()], options)
    }

    /// Prescribed values with the inner tube's ends moved axially by `push`.
    pub fn pushed(&self, push: f64) -> Vec<f64> {
        let mut qp = self.model.prescribed_values();
        for &n in &self.inner_ends {
            qp[2 * n + 1] = push;
        }
        qp
    }

    /// Largest `|sigma_theta_h - sigma_theta| / p` over the element centres of both tubes
    /// (`sigma_theta` Lamé's at the centre's radius, `p` the outer interface pressure), from
    /// the displacement `q`.
    pub fn hoop_error(&self, q: &[f64]) -> Result<f64> {
        let solution = hycon::model::Solution { q: q.to_vec() };
        let mut worst: f64 = 0.0;
        for e in 0..self.model.mesh.n_elements() {
            let field = solution.stress_field(&self.model, e)?;
            let nodes = self.model.mesh.element(e);
            let r = nodes
                .iter()
                .map(|&i| self.model.mesh.nodes[i][0])
                .sum::<f64>()
                / nodes.len() as f64;
            let z = nodes
                .iter()
                .map(|&i| self.model.mesh.nodes[i][1])
                .sum::<f64>()
                / nodes.len() as f64;
            let hoop = field.at_full([r, z])[3];
            let exact = self.exact.hoop(r, e < self.outer_elements);
            worst = worst.max((hoop - exact).abs() / self.exact.outer);
        }
        Ok(worst)
    }
}

/// Two solid cylinders of radius `radius`, one material, pressed end to end by a uniform
/// axial pressure `p` on the upper one's top (consistent full-circle nodal forces
/// `integral N_i p 2 pi r dr`): the exact state is uniaxial, `sigma_z = -p`, so the contact
/// pressure is `p` everywhere, **on the axis too**. A = the lower cylinder's top (from the
/// outside to the axis), B = the upper one's bottom; `n_lower`, `n_upper` elements across the
/// radius (non-matching), 4 along each; the lower one's bottom held axially, the upper one's
/// top too at its exact displacement, the axis nodes held radially.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StackedCylinders {
    /// Radius of both cylinders.
    pub radius: f64,
    /// Elements across the radius of the lower (A) and the upper cylinder.
    pub n_lower: usize,
    /// Elements across the upper cylinder's radius.
    pub n_upper: usize,
    /// The axial pressure.
    pub pressure: f64,
    /// Initial gap between the two (closed by the load).
    pub gap: f64,
}

/// A built [`StackedCylinders`] scene.
#[derive(Debug, Clone)]
pub struct StackedScene {
    /// Both cylinders (lower first).
    pub model: Model,
    /// Lower top (A) against upper bottom (B).
    pub pair: ContactPair,
}

impl StackedCylinders {
    /// Build the model (`E = 1`, `nu = 0.3`; height 0.5 each).
    pub fn build(&self) -> Result<StackedScene> {
        let (e, nu, h) = (1.0, 0.3, 0.5);
        let material = Material::new(e, nu, 1.0, Analysis::Axisymmetric)?;
        let lower = tube(0.0, self.radius, h, self.n_lower, 4);
        let mut upper = tube(0.0, self.radius, h, self.n_upper, 4);
        for p in &mut upper.nodes {
            p[1] += h + self.gap;
        }
        let mut mesh = Mesh::new();
        mesh.append(&lower, 0, "lower.");
        let first_upper = mesh.append(&upper, 0, "upper.");
        let pair = ContactPair {
            a: chain(&mesh.edge_sets["lower.top"]),
            b: chain(&mesh.edge_sets["upper.bottom"]),
            friction: 0.0,
        };
        let at = |z: f64, range: std::ops::Range<usize>, mesh: &Mesh| -> Vec<usize> {
            range
                .filter(|&i| (mesh.nodes[i][1] - z).abs() < 1e-12)
                .collect()
        };
        let bottom = at(0.0, 0..first_upper, &mesh);
        let top = at(2.0 * h + self.gap, first_upper..mesh.n_nodes(), &mesh);
        let axis: Vec<usize> = (0..mesh.n_nodes())
            .filter(|&i| mesh.nodes[i][0] == 0.0)
            .collect();
        let top_edges = mesh.edge_sets["upper.top"].clone();
        let mut model = Model::new(mesh, vec![material], Formulation::Hybrid);
        // exact uniaxial state: eps_z = -p / E in both, the top moves by 2 h eps_z - gap
        let v_top = 2.0 * h * (-self.pressure / e) - self.gap;
        model.fix_dir(&bottom, 1, 0.0)?;
        model.fix_dir(&[top[0]], 1, v_top)?;
        model.fix_dir(&axis, 0, 0.0)?;
        // p on the top: consistent full-circle forces of a uniform pressure on each edge,
        // integral N_i p 2 pi r dr = 2 pi p h_e (2 r_i + r_j) / 6
        for [i, j] in top_edges {
            let (ri, rj) = (model.mesh.nodes[i][0], model.mesh.nodes[j][0]);
            let len = (rj - ri).abs();
            let f = |r0: f64, r1: f64| {
                -2.0 * std::f64::consts::PI * self.pressure * len * (2.0 * r0 + r1) / 6.0
            };
            model.nodal_forces.push((i, [0.0, f(ri, rj)]));
            model.nodal_forces.push((j, [0.0, f(rj, ri)]));
        }
        Ok(StackedScene { model, pair })
    }
}

/// Hertz's sphere on a half-space: `a = (3 P R / (4 E*))^(1/3)`, `p0 = 3 P / (2 pi a^2)`,
/// `p(r) = p0 sqrt(1 - r^2 / a^2)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzSphere {
    /// Contact radius `a`.
    pub radius: f64,
    /// Peak pressure `p0`.
    pub peak: f64,
}

impl HertzSphere {
    /// The closed form for load `p` (full circle), sphere radius `r`, effective modulus `e_star`.
    pub fn new(p: f64, r: f64, e_star: f64) -> Self {
        let a = (3.0 * p * r / (4.0 * e_star)).cbrt();
        HertzSphere {
            radius: a,
            peak: 3.0 * p / (2.0 * std::f64::consts::PI * a * a),
        }
    }

    /// Pressure at radius `r` (0 outside the contact).
    pub fn pressure(&self, r: f64) -> f64 {
        let s = 1.0 - (r / self.radius).powi(2);
        if s > 0.0 { self.peak * s.sqrt() } else { 0.0 }
    }

    /// The Hertz pressure with the moments `m1 = integral p r dr` and `m3 = integral p r^3 dr`
    /// of a computed pressure (per radian: `integral p dA = 2 pi m1`, `integral p r^2 dA =
    /// 2 pi m3`): for Hertz `m3 / m1 = 2 a^2 / 5` and `m1 = p0 a^2 / 3`, so
    /// `a = sqrt(5 m3 / (2 m1))` and `p0 = 3 m1 / a^2 = 6 m1^2 / (5 m3)` (the same as
    /// `3 P / (2 pi a^2)` with `P = 2 pi m1`). How the axisymmetric and the 3D spheres report
    /// their contact radius and peak.
    pub fn from_moments(m1: f64, m3: f64) -> Self {
        HertzSphere {
            radius: (2.5 * m3 / m1).sqrt(),
            peak: 1.2 * m1 * m1 / m3,
        }
    }
}

/// A sphere (radius `R`) pressed onto a half-space, axisymmetric: the sphere as the quarter
/// disk `r >= 0` of the meridian (the lower half of [`generate::half_disk_with`] cut at the
/// axis), its flat top `z = R` moved down by the approach; the half-space as the cylinder
/// `0 <= r <= 4R`, `-4R <= z <= 0`, held at its bottom. Both meshes graded 2:1 toward the
/// contact zone (`r <= 1.5 a`) with quadrilaterals only (`Transition::Quads`, the axisymmetric
/// hybrid element takes 4 nodes), element size `h = a / n` there, 16 cells per size band. The
/// axis nodes are held radially. A = the block's top (multipliers), B = the sphere's surface;
/// frictionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereOnBlock {
    /// Elements per target contact radius.
    pub elements_per_radius: usize,
    /// `R / a` of the target contact radius.
    pub radius_over_contact: f64,
    /// `E_sphere / E_block` (`E_block = 1`, `nu = 0.3` both).
    pub modulus_ratio: f64,
}

/// A built [`SphereOnBlock`].
#[derive(Debug, Clone)]
pub struct SphereScene {
    /// Block then sphere.
    pub model: Model,
    /// Block top (A) against the sphere's surface (B).
    pub pair: ContactPair,
    /// The sphere's top face nodes (axially prescribed).
    pub top: Vec<usize>,
    /// Effective modulus `E*`.
    pub e_star: f64,
    /// Target contact radius (`R = 1`).
    pub target: f64,
}

/// The quarter `x >= 0` of a mesh symmetric about `x = 0` with element edges along it: its
/// elements with every node at `x >= 0`, nodes renumbered; node sets `"arc"` and `"top"`: the
/// chains of the kept edges of those edge sets, in order.
fn right_half(m: &Mesh) -> Mesh {
    let mut out = Mesh::new();
    let mut new = vec![usize::MAX; m.n_nodes()];
    for e in 0..m.n_elements() {
        let nodes = m.element(e);
        // the generator's nodes on x = 0 sit there to round-off (1e-16): snapped onto the axis
        let snap = 1e-12;
        if nodes.iter().any(|&i| m.nodes[i][0] < -snap) {
            continue;
        }
        let ids: Vec<usize> = nodes
            .iter()
            .map(|&i| {
                if new[i] == usize::MAX {
                    let [x, y] = m.nodes[i];
                    new[i] = out.push_node([if x.abs() <= snap { 0.0 } else { x }, y]);
                }
                new[i]
            })
            .collect();
        out.push_element(&ids, m.element_material[e]);
    }
    for set in ["arc", "top"] {
        let kept: Vec<[usize; 2]> = m.edge_sets[set]
            .iter()
            .filter(|e| e.iter().all(|&i| new[i] != usize::MAX))
            .map(|e| e.map(|i| new[i]))
            .collect();
        out.node_sets.insert(set.into(), chain(&kept));
    }
    out
}

impl SphereOnBlock {
    /// Build the scene (`R = 1`).
    pub fn build(&self) -> Result<SphereScene> {
        let n = self.elements_per_radius as f64;
        let a = 1.0 / self.radius_over_contact;
        let h = a / n;
        let w = 4.0;
        let layers = 16;
        let zone = 1.5 * a;
        let block_grading = [generate::Grading::toward_line(
            [0.0, 0.0],
            [zone, 0.0],
            h,
            layers,
        )];
        let block = generate::graded_rectangle_with(
            0.0,
            -w,
            [w, w],
            [1, 1],
            &block_grading,
            generate::Transition::Quads,
        );
        let disk_grading = [generate::Grading::toward_line(
            [-zone, 0.0],
            [zone, 0.0],
            h,
            layers,
        )];
        let sphere = right_half(&generate::half_disk_with(
            1.0,
            &disk_grading,
            generate::Transition::Quads,
        ));
        let block_material = Material::new(1.0, 0.3, 1.0, Analysis::Axisymmetric)?;
        let sphere_material = Material::new(self.modulus_ratio, 0.3, 1.0, Analysis::Axisymmetric)?;
        let mut mesh = Mesh::new();
        mesh.append(&block, 0, "block.");
        mesh.append(&sphere, 1, "sphere.");
        let within = |set: &str, hi: f64, mesh: &Mesh| -> Vec<usize> {
            mesh.node_sets[set]
                .iter()
                .copied()
                .filter(|&i| mesh.nodes[i][0] <= hi)
                .collect()
        };
        let pair = ContactPair {
            a: within("block.top", zone + 0.5 * a, &mesh),
            b: within("sphere.arc", zone + a, &mesh),
            friction: 0.0,
        };
        let top = mesh.node_sets["sphere.top"].clone();
        let bottom: Vec<usize> = (0..mesh.n_nodes())
            .filter(|&i| mesh.nodes[i][1] == -w)
            .collect();
        let axis: Vec<usize> = (0..mesh.n_nodes())
            .filter(|&i| mesh.nodes[i][0] == 0.0)
            .collect();
        let mut model = Model::new(
            mesh,
            vec![block_material, sphere_material],
            Formulation::Hybrid,
        );
        model.fix_dir(&bottom, 1, 0.0)?;
        model.fix_dir(&axis, 0, 0.0)?;
        model.fix_dir(&top, 1, 0.0)?;
        let e_star = 1.0
            / (1.0 / block_material.effective_modulus()
                + 1.0 / sphere_material.effective_modulus());
        Ok(SphereScene {
            model,
            pair,
            top,
            e_star,
            target: a,
        })
    }
}

/// The sphere's contact pressure against Hertz at the same load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereComparison {
    /// Total normal load `P` (full circle, from the contact forces on A).
    pub load: f64,
    /// Hertz at that load.
    pub hertz: HertzSphere,
    /// Peak pressure read at the axis: the multiplier of the node at `r = 0`.
    pub peak: f64,
    /// Peak pressure from the moments on `r dr` ([`HertzSphere::from_moments`]).
    pub peak_from_moments: f64,
    /// Contact radius from the pressure's moments on `r dr` ([`HertzSphere::from_moments`]).
    pub radius: f64,
    /// `||p_h - p_H|| / ||p_H||` in L2 over `r dr` (the surface measure), `p_h` linear
    /// between the A nodes.
    pub l2_error: f64,
    /// The same with the pressures from the equivalent nodal forces, `p_k = -n_k . f_k /
    /// weight_k`.
    pub l2_error_forces: f64,
    /// Nodes in contact.
    pub active: usize,
}

/// 5-point Gauss-Legendre on [0, 1]: (abscissa, weight).
pub(crate) const GAUSS5: [(f64, f64); 5] = [
    (0.046_910_077_030_668, 0.118_463_442_528_095),
    (0.230_765_344_947_158, 0.239_314_335_249_683),
    (0.5, 0.284_444_444_444_444_4),
    (0.769_234_655_052_842, 0.239_314_335_249_683),
    (0.953_089_922_969_332, 0.118_463_442_528_095),
];

impl SphereScene {
    /// The contact analysis.
    pub fn analysis(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        ContactAnalysis::new(self.model.clone(), vec![self.pair.clone()], options)
    }

    /// Prescribed values: the sphere's top moved down by `approach`.
    pub fn prescribed(&self, approach: f64) -> Vec<f64> {
        let mut qp = self.model.prescribed_values();
        for &n in &self.top {
            qp[2 * n + 1] = -approach;
        }
        qp
    }

    /// Hertz's approach `a^2 / R` of the target contact radius.
    pub fn hertz_approach(&self) -> f64 {
        self.target * self.target
    }

    /// Compare the converged multipliers with Hertz at the converged load (small kinematics:
    /// positions are the reference ones).
    pub fn compare(&self, analysis: &ContactAnalysis) -> Result<SphereComparison> {
        let nodes = analysis.node_results(0)?;
        let load: f64 = nodes
            .iter()
            .map(|n| -(n.frame.normal().dot(&n.force)))
            .sum();
        let hertz = HertzSphere::new(load, 1.0, self.e_star);
        let points = self.profile(&nodes, |n| -n.tn);
        let from_forces = self.profile(&nodes, |n| -(n.frame.normal().dot(&n.force)) / n.weight);
        let m = moments(&points, &hertz);
        let fit = HertzSphere::from_moments(m.m1, m.m3);
        Ok(SphereComparison {
            load,
            hertz,
            peak: points[0][1],
            peak_from_moments: fit.peak,
            radius: fit.radius,
            l2_error: m.l2_error,
            l2_error_forces: moments(&from_forces, &hertz).l2_error,
            active: nodes.iter().filter(|n| n.tn < 0.0).count(),
        })
    }
}

impl SphereScene {
    /// The contact pressure `-tn` (the multipliers) at the A nodes, `[r, p]` sorted by `r`.
    ///
    /// # Errors
    /// Those of `ContactAnalysis::node_results` (no converged increment).
    pub fn pressure_profile(&self, analysis: &ContactAnalysis) -> Result<Vec<[f64; 2]>> {
        Ok(self.profile(&analysis.node_results(0)?, |n| -n.tn))
    }

    /// `[r, pressure(node)]` of the A nodes `nodes`, sorted by `r`.
    fn profile(
        &self,
        nodes: &[NodeResult],
        pressure: impl Fn(&NodeResult) -> f64,
    ) -> Vec<[f64; 2]> {
        let mut points: Vec<[f64; 2]> = nodes
            .iter()
            .map(|n| [self.model.mesh.nodes[n.node][0], pressure(n)])
            .collect();
        points.sort_by(|u, v| u[0].total_cmp(&v[0]));
        points
    }
}

/// One run of [`SphereOnBlock::edge_sweep`]: the sphere pressed so that Hertz's contact
/// radius falls at a chosen place between two A nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereEdgeRun {
    /// Hertz's contact radius at the computed load, in element sizes `h = a_target / n`.
    pub radius_over_h: f64,
    /// The comparison with Hertz.
    pub comparison: SphereComparison,
}

impl SphereEdgeRun {
    /// Where the edge falls between the last node inside and the first outside, in `[0, 1)`.
    pub fn edge_position(&self) -> f64 {
        self.radius_over_h - self.radius_over_h.floor()
    }
}

impl SphereOnBlock {
    /// The comparison with Hertz against where the contact edge falls between two nodes (as
    /// `hycon bench edge` does for the plane scene): one analysis, pressed first by Hertz's
    /// approach `a^2 / R`, then so that Hertz's radius lies at `positions` evenly spaced
    /// places of one element, `a_H / h = k + (j + 1/2) / positions` (the approach scaled by
    /// `(a_H / a_1)^2`: the approach is `a^2 / R`).
    pub fn edge_sweep(&self, positions: usize) -> Result<Vec<SphereEdgeRun>> {
        let scene = self.build()?;
        let mut analysis = scene.analysis(ContactOptions::default())?;
        let f = vec![0.0; scene.model.external_forces().len()];
        let h = scene.target / self.elements_per_radius as f64;
        let mut press = |approach: f64| -> Result<SphereEdgeRun> {
            analysis.increment(&f, &scene.prescribed(approach))?;
            let comparison = scene.compare(&analysis)?;
            Ok(SphereEdgeRun {
                radius_over_h: comparison.hertz.radius / h,
                comparison,
            })
        };
        let approach = scene.hertz_approach();
        let first = press(approach)?;
        let k = first.radius_over_h.floor();
        (0..positions)
            .map(|j| {
                let target = k + (j as f64 + 0.5) / positions as f64;
                press(approach * (target / first.radius_over_h).powi(2))
            })
            .collect()
    }
}

/// The moments `M1 = integral p r dr`, `M3 = integral p r^3 dr` of a pressure linear between
/// `points` (`[r, p]`, sorted by `r`) and its relative L2 error against `hertz` on `r dr`.
struct Moments {
    m1: f64,
    m3: f64,
    l2_error: f64,
}

/// [`Moments`] of `points`: exact for the piecewise-linear pressure (5-point Gauss, degree 9),
/// split at `r = a` for Hertz's square-root edge.
fn moments(points: &[[f64; 2]], hertz: &HertzSphere) -> Moments {
    let (mut m1, mut m3, mut num, mut den) = (0.0, 0.0, 0.0, 0.0);
    for w in points.windows(2) {
        let ([ra, pa], [rb, pb]) = (w[0], w[1]);
        let mut cuts = vec![ra];
        if ra < hertz.radius && hertz.radius < rb {
            cuts.push(hertz.radius);
        }
        cuts.push(rb);
        for c in cuts.windows(2) {
            for (g, wt) in GAUSS5 {
                let r = c[0] + g * (c[1] - c[0]);
                let ph = pa + (r - ra) / (rb - ra) * (pb - pa);
                let d = wt * (c[1] - c[0]) * r;
                m1 += d * ph;
                m3 += d * ph * r * r;
                num += d * (ph - hertz.pressure(r)).powi(2);
                den += d * hertz.pressure(r).powi(2);
            }
        }
    }
    Moments {
        m1,
        m3,
        l2_error: (num / den).sqrt(),
    }
}
