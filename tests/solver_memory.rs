//! A factor larger than the memory the process may use is an error, never an abort.
//!
//! Its own test binary: the address-space limit it sets (`RLIMIT_AS`) holds for the whole
//! process. The limit is the current address space plus 256 MiB; the cube of 30 x 30 x 30
//! bricks needs more than twice that for `L` alone, so its analysis fits and its factorization
//! cannot.

use hycon::assembly::DofMap;
use hycon::solid::mesh::SolidMesh;
use hycon::solid::model::SolidSystem;
use hycon::solid::{BrickFormulation, Isotropic};
use hycon::solver::Backend;

/// The process' current virtual size (Linux `/proc/self/status`, `VmSize`), bytes.
fn virtual_size() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status.lines().find(|l| l.starts_with("VmSize:")).unwrap();
    let kib: u64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    kib * 1024
}

#[test]
fn a_factor_beyond_memory_is_an_error() {
    let n = 30;
    let mesh = SolidMesh::uniform([1.0, 1.0, 1.0], [n, n, n]);
    let fixed = mesh
        .nodes_where(|p| p[0] == 0.0)
        .into_iter()
        .flat_map(|k| [3 * k, 3 * k + 1, 3 * k + 2]);
    let dofs = DofMap::new(mesh.n_nodes(), 3, fixed).unwrap();
    let mut system = SolidSystem::new(&mesh, dofs, Backend::Faer).unwrap();
    let factor_bytes = system.cholesky().nnz_l() as u64 * 8;
    let headroom = 256 << 20;
    assert!(
        factor_bytes > 2 * headroom,
        "{factor_bytes} bytes fit the headroom"
    );

    let limit = virtual_size() + headroom;
    let rlimit = libc::rlimit {
        rlim_cur: limit,
        rlim_max: libc::RLIM_INFINITY,
    };
    // SAFETY: setrlimit reads the struct it is given; lowering the soft limit needs no privilege.
    assert_eq!(unsafe { libc::setrlimit(libc::RLIMIT_AS, &rlimit) }, 0);

    let material = Isotropic::new(1000.0, 0.3).unwrap();
    let err = system
        .assemble_and_factor(&mesh, &[material], BrickFormulation::Hybrid18, &[])
        .expect_err("a factor over twice the headroom");
    let message = err.to_string();
    assert!(message.contains("out of memory"), "{message}");
    assert!(message.contains("GB"), "{message}");
    assert_eq!(system.cholesky().factorizations(), 0);
}
