//! The reference contact scene of the paper: a half disk of radius `R` pressed onto a much larger
//! block, plane strain, both meshes graded 2:1 toward the contact zone with transition elements.
//!
//! Set-up (every number stated, since finite bodies shift Hertz by a few tenths of a percent):
//! block `[-4R, 4R] x [-4R, 0]` fixed on its bottom face; the lower half disk (centre `(0, R)`,
//! lowest point at the origin) with its flat top face `y = R` displacement-controlled
//! (`u = slide`, `v = -approach`); the block's top face is the multiplier side A, the disk's arc
//! the opposite side B. The element size at the contact is `h = a / n` with `a` the target
//! half-width and `n` the elements per half-width; `a` is chosen as `R / 16`, so `h` is a power
//! of two of the block's root cells and the meshes are exactly graded.

use super::iteration::{ContactAnalysis, ContactOptions, ContactPair, NodeResult};
use crate::cases::Hertz;
use crate::element::Formulation;
use crate::error::{Error, Result};
use crate::material::{Analysis, Material};
use crate::mesh::Mesh;
use crate::mesh::generate::{self, Grading};
use crate::model::Model;

/// The disk-on-block scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiskOnBlock {
    /// Disk radius `R`.
    pub radius: f64,
    /// Elements per contact half-width at the contact (sets `h = a / n`; a power of two).
    pub elements_per_half_width: usize,
    /// `E_disk / E_block` (`E_block = 1` in the chosen units times `modulus_scale`).
    pub modulus_ratio: f64,
    /// Young's modulus of the block.
    pub block_modulus: f64,
    /// Poisson's ratio of both bodies.
    pub poisson: f64,
    /// Coulomb friction coefficient.
    pub friction: f64,
    /// Element formulation.
    pub formulation: Formulation,
    /// How far (in target half-widths) the contact zone travels to the right: the fine zone and
    /// the contact candidates extend that far.
    pub travel: f64,
}

impl Default for DiskOnBlock {
    fn default() -> Self {
        DiskOnBlock {
            radius: 1.0,
            elements_per_half_width: 16,
            modulus_ratio: 1.0,
            block_modulus: 1.0,
            poisson: 0.3,
            friction: 0.0,
            formulation: Formulation::Hybrid,
            travel: 0.0,
        }
    }
}

/// Pressure along the contact compared with Hertz at the same load.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzComparison {
    /// Total normal load `P` per unit thickness (from the contact forces).
    pub load: f64,
    /// Closed form for that load.
    pub hertz: Hertz,
    /// Centre of the pressure distribution (x).
    pub centre: f64,
    /// Half-width fitted to the nodal pressures (`p^2 = p0^2 (1 - (x - c)^2 / a^2)`, least
    /// squares over the nodes in contact).
    pub half_width: f64,
    /// Peak pressure from the same fit.
    pub peak: f64,
    /// `|| p - p_Hertz ||_L2 / || p_Hertz ||_L2` over the contact surface (nodal values,
    /// tributary-length weights), multiplier pressures.
    pub l2_error: f64,
    /// Same, from the equivalent nodal forces divided by the tributary lengths.
    pub l2_error_forces: f64,
    /// Nodes in contact.
    pub active: usize,
    /// `sum |ts| / sum |tn|` (0 for frictionless).
    pub tangential_ratio: f64,
}

/// The built scene: the model, the contact pair, and what the loading needs.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Both bodies in one model (block first, then the disk).
    pub model: Model,
    /// Block top (A) against disk arc (B).
    pub pair: ContactPair,
    /// Disk top-face nodes (displacement-controlled).
    pub top: Vec<usize>,
    /// Effective modulus `E*`.
    pub e_star: f64,
    /// Target half-width `a = R / 16`.
    pub half_width: f64,
}

impl DiskOnBlock {
    /// Target half-width `a = R / 16`.
    pub fn target_half_width(&self) -> f64 {
        self.radius / 16.0
    }

    /// Build the meshes, materials, boundary conditions and contact pair.
    pub fn build(&self) -> Result<Scene> {
        let n = self.elements_per_half_width;
        if n == 0 || !n.is_power_of_two() || n > 256 {
            return Err(Error::InvalidInput(format!(
                "elements per half-width must be a power of two in 1..=256, got {n}"
            )));
        }
        let r = self.radius;
        let a = self.target_half_width();
        let h = a / n as f64;
        // fine zone: the contact zone, where it travels, and a margin
        let (x0, x1) = (-1.5 * a, (1.5 + self.travel) * a);
        let block = generate::graded_rectangle(
            -4.0 * r,
            -4.0 * r,
            8.0 * r,
            4.0 * r,
            2,
            1,
            &Grading::toward_line([x0, 0.0], [x1, 0.0], h, 8),
        );
        let disk_zone = 1.5 * a + self.travel * a;
        let disk = generate::half_disk(
            r,
            &Grading::toward_line([-disk_zone, 0.0], [disk_zone, 0.0], h, 8),
        );
        let block_material =
            Material::new(self.block_modulus, self.poisson, 1.0, Analysis::PlaneStrain)?;
        let disk_material = Material::new(
            self.block_modulus * self.modulus_ratio,
            self.poisson,
            1.0,
            Analysis::PlaneStrain,
        )?;
        let mut mesh = Mesh::new();
        mesh.append(&block, 0, "block.");
        mesh.append(&disk, 1, "disk.");
        let within = |set: &str, lo: f64, hi: f64, mesh: &Mesh| -> Vec<usize> {
            mesh.node_sets[set]
                .iter()
                .copied()
                .filter(|&i| (lo..=hi).contains(&mesh.nodes[i][0]))
                .collect()
        };
        // A: block top (ordered right to left, body below); B: disk arc (left to right, wider)
        let pair = ContactPair {
            a: within("block.top", x0 - 0.5 * a, x1 + 0.5 * a, &mesh),
            b: within("disk.arc", -disk_zone - a, disk_zone + a, &mesh),
            friction: self.friction,
        };
        let top = mesh.node_sets["disk.top"].clone();
        let bottom = mesh.node_sets["block.bottom"].clone();
        let mut model = Model::new(mesh, vec![block_material, disk_material], self.formulation);
        model.fix(&bottom, [0.0, 0.0]);
        model.fix(&top, [0.0, 0.0]);
        Ok(Scene {
            model,
            pair,
            top,
            e_star: Hertz::effective_modulus(&block_material, &disk_material),
            half_width: a,
        })
    }
}

impl Scene {
    /// Prescribed values: the disk's top face moved by `(slide, -approach)`.
    pub fn prescribed(&self, approach: f64, slide: f64) -> Vec<f64> {
        let mut qp = vec![0.0; 2 * self.model.mesh.n_nodes()];
        for &n in &self.top {
            qp[2 * n] = slide;
            qp[2 * n + 1] = -approach;
        }
        qp
    }

    /// The contact analysis of this scene (factors `K` and builds the flexibility).
    pub fn analysis(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        ContactAnalysis::new(self.model.clone(), vec![self.pair.clone()], options)
    }

    /// An approach that gives roughly the target half-width: one increment at a trial
    /// approach `a^2 / R` measures the load, then the approach is scaled linearly to the Hertz
    /// load `P = pi a^2 E* / (4 R)` (in 2D the load is nearly linear in the approach). The
    /// trial increment is taken on `analysis`, so the caller's next increment continues from it.
    pub fn calibrated_approach(&self, analysis: &mut ContactAnalysis, radius: f64) -> Result<f64> {
        let a = self.half_width;
        let trial = a * a / radius;
        let f = vec![0.0; 2 * self.model.mesh.n_nodes()];
        analysis.increment(&f, &self.prescribed(trial, 0.0))?;
        let load = total_load(&analysis.node_results(0)?);
        if load <= 0.0 {
            return Err(Error::Contact("no contact at the trial approach".into()));
        }
        let target = std::f64::consts::PI * a * a * self.e_star / (4.0 * radius);
        Ok(trial * target / load)
    }

    /// Compare the converged pressures of `analysis` with Hertz at the same load.
    pub fn compare(&self, analysis: &ContactAnalysis, radius: f64) -> Result<HertzComparison> {
        compare_with_hertz(&analysis.node_results(0)?, radius, self.e_star)
    }
}

/// Total normal load `P = sum_j -n . f_j` on the A side.
pub fn total_load(nodes: &[NodeResult]) -> f64 {
    nodes
        .iter()
        .map(|n| -(n.normal[0] * n.force[0] + n.normal[1] * n.force[1]))
        .sum()
}

/// Hertz comparison of nodal results along a straight A surface (x is the coordinate along it).
pub fn compare_with_hertz(
    nodes: &[NodeResult],
    radius: f64,
    e_star: f64,
) -> Result<HertzComparison> {
    let load = total_load(nodes);
    if load <= 0.0 {
        return Err(Error::Contact("no compressive contact load".into()));
    }
    let hertz = Hertz::new(load, radius, e_star);
    let pressure = |n: &NodeResult| -n.tn;
    let force_pressure =
        |n: &NodeResult| -(n.normal[0] * n.force[0] + n.normal[1] * n.force[1]) / n.weight;
    let weight_sum: f64 = nodes.iter().map(|n| pressure(n) * n.weight).sum();
    let centre = nodes
        .iter()
        .map(|n| pressure(n) * n.weight * n.position[0])
        .sum::<f64>()
        / weight_sum;
    let active: Vec<&NodeResult> = nodes.iter().filter(|n| n.tn < 0.0).collect();
    // least squares p^2 = A - B (x - c)^2
    let (mut sxx, mut sx, mut sy, mut sxy, mut m) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for n in &active {
        let x2 = (n.position[0] - centre).powi(2);
        let p2 = pressure(n).powi(2);
        sxx += x2 * x2;
        sx += x2;
        sy += p2;
        sxy += x2 * p2;
        m += 1.0;
    }
    let slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    let intercept = (sy - slope * sx) / m;
    let (peak, half_width) = (intercept.sqrt(), (intercept / -slope).sqrt());
    let l2 = |p: &dyn Fn(&NodeResult) -> f64| {
        let (mut num, mut den) = (0.0, 0.0);
        for n in nodes {
            let exact = hertz.pressure(n.position[0] - centre);
            num += n.weight * (p(n) - exact).powi(2);
            den += n.weight * exact * exact;
        }
        (num / den).sqrt()
    };
    let tn_sum: f64 = nodes.iter().map(|n| n.tn.abs()).sum();
    let ts_sum: f64 = nodes.iter().map(|n| n.ts.abs()).sum();
    Ok(HertzComparison {
        load,
        hertz,
        centre,
        half_width,
        peak,
        l2_error: l2(&pressure),
        l2_error_forces: l2(&force_pressure),
        active: active.len(),
        tangential_ratio: ts_sum / tn_sum,
    })
}
