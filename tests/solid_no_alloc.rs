//! The brick kernels run millions of times: they must not touch the heap. A counting global
//! allocator proves it for both bricks, including stress recovery and face tractions (the plane
//! kernels' twin is `tests/no_alloc.rs`). It counts only the
//! allocations of the thread that runs the kernels: the test harness's own threads allocate
//! whenever they like (a CI run once saw 4 such allocations during the loop).

use hycon::solid::{self, BrickFormulation, BrickMatrix, Isotropic};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Whether this thread's allocations are counted (const-initialized: reading it never
    /// allocates).
    static COUNTED: Cell<bool> = const { Cell::new(false) };
}

// SAFETY: forwards to the system allocator, only counting calls.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTED.with(Cell::get) {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn brick_kernels_do_not_allocate() {
    let m = Isotropic::new(1.0, 0.3).unwrap();
    let x = [
        [0.0, 0.0, 0.0],
        [2.1, 0.2, -0.1],
        [2.4, 1.9, 0.2],
        [-0.2, 1.5, 0.1],
        [0.3, -0.1, 1.2],
        [2.0, 0.1, 1.4],
        [2.2, 2.2, 1.7],
        [0.1, 1.7, 1.1],
    ];
    let q = [1e-3; 24];
    let mut k = BrickMatrix::zeros();
    COUNTED.with(|c| c.set(true));
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut checksum = 0.0;
    for _ in 0..20 {
        for f in BrickFormulation::ALL {
            solid::stiffness_into(f, &x, &m, &mut k).unwrap();
            let field = solid::recover_stress(f, &x, &m, &q).unwrap();
            checksum +=
                k[(0, 0)] + field.at([1.0, 0.9, 0.7])[0] + field.face_traction(3, 0.2, 0.1)[1];
        }
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert!(checksum.is_finite());
    assert_eq!(
        after - before,
        0,
        "brick kernels allocated {} times",
        after - before
    );
    // the counter does see allocations
    let boxed = std::hint::black_box(Box::new(checksum));
    assert!(ALLOCATIONS.load(Ordering::SeqCst) > after && boxed.is_finite());
    COUNTED.with(|c| c.set(false));
}
