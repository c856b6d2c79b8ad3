//! The element kernels run millions of times: they must not touch the heap. A counting global
//! allocator proves it for every element kind, including stress recovery. It counts only the
//! allocations of the thread that runs the kernels: the test harness's own threads allocate
//! whenever they like (a CI run once saw 4 such allocations during the loop).

use hycon::element::{self, ElementMatrix, Formulation};
use hycon::{Analysis, Material};
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
fn kernels_do_not_allocate() {
    let m = Material::new(1.0, 0.3, 1.0, Analysis::PlaneStrain).unwrap();
    let quad = [[0.0, 0.0], [1.1, 0.1], [1.0, 0.9], [-0.1, 1.0]];
    let five = [quad[0], quad[1], [1.05, 0.5], quad[2], quad[3]];
    let six = [
        quad[0],
        [0.55, 0.05],
        quad[1],
        [1.05, 0.5],
        quad[2],
        quad[3],
    ];
    let axi = Material::new(1.0, 0.3, 1.0, Analysis::Axisymmetric).unwrap();
    let ring = [[0.5, 0.0], [1.6, 0.1], [1.5, 0.9], [0.4, 1.0]];
    let cases: [(Formulation, &[[f64; 2]], &Material); 7] = [
        (Formulation::Hybrid, &quad, &m),
        (Formulation::Hybrid, &five, &m),
        (Formulation::Hybrid, &six, &m),
        (Formulation::PianSumihara, &quad, &m),
        (Formulation::Q4, &quad, &m),
        (Formulation::Hybrid, &ring, &axi),
        (Formulation::Q4, &ring, &axi),
    ];
    let mut k = ElementMatrix::zeros();
    let q = [1e-3; 12];
    COUNTED.with(|c| c.set(true));
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut checksum = 0.0;
    for _ in 0..100 {
        for (f, coords, m) in cases {
            element::stiffness_into(f, coords, m, &mut k).unwrap();
            let field = element::recover_stress(f, coords, m, &q[..2 * coords.len()]).unwrap();
            checksum += k[(0, 0)] + field.at_full([0.5, 0.5])[3] + field.edge_traction(1, 0.5)[1];
        }
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert!(checksum.is_finite());
    assert_eq!(
        after - before,
        0,
        "element kernels allocated {} times",
        after - before
    );
    // the counter does see allocations
    let boxed = std::hint::black_box(Box::new(checksum));
    assert!(ALLOCATIONS.load(Ordering::SeqCst) > after && boxed.is_finite());
    COUNTED.with(|c| c.set(false));
}
