//! The increment driver: one increment from `ContactAnalysis::increment` to its converged
//! state, with what it keeps between increments ([`Driver`]).
//!
//! `increment` hands the step to the cutback ([`ContactAnalysis::cut_increment`]), which runs
//! it whole ([`ContactAnalysis::run_increment`]: the load solve, the start states, the
//! iteration, and the fallback's restarts) and, if that fails for a reason a shorter step may
//! remove ([`Failure`]), in sub-increments. [`ContactAnalysis::iterate`] is the contact
//! iteration of one attempt: per iteration the boundary algebra's solve (`boundary.rs`), the
//! contact geometry at the new iterate (`surfaces.rs`), the measures of the iterate
//! (`checks.rs`) and the active set's decisions (`active_set/`).
//!
//! # The cutback
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

use super::active_set::{ActiveSet, BNodes, Commit, Convergence, Iterate, Locks, count};
use super::boundary::{self, Solution};
use super::checks::{self, change_ratio};
use super::export::IncrementStart;
use super::fallback::Linearization;
use super::plate::{Border, Controls, Plate, plate_force};
use super::small_system::SmallSystem;
use super::surfaces::Pairing;
use super::{
    CONDITION_LIMIT, ContactAnalysis, ContactSurface, IncrementInfo, IterationRecord, Kinematics,
    Monitor, NodeData, NodeState, PlateControl, Timings, Traction, loads,
};
use crate::contact::space::Vector;
use crate::error::{ContactError, Error, Result};
use std::sync::{Mutex, OnceLock, PoisonError};

/// The increment driver's data: the increment counters, the records and timings, the
/// monitor, the fallback's switch and count, and what the last converged increments settled
/// and converged with.
pub(super) struct Driver {
    /// The last converged increment's number.
    pub(super) increment: usize,
    /// The sub-increment the iteration runs in (see [`IterationRecord::sub_increment`]).
    pub(super) sub_increment: usize,
    pub(super) records: Vec<IterationRecord>,
    pub(super) timings: Timings,
    /// Behind a lock only so that the analysis is `Sync` (a `Monitor` is `Send`, not `Sync`):
    /// it is only called from `&mut self`.
    pub(super) monitor: Mutex<Option<Monitor>>,
    /// Start a failed increment again from the fallback's states (`fallback.rs`; on unless a
    /// benchmark turns it off, see `ContactAnalysis::set_fallback`).
    pub(super) fallback: bool,
    /// Increments that converged from the fallback's states.
    pub(super) fallbacks: usize,
    /// What the last converged increment without a plate settled with.
    pub(super) settled: Option<Settled>,
    /// The largest `|q_c|` change of a converged increment so far (0 before the first): the
    /// scale to which the state is known (see `ContactAnalysis::resolution`).
    pub(super) largest_motion: f64,
    /// The largest motion of one contact node (the length of its displacement change) in a
    /// converged increment so far (see `motion_scale`).
    pub(super) largest_node_motion: f64,
    /// Loads and contact forces of the last converged increment, for the full field.
    pub(super) converged: Option<Converged>,
    /// The same for the increment before it (for displacement increments).
    pub(super) previous: Option<Converged>,
    /// The full displacement field of the last converged increment, once asked for, with the
    /// seconds its recovery took (set from `&self` queries; taken when an increment converges).
    pub(super) field: OnceLock<(Vec<f64>, f64)>,
    /// Seconds of displacement recoveries not kept in `field` (displacement increments).
    pub(super) recovery: Mutex<f64>,
    /// Where the last increment converged from, for its local problem (`export.rs`); `None`
    /// before the first increment and after a failed one.
    pub(super) linearized: Option<IncrementStart>,
}

impl Driver {
    /// Before the first increment, with the constructor's `timings`.
    pub(super) fn new(timings: Timings) -> Self {
        Driver {
            increment: 0,
            sub_increment: 1,
            records: Vec::new(),
            timings,
            monitor: Mutex::new(None),
            fallback: true,
            fallbacks: 0,
            settled: None,
            largest_motion: 0.0,
            largest_node_motion: 0.0,
            converged: None,
            previous: None,
            field: OnceLock::new(),
            recovery: Mutex::new(0.0),
            linearized: None,
        }
    }

    /// Show `record` to the monitor, if there is one: whether the iteration goes on.
    pub(super) fn watch(&mut self, record: &IterationRecord) -> bool {
        let monitor = self.monitor.get_mut();
        monitor
            .unwrap_or_else(PoisonError::into_inner)
            .as_mut()
            .is_none_or(|m| m(record))
    }

    /// What a converged increment changes of the driver (the cutback's snapshot).
    fn reached(&self) -> Reached {
        Reached {
            converged: self.converged.clone(),
            previous: self.previous.clone(),
            settled: self.settled.clone(),
            largest_motion: self.largest_motion,
            largest_node_motion: self.largest_node_motion,
            increment: self.increment,
            records: self.records.len(),
        }
    }

    /// Put back what [`reached`](Self::reached) took.
    fn restore(&mut self, r: Reached) {
        self.converged = r.converged;
        self.previous = r.previous;
        self.settled = r.settled;
        self.largest_motion = r.largest_motion;
        self.largest_node_motion = r.largest_node_motion;
        self.increment = r.increment;
        self.records.truncate(r.records);
    }

    /// Count the recovery time of a displacement field that is dropped.
    fn count_recovery(&mut self, field: OnceLock<(Vec<f64>, f64)>) {
        if let Some((_, seconds)) = field.into_inner() {
            self.timings.recovery += seconds;
        }
    }

    /// Put back the displacement field `field`, counting the recovery of the one it replaces.
    fn restore_field(&mut self, field: OnceLock<(Vec<f64>, f64)>) {
        let replaced = std::mem::replace(&mut self.field, field);
        self.count_recovery(replaced);
    }
}

/// What a converged increment changes of the [`Driver`].
struct Reached {
    converged: Option<Converged>,
    previous: Option<Converged>,
    settled: Option<Settled>,
    largest_motion: f64,
    largest_node_motion: f64,
    increment: usize,
    records: usize,
}

/// What a converged increment without a plate settled with: its load (`f` and `q_p` at the
/// prescribed dofs), the locks of its contact set, and how its rules judged B nodes
/// penetrating open segments (at convergence only in the fallback's last attempt, see
/// [`BNodes`]).
#[derive(Clone)]
pub(super) struct Settled {
    pub(super) load: Vec<f64>,
    pub(super) locks: Locks,
    pub(super) b_nodes: BNodes,
}

/// What the full field of a converged increment is recovered from.
#[derive(Debug, Clone)]
pub(super) struct Converged {
    /// External loads over the field.
    pub(super) load: Vec<f64>,
    /// Prescribed values (empty for a host).
    pub(super) prescribed: Vec<f64>,
    /// Contact forces at the contact dofs (`dofs` order).
    pub(super) contact: Vec<f64>,
}

/// What one increment's iteration starts from: its loads and their solve, the start state.
pub(super) struct Attempt<'a> {
    number: usize,
    f: &'a [f64],
    qp: &'a [f64],
    control: Option<Controls>,
    /// The load solve at the contact dofs.
    pub(super) u0c: &'a [f64],
    pub(super) border: Option<&'a Border>,
    force0: Vector,
    /// The load (`f` and `q_p`) the increment's locks are kept with.
    load: &'a [f64],
    /// The converged displacement of the contact dofs the increment starts from.
    pub(super) startc: Vec<f64>,
    resolution: f64,
    clock: std::time::Instant,
    flexibility_before: f64,
}

/// How an iteration proposes the next states from an iterate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Proposer {
    /// The paper's rules (`active_set/rules.rs`) from the iterate's tractions and slips.
    Rules,
    /// The states of the solution of the contact conditions linearized at the iterate (its
    /// geometry, its gaps), over the nodes closed or penetrating there and their neighbours,
    /// solved exactly by the fallback's semi-smooth Newton method (`fallback.rs`): a slip
    /// node's direction is its trial traction's at every iterate, never kept from an earlier
    /// one. The iteration is then a fixed point of the geometry alone (docs/method.md, "The
    /// fallback"); B nodes are judged at convergence.
    Linearized,
}

/// What may settle an increment that failed with an error.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Failure {
    /// The rules did not settle: the iteration cap, a cycling contact set, a node locked in
    /// slip sliding against its friction, a node locked open penetrating, a converged state
    /// violating the contact conditions. The fallback's states may settle it, and a shorter
    /// step may.
    Unsettled,
    /// The step reaches beyond what the geometry resolves: a node beyond the pairing's reach,
    /// positions the geometry cannot resolve. A shorter step may settle it; the fallback's
    /// states (of the same geometry) cannot.
    TooLong,
    /// Nothing the iteration may retry: bad input, a singular system, non-finite values, a
    /// node left uncovered, small kinematics exceeded, a host's or monitor's failure.
    Final,
}

impl Failure {
    /// The class of `e`.
    pub(super) fn of(e: &Error) -> Self {
        match e {
            Error::Contact(
                ContactError::NoConvergence { .. }
                | ContactError::Cycling { .. }
                | ContactError::SlipReversal { .. }
                | ContactError::EdgePenetration { .. }
                | ContactError::ConditionViolated { .. },
            ) => Failure::Unsettled,
            Error::Contact(
                ContactError::BeyondSearchDistance { .. } | ContactError::Unresolved { .. },
            ) => Failure::TooLong,
            _ => Failure::Final,
        }
    }

    /// Whether the increment is tried again from the fallback's states.
    pub(super) fn fallback_may_settle(self) -> bool {
        self == Failure::Unsettled
    }

    /// Whether the cutback tries a shorter step.
    pub(super) fn shorter_step_may_settle(self) -> bool {
        self != Failure::Final
    }
}

/// What a failed try may change in the analysis besides timings and the caches of `K`'s
/// responses, and what a converged sub-increment changes of the boundary algebra, taken before
/// the first try: each part's own snapshot (the boundary algebra's load solves kept and
/// converged contact displacement, the pairing, widened by a try), and the displacement field,
/// moved out (nothing reads it during an increment).
struct Before {
    boundary: boundary::Snapshot,
    pairing: Pairing,
    field: OnceLock<(Vec<f64>, f64)>,
}

/// The rest of the state a converged sub-increment changes, taken when the first try failed
/// (which left it as it was): the node data, the driver's, the plate.
struct Converging {
    nodes: Vec<Vec<NodeData>>,
    driver: Reached,
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
            boundary: self.boundary.snapshot(),
            pairing: self.surfaces.pairing(),
            field: std::mem::take(&mut self.driver.field),
        }
    }

    fn converging(&self) -> Converging {
        Converging {
            nodes: self.nodes.clone(),
            driver: self.driver.reached(),
            plate: self.plate.clone(),
        }
    }

    /// Put back what [`before`](Self::before) took. If a try widened the pairing (small
    /// kinematics, see `Surfaces::widen`), the node flexibility may hold directions of the wider
    /// pairing: it is emptied, to be rebuilt as nodes close.
    fn restore_before(&mut self, b: Before) {
        if self.surfaces.restore_pairing(b.pairing) {
            self.boundary.forget_directions();
        }
        self.boundary.restore(b.boundary);
        self.driver.restore_field(b.field);
    }

    /// Keep the result of a converged increment: the field moved out by
    /// [`before`](Self::before) belongs to the state before it (its recovery time is counted,
    /// as [`finish`](Self::finish) counts it).
    fn forget_before(&mut self, b: Before) {
        self.driver.count_recovery(b.field);
    }

    fn restore_converging(&mut self, c: Converging) {
        self.nodes = c.nodes;
        self.driver.restore(c.driver);
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
        self.driver.previous = converging.driver.converged;
        self.driver.increment = info.increment;
        self.driver.sub_increment = 1;
        Ok(info)
    }
}

impl ContactAnalysis {
    /// Apply one load increment: total external forces `f` and total prescribed displacement
    /// values `qp` (both over all dofs; `qp` read at the prescribed dofs). On success the
    /// converged state advances; on failure it is left as it was and the error says why.
    pub fn increment(&mut self, f: &[f64], qp: &[f64]) -> Result<IncrementInfo> {
        if self.plate.is_some() {
            return Err(Error::InvalidInput(
                "this analysis has a rigid plate: use increment_with_plate".into(),
            ));
        }
        self.cut_increment(f, qp, None)
    }

    /// Whether an increment that the paper's rules do not settle starts again from the states
    /// of the solution of its linearized conditions (`fallback.rs`; on by default). Off, the
    /// iteration is the paper's alone, as before 0.7.0: a benchmark's control (`hycon bench
    /// presses` compares the two), not an option.
    pub fn set_fallback(&mut self, on: bool) {
        self.driver.fallback = on;
    }

    /// How many increments so far converged only from the fallback's states (see
    /// [`set_fallback`](Self::set_fallback)).
    pub fn fallbacks(&self) -> usize {
        self.driver.fallbacks
    }

    /// Call `monitor` with every iteration record from now on, also those of the tries the
    /// automatic cutback halves (see [`IterationRecord::sub_increment`]; `None` removes it).
    /// When it returns `false` the increment stops with [`Error::Callback`] (not retried) and
    /// the last converged state is kept.
    pub fn set_monitor(&mut self, monitor: Option<Monitor>) {
        *self
            .driver
            .monitor
            .get_mut()
            .unwrap_or_else(PoisonError::into_inner) = monitor;
    }

    fn run_increment(
        &mut self,
        f: &[f64],
        qp: &[f64],
        control: Option<Controls>,
    ) -> Result<IncrementInfo> {
        let number = self.driver.increment + 1;
        self.driver.linearized = None;
        let loads::Solved {
            u0c,
            plate_force: force0,
            load,
        } = {
            let (bodies, plate, dim) = (&*self.bodies, &self.plate, self.dim());
            let force = |u0: &[f64]| match plate {
                Some(p) => plate_force(bodies, &p.nodes, u0, f),
                None => Ok(Vector::zero(dim)),
            };
            self.boundary.load_solve(bodies, (f, qp), number, force)?
        };
        finite(&u0c, number, 0)?;
        let border = control.and_then(|c| self.border(c, force0));
        let mut states: Vec<Vec<NodeState>> = self
            .nodes
            .iter()
            .map(|v| v.iter().map(|d| d.state).collect())
            .collect();
        if border.is_some() && states.iter().flatten().all(|s| *s == NodeState::Open) {
            // a force-controlled body needs a support to start from: the nearest node
            self.close_nearest(&self.surfaces.current, &mut states);
        }
        // the same totals again: resume with the last increment's locks and its way of
        // judging B nodes, so that a contact set it settled by locking or in the fallback's
        // last attempt settles at once on the same state
        let (locks, b_nodes) = match (&self.driver.settled, control) {
            (Some(last), None) if last.load == load => (last.locks.clone(), last.b_nodes),
            _ => (Locks::default(), BNodes::Pointwise),
        };
        let attempt = Attempt {
            number,
            f,
            qp,
            control,
            u0c: &u0c,
            border: border.as_ref(),
            force0,
            load: &load,
            startc: self.boundary.qc.clone(),
            resolution: self.resolution(),
            clock: std::time::Instant::now(),
            // columns of a lazy F built during the iteration count as flexibility
            flexibility_before: self.boundary.flexibility_seconds,
        };
        let mut records = Vec::new();
        let proposer = self.first_proposer();
        let b_nodes = match proposer {
            Proposer::Rules => b_nodes,
            Proposer::Linearized => BNodes::AtConvergence,
        };
        let first = self.iterate(&attempt, states, locks, b_nodes, proposer, &mut records);
        match first {
            Err(e)
                if self.driver.fallback
                    && (border.is_none() || self.dim() == 3)
                    && proposer == Proposer::Rules
                    && Failure::of(&e).fallback_may_settle() =>
            {
                // the paper's rules did not settle: start again from the states of the
                // solution of the linearized conditions (fallback.rs), first with the
                // paper's rules from those states, then with B nodes checked pointwise only at
                // convergence (`BNodes::AtConvergence`)
                let states = self.fallback_states(&attempt).map_err(|_| e.clone())?;
                let info = if self.dim() == 3 {
                    // on a face the slip directions turn with the geometry: the linearized
                    // conditions propose the states at every iterate
                    self.iterate(
                        &attempt,
                        states,
                        Locks::default(),
                        BNodes::AtConvergence,
                        Proposer::Linearized,
                        &mut records,
                    )
                } else {
                    self.iterate(
                        &attempt,
                        states.clone(),
                        Locks::default(),
                        BNodes::Pointwise,
                        Proposer::Rules,
                        &mut records,
                    )
                    .or_else(|_| {
                        self.iterate(
                            &attempt,
                            states,
                            Locks::default(),
                            BNodes::AtConvergence,
                            Proposer::Rules,
                            &mut records,
                        )
                    })
                };
                // a state that settled but breaks a condition says more than the rules' failure
                let info = info.map_err(|last| match last {
                    Error::Contact(ContactError::ConditionViolated { .. }) => last,
                    _ => e,
                })?;
                self.driver.fallbacks += 1;
                Ok(info)
            }
            other => other,
        }
    }

    /// How an increment's iteration proposes states first (docs/method.md, "The solver
    /// order"): on faces (3D) with friction, the linearized conditions
    /// ([`Proposer::Linearized`], bordered by a force-controlled plate's translations); the
    /// paper's rules otherwise. On a face the rules' slip directions follow the slip from
    /// iterate to iterate, a fixed point that under finite kinematics does not settle while
    /// the geometry follows the iterate (the block pressed on the flat of
    /// `hycon_lab::slide3d`: 60 iterations, `R` still 0.05 to 0.4), and that takes 23 to 62
    /// iterations where it settles; the linearized conditions settle the same presses in 3 or
    /// 4 (measured in docs/method.md).
    fn first_proposer(&self) -> Proposer {
        let friction = (self.surfaces.laws.iter()).any(|law| !law.is_frictionless());
        if self.dim() == 3 && friction {
            Proposer::Linearized
        } else {
            Proposer::Rules
        }
    }

    /// The iteration of one increment from `states` and `locks` (module docs), its records
    /// appended to `records`; on convergence the state advances.
    fn iterate(
        &mut self,
        attempt: &Attempt<'_>,
        states: Vec<Vec<NodeState>>,
        locks: Locks,
        b_nodes: BNodes,
        proposer: Proposer,
        records: &mut Vec<IterationRecord>,
    ) -> Result<IncrementInfo> {
        let Attempt {
            number,
            f,
            qp,
            control,
            u0c,
            border,
            force0,
            load,
            ref startc,
            resolution,
            clock,
            flexibility_before,
        } = *attempt;
        // iterate on the contact dofs only; geometry from the start configuration
        let mut uc = startc.clone();
        let mut surfaces = self.surfaces.current.clone();
        let mut set = ActiveSet::new(states, locks, self.options.lock_rounds).judging(b_nodes);
        let convergence = Convergence::new(self.options.tolerance);
        let first_record = records.len();
        // time of the refactor-every-iteration variant (feature `oracles`), counted as
        // factorization
        #[allow(unused_mut)]
        let mut refactoring = 0.0;
        let mut last: Option<(SmallSystem, Solution)> = None;
        for step in 1..=self.options.max_iterations {
            // iterations are counted over the increment's attempts
            let iteration = first_record + step;
            #[cfg(feature = "oracles")]
            if self.boundary.refactor_each_iteration && step > 1 {
                refactoring += self.refactor()?;
            }
            let states = set.states();
            let laws = &self.surfaces.laws;
            let system = (self.boundary).build_system(&surfaces, laws, states, &uc, startc);
            // the contact set settled and R measured the last change: the same system again,
            // whose solution is the last one to the bit (no factorization, no substitution)
            let solution = match last.take() {
                Some((previous, solution)) if previous == system => solution,
                _ => self.boundary.solve_iteration(
                    &mut *self.bodies,
                    &self.surfaces,
                    &system,
                    u0c,
                    border,
                )?,
            };
            let (tau, plate_motion, condition, uc_new) = solution.clone();
            let forces = system.forces(&tau, self.boundary.dofs.len());
            finite(&uc_new, number, iteration)?;
            self.surfaces
                .widen(&uc_new, &mut surfaces, &*self.bodies, &mut self.boundary)?;
            let motion = checks::largest_node_motion(&uc_new, startc, self.dim());
            self.surfaces.update(
                &mut surfaces,
                &*self.bodies,
                &self.boundary,
                &uc_new,
                (number, motion),
            )?;
            let tractions = system.tractions(&tau, &surfaces, states, &self.surfaces.laws);
            let proposed = match proposer {
                Proposer::Rules => {
                    self.update_states(&set, &tractions, &surfaces, &uc_new, startc)?
                }
                Proposer::Linearized => {
                    let at = Linearization {
                        uc: &uc_new,
                        probe: &uc_new,
                        startc,
                        u0c,
                        border,
                    };
                    self.linearized_states(&surfaces, states, at)?
                }
            };
            let changes = set.changes(&proposed);
            let r = change_ratio(&uc_new, &uc, startc, resolution, self.options.tolerance);
            if !r.is_finite() {
                return Err(ContactError::NonFinite {
                    increment: number,
                    iteration,
                }
                .into());
            }
            let violation = self.violation(
                &surfaces,
                states,
                &tractions,
                set.b_nodes(),
                &uc_new,
                startc,
            );
            let (active, stick, slip) = set.count();
            let record = IterationRecord {
                increment: number,
                iteration,
                active,
                stick,
                slip,
                changes,
                r,
                condition,
                violation: violation.relative,
                sub_increment: self.driver.sub_increment,
            };
            records.push(record);
            if !self.driver.watch(&record) {
                return Err(Error::Callback(format!(
                    "increment {number}: the monitor stopped the iteration at iteration \
                     {iteration}"
                )));
            }
            uc = uc_new;
            let iterate = Iterate {
                changes,
                r,
                residual: None,
            };
            if convergence.reached(&iterate) {
                let states = set.states();
                self.uncovered(&surfaces, states)?;
                self.passed_through(&surfaces, states, &uc, startc)?;
                self.locks_hold(number, &surfaces, &set, &uc, startc)?;
                self.small_sliding(number, states, &uc)?;
                if violation.relative > CONDITION_LIMIT {
                    return Err(ContactError::ConditionViolated {
                        increment: number,
                        node: self.external_a(violation.node),
                        condition: violation.condition,
                        relative: violation.relative,
                    }
                    .into());
                }
                self.driver.timings.factorization += refactoring;
                self.driver.timings.iterations += clock.elapsed().as_secs_f64()
                    - refactoring
                    - (self.boundary.flexibility_seconds - flexibility_before);
                let mut prescribed = qp.to_vec();
                if let (Some(plate), Some(control)) = (&mut self.plate, control) {
                    let directions = border.map_or(&[][..], |b| &b.directions[..]);
                    plate.settle(
                        control,
                        (directions, &plate_motion),
                        force0,
                        &forces,
                        &mut prescribed,
                    );
                }
                let converged = Converged {
                    load: f.to_vec(),
                    prescribed,
                    contact: forces,
                };
                self.driver.linearized = Some(IncrementStart {
                    startc: startc.clone(),
                    u0c: u0c.to_vec(),
                    border: border.cloned(),
                });
                self.driver.settled = control.is_none().then(|| Settled {
                    load: load.to_vec(),
                    locks: set.locks().clone(),
                    b_nodes: set.b_nodes(),
                });
                return Ok(self.finish(
                    number,
                    iteration,
                    set.states(),
                    &tractions,
                    uc,
                    surfaces,
                    converged,
                    std::mem::take(records),
                ));
            }
            last = Some((system, solution));
            if let Commit::Cycle { returns_to, node } = set.commit(proposed) {
                return Err(ContactError::Cycling {
                    increment: number,
                    iteration,
                    returns_to,
                    node: self.external_a(node),
                }
                .into());
            }
        }
        Err(ContactError::NoConvergence {
            increment: number,
            iterations: records.len(),
            last_r: records.last().map_or(f64::NAN, |r: &IterationRecord| r.r),
        }
        .into())
    }
}

impl ContactAnalysis {
    /// A displacement scale below which an increment's iterates cannot be told apart, the
    /// `floor` of the convergence measure [`change_ratio`]: 0 under small kinematics (given
    /// the contact set the problem is linear and a repeated increment reproduces the state to
    /// round-off). Under finite kinematics the geometry is nonlinear and evaluated at `X + u`:
    /// every converged increment stopped within `tolerance` of its own motion, so an increment
    /// is measured against at least the largest of those motions (a repeated increment then
    /// converges at once instead of refining the last fixed point against its own tiny motion),
    /// and against round-off of the positions, `POSITION_ROUND_OFF |X| / tolerance` (a model
    /// far from its origin).
    fn resolution(&self) -> f64 {
        match self.options.kinematics {
            Kinematics::Small => 0.0,
            Kinematics::Finite => {
                let x = self.bodies.positions();
                let positions: Vec<f64> = self.boundary.dofs.iter().map(|&d| x[d]).collect();
                let round_off = checks::POSITION_ROUND_OFF * checks::norm2(&positions);
                self.driver
                    .largest_motion
                    .max(round_off / self.options.tolerance)
            }
        }
    }

    /// Accept the converged iterate: store the contact state, the node data and the records;
    /// the full field is recovered only when asked for.
    #[allow(clippy::too_many_arguments)]
    fn finish(
        &mut self,
        number: usize,
        iterations: usize,
        states: &[Vec<NodeState>],
        tractions: &[Vec<Traction>],
        uc: Vec<f64>,
        surfaces: Vec<ContactSurface>,
        converged: Converged,
        records: Vec<IterationRecord>,
    ) -> IncrementInfo {
        let motion: Vec<f64> = uc
            .iter()
            .zip(&self.boundary.qc)
            .map(|(a, b)| a - b)
            .collect();
        self.driver.largest_motion = self.driver.largest_motion.max(checks::norm2(&motion));
        self.driver.largest_node_motion = (self.driver.largest_node_motion).max(
            checks::largest_node_motion(&uc, &self.boundary.qc, self.dim()),
        );
        self.boundary.qc = uc;
        self.surfaces.current = surfaces;
        self.driver.previous = self.driver.converged.replace(converged);
        if let Some((_, seconds)) = self.driver.field.take() {
            self.driver.timings.recovery += seconds;
        }
        for (p, s) in states.iter().enumerate() {
            for (k, &state) in s.iter().enumerate() {
                let traction = tractions[p][k];
                self.nodes[p][k] = NodeData { state, traction };
            }
        }
        self.driver.increment = number;
        self.driver.records.extend(records);
        let (active, _, slip) = count(states);
        IncrementInfo {
            increment: number,
            iterations,
            active,
            slip,
            sub_increments: 1,
            cutbacks: 0,
        }
    }
}

/// An iterate's displacements `u` must be finite (see [`ContactError::NonFinite`]).
fn finite(u: &[f64], increment: usize, iteration: usize) -> Result<()> {
    if u.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(ContactError::NonFinite {
            increment,
            iteration,
        }
        .into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rules' failures go to the fallback and the cutback, a step too long to the cutback
    /// only, the rest to neither.
    #[test]
    fn each_failure_has_one_remedy() {
        let unsettled: Error = ContactError::NoConvergence {
            increment: 1,
            iterations: 60,
            last_r: 1.0,
        }
        .into();
        let too_long: Error = ContactError::BeyondSearchDistance {
            node: 3,
            element: vec![1, 2],
            depth: 1.0,
            search_distance: 0.5,
        }
        .into();
        let last = Error::Singular("K".into());
        assert_eq!(Failure::of(&unsettled), Failure::Unsettled);
        assert_eq!(Failure::of(&too_long), Failure::TooLong);
        assert_eq!(Failure::of(&last), Failure::Final);
        let remedies = |e: &Error| {
            let f = Failure::of(e);
            (f.fallback_may_settle(), f.shorter_step_may_settle())
        };
        assert_eq!(remedies(&unsettled), (true, true));
        assert_eq!(remedies(&too_long), (false, true));
        assert_eq!(remedies(&last), (false, false));
    }
}
