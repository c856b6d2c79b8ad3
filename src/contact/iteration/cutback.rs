//! The automatic cutback: an increment that fails for an iteration reason is taken again in
//! sub-increments between the last converged state and the target.
//!
//! With `s` the fraction of the increment reached, a sub-increment to `s'` applies the loads
//! and prescribed values (and a plate's controls)
//!
//! ```text
//! v(s') = v_start + s' (v_target - v_start)
//! ```
//!
//! (`v(1)` is the target itself, bit for bit). A converged sub-increment is committed as the
//! start of the next one, so friction's path dependence is followed sub-increment by
//! sub-increment. A sub-increment that fails for an iteration reason is halved and tried again
//! (down to `2^-cutback_depth` of the increment and no shorter than `cutback_min_fraction`);
//! after two converged sub-increments in a row the step doubles again. `K` is never factored
//! again: an interpolated load is a combination of the start's and the target's loads, whose
//! solves are kept ([`super::loads`]), so it costs no solve.
//!
//! The host's increment stays one increment: the increment number advances once, the records
//! of the converged sub-increments carry their index
//! ([`IterationRecord::sub_increment`]), and the displacement increment spans the whole
//! step. When the cutback reaches its limit, or a sub-increment fails for a reason that a
//! shorter step cannot remove (bad input, a singular system, a callback's failure, a node
//! left uncovered, small kinematics exceeded), everything the increment changed is restored
//! and the error returned: the analysis is exactly as before the call.

use super::failure::Failure;
use super::{
    ContactAnalysis, ContactSurface, Controls, Converged, IncrementInfo, LoadSolve, NodeData,
    NodeFlexibility, OnceLock, Plate, PlateControl, Result, Settled,
};
use crate::contact::space::Vector;

/// What a failed try may change in the analysis besides timings and the caches of `K`'s
/// responses (the load solves kept, and the pairing when it is widened), taken before the
/// first try: no vector is copied (the load solves are shared, and the displacement field is
/// moved out, nothing reading it during an increment).
struct Before {
    loads: Vec<std::sync::Arc<LoadSolve>>,
    reach: Vec<f64>,
    reference: Vec<ContactSurface>,
    surfaces: Vec<ContactSurface>,
    field: OnceLock<(Vec<f64>, f64)>,
}

/// The rest of the state a converged sub-increment changes, taken when the first try failed
/// (which left it as it was).
struct Converging {
    qc: Vec<f64>,
    nodes: Vec<Vec<NodeData>>,
    converged: Option<Converged>,
    previous: Option<Converged>,
    settled: Option<Settled>,
    largest_motion: f64,
    largest_node_motion: f64,
    increment: usize,
    records: usize,
    plate: Option<Plate>,
}

/// The start and the target of an increment, interpolated.
struct Path<'a> {
    f: (Vec<f64>, &'a [f64]),
    qp: (Vec<f64>, &'a [f64]),
    /// The plate's start values per direction (its converged displacement or force, as the
    /// target controls it) and the target controls.
    control: Option<(Vector, Controls)>,
}

/// `a + s (b - a)`, exactly `b` at `s = 1`.
fn lerp(a: f64, b: f64, s: f64) -> f64 {
    if s == 1.0 { b } else { a + s * (b - a) }
}

impl Path<'_> {
    /// Loads, prescribed values and plate controls at fraction `s` of the increment.
    fn at(&self, s: f64) -> (Vec<f64>, Vec<f64>, Option<Controls>) {
        let mix = |(a, b): &(Vec<f64>, &[f64])| -> Vec<f64> {
            a.iter()
                .zip(b.iter())
                .map(|(&a, &b)| lerp(a, b, s))
                .collect()
        };
        let control = self.control.map(|(start, target)| {
            target.map(|d, c| match c {
                PlateControl::Displacement(u) => PlateControl::Displacement(lerp(start[d], u, s)),
                PlateControl::Force(f) => PlateControl::Force(lerp(start[d], f, s)),
            })
        });
        (mix(&self.f), mix(&self.qp), control)
    }
}

impl ContactAnalysis {
    fn before(&mut self) -> Before {
        Before {
            loads: self.boundary.loads.clone(),
            reach: self.surfaces.reach.clone(),
            reference: self.surfaces.reference.clone(),
            surfaces: self.surfaces.current.clone(),
            field: std::mem::take(&mut self.driver.field),
        }
    }

    fn converging(&self) -> Converging {
        Converging {
            qc: self.boundary.qc.clone(),
            nodes: self.nodes.clone(),
            converged: self.driver.converged.clone(),
            previous: self.driver.previous.clone(),
            settled: self.driver.settled.clone(),
            largest_motion: self.driver.largest_motion,
            largest_node_motion: self.driver.largest_node_motion,
            increment: self.driver.increment,
            records: self.driver.records.len(),
            plate: self.plate.clone(),
        }
    }

    /// Put back what [`before`](Self::before) took. If a try widened the pairing (small
    /// kinematics, see `widen_pairing`), the node flexibility may hold directions of the wider
    /// pairing: it is emptied, to be rebuilt as nodes close.
    fn restore_before(&mut self, b: Before) {
        if b.reach != self.surfaces.reach {
            self.boundary.node_flexibility =
                NodeFlexibility::new(self.surfaces.pairs.iter().map(|p| p.a.len()));
        }
        self.boundary.loads = b.loads;
        self.surfaces.reach = b.reach;
        self.surfaces.reference = b.reference;
        self.surfaces.current = b.surfaces;
        if let Some((_, seconds)) = self.driver.field.take() {
            self.driver.timings.recovery += seconds;
        }
        self.driver.field = b.field;
    }

    /// Keep the result of a converged increment: the field moved out by
    /// [`before`](Self::before) belongs to the state before it (its recovery time is counted,
    /// as [`finish`](Self::finish) counts it).
    fn forget_before(&mut self, b: Before) {
        if let Some((_, seconds)) = b.field.into_inner() {
            self.driver.timings.recovery += seconds;
        }
    }

    fn restore_converging(&mut self, c: Converging) {
        self.boundary.qc = c.qc;
        self.nodes = c.nodes;
        self.driver.converged = c.converged;
        self.driver.previous = c.previous;
        self.driver.settled = c.settled;
        self.driver.largest_motion = c.largest_motion;
        self.driver.largest_node_motion = c.largest_node_motion;
        self.driver.increment = c.increment;
        self.driver.records.truncate(c.records);
        self.plate = c.plate;
    }

    /// The interpolation between the last converged state and the target `(f, qp, control)`.
    fn path<'a>(&self, f: &'a [f64], qp: &'a [f64], control: Option<Controls>) -> Path<'a> {
        let (f0, qp0) = match &self.driver.converged {
            Some(c) => (c.load.clone(), c.prescribed.clone()),
            None => (vec![0.0; f.len()], vec![0.0; qp.len()]),
        };
        let control = control.map(|target| {
            let zero = Vector::zero(self.dim());
            let (u, force) = self.plate().unwrap_or((zero, zero));
            let start = target.values(|d, c| match c {
                PlateControl::Displacement(_) => u[d],
                PlateControl::Force(_) => force[d],
            });
            (start, target)
        });
        Path {
            f: (f0, f),
            qp: (qp0, qp),
            control,
        }
    }

    /// One increment to the target `(f, qp, control)` with the automatic cutback (see the
    /// module documentation): the whole step first, then halved sub-increments if it fails
    /// for an iteration reason.
    pub(super) fn cut_increment(
        &mut self,
        f: &[f64],
        qp: &[f64],
        control: Option<Controls>,
    ) -> Result<IncrementInfo> {
        self.driver.sub_increment = 1;
        let depth = self.options.cutback_depth;
        if depth == 0 {
            return self.run_increment(f, qp, control);
        }
        // the step's lengths are powers of 2: `smallest` is the shortest the limits allow
        let smallest = (0..depth)
            .map(|k| 0.5f64.powi(k as i32 + 1))
            .take_while(|&h| h >= self.options.cutback_min_fraction)
            .last()
            .unwrap_or(1.0);
        let before = self.before();
        // the whole step first: most increments end here
        let first = self.run_increment(f, qp, control);
        let cut =
            matches!(&first, Err(e) if Failure::of(e).shorter_step_may_settle() && smallest < 1.0);
        if !cut {
            match first {
                Ok(_) => self.forget_before(before),
                Err(_) => self.restore_before(before),
            }
            return first;
        }
        // the first try left the converged state as it was: keep it for a failure below
        let converging = self.converging();
        let path = self.path(f, qp, control);
        let mut info = IncrementInfo {
            increment: self.driver.increment + 1,
            iterations: 0,
            active: 0,
            slip: 0,
            sub_increments: 0,
            cutbacks: 1,
        };
        let (mut reached, mut step, mut streak) = (0.0f64, 0.5f64, 0);
        while reached < 1.0 {
            let next = if reached + step >= 1.0 {
                1.0
            } else {
                reached + step
            };
            let (f_s, mut qp_s, control_s) = path.at(next);
            if let Some(control) = control_s {
                // a force-controlled plate direction's motion is solved for, not prescribed
                self.drive_plate(&mut qp_s, control);
            }
            self.driver.sub_increment = info.sub_increments + 1;
            // every sub-increment is increment number `info.increment`
            self.driver.increment = info.increment - 1;
            match self.run_increment(&f_s, &qp_s, control_s) {
                Ok(done) => {
                    info.iterations += done.iterations;
                    info.active = done.active;
                    info.slip = done.slip;
                    info.sub_increments += 1;
                    reached = next;
                    streak += 1;
                    if streak == 2 && step < 1.0 {
                        (step, streak) = (2.0 * step, 0);
                    }
                }
                Err(e) if Failure::of(&e).shorter_step_may_settle() && step > smallest => {
                    info.cutbacks += 1;
                    (step, streak) = (0.5 * step, 0);
                }
                Err(e) => {
                    self.restore_converging(converging);
                    self.restore_before(before);
                    self.driver.sub_increment = 1;
                    return Err(e);
                }
            }
        }
        self.forget_before(before);
        // the increment spans the whole step: its displacement increment is from the start
        self.driver.previous = converging.converged;
        self.driver.increment = info.increment;
        self.driver.sub_increment = 1;
        Ok(info)
    }
}
