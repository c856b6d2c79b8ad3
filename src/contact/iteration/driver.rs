//! The increment driver: what runs one increment and what it keeps between increments.

use super::active_set::{BNodes, Locks};
use super::{IterationRecord, Monitor, Timings};
use std::sync::{Mutex, OnceLock};

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
        }
    }
}

/// What a converged increment without a plate settled with: its load (`f` and `q_p` at the
/// prescribed dofs), the locks of its contact set, and how its rules judged B nodes
/// penetrating open segments (at convergence only in the fallback's last attempt, see
/// `rules.rs`).
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
