//! Random two-block presses, to see how often the contact iteration fails and why: the problem
//! distribution of `tests/contact_properties.rs` (a lower block `[0, 2] x [0, 1]` held at its
//! bottom, an upper block of random width, position and mesh a random gap above it, pressed
//! down and then moved sideways through its top; random moduli, Poisson's ratios, friction and
//! kinematics), drawn from a seed.

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, ContactPair, Kinematics};
use hycon::element::Formulation;
use hycon::error::{ContactError, Error, Result};
use hycon::material::{Analysis, Material};
use hycon::mesh::Mesh;
use hycon::model::Model;
use std::collections::BTreeMap;

/// One random press.
#[derive(Debug, Clone)]
pub struct Press {
    /// Cells of the lower block, across and up.
    pub lower: [usize; 2],
    /// Cells of the upper block.
    pub upper: [usize; 2],
    /// Left end of the upper block.
    pub left: f64,
    /// Width of the upper block.
    pub width: f64,
    /// Initial gap between the blocks.
    pub gap: f64,
    /// How far the top is pressed down beyond the gap.
    pub depth: f64,
    /// How far the top then moves sideways.
    pub slide: f64,
    /// Young's modulus of the upper block (the lower one's is 1).
    pub upper_modulus: f64,
    /// Poisson's ratios, lower and upper.
    pub poisson: [f64; 2],
    /// Friction coefficient (0 for half of the presses).
    pub friction: f64,
    /// Contact kinematics.
    pub kinematics: Kinematics,
}

/// A xorshift64 generator: reproducible draws from a seed, nothing more is needed here.
struct Draws(u64);

impl Draws {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// An integer in `lo..=hi`.
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + ((self.unit() * (hi - lo + 1) as f64) as usize).min(hi - lo)
    }
}

impl Press {
    /// The `count` presses of `seed`, with the ranges of `tests/contact_properties.rs`.
    pub fn draw(count: usize, seed: u64) -> Vec<Press> {
        let mut d = Draws(seed | 1);
        (0..count)
            .map(|_| {
                let lower = [d.int(1, 5) + 1, d.int(1, 3)];
                let upper = [d.int(1, 4), d.int(1, 3)];
                let (left, width) = (d.range(0.1, 0.8), d.range(0.4, 1.0));
                let gap = d.range(0.0, 1e-3);
                let depth = d.range(1e-4, 1e-2);
                let slide = d.range(-0.2, 0.2) * depth;
                let upper_modulus = 10f64.powf(d.range(-2.0, 2.0));
                let poisson = [d.range(-0.2, 0.45), d.range(-0.2, 0.45)];
                let friction = if d.unit() < 0.5 {
                    0.0
                } else {
                    d.range(0.05, 0.6)
                };
                let kinematics = if d.unit() < 0.5 {
                    Kinematics::Small
                } else {
                    Kinematics::Finite
                };
                Press {
                    lower,
                    upper,
                    left,
                    width,
                    gap,
                    depth,
                    slide,
                    upper_modulus,
                    poisson,
                    friction,
                    kinematics,
                }
            })
            .collect()
    }

    /// Press, slide, and repeat the last totals (three increments); the first error, if any.
    pub fn run(&self) -> Result<()> {
        let mut mesh = Mesh::new();
        let lower = block(&mut mesh, [0.0, 0.0], [2.0, 1.0], self.lower, 0);
        let upper = block(
            &mut mesh,
            [self.left, 1.0 + self.gap],
            [self.width, 1.0],
            self.upper,
            1,
        );
        let row = |ids: &[usize], n: [usize; 2], j: usize| {
            ids[j * (n[0] + 1)..(j + 1) * (n[0] + 1)].to_vec()
        };
        let a = row(&upper, self.upper, 0);
        let mut b = row(&lower, self.lower, self.lower[1]);
        b.reverse();
        let top = row(&upper, self.upper, self.upper[1]);
        let n = mesh.n_nodes();
        let materials = vec![
            Material::new(1.0, self.poisson[0], 1.0, Analysis::PlaneStrain)?,
            Material::new(
                self.upper_modulus,
                self.poisson[1],
                1.0,
                Analysis::PlaneStrain,
            )?,
        ];
        let mut model = Model::new(mesh, materials, Formulation::Hybrid);
        model.fix(&row(&lower, self.lower, 0), [0.0, 0.0])?;
        model.fix(&top, [0.0, 0.0])?;
        let pair = ContactPair {
            a,
            b,
            friction: self.friction,
        };
        let options = ContactOptions {
            kinematics: self.kinematics,
            ..ContactOptions::default()
        };
        let mut analysis = ContactAnalysis::new(model, vec![pair], options)?;
        let f = vec![0.0; 2 * n];
        let totals = |slide: f64| {
            let mut qp = vec![0.0; 2 * n];
            for &node in &top {
                qp[2 * node] = slide;
                qp[2 * node + 1] = -(self.gap + self.depth);
            }
            qp
        };
        for slide in [0.0, self.slide, self.slide] {
            analysis.increment(&f, &totals(slide))?;
        }
        Ok(())
    }
}

/// A grid block from `origin` of `size` in `cells` quads into `mesh`; its node ids row by row.
fn block(
    mesh: &mut Mesh,
    origin: [f64; 2],
    size: [f64; 2],
    cells: [usize; 2],
    material: usize,
) -> Vec<usize> {
    let mut ids = Vec::new();
    for j in 0..=cells[1] {
        for i in 0..=cells[0] {
            ids.push(mesh.push_node([
                origin[0] + size[0] * i as f64 / cells[0] as f64,
                origin[1] + size[1] * j as f64 / cells[1] as f64,
            ]));
        }
    }
    let at = |i: usize, j: usize| ids[j * (cells[0] + 1) + i];
    for j in 0..cells[1] {
        for i in 0..cells[0] {
            mesh.push_element(
                &[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)],
                material,
            );
        }
    }
    ids
}

/// What happened to a set of presses: how many converged, and for the failures the error's
/// kind (with or without friction); for a node locked in slip that slid against its friction,
/// how far (over the increment's motion) by decade.
#[derive(Debug, Default)]
pub struct Outcomes {
    /// Presses whose three increments converged.
    pub converged: usize,
    /// Failed presses by error kind and friction.
    pub failed: BTreeMap<String, usize>,
    /// `SlipReversal` failures by the decade of their slide over the increment's motion.
    pub slip_reversal_decades: BTreeMap<i32, usize>,
}

/// Run every press of `presses` and count the outcomes.
pub fn outcomes(presses: &[Press]) -> Outcomes {
    let mut out = Outcomes::default();
    for press in presses {
        let Err(e) = press.run() else {
            out.converged += 1;
            continue;
        };
        if let Error::Contact(ContactError::SlipReversal { relative, .. }) = &e {
            *out.slip_reversal_decades
                .entry(relative.log10().floor() as i32)
                .or_default() += 1;
        }
        let friction = if press.friction > 0.0 {
            "with friction"
        } else {
            "frictionless"
        };
        *out.failed
            .entry(format!("{}, {friction}", kind(&e)))
            .or_default() += 1;
    }
    out
}

/// The error's variant by name (`SlipReversal`, `Singular`).
fn kind(e: &Error) -> String {
    let debug = match e {
        Error::Contact(c) => format!("{c:?}"),
        other => format!("{other:?}"),
    };
    debug
        .split(|c: char| !c.is_alphanumeric())
        .next()
        .unwrap_or_default()
        .to_string()
}
