//! FCLIB's local problems out and in (feature `fclib`, docs/fclib.md): a
//! [`LocalProblem`] `u = W r + q` with its Coulomb coefficients, and optionally its solution,
//! written to and read from the Friction Contact Library's HDF5 files through libfclib 3.1.
//!
//! * [`write_local`]: `/fclib_local` with `W` in compressed columns (exact zeros dropped, no
//!   `V`, `R`, `s`), `q`, `mu`, `spacedim` and the info record (title, description,
//!   math_info); with a solution, FCLIB's `/solution` record (`r` and `u = W r + q`).
//! * [`read_local`]: the problem and the `/solution` reactions if the file holds them; `W` in
//!   any of FCLIB's three storages (compressed columns or rows, triplets; CSparse's index
//!   conventions, which Siconos and libfclib's merit function use).
//! * [`merit`]: libfclib's own natural-map merit function `fclib_merit_local` (3D only).
//!
//! libfclib ends the process (`exit(1)`) when an HDF5 call fails inside it, and reads datasets
//! into buffers sized by other datasets: [`read_local`] therefore checks the file's structure
//! and every size with HDF5 itself first, so a damaged or foreign file is an [`Error`], never a
//! crash. (Writing, only a failure after the file was created, such as a full disk, would end
//! the process.) Every call into libfclib and HDF5 holds one lock.

use hycon::contact::local::LocalProblem;
use nalgebra::DMatrix;
use std::ffi::{CStr, CString, c_char, c_int, c_void};
use std::path::{Path, PathBuf};
use std::ptr;
use std::sync::{Mutex, MutexGuard};

/// bindgen's bindings of fclib.h and of the HDF5 calls used here (lab/build.rs).
#[allow(
    non_upper_case_globals,
    non_camel_case_types,
    non_snake_case,
    dead_code,
    unsafe_op_in_unsafe_fn,
    clippy::all
)]
mod sys {
    include!(concat!(env!("OUT_DIR"), "/fclib_bindings.rs"));
}

/// HDF5's `H5P_DEFAULT` and `H5E_DEFAULT` (`(hid_t) 0`, macros bindgen does not translate).
const H5_DEFAULT: sys::hid_t = 0;
/// HDF5's `H5F_ACC_RDONLY`.
const H5F_ACC_RDONLY: u32 = 0;

/// The free-text record FCLIB keeps with a problem (`/fclib_local/info`).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Metadata {
    /// The problem's title.
    pub title: String,
    /// A short description: where the problem comes from.
    pub description: String,
    /// Its known mathematical properties (FCLIB's `math_info`).
    pub math_info: String,
}

/// Why an FCLIB file could not be written or read.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The file is missing or unreadable, or could not be created or written.
    #[error("{path}: {1}", path = .0.display())]
    Io(PathBuf, String),
    /// The file is not an FCLIB local problem hycon reads: not HDF5, a group or dataset missing,
    /// or sizes that disagree.
    #[error("{path}: not an FCLIB local problem hycon reads: {1}", path = .0.display())]
    Format(PathBuf, String),
    /// The problem read is not a valid [`LocalProblem`] (e.g. `W` not symmetric).
    #[error("{path}: {1}", path = .0.display())]
    Problem(PathBuf, hycon::Error),
}

/// The lock every call into libfclib and HDF5 holds (module docs); HDF5's automatic printing
/// of its error stacks is off while it is held (failures are reported as [`Error`]s).
fn library() -> MutexGuard<'static, ()> {
    static LIBRARY: Mutex<()> = Mutex::new(());
    let guard = LIBRARY.lock().unwrap_or_else(|e| e.into_inner());
    // SAFETY: H5Eset_auto2 with a null function turns the printing off for the default stack.
    unsafe { sys::H5Eset_auto2(H5_DEFAULT, None, ptr::null_mut()) };
    guard
}

fn c_path(path: &Path) -> Result<CString, Error> {
    CString::new(path.as_os_str().as_encoded_bytes())
        .map_err(|_| Error::Io(path.into(), "the path holds a NUL byte".into()))
}

fn c_text(text: &str) -> CString {
    CString::new(text.replace('\0', " ")).expect("NUL bytes replaced")
}

/// `W` in compressed columns without its exact zeros, as libfclib takes it (`nz = -1`).
struct Csc {
    p: Vec<c_int>,
    i: Vec<c_int>,
    x: Vec<f64>,
}

impl Csc {
    fn new(w: &DMatrix<f64>) -> Csc {
        let mut csc = Csc {
            p: vec![0],
            i: Vec::new(),
            x: Vec::new(),
        };
        for column in w.column_iter() {
            for (row, &v) in column.iter().enumerate() {
                if v != 0.0 {
                    csc.i.push(row as c_int);
                    csc.x.push(v);
                }
            }
            csc.p.push(csc.x.len() as c_int);
        }
        csc
    }
}

/// Runs `f` on libfclib's view of `problem` (`W` in compressed columns, no `V`, `R`, `s`) and of
/// `info`; the pointers live as long as the call.
fn with_fclib_local<T>(
    problem: &LocalProblem,
    info: Option<&Metadata>,
    f: impl FnOnce(&mut sys::fclib_local) -> T,
) -> T {
    let m = problem.q().len() as c_int;
    let mut csc = Csc::new(problem.w());
    let mut w = sys::fclib_matrix {
        nzmax: csc.x.len() as c_int,
        m,
        n: m,
        p: csc.p.as_mut_ptr(),
        i: csc.i.as_mut_ptr(),
        x: csc.x.as_mut_ptr(),
        nz: -1,
        info: ptr::null_mut(),
    };
    let texts = info.map(|i| [&i.title, &i.description, &i.math_info].map(|t| c_text(t)));
    let mut record = texts
        .as_ref()
        .map(|[title, description, math_info]| sys::fclib_info {
            title: title.as_ptr().cast_mut(),
            description: description.as_ptr().cast_mut(),
            math_info: math_info.as_ptr().cast_mut(),
        });
    let (mut q, mut mu) = (problem.q().to_vec(), problem.mu().to_vec());
    let mut local = sys::fclib_local {
        W: &mut w,
        V: ptr::null_mut(),
        R: ptr::null_mut(),
        mu: mu.as_mut_ptr(),
        q: q.as_mut_ptr(),
        s: ptr::null_mut(),
        spacedim: problem.dim() as c_int,
        info: record.as_mut().map_or(ptr::null_mut(), |r| r as *mut _),
    };
    f(&mut local)
}

/// Writes `problem` (and `solution`, its reactions `r`, with `u = W r + q`) as an FCLIB local
/// problem file at `path`, replacing a file already there (module docs).
///
/// # Errors
/// [`Error::Io`] if the file cannot be created or written, if `solution` does not have one
/// entry per row of `W`, or if the problem is too large for FCLIB's 32-bit indices.
pub fn write_local(
    path: &Path,
    problem: &LocalProblem,
    solution: Option<&[f64]>,
    info: &Metadata,
) -> Result<(), Error> {
    let fail = |what: String| Err(Error::Io(path.into(), what));
    let m = problem.q().len();
    if let Some(r) = solution.filter(|r| r.len() != m) {
        return fail(format!(
            "the solution has {} entries, W has {m} rows",
            r.len()
        ));
    }
    if m * m > c_int::MAX as usize {
        return fail(format!("W of side {m} is beyond FCLIB's 32-bit indices"));
    }
    let c_path = c_path(path)?;
    if path.exists() {
        std::fs::remove_file(path).or_else(|e| fail(format!("cannot replace it: {e}")))?;
    }
    let _library = library();
    // SAFETY: every pointer of the view lives through the call; libfclib only reads them.
    let written = with_fclib_local(problem, Some(info), |local| unsafe {
        sys::fclib_write_local(local, c_path.as_ptr())
    });
    if written != 1 {
        return fail("libfclib could not create the file (fclib_write_local failed)".into());
    }
    if let Some(r) = solution {
        // SAFETY: u and r have the W->n entries libfclib writes from them; v and l are not
        // read for a local problem without R.
        let written = with_solution_record(problem, r, |record| unsafe {
            sys::fclib_write_solution(record, c_path.as_ptr())
        });
        if written != 1 {
            return fail("libfclib could not add the solution (fclib_write_solution)".into());
        }
    }
    Ok(())
}

/// Reads the FCLIB local problem at `path` and the reactions `r` of its `/solution` record if
/// it has one (module docs).
///
/// # Errors
/// [`Error::Io`] for a missing or unreadable file, [`Error::Format`] for a file that is not
/// an FCLIB local problem (not HDF5, a global or mixed problem, a dataset missing or of a
/// size that disagrees, indices out of range), [`Error::Problem`] for a problem
/// [`LocalProblem::new`] refuses (e.g. `W` not symmetric).
pub fn read_local(path: &Path) -> Result<(LocalProblem, Option<Vec<f64>>), Error> {
    read_local_with_info(path).map(|(problem, solution, _)| (problem, solution))
}

/// [`read_local`] and the file's info record (empty fields where it has none).
///
/// # Errors
/// Those of [`read_local`].
pub fn read_local_with_info(
    path: &Path,
) -> Result<(LocalProblem, Option<Vec<f64>>, Metadata), Error> {
    if let Err(e) = std::fs::File::open(path) {
        return Err(Error::Io(path.into(), format!("cannot open it: {e}")));
    }
    let format = |what: String| Error::Format(path.into(), what);
    let c_path = c_path(path)?;
    let _library = library();
    // SAFETY: a NUL-terminated path.
    if unsafe { sys::H5Fis_hdf5(c_path.as_ptr()) } <= 0 {
        return Err(format("not an HDF5 file".into()));
    }
    let has_solution = {
        let file = H5File::open(&c_path).ok_or_else(|| format("HDF5 cannot open it".into()))?;
        file.check_local().map_err(format)?
    };
    // SAFETY: the file's structure and sizes were checked above, so libfclib neither fails an
    // HDF5 call nor overruns a buffer; the result is freed by the guard.
    let owned = FclibLocal(unsafe { sys::fclib_read_local(c_path.as_ptr()) });
    if owned.0.is_null() {
        return Err(format("fclib_read_local failed".into()));
    }
    // SAFETY: non-null, filled by fclib_read_local, freed when `owned` drops.
    let local = unsafe { &*owned.0 };
    let m = nonnegative(unsafe { (*local.W).m });
    let d = nonnegative(local.spacedim);
    // SAFETY: W was checked and read by libfclib with the checked sizes.
    let w = unsafe { dense(&*local.W) }.map_err(format)?;
    // SAFETY: q has W->m entries and mu W->m / spacedim (checked, allocated so by libfclib).
    let (q, mu) = unsafe {
        (
            std::slice::from_raw_parts(local.q, m).to_vec(),
            std::slice::from_raw_parts(local.mu, m / d).to_vec(),
        )
    };
    let solution = if has_solution {
        // SAFETY: /solution's u and r were checked to have W->n entries.
        let record = FclibSolution(unsafe { sys::fclib_read_solution(c_path.as_ptr()) });
        if record.0.is_null() {
            return Err(format("fclib_read_solution failed".into()));
        }
        // SAFETY: r has W->n = m entries.
        Some(unsafe { std::slice::from_raw_parts((*record.0).r, m).to_vec() })
    } else {
        None
    };
    // SAFETY: null or a record of NUL-terminated strings read by libfclib.
    let info = unsafe {
        local
            .info
            .as_ref()
            .map_or_else(Metadata::default, |i| Metadata {
                title: text(i.title),
                description: text(i.description),
                math_info: text(i.math_info),
            })
    };
    let problem = LocalProblem::new(d, w, q, mu).map_err(|e| Error::Problem(path.into(), e))?;
    Ok((problem, solution, info))
}

/// libfclib's merit function `fclib_merit_local(problem, MERIT_1, r)` of the reactions `r`:
/// the natural map's norm over `1 + sqrt(|q|)` (docs/fclib.md, "Residuals"). `None` where
/// libfclib 3.1 has none (2D problems) and for an `r` without one entry per row of `W`.
pub fn merit(problem: &LocalProblem, r: &[f64]) -> Option<f64> {
    if problem.dim() != 3 || r.len() != problem.q().len() {
        return None;
    }
    // SAFETY: the view and the record live through the call, r and u have W->n entries, and
    // libfclib's merit function only reads them (V and R null: no equality part).
    Some(with_solution_record(problem, r, |record| {
        with_fclib_local(problem, None, |local| unsafe {
            sys::fclib_merit_local(local, sys::fclib_merit_MERIT_1, record)
        })
    }))
}

/// `f` given FCLIB's solution record of the reactions `r` (`u = W r + q` beside them; no `v`
/// and `l`, which a local problem has not), its arrays alive through the call.
fn with_solution_record<T>(
    problem: &LocalProblem,
    r: &[f64],
    f: impl FnOnce(&mut sys::fclib_solution) -> T,
) -> T {
    let (mut r, mut u) = (r.to_vec(), problem.velocity(r));
    let mut record = sys::fclib_solution {
        v: ptr::null_mut(),
        u: u.as_mut_ptr(),
        r: r.as_mut_ptr(),
        l: ptr::null_mut(),
    };
    f(&mut record)
}

unsafe extern "C" {
    /// The C library's `free`, for what libfclib allocates.
    fn free(p: *mut c_void);
}

/// Owns a problem from `fclib_read_local` (fclib_delete_local frees its members, not itself).
struct FclibLocal(*mut sys::fclib_local);

impl Drop for FclibLocal {
    fn drop(&mut self) {
        if !self.0.is_null() {
            // SAFETY: allocated by fclib_read_local with malloc, members included.
            unsafe {
                sys::fclib_delete_local(self.0);
                free(self.0.cast());
            }
        }
    }
}

/// Owns one solution from `fclib_read_solution`.
struct FclibSolution(*mut sys::fclib_solution);

impl Drop for FclibSolution {
    fn drop(&mut self) {
        if !self.0.is_null() {
            // SAFETY: one record allocated by fclib_read_solution; this frees it and its members.
            unsafe { sys::fclib_delete_solutions(self.0, 1) };
        }
    }
}

fn nonnegative(v: c_int) -> usize {
    usize::try_from(v).expect("checked before libfclib read it")
}

/// The dense `W` of libfclib's matrix in any of its storages: compressed columns (`nz = -1`:
/// `p` column pointers, `i` row indices), compressed rows (`nz = -2`: `p` row pointers, `i`
/// column indices) or `nz` triplets (`i` rows, `p` columns, duplicates summed), as CSparse and
/// Siconos take them. Errors name an index out of range or pointers that decrease.
///
/// # Safety
/// `mat`'s arrays hold the entries its sizes say (checked by [`H5File::check_local`]).
unsafe fn dense(mat: &sys::fclib_matrix) -> Result<DMatrix<f64>, String> {
    let (m, n) = (nonnegative(mat.m), nonnegative(mat.n));
    let mut w = DMatrix::zeros(m, n);
    let index = |v: c_int, below: usize, what: &str| {
        usize::try_from(v)
            .ok()
            .filter(|&k| k < below)
            .ok_or_else(|| format!("W: {what} {v} out of range 0..{below}"))
    };
    let compressed = |outer: usize, inner: usize, what: [&str; 2]| {
        // SAFETY: p has outer + 1 entries and i, x nzmax (caller's contract).
        let p = unsafe { std::slice::from_raw_parts(mat.p, outer + 1) };
        let nzmax = nonnegative(mat.nzmax);
        let (i, x) = unsafe {
            (
                std::slice::from_raw_parts(mat.i, nzmax),
                std::slice::from_raw_parts(mat.x, nzmax),
            )
        };
        if p[0] != 0 || p.windows(2).any(|s| s[1] < s[0]) || nonnegative(p[outer].max(0)) > nzmax {
            return Err(format!(
                "W's {} pointers do not rise from 0 to at most nzmax = {nzmax}",
                what[0]
            ));
        }
        let mut entries = Vec::new();
        for k in 0..outer {
            for e in nonnegative(p[k])..nonnegative(p[k + 1]) {
                entries.push((k, index(i[e], inner, what[1])?, x[e]));
            }
        }
        Ok(entries)
    };
    let entries: Vec<(usize, usize, f64)> = match mat.nz {
        -1 => compressed(n, m, ["column", "row index"])?
            .into_iter()
            .map(|(col, row, v)| (row, col, v))
            .collect(),
        -2 => compressed(m, n, ["row", "column index"])?,
        nz => {
            let nz = nonnegative(nz);
            // SAFETY: p, i and x have nz entries (caller's contract).
            let (p, i, x) = unsafe {
                (
                    std::slice::from_raw_parts(mat.p, nz),
                    std::slice::from_raw_parts(mat.i, nz),
                    std::slice::from_raw_parts(mat.x, nz),
                )
            };
            let mut entries = Vec::with_capacity(nz);
            for k in 0..nz {
                entries.push((
                    index(i[k], m, "row index")?,
                    index(p[k], n, "column index")?,
                    x[k],
                ));
            }
            entries
        }
    };
    for (row, col, v) in entries {
        w[(row, col)] += v;
    }
    Ok(w)
}

/// An HDF5 file open read-only, to check its structure before libfclib reads it.
struct H5File(sys::hid_t);

impl H5File {
    fn open(path: &CStr) -> Option<H5File> {
        // SAFETY: a NUL-terminated path; the id is closed on drop.
        let id = unsafe { sys::H5Fopen(path.as_ptr(), H5F_ACC_RDONLY, H5_DEFAULT) };
        (id >= 0).then_some(H5File(id))
    }

    fn exists(&self, name: &str) -> bool {
        let name = c_text(name);
        // SAFETY: an open file and a NUL-terminated name; a missing parent group is a failure
        // (negative), taken as absence.
        unsafe { sys::H5Lexists(self.0, name.as_ptr(), H5_DEFAULT) > 0 }
    }

    /// The class and dimensions of the dataset `name` (none if it is not a dataset).
    fn shape(&self, name: &str) -> Option<(sys::H5T_class_t, Vec<u64>)> {
        if !self.exists(name) {
            return None;
        }
        let c_name = c_text(name);
        let mut rank: c_int = 0;
        // SAFETY: an open file, a NUL-terminated name, and room for any rank (HDF5 caps it at
        // 32).
        unsafe {
            if sys::H5LTget_dataset_ndims(self.0, c_name.as_ptr(), &mut rank) < 0 {
                return None;
            }
            let mut dims = [0 as sys::hsize_t; 32];
            let (mut class, mut size) = (sys::H5T_class_t_H5T_NO_CLASS, 0usize);
            let rank = usize::try_from(rank).ok().filter(|&r| r <= dims.len())?;
            if sys::H5LTget_dataset_info(
                self.0,
                c_name.as_ptr(),
                dims.as_mut_ptr(),
                &mut class,
                &mut size,
            ) < 0
            {
                return None;
            }
            Some((class, dims[..rank].to_vec()))
        }
    }

    /// The length of the one-dimensional numeric dataset `name`.
    fn len(&self, name: &str) -> Result<usize, String> {
        match self.shape(name) {
            Some((class, dims))
                if dims.len() == 1
                    && (class == sys::H5T_class_t_H5T_INTEGER
                        || class == sys::H5T_class_t_H5T_FLOAT) =>
            {
                Ok(dims[0] as usize)
            }
            Some(_) => Err(format!("{name} is not a one-dimensional numeric dataset")),
            None => Err(format!("no dataset {name}")),
        }
    }

    /// `name` has `expected` entries.
    fn sized(&self, name: &str, expected: usize) -> Result<(), String> {
        match self.len(name)? {
            len if len == expected => Ok(()),
            len => Err(format!("{name} has {len} entries, {expected} expected")),
        }
    }

    /// The integer of the one-entry dataset `name`.
    fn int(&self, name: &str) -> Result<c_int, String> {
        self.sized(name, 1)?;
        let c_name = c_text(name);
        let mut value: c_int = 0;
        // SAFETY: a one-entry dataset read into one int.
        if unsafe { sys::H5LTread_dataset_int(self.0, c_name.as_ptr(), &mut value) } < 0 {
            return Err(format!("{name} cannot be read as an integer"));
        }
        Ok(value)
    }

    /// `name`, if present, is a string dataset.
    fn optional_string(&self, name: &str) -> Result<(), String> {
        match self.shape(name) {
            Some((class, _)) if class != sys::H5T_class_t_H5T_STRING => {
                Err(format!("{name} is not a string"))
            }
            _ => Ok(()),
        }
    }

    /// Checks everything libfclib's `fclib_read_local` and `fclib_read_solution` read
    /// (structure, sizes, types), so that neither fails an HDF5 call nor overruns a buffer;
    /// returns whether the file holds a solution.
    fn check_local(&self) -> Result<bool, String> {
        if !self.exists("/fclib_local") {
            return Err(if self.exists("/fclib_global") {
                "it holds a global problem (/fclib_global); hycon reads local ones".into()
            } else {
                "no /fclib_local group".into()
            });
        }
        if self.exists("/fclib_global") {
            return Err("it holds a global problem (/fclib_global) beside the local one".into());
        }
        if self.exists("/fclib_local/V") || self.exists("/fclib_local/R") {
            return Err("a mixed local problem (V, R, s); hycon reads W, q, mu only".into());
        }
        let d = self.int("/fclib_local/spacedim")?;
        if d != 2 && d != 3 {
            return Err(format!("spacedim is {d}, not 2 or 3"));
        }
        let m = self.check_matrix("/fclib_local/W", d)?;
        self.sized("/fclib_local/vectors/q", m)?;
        self.sized("/fclib_local/vectors/mu", m / nonnegative(d))?;
        for text in ["title", "description", "math_info"] {
            self.optional_string(&format!("/fclib_local/info/{text}"))?;
        }
        if !self.exists("/solution") {
            return Ok(false);
        }
        self.sized("/solution/u", m)?;
        self.sized("/solution/r", m)?;
        Ok(true)
    }

    /// Checks the matrix group `group` as `read_matrix` of libfclib reads it: square, of a side
    /// that is a multiple of `d`, its arrays of the lengths its storage implies; returns the
    /// side.
    fn check_matrix(&self, group: &str, d: c_int) -> Result<usize, String> {
        let field = |f: &str| format!("{group}/{f}");
        let [nzmax, m, n, nz] = ["nzmax", "m", "n", "nz"].map(|f| self.int(&field(f)));
        let (nzmax, m, n, nz) = (nzmax?, m?, n?, nz?);
        if m <= 0 || m != n || m % d != 0 {
            return Err(format!(
                "{group} is {m} x {n}: not square of a positive side that is a multiple of \
                 spacedim {d}"
            ));
        }
        if nzmax < 0 {
            return Err(format!("{group}: nzmax is {nzmax}"));
        }
        let (nzmax, side) = (nonnegative(nzmax), nonnegative(m));
        let [p, i, x] = match nz {
            -1 | -2 => [side + 1, nzmax, nzmax],
            nz if nz >= 0 && nonnegative(nz) <= nzmax => [nonnegative(nz); 3],
            nz => {
                return Err(format!(
                    "{group}: nz = {nz} (nzmax {nzmax}) is no FCLIB storage"
                ));
            }
        };
        self.sized(&field("p"), p)?;
        self.sized(&field("i"), i)?;
        self.sized(&field("x"), x)?;
        if self.exists(&field("conditioning")) {
            for f in ["conditioning", "determinant", "rank"] {
                self.sized(&field(f), 1)?;
            }
            self.optional_string(&field("comment"))?;
        }
        Ok(side)
    }
}

impl Drop for H5File {
    fn drop(&mut self) {
        // SAFETY: an id from H5Fopen, closed once.
        unsafe { sys::H5Fclose(self.0) };
    }
}

/// The C string of one of libfclib's `char *` fields (empty if null).
///
/// # Safety
/// `p` is null or a NUL-terminated string.
unsafe fn text(p: *const c_char) -> String {
    if p.is_null() {
        return String::new();
    }
    // SAFETY: the caller's contract.
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}
