//! Siconos' numerics library (`libsiconos_numerics`, version 4.4.0 as Debian 12 ships it in
//! `libsiconos-numerics-dev`) on hycon's local problems
//! ([`hycon::contact::local::LocalProblem`], docs/method.md "The local problem"): the same
//! `u = W r + q` handed in memory to Siconos' `fc3d` solvers, and Siconos' own residual
//! `fc3d_compute_error` of any reactions.
//!
//! Behind the lab's `siconos` feature, and only for the side-by-side bench (`hycon bench
//! siconos`, docs/bench/siconos.md): the declarations below are written by hand from the
//! 4.4.0 headers (`/usr/include/siconos/numerics/`), so the feature checks without Siconos
//! installed; linking needs `libsiconos_numerics.so`. The lab test `siconos::` compiles a C
//! program against the installed headers and compares every field offset and size with
//! these.
//!
//! Siconos' residual differs from [`LocalProblem::natural_map_residual`] in its scale: both
//! take `e = sqrt(sum_i |r_i - P_K_i(r_i - û_i)|^2)`, Siconos divides it by
//! `max(|q|, |r|, |u|)` where hycon divides by `|q|` (and, for `mu = 0`, Siconos projects a
//! trial point `(n < 0, 0, 0)` to zero where hycon keeps it: docs/bench/siconos.md).

use hycon::contact::local::LocalProblem;
use std::os::raw::c_int;

/// The C declarations (Siconos 4.4.0 headers: `NumericsMatrix.h`, `FrictionContactProblem.h`,
/// `SolverOptions.h`, `NonSmoothDrivers.h`, `fc3d_compute_error.h`, `Friction_cst.h`).
pub mod ffi {
    use std::os::raw::{c_int, c_void};

    /// `NM_DENSE` of `NM_types`: column-major `double*` in `matrix0`.
    pub const NM_DENSE: c_int = 0;
    /// `SICONOS_FRICTION_3D_NSGS`: non-smooth Gauss-Seidel.
    pub const SICONOS_FRICTION_3D_NSGS: c_int = 500;
    /// `SICONOS_FRICTION_3D_NSN_AC`: the semi-smooth Newton method on Alart-Curnier's function.
    pub const SICONOS_FRICTION_3D_NSN_AC: c_int = 504;
    /// `SICONOS_IPARAM_MAX_ITER`.
    pub const SICONOS_IPARAM_MAX_ITER: usize = 0;
    /// `SICONOS_IPARAM_ITER_DONE`.
    pub const SICONOS_IPARAM_ITER_DONE: usize = 1;
    /// `SICONOS_DPARAM_TOL`.
    pub const SICONOS_DPARAM_TOL: usize = 0;
    /// `SICONOS_DPARAM_RESIDU`: the solver's last `fc3d_compute_error`.
    pub const SICONOS_DPARAM_RESIDU: usize = 1;
    /// `SICONOS_FRICTION_3D_NSN_LINESEARCH`.
    pub const SICONOS_FRICTION_3D_NSN_LINESEARCH: usize = 11;
    /// `SICONOS_FRICTION_3D_NSN_LINESEARCH_NO`.
    pub const SICONOS_FRICTION_3D_NSN_LINESEARCH_NO: c_int = -1;
    /// `SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY`.
    pub const SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY: usize = 14;
    /// `SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN`: 50 extragradient iterations to
    /// `sqrt(tol)` before the Newton method.
    pub const SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN: c_int = 3;

    /// `struct NumericsMatrix` (`NumericsMatrix.h`).
    #[repr(C)]
    pub struct NumericsMatrix {
        /// `NM_types storageType`.
        pub storage_type: c_int,
        /// Rows.
        pub size0: c_int,
        /// Columns.
        pub size1: c_int,
        /// Dense storage, column-major.
        pub matrix0: *mut f64,
        /// `SparseBlockStructuredMatrix*`.
        pub matrix1: *mut c_void,
        /// `NumericsSparseMatrix*`.
        pub matrix2: *mut c_void,
        /// `NumericsMatrixInternalData*`.
        pub internal_data: *mut c_void,
        /// `NumericsDataVersion` (one `uint64_t`).
        pub version: u64,
        /// `NumericsMatrix* destructible`.
        pub destructible: *mut NumericsMatrix,
    }

    /// `struct FrictionContactProblem` (`FrictionContactProblem.h`).
    #[repr(C)]
    pub struct FrictionContactProblem {
        /// Components per contact (3).
        pub dimension: c_int,
        /// Contacts.
        pub number_of_contacts: c_int,
        /// `W`.
        pub m: *mut NumericsMatrix,
        /// `q`.
        pub q: *mut f64,
        /// The Coulomb coefficients.
        pub mu: *mut f64,
    }

    /// `struct SolverOptions` (`SolverOptions.h`).
    #[repr(C)]
    pub struct SolverOptions {
        /// `solverId`.
        pub solver_id: c_int,
        /// `isSet` (C `bool`).
        pub is_set: bool,
        /// Length of `iparam`.
        pub i_size: c_int,
        /// Integer parameters.
        pub iparam: *mut c_int,
        /// Length of `dparam`.
        pub d_size: c_int,
        /// Real parameters.
        pub dparam: *mut f64,
        /// `filterOn`.
        pub filter_on: bool,
        /// `dWorkSize`.
        pub d_work_size: usize,
        /// `dWork`.
        pub d_work: *mut f64,
        /// `iWorkSize`.
        pub i_work_size: usize,
        /// `iWork`.
        pub i_work: *mut c_int,
        /// `numberOfInternalSolvers`.
        pub number_of_internal_solvers: usize,
        /// `internalSolvers`.
        pub internal_solvers: *mut *mut SolverOptions,
        /// `Callback*`.
        pub callback: *mut c_void,
        /// `solverParameters`.
        pub solver_parameters: *mut c_void,
        /// `solverData`.
        pub solver_data: *mut c_void,
    }

    #[link(name = "siconos_numerics")]
    unsafe extern "C" {
        /// A matrix of `storageType` with its storage allocated.
        pub fn NM_create(storage_type: c_int, size0: c_int, size1: c_int) -> *mut NumericsMatrix;
        /// Frees the matrix, its storage and the struct; returns NULL.
        pub fn NM_free(m: *mut NumericsMatrix) -> *mut NumericsMatrix;
        /// Options with the solver's defaults.
        pub fn solver_options_create(solver_id: c_int) -> *mut SolverOptions;
        /// Frees options created by `solver_options_create`.
        pub fn solver_options_delete(options: *mut SolverOptions);
        /// Solves from `reaction` (the start); 0 when the solver met its tolerance.
        pub fn fc3d_driver(
            problem: *mut FrictionContactProblem,
            reaction: *mut f64,
            velocity: *mut f64,
            options: *mut SolverOptions,
        ) -> c_int;
        /// Writes `w = M z + q` and the residual of `z` divided by `max(norm, |z|, |w|)` to
        /// `error`; 0 when it is at most `tolerance`. `options` is not read.
        pub fn fc3d_compute_error(
            problem: *mut FrictionContactProblem,
            z: *mut f64,
            w: *mut f64,
            tolerance: f64,
            options: *mut SolverOptions,
            norm: f64,
            error: *mut f64,
        ) -> c_int;
    }
}

/// A Siconos `fc3d` solver with its options.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SiconosSolver {
    /// `SICONOS_FRICTION_3D_NSN_AC` with its defaults (Goldstein-Price line search,
    /// `rho` from the contacts' spectral norms).
    NsnAc,
    /// NSN_AC without line search.
    NsnAcNoLineSearch,
    /// NSN_AC warm-started by the extragradient method
    /// (`SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN`), without line search: the
    /// fastest on the finite-element sets of Acary, Bremond and Huber (2018).
    NsnAcExtragradient,
    /// `SICONOS_FRICTION_3D_NSGS` with its defaults (one-contact Newton on each contact).
    Nsgs,
}

impl SiconosSolver {
    /// Every solver, in table order.
    pub const ALL: [SiconosSolver; 4] = [
        SiconosSolver::NsnAc,
        SiconosSolver::NsnAcNoLineSearch,
        SiconosSolver::NsnAcExtragradient,
        SiconosSolver::Nsgs,
    ];

    /// The name in tables.
    pub fn name(self) -> &'static str {
        match self {
            SiconosSolver::NsnAc => "siconos NSN_AC",
            SiconosSolver::NsnAcNoLineSearch => "siconos NSN_AC no LS",
            SiconosSolver::NsnAcExtragradient => "siconos EG+NSN_AC",
            SiconosSolver::Nsgs => "siconos NSGS",
        }
    }
}

/// A solve by Siconos.
#[derive(Debug, Clone, PartialEq)]
pub struct SiconosSolve {
    /// The reactions.
    pub r: Vec<f64>,
    /// `fc3d_driver`'s info: 0 when the solver met its tolerance.
    pub info: i32,
    /// Iterations done (`iparam[SICONOS_IPARAM_ITER_DONE]`).
    pub iterations: i32,
    /// The solver's last residual (`dparam[SICONOS_DPARAM_RESIDU]`).
    pub residual: f64,
}

/// A [`LocalProblem`] of three components per contact as Siconos'
/// `FrictionContactProblem`, `W` dense. Owns every C allocation it hands out.
pub struct SiconosProblem {
    matrix: *mut ffi::NumericsMatrix,
    q: Vec<f64>,
    mu: Vec<f64>,
    contacts: usize,
}

impl SiconosProblem {
    /// Siconos' copy of `problem`; `None` unless it has three components per contact (the
    /// `fc3d` solvers') or when Siconos cannot allocate `W`.
    pub fn new(problem: &LocalProblem) -> Option<Self> {
        let m = problem.q().len();
        if problem.dim() != 3 || m == 0 {
            return None;
        }
        let size = c_int::try_from(m).ok()?;
        // SAFETY: NM_create allocates an m x m dense matrix (or returns NULL).
        let matrix = unsafe { ffi::NM_create(ffi::NM_DENSE, size, size) };
        if matrix.is_null() {
            return None;
        }
        // SAFETY: a dense NumericsMatrix from NM_create holds m * m doubles in matrix0,
        // column-major as nalgebra's DMatrix.
        unsafe {
            let values = std::slice::from_raw_parts_mut((*matrix).matrix0, m * m);
            values.copy_from_slice(problem.w().as_slice());
        }
        Some(SiconosProblem {
            matrix,
            q: problem.q().to_vec(),
            mu: problem.mu().to_vec(),
            contacts: problem.contacts(),
        })
    }

    /// The C problem over this one's storage. Siconos' solvers and `fc3d_compute_error`
    /// read `W`, `q` and `mu` and write none of them.
    fn raw(&self) -> ffi::FrictionContactProblem {
        ffi::FrictionContactProblem {
            dimension: 3,
            number_of_contacts: self.contacts as c_int,
            m: self.matrix,
            q: self.q.as_ptr().cast_mut(),
            mu: self.mu.as_ptr().cast_mut(),
        }
    }

    /// Solves by `solver` from `r = 0` until Siconos' residual is below `tolerance` or
    /// after `max_iterations`.
    pub fn solve(
        &self,
        solver: SiconosSolver,
        tolerance: f64,
        max_iterations: i32,
    ) -> SiconosSolve {
        let id = match solver {
            SiconosSolver::Nsgs => ffi::SICONOS_FRICTION_3D_NSGS,
            _ => ffi::SICONOS_FRICTION_3D_NSN_AC,
        };
        let n = self.q.len();
        let (mut r, mut u) = (vec![0.0; n], vec![0.0; n]);
        let mut raw = self.raw();
        // SAFETY: the options come from solver_options_create, with iparam and dparam of
        // OPTIONS_PARAM_SIZE (20) entries, every index written below is under 20; the problem
        // points at live storage of the sizes it states, r and u hold 3 per contact; the
        // options are deleted once, after their last use.
        unsafe {
            let options = ffi::solver_options_create(id);
            assert!(!options.is_null(), "Siconos could not create options");
            let (iparam, dparam) = ((*options).iparam, (*options).dparam);
            *iparam.add(ffi::SICONOS_IPARAM_MAX_ITER) = max_iterations;
            *dparam.add(ffi::SICONOS_DPARAM_TOL) = tolerance;
            if matches!(
                solver,
                SiconosSolver::NsnAcNoLineSearch | SiconosSolver::NsnAcExtragradient
            ) {
                *iparam.add(ffi::SICONOS_FRICTION_3D_NSN_LINESEARCH) =
                    ffi::SICONOS_FRICTION_3D_NSN_LINESEARCH_NO;
            }
            if solver == SiconosSolver::NsnAcExtragradient {
                *iparam.add(ffi::SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY) =
                    ffi::SICONOS_FRICTION_3D_NSN_HYBRID_STRATEGY_VI_EG_NSN;
            }
            let info = ffi::fc3d_driver(&mut raw, r.as_mut_ptr(), u.as_mut_ptr(), options);
            let solve = SiconosSolve {
                r: std::mem::take(&mut r),
                info,
                iterations: *iparam.add(ffi::SICONOS_IPARAM_ITER_DONE),
                residual: *dparam.add(ffi::SICONOS_DPARAM_RESIDU),
            };
            ffi::solver_options_delete(options);
            solve
        }
    }

    /// Siconos' `fc3d_compute_error` of the reactions `r` with `norm = |q|` (as its solvers
    /// call it): `e / max(|q|, |r|, |u|)` (module docs).
    pub fn compute_error(&self, r: &[f64]) -> f64 {
        assert_eq!(r.len(), self.q.len(), "reactions of another problem");
        let norm_q = self.q.iter().map(|v| v * v).sum::<f64>().sqrt();
        let (mut z, mut w) = (r.to_vec(), vec![0.0; r.len()]);
        let mut raw = self.raw();
        let mut error = f64::NAN;
        // SAFETY: the problem points at live storage of the sizes it states, z and w hold
        // 3 per contact, fc3d_compute_error does not read its options (4.4.0's
        // fc3d_compute_error.c).
        unsafe {
            ffi::fc3d_compute_error(
                &mut raw,
                z.as_mut_ptr(),
                w.as_mut_ptr(),
                0.0,
                std::ptr::null_mut(),
                norm_q,
                &mut error,
            );
        }
        error
    }
}

impl Drop for SiconosProblem {
    fn drop(&mut self) {
        // SAFETY: the matrix came from NM_create and is freed once.
        unsafe {
            ffi::NM_free(self.matrix);
        }
    }
}
