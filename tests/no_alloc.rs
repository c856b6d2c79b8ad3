//! The element kernels run millions of times: they must not touch the heap. A counting global
//! allocator proves it for every plane element kind and both bricks, including stress recovery
//! and face tractions. It counts only the allocations of the thread that runs the kernels, in a
//! counter of that thread: the test harness and the other tests allocate whenever they like
//! (a CI run once saw 4 such allocations during the loop; a shared counter once saw another
//! test's check below).

use hycon::element::{self, ElementMatrix, Formulation};
use hycon::solid::{self, BrickFormulation, BrickMatrix, Isotropic};
use hycon::{Analysis, Material};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    /// Whether this thread's allocations are counted, and how many were (const-initialized:
    /// reading them never allocates).
    static COUNTED: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: forwards to the system allocator, only counting calls.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTED.with(Cell::get) {
            ALLOCATIONS.with(|n| n.set(n.get() + 1));
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

/// Heap allocations made by this thread while `f` runs.
fn allocations_during(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    COUNTED.with(|c| c.set(true));
    f();
    COUNTED.with(|c| c.set(false));
    ALLOCATIONS.with(Cell::get) - before
}

#[test]
fn the_counter_sees_allocations() {
    let n = allocations_during(|| {
        std::hint::black_box(Box::new(1.0));
    });
    assert_eq!(n, 1);
}

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
    let mut checksum = 0.0;
    let allocations = allocations_during(|| {
        for _ in 0..100 {
            for (f, coords, m) in cases {
                element::stiffness_into(f, coords, m, &mut k).unwrap();
                let field = element::recover_stress(f, coords, m, &q[..2 * coords.len()]).unwrap();
                checksum +=
                    k[(0, 0)] + field.at_full([0.5, 0.5])[3] + field.edge_traction(1, 0.5)[1];
            }
        }
    });
    assert!(checksum.is_finite());
    assert_eq!(
        allocations, 0,
        "element kernels allocated {allocations} times"
    );
}

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
    let mut checksum = 0.0;
    let allocations = allocations_during(|| {
        for _ in 0..20 {
            for f in BrickFormulation::ALL {
                solid::stiffness_into(f, &x, &m, &mut k).unwrap();
                let field = solid::recover_stress(f, &x, &m, &q).unwrap();
                checksum +=
                    k[(0, 0)] + field.at([1.0, 0.9, 0.7])[0] + field.face_traction(3, 0.2, 0.1)[1];
            }
        }
    });
    assert!(checksum.is_finite());
    assert_eq!(
        allocations, 0,
        "brick kernels allocated {allocations} times"
    );
}
