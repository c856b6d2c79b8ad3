//! Random two-block presses, to see how often the contact iteration fails and why: a lower
//! block `[0, 2] x [0, 1]` held at its bottom, an upper block of random width, position and
//! mesh a random gap above it, pressed down and then moved sideways through its top, the last
//! totals repeated; random moduli, Poisson's ratios, friction and kinematics, drawn from a
//! seed. Two distributions ([`Ranges`]): the narrow one of `tests/contact_properties.rs`
//! (0.6.2's bench) and the wide one of 0.7.0 (friction 0.05 to 1, modulus ratios 1e-4 to 1e4,
//! meshes up to 32 elements a side). Every press runs with hycon's rules (fallback and
//! cutback) and with the paper's alone (`ContactAnalysis::set_fallback(false)`), and each
//! failure is classified against a reference run of the same problem in many small
//! sub-increments.

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, ContactPair, Kinematics};
use hycon::element::Formulation;
use hycon::error::{Error, Result};
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

/// Which problems [`Press::draw`] draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ranges {
    /// The ranges of `tests/contact_properties.rs` and 0.6.2's bench: meshes of 2-6 x 1-3
    /// (lower) and 1-4 x 1-3 (upper) elements, friction 0.05 to 0.6 (half of the presses
    /// frictionless), modulus ratios 1e-2 to 1e2; the generator seeded with `seed | 1` (so
    /// seeds 2 and 3 draw the same presses, as in 0.6.2).
    Narrow,
    /// 0.7.0's: meshes of 2-32 x 1-8 (lower) and 1-24 x 1-8 (upper) elements (the counts
    /// across log-uniform), friction 0.05 to 1 (half frictionless), modulus ratios 1e-4 to
    /// 1e4, the generator seeded through splitmix64 (every seed its own presses).
    Wide,
}

impl std::str::FromStr for Ranges {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "narrow" => Ok(Ranges::Narrow),
            "wide" => Ok(Ranges::Wide),
            _ => Err(format!("unknown ranges {s:?} (narrow or wide)")),
        }
    }
}

/// splitmix64's output function: distinct seeds, distinct well-mixed states.
fn splitmix(seed: u64) -> u64 {
    let mut z = seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
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

    /// An integer in `lo..=hi`, log-uniform (`lo >= 1`).
    fn log_int(&mut self, lo: usize, hi: usize) -> usize {
        let (a, b) = ((lo as f64).ln(), ((hi + 1) as f64).ln());
        (self.range(a, b).exp() as usize).clamp(lo, hi)
    }
}

impl Press {
    /// The `count` presses of `seed` with the narrow ranges of `tests/contact_properties.rs`.
    pub fn draw(count: usize, seed: u64) -> Vec<Press> {
        Self::draw_from(Ranges::Narrow, count, seed)
    }

    /// The `count` presses of `seed` with `ranges`.
    pub fn draw_from(ranges: Ranges, count: usize, seed: u64) -> Vec<Press> {
        let wide = ranges == Ranges::Wide;
        let mut d = Draws(if wide { splitmix(seed) | 1 } else { seed | 1 });
        (0..count)
            .map(|_| {
                let (lower, upper) = if wide {
                    (
                        [d.log_int(2, 32), d.int(1, 8)],
                        [d.log_int(1, 24), d.int(1, 8)],
                    )
                } else {
                    ([d.int(1, 5) + 1, d.int(1, 3)], [d.int(1, 4), d.int(1, 3)])
                };
                let (left, width) = (d.range(0.1, 0.8), d.range(0.4, 1.0));
                let gap = d.range(0.0, 1e-3);
                let depth = d.range(1e-4, 1e-2);
                let slide = d.range(-0.2, 0.2) * depth;
                let decades = if wide { 4.0 } else { 2.0 };
                let upper_modulus = 10f64.powf(d.range(-decades, decades));
                let poisson = [d.range(-0.2, 0.45), d.range(-0.2, 0.45)];
                let friction = if d.unit() < 0.5 {
                    0.0
                } else {
                    d.range(0.05, if wide { 1.0 } else { 0.6 })
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
        self.run_with(ContactOptions::default()).map(drop)
    }

    /// [`run`](Self::run) with `options` (the kinematics are the press's); the analysis after
    /// its three increments.
    pub fn run_with(&self, options: ContactOptions) -> Result<ContactAnalysis> {
        self.run_in(options, true, 1)
    }

    /// The press in `steps` increments per phase (press, slide; then the last totals again),
    /// with the fallback on or off (`ContactAnalysis::set_fallback`).
    pub fn run_in(
        &self,
        options: ContactOptions,
        fallback: bool,
        steps: usize,
    ) -> Result<ContactAnalysis> {
        let (mut analysis, top) = self.analysis(options)?;
        analysis.set_fallback(fallback);
        let steps = steps.max(1);
        let fraction = |i: usize| i as f64 / steps as f64;
        let path = (1..=steps)
            .map(|i| (fraction(i), 0.0))
            .chain((1..=steps).map(|i| (1.0, fraction(i) * self.slide)))
            .chain([(1.0, self.slide)]);
        for (press, slide) in path {
            let (f, qp) = self.totals_at(&analysis, &top, press, slide);
            analysis.increment(&f, &qp)?;
        }
        Ok(analysis)
    }

    /// The press's analysis (before any increment) with `options` (the kinematics are the
    /// press's), and the upper block's top nodes.
    pub fn analysis(&self, options: ContactOptions) -> Result<(ContactAnalysis, Vec<usize>)> {
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
            ..options
        };
        Ok((ContactAnalysis::new(model, vec![pair], options)?, top))
    }

    /// The loads `(f, qp)` of the increment that presses the top down by the gap and the depth
    /// and moves it sideways by `slide` (totals).
    pub fn totals(&self, analysis: &ContactAnalysis, top: &[usize], slide: f64) -> Totals {
        self.totals_at(analysis, top, 1.0, slide)
    }

    /// [`totals`](Self::totals) with the top pressed by `press` times the gap and the depth.
    fn totals_at(
        &self,
        analysis: &ContactAnalysis,
        top: &[usize],
        press: f64,
        slide: f64,
    ) -> Totals {
        let n = analysis.field_len();
        let mut qp = vec![0.0; n];
        for &node in top {
            qp[2 * node] = slide;
            qp[2 * node + 1] = -press * (self.gap + self.depth);
        }
        (vec![0.0; n], qp)
    }
}

/// External forces and prescribed values of one increment (both over all dofs).
pub type Totals = (Vec<f64>, Vec<f64>);

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

/// Sub-increments per phase of the reference run that classifies a failure.
pub const REFERENCE_STEPS: usize = 50;

/// The options of the reference run: the defaults with the slip tolerance divided by
/// [`REFERENCE_STEPS`]. A slide against friction is a path quantity: each of the reference's
/// steps accepts one below the tolerance, and with the default tolerance in every step the
/// reference would accept `REFERENCE_STEPS` times what one increment may slide against its
/// friction. Seed 1's presses 1599 and 2474 (`--count 20000`, a stiff A with friction)
/// "settled" in the reference only that way: with this tolerance they fail there too, as they
/// do in one increment.
pub fn reference_options() -> ContactOptions {
    let defaults = ContactOptions::default();
    ContactOptions {
        slip_tolerance: defaults.slip_tolerance / REFERENCE_STEPS as f64,
        ..defaults
    }
}

/// What happened to a set of presses with hycon's rules (`new`: fallback and cutback) and
/// with the paper's alone (`paper`).
#[derive(Debug, Default)]
pub struct Outcomes {
    /// Presses.
    pub count: usize,
    /// Presses whose three increments converged, with the new rules.
    pub converged: usize,
    /// Failed presses by error kind and friction, with the new rules; each failure's class
    /// says whether the reference run in [`REFERENCE_STEPS`] sub-increments per phase settles
    /// ("the reference settles": a failure the rules must not have) or fails too (with its
    /// error kind: a problem without an answer that the increments can reach).
    pub failed: BTreeMap<String, usize>,
    /// The indices (from 0, in draw order) of the failed presses the reference settles.
    pub reference_settles: Vec<usize>,
    /// The same with the paper's rules alone, without the fallback and the cutback, as in 0.6.2
    /// (no reference run).
    pub paper_failed: BTreeMap<String, usize>,
    /// Presses converged with the paper's rules alone.
    pub paper_converged: usize,
    /// Presses that converged only through the fallback (in at least one increment).
    pub by_fallback: usize,
    /// Presses whose increments the automatic cutback split (in at least one increment).
    pub by_cutback: usize,
    /// Converged presses whose largest condition violation at convergence exceeds
    /// `CONDITION_LIMIT` (must be none: the core fails such an increment).
    pub violating: usize,
    /// The largest condition violation at convergence over the converged presses.
    pub worst_violation: f64,
    /// Over the presses that converged both ways: count, iterations with the new rules and
    /// with the paper's, seconds with each.
    pub both: usize,
    /// Iterations (new rules, paper's rules) over the presses converged both ways.
    pub iterations: [usize; 2],
    /// Seconds (new rules, paper's rules) over the presses converged both ways.
    pub seconds: [f64; 2],
    /// Iterations and seconds of the presses converged only with the new rules.
    pub rescued: (usize, usize, f64),
    /// Seconds of the failed presses with the new rules (the cutback's tries included).
    pub failed_seconds: f64,
    /// One line per press, in the order run: what `hycon bench presses --list` writes.
    pub listing: Vec<PressLine>,
}

/// How one press ended, both ways: the line `hycon bench presses --list` writes for it, to
/// compare two versions press by press.
#[derive(Debug, Clone, PartialEq)]
pub struct PressLine {
    /// The press's index in its draw (from 0).
    pub index: usize,
    /// Its outcome class with hycon's rules: `converged` (with `fallback` or `cutback` when
    /// they were needed) or the failure's class as [`Outcomes::failed`] counts it.
    pub outcome: String,
    /// Iterations with hycon's rules (records of the converged analysis; none when failed).
    pub iterations: Option<usize>,
    /// Its outcome with the paper's rules alone: `converged` or the error's kind.
    pub paper: String,
    /// Iterations with the paper's rules alone.
    pub paper_iterations: Option<usize>,
}

impl std::fmt::Display for PressLine {
    /// `index<TAB>outcome<TAB>iterations<TAB>paper<TAB>paper iterations` (`-` for none).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let count = |n: Option<usize>| n.map_or("-".to_string(), |n| n.to_string());
        write!(
            f,
            "{}\t{}\t{}\t{}\t{}",
            self.index,
            self.outcome,
            count(self.iterations),
            self.paper,
            count(self.paper_iterations)
        )
    }
}

/// The largest condition violation at convergence (the last record of each increment).
pub fn converged_violation(analysis: &ContactAnalysis) -> f64 {
    let records = analysis.records();
    records
        .iter()
        .enumerate()
        .filter(|(i, r)| {
            records
                .get(i + 1)
                .is_none_or(|n| n.increment != r.increment)
        })
        .map(|(_, r)| r.violation)
        .fold(0.0, f64::max)
}

/// Run every press of `presses` (each with its index in its draw) both ways and count the
/// outcomes; classify each failure of the new rules against the reference run.
pub fn outcomes(presses: &[(usize, Press)]) -> Outcomes {
    let mut out = Outcomes {
        count: presses.len(),
        ..Outcomes::default()
    };
    let friction = |p: &Press| {
        if p.friction > 0.0 {
            "with friction"
        } else {
            "frictionless"
        }
    };
    for (index, press) in presses.iter().map(|(i, p)| (*i, p)) {
        // hycon: the fallback and the automatic cutback on (the defaults); the paper's rules
        // alone: both off, as in 0.6.2
        let timed = |fallback: bool| {
            let options = ContactOptions {
                cutback_depth: if fallback {
                    ContactOptions::default().cutback_depth
                } else {
                    0
                },
                ..ContactOptions::default()
            };
            let clock = std::time::Instant::now();
            let r = press.run_in(options, fallback, 1);
            (r, clock.elapsed().as_secs_f64())
        };
        let (new, new_seconds) = timed(true);
        let (paper, paper_seconds) = timed(false);
        let paper_line = match &paper {
            Ok(_) => {
                out.paper_converged += 1;
                "converged".to_string()
            }
            Err(e) => {
                let class = format!("{}, {}", kind(e), friction(press));
                *out.paper_failed.entry(class.clone()).or_default() += 1;
                class
            }
        };
        let paper_iterations = paper.as_ref().ok().map(|b| b.records().len());
        match (&new, &paper) {
            (Ok(a), Ok(b)) => {
                out.both += 1;
                out.iterations[0] += a.records().len();
                out.iterations[1] += b.records().len();
                out.seconds[0] += new_seconds;
                out.seconds[1] += paper_seconds;
            }
            (Ok(a), Err(_)) => {
                out.rescued.0 += 1;
                out.rescued.1 += a.records().len();
                out.rescued.2 += new_seconds;
            }
            _ => {}
        }
        let (outcome, iterations) = match new {
            Ok(a) => {
                out.converged += 1;
                let fallback = a.fallbacks() > 0;
                let cutback = a.records().iter().any(|r| r.sub_increment > 1);
                out.by_fallback += usize::from(fallback);
                out.by_cutback += usize::from(cutback);
                let v = converged_violation(&a);
                out.worst_violation = out.worst_violation.max(v);
                out.violating += usize::from(v > hycon::contact::iteration::CONDITION_LIMIT);
                let mut outcome = "converged".to_string();
                for (used, name) in [(fallback, "fallback"), (cutback, "cutback")] {
                    if used {
                        outcome.push_str(&format!(", {name}"));
                    }
                }
                (outcome, Some(a.records().len()))
            }
            Err(e) => {
                out.failed_seconds += new_seconds;
                let class = match press.run_in(reference_options(), true, REFERENCE_STEPS) {
                    Ok(_) => {
                        out.reference_settles.push(index);
                        "the reference settles".to_string()
                    }
                    Err(r) => format!("the reference fails too ({})", kind(&r)),
                };
                let class = format!("{}, {}: {class}", kind(&e), friction(press));
                *out.failed.entry(class.clone()).or_default() += 1;
                (class, None)
            }
        };
        out.listing.push(PressLine {
            index,
            outcome,
            iterations,
            paper: paper_line,
            paper_iterations,
        });
    }
    out
}

/// The error's variant by name (`SlipReversal`, `Singular`), with the condition of a
/// `ConditionViolated`.
fn kind(e: &Error) -> String {
    if let Error::Contact(hycon::ContactError::ConditionViolated { condition, .. }) = e {
        return format!("ConditionViolated ({condition})");
    }
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
