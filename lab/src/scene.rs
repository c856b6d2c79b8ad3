//! The reference contact scene of the paper: a half disk of radius `R` pressed onto a much larger
//! block, plane strain, both meshes graded 2:1 toward the contact zone with transition elements.
//!
//! Set-up (every number stated, since finite bodies shift Hertz by a few tenths of a percent):
//! block `[-4R, 4R] x [-4R, 0]` fixed on its bottom face; the lower half disk (centre `(0, R)`,
//! lowest point at the origin) with its flat top face `y = R` displacement-controlled
//! (`u = slide`, `v = -approach`); the block's top face is the multiplier side A, the disk's arc
//! the opposite side B. The element size at the contact is `h = a / n` with `a` the target
//! half-width and `n` the elements per half-width; `a` is `R / 64`, so `h` is a power of two of
//! the block's root cells and the meshes are exactly graded. Both meshes are graded 2:1 toward
//! the contact zone with 16 cells per size band ([`DiskOnBlock::band_layers`]); the disk's band
//! follows its arc where the arc rises out of the band of the line `y = 0` (`arc_chords`), so
//! the arc keeps size `h` over the whole fine zone at any R/a.
//! ([`DiskOnBlock::radius_over_half_width`] sets another power of two for `R / a`; 64 is the
//! reference scene.)
//!
//! Mesh variants: [`DiskOnBlock::transition`] `Transition::Elements` (the reference scene: one
//! element per quadtree leaf, 5- and 6-node transition elements, hybrid elements only) or
//! `Transition::Quads` (4-node quadrilaterals only, the same grading joined by templates, see
//! [`generate::graded_layout_with`]; needed by Pian-Sumihara and Q4, and run with the hybrid
//! element too, to separate element effects from mesh effects). Both have element size `h` at
//! the contact and `band_layers` elements per size band. [`DiskOnBlock::max_element_size`] caps the element
//! size everywhere (a uniformly finer far field: large models with the same contact zone).
//!
//! Why `a / R = 1/64`: under finite kinematics the contact geometry is evaluated in the current
//! configuration, so the comparison with (linear) Hertz carries an offset of order `a / R` (the
//! deformed surfaces tilt by about `p0 / E*`): measured at 16 elements per half-width, the
//! half-width is low by 1.0%, 0.55% and 0.33% at `a / R` = 1/16, 1/32 and 1/64. Small
//! kinematics (the default) solve the linearized problem of Hertz theory and have no such
//! offset; 64 stays the reference so that both kinematics run on one scene.

use crate::cases::Hertz;
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, Kinematics, NodeResult,
};
use hycon::element::Formulation;
use hycon::error::{Error, Result};
use hycon::material::{Analysis, Material};
use hycon::mesh::Mesh;
use hycon::mesh::generate::{self, Grading, Target, Transition};
use hycon::model::Model;

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
    /// Node-to-node meshes: the block's top nodes face the disk's arc nodes in the contact zone
    /// (otherwise node-to-internode). See [`DiskOnBlock::build`].
    pub node_to_node: bool,
    /// How the graded meshes join fine and coarse cells: transition elements (the reference
    /// scene; hybrid elements only) or 4-node quadrilaterals only (any element).
    pub transition: Transition,
    /// Largest element size anywhere, in radii (`None`: no cap, the graded meshes coarsen to
    /// their root cells). A cap refines the far field uniformly: large models with the same
    /// contact zone.
    pub max_element_size: Option<f64>,
    /// `R / a`, a power of two from 4 to 2^16 (64 in the reference scene). A smaller target
    /// half-width shrinks the O(a / R) offset of the current-configuration geometry against
    /// linear Hertz. Node-to-node meshes take the largest `n h` not above `R` / this.
    pub radius_over_half_width: usize,
    /// Cells of each size between the contact zone and the next coarser size band, in both
    /// meshes (16 in the reference scene, at least 2). The mesh around the contact is then
    /// graded with a fixed ratio of element size to distance, so its error in the field near
    /// the contact does not fall with `n`: at 8 cells per band the half-width and peak are
    /// offset by about 0.11% at every `n`, at 16 by 0.04%, at 32 by 0.015%.
    pub band_layers: usize,
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
            node_to_node: false,
            transition: Transition::Elements,
            max_element_size: None,
            radius_over_half_width: 64,
            band_layers: 16,
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
    /// Half-width from the second moment of the multiplier pressure (for Hertz,
    /// `integral p x^2 dx / integral p dx = a^2 / 4`, so `a = 2 sqrt(M2 / M0)`).
    pub half_width: f64,
    /// Multiplier pressure at the pressure centre (linear between nodes).
    pub peak: f64,
    /// `|| p_h - p_Hertz ||_L2 / || p_Hertz ||_L2` along the surface, `p_h` the multiplier
    /// pressure, linear between nodes (as the method interpolates it).
    pub l2_error: f64,
    /// Same, with nodal pressures from the equivalent nodal forces divided by the tributary
    /// lengths.
    pub l2_error_forces: f64,
    /// The least L2 error any pressure linear between the same A nodes can have: that of the
    /// L2 projection of Hertz onto their hat functions (see [`best_approximation`]). It depends
    /// on where the contact edge falls between two nodes.
    pub best_l2_error: f64,
    /// The least L2 error any pressure linear between the same A nodes and zero at the open
    /// ones can have (see [`best_approximation_on`]): the bound for pressures with the method's
    /// own contact set, which the multipliers are. `l2_error` is never below it.
    pub best_active_l2_error: f64,
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
    /// Target half-width `a` (`R / 64` in the reference scene).
    pub half_width: f64,
    /// Disk radius `R`.
    pub radius: f64,
}

impl DiskOnBlock {
    /// Target half-width `a`: `R / 64` (generally `R /`
    /// [`radius_over_half_width`](Self::radius_over_half_width)) for node-to-internode meshes;
    /// for node-to-node meshes the largest `n h` not above that with `h` the block's cell size
    /// (see [`DiskOnBlock::build`]).
    pub fn target_half_width(&self) -> f64 {
        self.radius * self.unit_geometry().0
    }

    /// `(a, h, W)` for `R = 1`: target half-width, element size at the contact, block
    /// half-width (the block is `[-W, W] x [-W_depth, 0]`, root cells of size `W`).
    fn unit_geometry(&self) -> (f64, f64, f64) {
        let n = self.elements_per_half_width.max(1) as f64;
        let a = 1.0 / self.radius_over_half_width.max(1) as f64;
        if self.node_to_node {
            // the disk's arc cells at the contact are (pi / 8) / 2^k long (45-degree O-grid
            // patches of 2 root cells): a block of root size 2 pi has cells of the same length
            let w = 2.0 * std::f64::consts::PI;
            let mut h = w;
            while n * h > a {
                h /= 2.0;
            }
            (n * h, h, w)
        } else {
            (a, a / n, 4.0)
        }
    }

    /// Build the meshes, materials, boundary conditions and contact pair.
    pub fn build(&self) -> Result<Scene> {
        let n = self.elements_per_half_width;
        if n == 0 || !n.is_power_of_two() || n > 512 {
            return Err(Error::InvalidInput(format!(
                "elements per half-width must be a power of two in 1..=512, got {n}"
            )));
        }
        let q = self.radius_over_half_width;
        if !q.is_power_of_two() || !(4..=1 << 16).contains(&q) {
            return Err(Error::InvalidInput(format!(
                "R / a must be a power of two in 4..=65536, got {q}"
            )));
        }
        if self.transition == Transition::Elements && self.formulation != Formulation::Hybrid {
            return Err(Error::InvalidInput(format!(
                "the {} element takes 4-node quadrilaterals only: use transition = Quads",
                self.formulation.name()
            )));
        }
        if self.band_layers < 2 {
            return Err(Error::InvalidInput(format!(
                "band_layers must be at least 2, got {}",
                self.band_layers
            )));
        }
        if let Some(cap) = self.max_element_size
            && !(cap.is_finite() && cap > 0.0)
        {
            return Err(Error::InvalidInput(format!(
                "max_element_size must be positive and finite, got {cap}"
            )));
        }
        // meshes and candidate sets are built for R = 1 and then scaled, so that every mesh
        // decision (grading thresholds, set membership) is the same in any unit system
        let r = 1.0;
        let (a, h, w) = self.unit_geometry();
        // a cap refines every cell above it (whatever its distance from the target)
        let cap = self.max_element_size.map(|c| Grading {
            target: Target::Point([0.0, 0.0]),
            min_size: c,
            layers: usize::MAX / 4,
        });
        // fine zone: the contact zone, where it travels, and a margin
        let (x0, x1) = (-1.5 * a, (1.5 + self.travel) * a);
        let layers = self.band_layers;
        let block_gradings: Vec<Grading> = [Grading::toward_line([x0, 0.0], [x1, 0.0], h, layers)]
            .into_iter()
            .chain(cap)
            .collect();
        let mut block = generate::graded_rectangle_with(
            -w,
            -w,
            [2.0 * w, w],
            [2, 1],
            &block_gradings,
            self.transition,
        );
        let disk_zone = 1.5 * a + self.travel * a;
        // node-to-node: the disk's arc cells must stop at length h; their longest edge is the
        // radial one, about 1.2 h at the contact, hence the 1.3
        let disk_size = if self.node_to_node { 1.3 * h } else { h };
        let disk_gradings: Vec<Grading> = [Grading::toward_line(
            [-disk_zone, 0.0],
            [disk_zone, 0.0],
            disk_size,
            layers,
        )]
        .into_iter()
        .chain(arc_chords(r, disk_zone, disk_size, layers))
        .chain(cap)
        .collect();
        let disk = generate::half_disk_with(r, &disk_gradings, self.transition);
        if self.node_to_node {
            // only where the block's cells are all of size h (within 4 h of the graded line,
            // so no transition element's straight edge is bent by the move)
            face_nodes(&mut block, &disk, x0 - 2.0 * h, x1 + 2.0 * h, h)?;
        }
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
        for p in &mut mesh.nodes {
            *p = p.map(|c| c * self.radius);
        }
        let top = mesh.node_sets["disk.top"].clone();
        let bottom = mesh.node_sets["block.bottom"].clone();
        let mut model = Model::new(mesh, vec![block_material, disk_material], self.formulation);
        model.fix(&bottom, [0.0, 0.0])?;
        model.fix(&top, [0.0, 0.0])?;
        Ok(Scene {
            model,
            pair,
            top,
            e_star: Hertz::effective_modulus(&block_material, &disk_material),
            half_width: self.target_half_width(),
            radius: self.radius,
        })
    }
}

/// Gradings that keep the disk's arc at element size `h` over `|x| <= zone` where it rises
/// above half the band that the line `y = 0` refines (`layers h / 2`): toward chords of the arc
/// (radius `r`, lowest point at the origin) with sagitta at most `h`. Below that height the
/// line's band already holds the arc (none are made: the reference scene's meshes are those
/// of the line alone up to n = 256 at R/a = 64 and n = 128 at R/a = 32). Without them the arc
/// coarsened where it rose out of the band (at R/a = 4, n = 512: 1.6 h from 0.48 a, 6.1 h
/// from 0.95 a), so the multiplier side A was finer than B inside the contact zone and, with
/// a soft disk, the contact system near singular.
fn arc_chords(r: f64, zone: f64, h: f64, layers: usize) -> Vec<Grading> {
    let rise = 0.5 * layers as f64 * h;
    if rise >= r {
        return Vec::new();
    }
    let from = (rise * (2.0 * r - rise)).sqrt();
    if from >= zone {
        return Vec::new();
    }
    let chord = (8.0 * r * h).sqrt();
    let pieces = ((zone - from) / chord).ceil() as usize;
    let arc = |x: f64| [x, r - (r * r - x * x).sqrt()];
    let end = |i: usize| from + (zone - from) * i as f64 / pieces as f64;
    (0..pieces)
        .flat_map(|i| [(end(i), end(i + 1)), (-end(i + 1), -end(i))])
        .map(|(x0, x1)| Grading::toward_line(arc(x0), arc(x1), h, layers))
        .collect()
}

/// Move the block's top nodes in `[lo, hi]` horizontally onto the x of the disk's arc nodes they
/// face (node-to-node meshes; outside `[lo, hi]`, beyond the contact zone, the meshes stay
/// node-to-internode). Every such node must have a disk node within 5% of `h` (the arc
/// nodes sit at `sin(theta)`, off a uniform grid by `x^3 / 6`, 1% of `h` at the edge of the
/// zone), else the meshes are not node-to-node and this says so.
fn face_nodes(block: &mut Mesh, disk: &Mesh, lo: f64, hi: f64, h: f64) -> Result<()> {
    let arc: Vec<f64> = disk.node_sets["arc"]
        .iter()
        .map(|&i| disk.nodes[i][0])
        .collect();
    for &i in &block.node_sets["top"] {
        let x = block.nodes[i][0];
        if !(lo..=hi).contains(&x) {
            continue;
        }
        let nearest = arc
            .iter()
            .copied()
            .min_by(|p, q| (p - x).abs().total_cmp(&(q - x).abs()))
            .unwrap_or(f64::INFINITY);
        if (nearest - x).abs() > 0.05 * h {
            return Err(Error::InvalidInput(format!(
                "node-to-node meshes: no disk node faces the block node at x = {x:.6} (nearest \
                 {nearest:.6}, h = {h:.3e})"
            )));
        }
        block.nodes[i][0] = nearest;
    }
    Ok(())
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

    /// The contact analysis with the disk's top face tied to a rigid plate, for force control
    /// ([`ContactAnalysis::increment_with_plate`]).
    pub fn plate_analysis(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        ContactAnalysis::with_plate(
            self.model.clone(),
            vec![self.pair.clone()],
            options,
            self.top.clone(),
        )
    }

    /// The Hertz load `P = pi a^2 E* / (4 R)` per unit thickness of the target half-width.
    pub fn hertz_load(&self) -> f64 {
        std::f64::consts::PI * self.half_width.powi(2) * self.e_star / (4.0 * self.radius)
    }

    /// The contact analysis of this scene (factors `K` and builds the flexibility).
    pub fn analysis(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        ContactAnalysis::new(self.model.clone(), vec![self.pair.clone()], options)
    }

    /// The analysis pressed to the Hertz load in one increment after the calibration (see
    /// [`calibrated_approach`](Self::calibrated_approach)), with the approach it took.
    pub fn pressed(&self, options: ContactOptions) -> Result<(ContactAnalysis, f64)> {
        let mut analysis = self.analysis(options)?;
        let approach = self.calibrated_approach(&mut analysis)?;
        let f = vec![0.0; 2 * self.model.mesh.n_nodes()];
        analysis.increment(&f, &self.prescribed(approach, 0.0))?;
        Ok((analysis, approach))
    }

    /// An approach that gives roughly the target half-width: one increment at a trial
    /// approach `a^2 / R` measures the load, then the approach is scaled linearly to the Hertz
    /// load `P = pi a^2 E* / (4 R)` (in 2D the load is nearly linear in the approach). The
    /// trial increment is taken on `analysis`, so the caller's next increment continues from it.
    pub fn calibrated_approach(&self, analysis: &mut ContactAnalysis) -> Result<f64> {
        let radius = self.radius;
        let a = self.half_width;
        let trial = a * a / radius;
        let f = vec![0.0; 2 * self.model.mesh.n_nodes()];
        analysis.increment(&f, &self.prescribed(trial, 0.0))?;
        let load = total_load(&analysis.node_results(0)?);
        if load <= 0.0 {
            return Err(Error::InvalidInput(
                "calibration: no contact at the trial approach".into(),
            ));
        }
        Ok(trial * self.hertz_load() / load)
    }

    /// Compare the converged pressures of `analysis` with Hertz at the same load (positions
    /// as in [`node_results`](Self::node_results)).
    pub fn compare(&self, analysis: &ContactAnalysis) -> Result<HertzComparison> {
        compare_with_hertz(&self.node_results(analysis)?, self.radius, self.e_star)
    }

    /// The converged A-node results of the pair, with `position` in the configuration the
    /// contact geometry lives in: the reference position under small kinematics (the
    /// coordinate of linear Hertz and Cattaneo-Mindlin theory; the surface's own tangential
    /// displacement would shift the profile by O(a / R)), the current one under finite
    /// kinematics.
    pub fn node_results(&self, analysis: &ContactAnalysis) -> Result<Vec<NodeResult>> {
        let mut nodes = analysis.node_results(0)?;
        if analysis.options().kinematics == Kinematics::Small {
            for n in &mut nodes {
                n.position = self.model.mesh.nodes[n.node].into();
            }
        }
        Ok(nodes)
    }
}

impl Scene {
    /// The L2 error against Hertz (same definition as [`HertzComparison::l2_error`]) of the
    /// pressure recovered from the block's element stresses, the paper's way (a). Recovers the
    /// full field (one solve) if it was not yet.
    pub fn stress_pressure_error(&self, analysis: &mut ContactAnalysis) -> Result<f64> {
        let comparison = self.compare(analysis)?;
        let tractions = analysis.stress_tractions(0)?;
        let nodes = self.node_results(analysis)?;
        let mut points: Vec<[f64; 2]> = nodes
            .iter()
            .zip(&tractions)
            .map(|(n, t)| [n.position[0] - comparison.centre, (-t.0).max(0.0)])
            .collect();
        points.sort_by(|a, b| a[0].total_cmp(&b[0]));
        Ok(l2_error(&points, &comparison.hertz))
    }
}

/// Total normal load `P = sum_j -n . f_j` on the A side.
pub fn total_load(nodes: &[NodeResult]) -> f64 {
    nodes
        .iter()
        .map(|n| -(n.frame.normal().dot(&n.force)))
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
        return Err(Error::InvalidInput(
            "no compressive contact load to compare with Hertz".into(),
        ));
    }
    let hertz = Hertz::new(load, radius, e_star);
    let pressure = |n: &NodeResult| -n.tn;
    let force_pressure = |n: &NodeResult| -(n.frame.normal().dot(&n.force)) / n.weight;
    let weight_sum: f64 = nodes.iter().map(|n| pressure(n) * n.weight).sum();
    let centre = nodes
        .iter()
        .map(|n| pressure(n) * n.weight * n.position[0])
        .sum::<f64>()
        / weight_sum;
    let active = nodes.iter().filter(|n| n.tn < 0.0).count();
    // nodal pressures as a piecewise-linear function of x (A's nodes sorted by x)
    let mut by_x: Vec<&NodeResult> = nodes.iter().collect();
    by_x.sort_by(|a, b| a.position[0].total_cmp(&b.position[0]));
    let curve = |p: &dyn Fn(&NodeResult) -> f64| -> Vec<[f64; 2]> {
        by_x.iter()
            .map(|n| [n.position[0] - centre, p(n)])
            .collect()
    };
    let (multipliers, forces) = (curve(&pressure), curve(&force_pressure));
    let in_contact: Vec<bool> = by_x.iter().map(|n| n.tn < 0.0).collect();
    // second moment: for Hertz, integral p x^2 dx / integral p dx = a^2 / 4
    let (m0, m2) = moments(&multipliers);
    Ok(HertzComparison {
        load,
        hertz,
        centre,
        half_width: 2.0 * (m2 / m0).sqrt(),
        peak: interpolate(&multipliers, 0.0),
        l2_error: l2_error(&multipliers, &hertz),
        l2_error_forces: l2_error(&forces, &hertz),
        best_l2_error: l2_error(&best_approximation(&multipliers, &hertz), &hertz),
        best_active_l2_error: l2_error(
            &best_approximation_on(&multipliers, &in_contact, &hertz),
            &hertz,
        ),
        active,
        tangential_ratio: nodes.iter().map(|n| n.ts.norm()).sum::<f64>()
            / nodes.iter().map(|n| n.tn.abs()).sum::<f64>(),
    })
}

/// Value at `x` of the piecewise-linear function through `points` (sorted by x; 0 outside).
fn interpolate(points: &[[f64; 2]], x: f64) -> f64 {
    points
        .windows(2)
        .find(|w| w[0][0] <= x && x <= w[1][0])
        .map_or(0.0, |w| {
            let r = (x - w[0][0]) / (w[1][0] - w[0][0]);
            w[0][1] + r * (w[1][1] - w[0][1])
        })
}

/// `(integral p dx, integral p x^2 dx)` of the piecewise-linear `p` (exact: Simpson per piece).
fn moments(points: &[[f64; 2]]) -> (f64, f64) {
    points.windows(2).fold((0.0, 0.0), |(m0, m2), w| {
        let ([xa, pa], [xb, pb]) = (w[0], w[1]);
        let (xm, pm) = (0.5 * (xa + xb), 0.5 * (pa + pb));
        let h = (xb - xa) / 6.0;
        (
            m0 + h * (pa + 4.0 * pm + pb),
            m2 + h * (pa * xa * xa + 4.0 * pm * xm * xm + pb * xb * xb),
        )
    })
}

/// 8-point Gauss-Legendre on [-1, 1]: (abscissa, weight) for the positive half.
const G8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// `integral f(x, t) dx` over the piece `[xa, xb]` (`t` its own coordinate in [0, 1]), split
/// at `+-a`, where Hertz's pressure has its square-root edges, 8-point Gauss per part.
fn integrate(xa: f64, xb: f64, a: f64, f: &dyn Fn(f64, f64) -> f64) -> f64 {
    let mut cuts = vec![xa];
    cuts.extend([-a, a].into_iter().filter(|&c| xa < c && c < xb));
    cuts.push(xb);
    let mut sum = 0.0;
    for c in cuts.windows(2) {
        let (mid, half) = (0.5 * (c[0] + c[1]), 0.5 * (c[1] - c[0]));
        for (g, w) in G8 {
            for x in [mid - g * half, mid + g * half] {
                sum += w * half * f(x, (x - xa) / (xb - xa));
            }
        }
    }
    sum
}

/// Continuous relative L2 error `||p_h - p_H|| / ||p_H||` of the piecewise-linear nodal
/// pressure `points` (sorted by x) against Hertz, integrated along the surface.
pub fn l2_error(points: &[[f64; 2]], hertz: &Hertz) -> f64 {
    let a = hertz.half_width;
    let (mut num, mut den) = (0.0, 0.0);
    for w in points.windows(2) {
        let ([xa, pa], [xb, pb]) = (w[0], w[1]);
        num += integrate(xa, xb, a, &|x, t| {
            (pa + t * (pb - pa) - hertz.pressure(x)).powi(2)
        });
        den += integrate(xa, xb, a, &|x, _| hertz.pressure(x).powi(2));
    }
    (num / den).sqrt()
}

/// The L2 projection of Hertz's pressure onto the hat functions of the nodes `points` (their
/// x; the values are ignored): the nodal values `c` of `M c = b` with the tridiagonal mass
/// matrix `M_ij = integral phi_i phi_j` and `b_i = integral phi_i p_H`, solved by the Thomas
/// algorithm. No pressure linear between these nodes is closer to Hertz in L2.
pub fn best_approximation(points: &[[f64; 2]], hertz: &Hertz) -> Vec<[f64; 2]> {
    best_approximation_on(points, &vec![true; points.len()], hertz)
}

/// The L2 projection of Hertz's pressure onto the hat functions of the nodes of `points` that
/// are `free`, the others held at zero: as [`best_approximation`] with the rows and columns of
/// the held nodes replaced by `c_i = 0`. With `free` the nodes in contact, no pressure linear
/// between the nodes and zero at the open ones is closer to Hertz in L2; the method's
/// multipliers are such a pressure, so their error is never below this one's.
pub fn best_approximation_on(points: &[[f64; 2]], free: &[bool], hertz: &Hertz) -> Vec<[f64; 2]> {
    let m = points.len();
    let a = hertz.half_width;
    let (mut diag, mut off, mut b) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
    for i in 0..m.saturating_sub(1) {
        let (xa, xb) = (points[i][0], points[i + 1][0]);
        diag[i] += (xb - xa) / 3.0;
        diag[i + 1] += (xb - xa) / 3.0;
        off[i] = (xb - xa) / 6.0;
        b[i] += integrate(xa, xb, a, &|x, t| (1.0 - t) * hertz.pressure(x));
        b[i + 1] += integrate(xa, xb, a, &|x, t| t * hertz.pressure(x));
    }
    for i in (0..m).filter(|&i| !free[i]) {
        (diag[i], b[i]) = (1.0, 0.0);
        off[i] = 0.0;
        if i > 0 {
            off[i - 1] = 0.0;
        }
    }
    // forward elimination (off[i] couples i and i + 1), then back substitution
    for i in 1..m {
        let factor = off[i - 1] / diag[i - 1];
        diag[i] -= factor * off[i - 1];
        b[i] -= factor * b[i - 1];
    }
    let mut c = vec![0.0; m];
    for i in (0..m).rev() {
        let next = if i + 1 < m { off[i] * c[i + 1] } else { 0.0 };
        c[i] = (b[i] - next) / diag[i];
    }
    points.iter().zip(c).map(|(p, v)| [p[0], v]).collect()
}
