//! The C ABI called the way a host code calls it: through the `extern "C"` functions with raw
//! pointers, lengths and integer enums, including every bad-input path. The C and C++ programs
//! of `c_examples/` are compiled and run by CMake's ctest (shared, static, valgrind, ASan).

use crate::common::last_error;
use hycon::element::{self, ElementMatrix, Formulation};
use hycon::ffi::*;
use hycon::{Analysis, Material};
use std::ffi::CStr;
use std::ptr;

const SQUARE: [f64; 8] = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
const STEEL: HyconMaterial = HyconMaterial {
    youngs: 210e3,
    poisson: 0.3,
    thickness: 1.0,
    analysis: HYCON_PLANE_STRAIN,
};
const SENTINEL: f64 = 12345.0;

/// Assert a status and that the last error message contains `part`.
#[track_caller]
fn assert_status(got: HyconStatus, want: HyconStatus, part: &str) {
    let message = last_error();
    assert_eq!(got, want, "status {got} (message: {message:?})");
    assert!(message.contains(part), "message {message:?} lacks {part:?}");
    if want != HYCON_OK {
        assert!(
            message.starts_with("hycon_"),
            "{message:?} names no function"
        );
    }
}

fn stiffness(kind: i32, coords: &[f64], m: &HyconMaterial, out: &mut [f64]) -> HyconStatus {
    // SAFETY: `coords` holds `coords.len() / 2` nodes, `out` is writable for its length.
    unsafe {
        hycon_element_stiffness(
            kind,
            coords.len() / 2,
            coords.as_ptr(),
            m,
            out.as_mut_ptr(),
            out.len(),
        )
    }
}

fn check(kind: i32, coords: &[f64]) -> HyconStatus {
    // SAFETY: `coords` holds `coords.len() / 2` nodes.
    unsafe { hycon_element_check(kind, coords.len() / 2, coords.as_ptr()) }
}

#[test]
fn version_matches_package() {
    let mut v = [-1i32; 3];
    // SAFETY: `v` holds 3 writable values.
    assert_eq!(unsafe { hycon_version(v.as_mut_ptr()) }, HYCON_OK);
    let pkg: Vec<i32> = env!("CARGO_PKG_VERSION")
        .split('.')
        .map(|p| p.parse().unwrap())
        .collect();
    assert_eq!(v.to_vec(), pkg);
    assert_eq!(
        [
            HYCON_VERSION_MAJOR,
            HYCON_VERSION_MINOR,
            HYCON_VERSION_PATCH
        ],
        v
    );
    assert_eq!(HYCON_VERSION, v[0] * 10000 + v[1] * 100 + v[2]);
    // SAFETY: NULL is allowed and rejected.
    assert_status(
        unsafe { hycon_version(ptr::null_mut()) },
        HYCON_ERROR_NULL_POINTER,
        "out is NULL",
    );
}

#[test]
fn material_layout_is_c_layout() {
    assert_eq!(size_of::<HyconMaterial>(), 32);
    assert_eq!(align_of::<HyconMaterial>(), 8);
    assert_eq!(std::mem::offset_of!(HyconMaterial, youngs), 0);
    assert_eq!(std::mem::offset_of!(HyconMaterial, poisson), 8);
    assert_eq!(std::mem::offset_of!(HyconMaterial, thickness), 16);
    assert_eq!(std::mem::offset_of!(HyconMaterial, analysis), 24);
}

/// The C entry point returns exactly what the safe Rust API computes (bit for bit), row-major.
#[test]
fn stiffness_matches_safe_api_bit_for_bit() {
    // 4 corners plus 2 mid-side nodes on straight edges
    let hexagon = [0.0, 0.0, 1.0, 0.1, 2.0, 0.2, 2.1, 1.1, 1.0, 1.05, -0.1, 1.0];
    let pentagon = [0.0, 0.0, 1.0, 0.0, 2.0, 0.0, 2.1, 1.3, 0.2, 1.0];
    let skewed = [0.0, 0.0, 2.0, 0.3, 2.4, 1.9, -0.2, 1.1];
    let cases: [(i32, Formulation, &[f64]); 7] = [
        (HYCON_ELEMENT_HYBRID, Formulation::Hybrid, &skewed),
        (HYCON_ELEMENT_HYBRID, Formulation::Hybrid, &pentagon),
        (HYCON_ELEMENT_HYBRID, Formulation::Hybrid, &hexagon),
        (
            HYCON_ELEMENT_PIAN_SUMIHARA,
            Formulation::PianSumihara,
            &skewed,
        ),
        (HYCON_ELEMENT_Q4, Formulation::Q4, &skewed),
        (HYCON_ELEMENT_Q4, Formulation::Q4, &SQUARE),
        (
            HYCON_ELEMENT_PIAN_SUMIHARA,
            Formulation::PianSumihara,
            &SQUARE,
        ),
    ];
    for analysis in [HYCON_PLANE_STRAIN, HYCON_PLANE_STRESS] {
        let m = HyconMaterial {
            youngs: 3.5,
            poisson: 0.49,
            thickness: 0.7,
            analysis,
        };
        let material = Material::new(
            3.5,
            0.49,
            0.7,
            if analysis == HYCON_PLANE_STRAIN {
                Analysis::PlaneStrain
            } else {
                Analysis::PlaneStress
            },
        )
        .unwrap();
        for (kind, formulation, coords) in cases {
            let n = coords.len() / 2;
            let nodes: Vec<[f64; 2]> = coords.chunks(2).map(|c| [c[0], c[1]]).collect();
            let mut expected = ElementMatrix::zeros();
            let n_dof =
                element::stiffness_into(formulation, &nodes, &material, &mut expected).unwrap();
            assert_eq!(n_dof, 2 * n);
            let mut k = vec![SENTINEL; n_dof * n_dof];
            assert_status(stiffness(kind, coords, &m, &mut k), HYCON_OK, "");
            for i in 0..n_dof {
                for j in 0..n_dof {
                    assert_eq!(
                        k[i * n_dof + j].to_bits(),
                        expected[(i, j)].to_bits(),
                        "{formulation:?} n={n} K[{i}][{j}]"
                    );
                }
            }
        }
    }
}

#[test]
fn null_pointers_are_rejected_and_outputs_untouched() {
    let mut k = [SENTINEL; 64];
    // SAFETY (all calls below): NULL pointers are allowed and must be rejected; the other
    // pointers are valid for the lengths passed.
    unsafe {
        assert_status(
            hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, ptr::null(), &STEEL, k.as_mut_ptr(), 64),
            HYCON_ERROR_NULL_POINTER,
            "coords is NULL",
        );
        assert_status(
            hycon_element_stiffness(
                HYCON_ELEMENT_Q4,
                4,
                SQUARE.as_ptr(),
                ptr::null(),
                k.as_mut_ptr(),
                64,
            ),
            HYCON_ERROR_NULL_POINTER,
            "material is NULL",
        );
        assert_status(
            hycon_element_stiffness(
                HYCON_ELEMENT_Q4,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                ptr::null_mut(),
                64,
            ),
            HYCON_ERROR_NULL_POINTER,
            "k_out is NULL",
        );
        let q = [0.0; 8];
        let mut out = [SENTINEL; 3];
        assert_status(
            hycon_element_stress(
                HYCON_ELEMENT_HYBRID,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q.as_ptr(),
                0.5,
                0.5,
                ptr::null_mut(),
            ),
            HYCON_ERROR_NULL_POINTER,
            "out is NULL",
        );
        let mut beta = [SENTINEL; 12];
        assert_status(
            hycon_element_stress_params(
                HYCON_ELEMENT_HYBRID,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q.as_ptr(),
                ptr::null_mut(),
                12,
                ptr::null_mut(),
            ),
            HYCON_ERROR_NULL_POINTER,
            "out is NULL but len is 12",
        );
        // `needed` is optional (NULL: not wanted); a misaligned one is rejected by name
        let mut words = [0usize; 2];
        let misaligned = words
            .as_mut_ptr()
            .cast::<u8>()
            .wrapping_add(1)
            .cast::<usize>();
        assert_status(
            hycon_element_stress_params(
                HYCON_ELEMENT_HYBRID,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q.as_ptr(),
                beta.as_mut_ptr(),
                12,
                misaligned,
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "needed is misaligned",
        );
        assert!(beta.iter().all(|&v| v == SENTINEL));
        assert_eq!(
            hycon_element_stress_params(
                HYCON_ELEMENT_HYBRID,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q.as_ptr(),
                beta.as_mut_ptr(),
                12,
                ptr::null_mut(),
            ),
            HYCON_OK
        );
        beta = [SENTINEL; 12];
        assert_status(
            hycon_element_edge_traction(
                HYCON_ELEMENT_HYBRID,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                ptr::null(),
                0,
                0.5,
                out.as_mut_ptr(),
            ),
            HYCON_ERROR_NULL_POINTER,
            "q is NULL",
        );
        assert!(out.iter().chain(&beta).all(|&v| v == SENTINEL));
    }
    assert!(k.iter().all(|&v| v == SENTINEL));
}

#[test]
fn lengths_are_checked() {
    let mut k = [SENTINEL; 64];
    assert_status(
        stiffness(HYCON_ELEMENT_HYBRID, &SQUARE, &STEEL, &mut k[..63]),
        HYCON_ERROR_BUFFER_TOO_SMALL,
        "k_out has length 63, 64 needed",
    );
    assert_status(
        stiffness(HYCON_ELEMENT_HYBRID, &SQUARE, &STEEL, &mut k[..0]),
        HYCON_ERROR_BUFFER_TOO_SMALL,
        "64 needed",
    );
    assert!(k.iter().all(|&v| v == SENTINEL));
    // (NULL, 0) is an empty array: too small, not a null pointer
    // SAFETY: (NULL, 0) is a valid empty output.
    let st = unsafe {
        hycon_element_stiffness(
            HYCON_ELEMENT_Q4,
            4,
            SQUARE.as_ptr(),
            &STEEL,
            ptr::null_mut(),
            0,
        )
    };
    assert_status(st, HYCON_ERROR_BUFFER_TOO_SMALL, "k_out");
    // node counts: checked before any coordinate is read (the pointer is only 4 nodes long)
    assert_status(
        stiffness(HYCON_ELEMENT_Q4, &SQUARE[..6], &STEEL, &mut k),
        HYCON_ERROR_BAD_ELEMENT,
        "3 nodes, this formulation takes 4",
    );
    // SAFETY: the node count is rejected before `coords` is read.
    let st = unsafe { hycon_element_check(HYCON_ELEMENT_HYBRID, 1 << 40, SQUARE.as_ptr()) };
    assert_status(st, HYCON_ERROR_BAD_ELEMENT, "takes 4 to 6");
    // SAFETY: as above.
    let st = unsafe { hycon_element_check(HYCON_ELEMENT_HYBRID, 0, ptr::null()) };
    assert_status(st, HYCON_ERROR_BAD_ELEMENT, "0 nodes");
    // beta buffer
    let q = [0.0, 0.0, 1e-3, 0.0, 1e-3, 0.0, 0.0, 0.0];
    let mut beta = [SENTINEL; 12];
    let mut n_beta = 99usize;
    // SAFETY: all pointers valid for the lengths passed.
    let st = unsafe {
        hycon_element_stress_params(
            HYCON_ELEMENT_PIAN_SUMIHARA,
            4,
            SQUARE.as_ptr(),
            &STEEL,
            q.as_ptr(),
            beta.as_mut_ptr(),
            4,
            &mut n_beta,
        )
    };
    assert_status(
        st,
        HYCON_ERROR_BUFFER_TOO_SMALL,
        "out has length 4, 5 needed",
    );
    assert_eq!(n_beta, 5); // `needed` is written on HYCON_ERROR_BUFFER_TOO_SMALL
    assert!(beta.iter().all(|&v| v == SENTINEL));
    // the size query writes `needed` only
    n_beta = 99;
    // SAFETY: all pointers valid for the lengths passed.
    let st = unsafe {
        hycon_element_stress_params(
            HYCON_ELEMENT_PIAN_SUMIHARA,
            4,
            SQUARE.as_ptr(),
            &STEEL,
            q.as_ptr(),
            ptr::null_mut(),
            0,
            &mut n_beta,
        )
    };
    assert_eq!(st, HYCON_OK);
    assert_eq!(n_beta, 5);
}

#[test]
fn non_finite_values_are_rejected() {
    let mut k = [SENTINEL; 64];
    for (i, bad) in [(3, f64::NAN), (0, f64::INFINITY), (7, f64::NEG_INFINITY)] {
        let mut c = SQUARE;
        c[i] = bad;
        assert_status(
            stiffness(HYCON_ELEMENT_HYBRID, &c, &STEEL, &mut k),
            HYCON_ERROR_INVALID_ARGUMENT,
            &format!("coords[{i}]"),
        );
        assert_status(
            check(HYCON_ELEMENT_Q4, &c),
            HYCON_ERROR_INVALID_ARGUMENT,
            "not finite",
        );
    }
    let q = [0.0; 8];
    let mut out = [SENTINEL; 3];
    let mut q_nan = q;
    q_nan[5] = f64::NAN;
    // SAFETY: all pointers valid for the lengths passed.
    unsafe {
        assert_status(
            hycon_element_stress(
                HYCON_ELEMENT_Q4,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q.as_ptr(),
                0.5,
                f64::NAN,
                out.as_mut_ptr(),
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "py = NaN",
        );
        assert_status(
            hycon_element_stress(
                HYCON_ELEMENT_Q4,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q_nan.as_ptr(),
                0.5,
                0.5,
                out.as_mut_ptr(),
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "q[5]",
        );
        assert_status(
            hycon_element_edge_traction(
                HYCON_ELEMENT_Q4,
                4,
                SQUARE.as_ptr(),
                &STEEL,
                q.as_ptr(),
                2,
                f64::NAN,
                out.as_mut_ptr(),
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "s = NaN",
        );
    }
    assert!(k.iter().chain(&out).all(|&v| v == SENTINEL));
}

#[test]
fn bad_enums_are_rejected() {
    let mut k = [SENTINEL; 64];
    for kind in [0, 4, -1, i32::MAX] {
        assert_status(
            stiffness(kind, &SQUARE, &STEEL, &mut k),
            HYCON_ERROR_INVALID_ARGUMENT,
            &format!("unknown element kind {kind}"),
        );
    }
    let mut m = STEEL;
    m.analysis = 0;
    assert_status(
        stiffness(HYCON_ELEMENT_Q4, &SQUARE, &m, &mut k),
        HYCON_ERROR_INVALID_MATERIAL,
        "unknown analysis 0",
    );
    m.analysis = HYCON_AXISYMMETRIC + 1;
    assert_status(
        stiffness(HYCON_ELEMENT_Q4, &SQUARE, &m, &mut k),
        HYCON_ERROR_INVALID_MATERIAL,
        "HYCON_AXISYMMETRIC = 3",
    );
    assert!(k.iter().all(|&v| v == SENTINEL));
}

#[test]
fn bad_materials_are_rejected() {
    let mut k = [SENTINEL; 64];
    type Spoil = fn(&mut HyconMaterial);
    let variants: [(Spoil, &str); 6] = [
        (|m| m.youngs = 0.0, "Young's modulus"),
        (|m| m.youngs = -5.0, "Young's modulus"),
        (|m| m.poisson = 0.5, "Poisson's ratio"),
        (|m| m.poisson = -1.0, "Poisson's ratio"),
        (|m| m.thickness = 0.0, "thickness"),
        (|m| m.youngs = f64::NAN, "non-finite"),
    ];
    for (spoil, part) in variants {
        let mut m = STEEL;
        spoil(&mut m);
        for kind in [
            HYCON_ELEMENT_HYBRID,
            HYCON_ELEMENT_PIAN_SUMIHARA,
            HYCON_ELEMENT_Q4,
        ] {
            assert_status(
                stiffness(kind, &SQUARE, &m, &mut k),
                HYCON_ERROR_INVALID_MATERIAL,
                part,
            );
        }
    }
    assert!(k.iter().all(|&v| v == SENTINEL));
}

#[test]
fn bad_shapes_give_bad_element_with_a_readable_message() {
    let clockwise = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0];
    let collinear = [0.0, 0.0, 1.0, 0.0, 2.0, 0.0, 3.0, 0.0];
    let coincident = [0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0];
    let dart = [0.0, 0.0, 2.0, 0.0, 0.5, 0.5, 0.0, 2.0];
    let mut k = [SENTINEL; 64];
    for kind in [
        HYCON_ELEMENT_HYBRID,
        HYCON_ELEMENT_PIAN_SUMIHARA,
        HYCON_ELEMENT_Q4,
    ] {
        assert_status(
            stiffness(kind, &clockwise, &STEEL, &mut k),
            HYCON_ERROR_BAD_ELEMENT,
            "inverted element (nodes must be counter-clockwise)",
        );
        assert_status(
            check(kind, &collinear),
            HYCON_ERROR_BAD_ELEMENT,
            "degenerate",
        );
        assert_status(
            check(kind, &coincident),
            HYCON_ERROR_BAD_ELEMENT,
            "degenerate",
        );
        assert_status(
            stiffness(kind, &dart, &STEEL, &mut k),
            HYCON_ERROR_BAD_ELEMENT,
            "non-convex element (interior angle above 180 degrees at local node 2)",
        );
        assert_status(check(kind, &SQUARE), HYCON_OK, "");
    }
    assert!(k.iter().all(|&v| v == SENTINEL));
}

#[test]
fn message_buffer_protocol() {
    assert_ne!(stiffness(0, &SQUARE, &STEEL, &mut [0.0; 64]), HYCON_OK);
    let full = last_error();
    let needed = full.len() + 1;
    let mut buf = [b'x' as std::ffi::c_char; 8];
    // SAFETY (all calls): `buf` is writable for the lengths passed; NULL only with the query.
    unsafe {
        assert_eq!(hycon_last_error_message(ptr::null_mut(), 0), needed);
        assert_eq!(hycon_last_error_message(ptr::null_mut(), 100), needed);
        assert_eq!(hycon_last_error_message(buf.as_mut_ptr(), 0), needed);
        assert_eq!(buf[0], b'x' as std::ffi::c_char, "len 0 writes nothing");
        assert_eq!(hycon_last_error_message(buf.as_mut_ptr(), 1), needed);
        assert_eq!(buf[0], 0);
        assert_eq!(hycon_last_error_message(buf.as_mut_ptr(), 8), needed);
        let truncated = CStr::from_ptr(buf.as_ptr()).to_str().unwrap();
        assert_eq!(truncated, &full[..7]);
    }
    assert!(full.starts_with("hycon_element_stiffness: unknown element kind 0"));
    // reading does not clear; a successful call does
    assert_eq!(last_error(), full);
    assert_eq!(check(HYCON_ELEMENT_Q4, &SQUARE), HYCON_OK);
    assert_eq!(last_error(), "");
}

#[test]
fn last_error_is_thread_local() {
    assert_ne!(check(0, &SQUARE), HYCON_OK);
    let here = last_error();
    std::thread::spawn(|| {
        assert_eq!(last_error(), "", "a new thread starts without an error");
        assert_ne!(check(HYCON_ELEMENT_Q4, &SQUARE[..6]), HYCON_OK);
        assert!(last_error().contains("3 nodes"));
    })
    .join()
    .unwrap();
    assert_eq!(last_error(), here);
}

#[test]
fn element_routines_are_thread_safe() {
    let threads: Vec<_> = (0..4)
        .map(|t| {
            std::thread::spawn(move || {
                let coords = [0.0, 0.0, 1.0 + t as f64, 0.0, 1.0, 1.0, 0.0, 1.0];
                let mut first = [0.0; 64];
                assert_eq!(
                    stiffness(HYCON_ELEMENT_HYBRID, &coords, &STEEL, &mut first),
                    0
                );
                for _ in 0..200 {
                    let mut k = [0.0; 64];
                    assert_eq!(stiffness(HYCON_ELEMENT_HYBRID, &coords, &STEEL, &mut k), 0);
                    assert_eq!(k, first);
                }
            })
        })
        .collect();
    for t in threads {
        t.join().unwrap();
    }
}

/// Axisymmetric mode (`HYCON_AXISYMMETRIC`): the stiffness equals the safe API's bit for bit,
/// `hycon_element_stress` writes 4 components (`{sigma_r, sigma_z, tau_rz, sigma_theta}`, and
/// not one more), `hycon_element_stress_components` says 4 (3 in plane), the hybrid element has
/// 7 beta; a thickness other than 1, Pian-Sumihara, a 5-node element and a node at `r < 0` are
/// rejected with messages that say why.
#[test]
fn axisymmetric_element_routines() {
    const AXI: HyconMaterial = HyconMaterial {
        youngs: 1000.0,
        poisson: 0.49,
        thickness: 1.0,
        analysis: HYCON_AXISYMMETRIC,
    };
    let coords = [0.0, 0.0, 2.0, 0.3, 2.4, 1.9, 0.0, 1.1]; // two nodes on the axis
    let nodes: Vec<[f64; 2]> = coords.chunks(2).map(|c| [c[0], c[1]]).collect();
    let q = [0.0, 0.0, 0.01, 0.002, 0.013, -0.004, 0.0, -0.003];
    let material = Material::new(1000.0, 0.49, 1.0, Analysis::Axisymmetric).unwrap();
    for (kind, f) in [
        (HYCON_ELEMENT_HYBRID, Formulation::Hybrid),
        (HYCON_ELEMENT_Q4, Formulation::Q4),
    ] {
        let mut k = [SENTINEL; 65];
        assert_status(stiffness(kind, &coords, &AXI, &mut k), HYCON_OK, "");
        let mut safe = ElementMatrix::zeros();
        element::stiffness_into(f, &nodes, &material, &mut safe).unwrap();
        for i in 0..8 {
            for j in 0..8 {
                assert_eq!(k[i * 8 + j], safe[(i, j)], "{f:?} ({i}, {j})");
            }
        }
        assert_eq!(k[64], SENTINEL);
        let field = element::recover_stress(f, &nodes, &material, &q).unwrap();
        let mut s = [SENTINEL; 5];
        let mut beta = [SENTINEL; HYCON_MAX_BETA];
        let mut n_beta = 0usize;
        // SAFETY: all pointers valid for the lengths documented (4 stress values here).
        unsafe {
            let ptrs = (coords.as_ptr(), &AXI as *const HyconMaterial, q.as_ptr());
            assert_status(
                hycon_element_stress(kind, 4, ptrs.0, ptrs.1, ptrs.2, 1.1, 0.8, s.as_mut_ptr()),
                HYCON_OK,
                "",
            );
            assert_status(
                hycon_element_stress_params(
                    kind,
                    4,
                    ptrs.0,
                    ptrs.1,
                    ptrs.2,
                    beta.as_mut_ptr(),
                    beta.len(),
                    &mut n_beta,
                ),
                HYCON_OK,
                "",
            );
        }
        assert_eq!(s[..4], field.at_full([1.1, 0.8]), "{f:?}");
        assert_eq!(s[4], SENTINEL, "{f:?}: a fifth value written");
        assert_eq!(n_beta, if f == Formulation::Hybrid { 7 } else { 0 });
    }
    let mut count = 0usize;
    // SAFETY: valid material and output.
    unsafe {
        assert_status(
            hycon_element_stress_components(&AXI, &mut count),
            HYCON_OK,
            "",
        );
        assert_eq!(count, 4);
        assert_status(
            hycon_element_stress_components(&STEEL, &mut count),
            HYCON_OK,
            "",
        );
        assert_eq!(count, 3);
        assert_status(
            hycon_element_stress_components(ptr::null(), &mut count),
            HYCON_ERROR_NULL_POINTER,
            "material is NULL",
        );
    }
    let mut k = [SENTINEL; 144];
    let thick = HyconMaterial {
        thickness: 2.0,
        ..AXI
    };
    assert_status(
        stiffness(HYCON_ELEMENT_HYBRID, &coords, &thick, &mut k),
        HYCON_ERROR_INVALID_MATERIAL,
        "2 pi r",
    );
    assert_status(
        stiffness(HYCON_ELEMENT_PIAN_SUMIHARA, &coords, &AXI, &mut k),
        HYCON_ERROR_BAD_ELEMENT,
        "not available in axisymmetric analysis",
    );
    let five = [1.0, 0.0, 1.5, 0.0, 2.0, 0.0, 2.0, 1.0, 1.0, 1.0];
    assert_status(
        stiffness(HYCON_ELEMENT_HYBRID, &five, &AXI, &mut k),
        HYCON_ERROR_BAD_ELEMENT,
        "4-node elements only",
    );
    let left = [-1.0, 0.0, 1.0, 0.0, 1.0, 1.0, -1.0, 1.0];
    assert_status(
        stiffness(HYCON_ELEMENT_Q4, &left, &AXI, &mut k),
        HYCON_ERROR_BAD_ELEMENT,
        "negative radius",
    );
    assert!(k.iter().all(|&v| v == SENTINEL), "written on an error");
}

/// The model API takes one analysis kind per model: an axisymmetric model is accepted, one whose
/// materials mix axisymmetric and plane strain is rejected (`HYCON_ERROR_INVALID_MATERIAL`), and
/// Pian-Sumihara in axisymmetry is `HYCON_ERROR_BAD_ELEMENT`.
#[test]
fn model_api_takes_one_analysis_kind() {
    const AXI: HyconMaterial = HyconMaterial {
        youngs: 1000.0,
        poisson: 0.3,
        thickness: 1.0,
        analysis: HYCON_AXISYMMETRIC,
    };
    let coords = [0.0, 0.0, 1.0, 0.0, 2.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 1.0];
    let offsets = [0usize, 4, 8];
    let nodes = [0usize, 1, 4, 3, 1, 2, 5, 4];
    let which = [0usize, 1];
    let new_model = |kind: i32, materials: &[HyconMaterial]| -> HyconStatus {
        let block = HyconElementBlock {
            offsets: offsets.as_ptr(),
            nodes: nodes.as_ptr(),
            n_elements: 2,
            materials: which.as_ptr(),
            kind,
        };
        let mut model: *mut HyconModel = ptr::null_mut();
        // SAFETY: all arrays hold the stated counts; the handle is freed below.
        unsafe {
            let st = hycon_model_new(
                &mut model,
                coords.as_ptr(),
                6,
                &block,
                materials.as_ptr(),
                materials.len(),
            );
            hycon_model_free(model);
            st
        }
    };
    assert_status(new_model(HYCON_ELEMENT_HYBRID, &[AXI, AXI]), HYCON_OK, "");
    assert_status(
        new_model(HYCON_ELEMENT_HYBRID, &[AXI, STEEL]),
        HYCON_ERROR_INVALID_MATERIAL,
        "one model takes one analysis kind",
    );
    assert_status(
        new_model(HYCON_ELEMENT_PIAN_SUMIHARA, &[AXI, AXI]),
        HYCON_ERROR_BAD_ELEMENT,
        "element 0: the Pian-Sumihara element is not available in axisymmetric analysis",
    );
}

#[test]
fn stress_routines_agree_with_safe_api() {
    let coords = [0.0, 0.0, 2.0, 0.3, 2.4, 1.9, -0.2, 1.1];
    let nodes: Vec<[f64; 2]> = coords.chunks(2).map(|c| [c[0], c[1]]).collect();
    let q = [0.0, 0.0, 0.01, 0.002, 0.013, -0.004, 0.001, -0.003];
    let material = Material::new(210e3, 0.3, 1.0, Analysis::PlaneStrain).unwrap();
    for (kind, f) in [
        (HYCON_ELEMENT_HYBRID, Formulation::Hybrid),
        (HYCON_ELEMENT_PIAN_SUMIHARA, Formulation::PianSumihara),
        (HYCON_ELEMENT_Q4, Formulation::Q4),
    ] {
        let field = element::recover_stress(f, &nodes, &material, &q).unwrap();
        let p = [1.1, 0.8];
        let mut s = [0.0; 3];
        let mut t = [0.0; 2];
        let mut beta = [SENTINEL; HYCON_MAX_BETA];
        let mut n_beta = 0usize;
        // SAFETY: all pointers valid for the lengths documented.
        unsafe {
            let ptrs = (coords.as_ptr(), &STEEL as *const HyconMaterial, q.as_ptr());
            assert_eq!(
                hycon_element_stress(kind, 4, ptrs.0, ptrs.1, ptrs.2, p[0], p[1], s.as_mut_ptr()),
                HYCON_OK
            );
            assert_eq!(
                hycon_element_edge_traction(
                    kind,
                    4,
                    ptrs.0,
                    ptrs.1,
                    ptrs.2,
                    2,
                    0.25,
                    t.as_mut_ptr()
                ),
                HYCON_OK
            );
            assert_eq!(
                hycon_element_stress_params(
                    kind,
                    4,
                    ptrs.0,
                    ptrs.1,
                    ptrs.2,
                    beta.as_mut_ptr(),
                    beta.len(),
                    &mut n_beta
                ),
                HYCON_OK
            );
        }
        assert_eq!(s, field.at(p), "{f:?}");
        assert_eq!(t, field.edge_traction(2, 0.25), "{f:?}");
        assert_eq!(&beta[..n_beta], field.beta(), "{f:?}");
        assert!(beta[n_beta..].iter().all(|&v| v == SENTINEL));
        let expected_n_beta = match f {
            Formulation::Hybrid => 7,
            Formulation::PianSumihara => 5,
            Formulation::Q4 => 0,
        };
        assert_eq!(n_beta, expected_n_beta);
    }
    // edge index and parameter range
    let mut t = [SENTINEL; 2];
    // SAFETY: all pointers valid for the lengths documented.
    unsafe {
        assert_status(
            hycon_element_edge_traction(
                HYCON_ELEMENT_HYBRID,
                4,
                coords.as_ptr(),
                &STEEL,
                q.as_ptr(),
                4,
                0.5,
                t.as_mut_ptr(),
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "edge 4 of a 4-node element",
        );
        assert_status(
            hycon_element_edge_traction(
                HYCON_ELEMENT_HYBRID,
                4,
                coords.as_ptr(),
                &STEEL,
                q.as_ptr(),
                0,
                -0.5,
                t.as_mut_ptr(),
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "outside [0, 1]",
        );
    }
    assert_eq!(t, [SENTINEL; 2]);
}

#[test]
fn status_names() {
    let name = |s| {
        // SAFETY: the function returns a static NUL-terminated string.
        unsafe { CStr::from_ptr(hycon_status_name(s)) }
            .to_str()
            .unwrap()
    };
    assert_eq!(name(HYCON_OK), "HYCON_OK");
    assert_eq!(name(HYCON_ERROR_NULL_POINTER), "HYCON_ERROR_NULL_POINTER");
    assert_eq!(
        name(HYCON_ERROR_BUFFER_TOO_SMALL),
        "HYCON_ERROR_BUFFER_TOO_SMALL"
    );
    assert_eq!(name(HYCON_ERROR_PANIC), "HYCON_ERROR_PANIC");
    assert_eq!(name(3), "HYCON_WARNING");
    assert_eq!(name(-50), "HYCON_ERROR_UNKNOWN");
    let codes = [
        HYCON_ERROR_NULL_POINTER,
        HYCON_ERROR_INVALID_ARGUMENT,
        HYCON_ERROR_INVALID_MATERIAL,
        HYCON_ERROR_BAD_ELEMENT,
        HYCON_ERROR_SINGULAR,
        HYCON_ERROR_SOLVER,
        HYCON_ERROR_BUFFER_TOO_SMALL,
        HYCON_ERROR_CONTACT,
        HYCON_ERROR_PANIC,
    ];
    for (i, &c) in codes.iter().enumerate() {
        assert!(c < 0, "errors are negative");
        assert!(codes[i + 1..].iter().all(|&d| d != c), "codes are distinct");
        assert!(name(c).starts_with("HYCON_ERROR_") && name(c) != "HYCON_ERROR_UNKNOWN");
    }
}
