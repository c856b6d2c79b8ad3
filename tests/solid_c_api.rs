//! The brick routines of the C ABI, called as a C host would: statuses, messages, the size
//! convention, and the numbers against the Rust kernels.

use crate::common::last_error;
use hycon::ffi::*;
use hycon::solid::{self, BrickFormulation, Isotropic};
use std::ptr::{null, null_mut};

const CUBE: [f64; 24] = [
    0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 1.0, 0.0, //
    0.0, 0.0, 1.5, 2.0, 0.0, 1.5, 2.0, 1.0, 1.5, 0.0, 1.0, 1.5,
];

fn nodes() -> [[f64; 3]; 8] {
    std::array::from_fn(|k| [CUBE[3 * k], CUBE[3 * k + 1], CUBE[3 * k + 2]])
}

#[test]
fn stiffness_matches_the_kernel() {
    let m = HyconSolidMaterial {
        youngs: 1000.0,
        poisson: 0.3,
    };
    let iso = Isotropic::new(1000.0, 0.3).unwrap();
    for (kind, f) in [
        (HYCON_BRICK_HYBRID18, BrickFormulation::Hybrid18),
        (HYCON_BRICK_H8, BrickFormulation::H8),
    ] {
        let mut k = vec![0.0; 576];
        // SAFETY: arrays of the documented sizes.
        let status = unsafe { hycon_brick_stiffness(kind, CUBE.as_ptr(), &m, k.as_mut_ptr(), 576) };
        assert_eq!(status, HYCON_OK, "{}", last_error());
        let mut expect = solid::BrickMatrix::zeros();
        solid::stiffness_into(f, &nodes(), &iso, &mut expect).unwrap();
        for i in 0..24 {
            for j in 0..24 {
                assert_eq!(k[i * 24 + j], expect[(i, j)]);
            }
        }
        // too small a buffer
        // SAFETY: as above, with a shorter length.
        let status = unsafe { hycon_brick_stiffness(kind, CUBE.as_ptr(), &m, k.as_mut_ptr(), 575) };
        assert_eq!(status, HYCON_ERROR_BUFFER_TOO_SMALL);
        assert!(last_error().contains("576"), "{}", last_error());
    }
}

#[test]
fn stresses_and_tractions_from_a_uniform_stretch() {
    let m = HyconSolidMaterial {
        youngs: 1000.0,
        poisson: 0.25,
    };
    // u = 1e-3 x: sxx = (lambda + 2 mu) 1e-3, syy = szz = lambda 1e-3
    let (lambda, mu) = (400.0, 400.0);
    let mut q = [0.0; 24];
    for k in 0..8 {
        q[3 * k] = 1e-3 * CUBE[3 * k];
    }
    let sxx = (lambda + 2.0 * mu) * 1e-3;
    for kind in [HYCON_BRICK_HYBRID18, HYCON_BRICK_H8] {
        let mut s = [0.0; 6];
        // SAFETY: arrays of the documented sizes.
        let status = unsafe {
            hycon_brick_stress(
                kind,
                CUBE.as_ptr(),
                &m,
                q.as_ptr(),
                0.3,
                0.2,
                1.1,
                s.as_mut_ptr(),
            )
        };
        assert_eq!(status, HYCON_OK, "{}", last_error());
        assert!((s[0] - sxx).abs() < 1e-12 && (s[1] - lambda * 1e-3).abs() < 1e-12);
        let mut t = [0.0; 3];
        // face 1 is xi = +1 (x = 2): traction (sxx, 0, 0)
        // SAFETY: as above.
        let status = unsafe {
            hycon_brick_face_traction(
                kind,
                CUBE.as_ptr(),
                &m,
                q.as_ptr(),
                1,
                0.5,
                -0.5,
                t.as_mut_ptr(),
            )
        };
        assert_eq!(status, HYCON_OK, "{}", last_error());
        assert!((t[0] - sxx).abs() < 1e-12 && t[1].abs() < 1e-12 && t[2].abs() < 1e-12);
        // SAFETY: as above.
        let status = unsafe {
            hycon_brick_face_traction(
                kind,
                CUBE.as_ptr(),
                &m,
                q.as_ptr(),
                6,
                0.0,
                0.0,
                t.as_mut_ptr(),
            )
        };
        assert_eq!(status, HYCON_ERROR_INVALID_ARGUMENT);
        // the size query, then the values
        let mut needed = usize::MAX;
        // SAFETY: the size query.
        let status = unsafe {
            hycon_brick_stress_params(
                kind,
                CUBE.as_ptr(),
                &m,
                q.as_ptr(),
                null_mut(),
                0,
                &mut needed,
            )
        };
        assert_eq!(status, HYCON_OK);
        let count = if kind == HYCON_BRICK_HYBRID18 { 18 } else { 0 };
        assert_eq!(needed, count);
        let mut beta = [0.0; HYCON_BRICK_MAX_BETA];
        // SAFETY: a buffer of HYCON_BRICK_MAX_BETA doubles.
        let status = unsafe {
            hycon_brick_stress_params(
                kind,
                CUBE.as_ptr(),
                &m,
                q.as_ptr(),
                beta.as_mut_ptr(),
                18,
                null_mut(),
            )
        };
        assert_eq!(status, HYCON_OK);
        if count > 0 {
            assert!((beta[0] - sxx).abs() < 1e-12);
        }
    }
}

#[test]
fn bad_inputs_are_statuses() {
    let m = HyconSolidMaterial {
        youngs: 1000.0,
        poisson: 0.3,
    };
    // SAFETY: a valid brick.
    assert_eq!(
        unsafe { hycon_brick_check(HYCON_BRICK_HYBRID18, CUBE.as_ptr()) },
        HYCON_OK
    );
    // SAFETY: NULL is checked.
    assert_eq!(
        unsafe { hycon_brick_check(HYCON_BRICK_H8, null()) },
        HYCON_ERROR_NULL_POINTER
    );
    // SAFETY: a valid array; the kind is checked.
    assert_eq!(
        unsafe { hycon_brick_check(7, CUBE.as_ptr()) },
        HYCON_ERROR_INVALID_ARGUMENT
    );
    let mut swapped = CUBE;
    swapped.rotate_left(12); // top face first: inverted
    // SAFETY: a valid array.
    assert_eq!(
        unsafe { hycon_brick_check(HYCON_BRICK_H8, swapped.as_ptr()) },
        HYCON_ERROR_BAD_ELEMENT
    );
    assert!(last_error().contains("inverted"), "{}", last_error());
    let mut nan = CUBE;
    nan[5] = f64::NAN;
    // SAFETY: a valid array.
    assert_eq!(
        unsafe { hycon_brick_check(HYCON_BRICK_H8, nan.as_ptr()) },
        HYCON_ERROR_INVALID_ARGUMENT
    );
    let bad = HyconSolidMaterial {
        youngs: 1000.0,
        poisson: 0.5,
    };
    let mut k = vec![0.0; 576];
    // SAFETY: arrays of the documented sizes.
    let status = unsafe {
        hycon_brick_stiffness(
            HYCON_BRICK_HYBRID18,
            CUBE.as_ptr(),
            &bad,
            k.as_mut_ptr(),
            576,
        )
    };
    assert_eq!(status, HYCON_ERROR_INVALID_MATERIAL);
    // SAFETY: NULL output with a length is checked.
    let status =
        unsafe { hycon_brick_stiffness(HYCON_BRICK_HYBRID18, CUBE.as_ptr(), &m, null_mut(), 576) };
    assert_eq!(status, HYCON_ERROR_NULL_POINTER);
    assert!(k.iter().all(|&v| v == 0.0), "outputs untouched on error");
}

/// MacNeal-Harder's 3D patch mesh, front brick (`tests/solid_validation.rs`): `det J < 0` at its
/// corner node 7, positive at the integration points; its face 0 warped by 48 degrees.
const FRONT: [f64; 24] = [
    0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.826, 0.288, 0.288, 0.249, 0.342, 0.192, //
    0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.677, 0.305, 0.683, 0.320, 0.186, 0.643,
];

/// The shape policy from C: the default warns (outputs written, status 1, a message naming the
/// corner and the face with their measures), strict is 0.8's error; every brick routine warns
/// alike and writes what the Rust kernel computes.
#[test]
fn shape_policy_warns_or_rejects() {
    let unset = HyconShapeReport {
        integration_jacobian: f64::NAN,
        corner_jacobian: f64::NAN,
        warp_degrees: f64::NAN,
        corner: 99,
        face: 99,
        warnings: -1,
    };
    let mut report = unset;
    // SAFETY: 24 readable doubles, a writable report.
    let status = unsafe {
        hycon_brick_shape(
            HYCON_BRICK_H8,
            FRONT.as_ptr(),
            HYCON_SHAPE_INTEGRATION_POINTS,
            &mut report,
        )
    };
    assert_eq!(status, HYCON_WARNING_SHAPE);
    let text = last_error();
    assert!(
        text.starts_with("hycon_brick_shape: warning: Jacobian not positive at local node 7")
            && text.contains("face 0 is warped by 48.0 degrees"),
        "{text}"
    );
    assert_eq!(
        (report.corner, report.face, report.warnings),
        (7, 0, HYCON_SHAPE_CORNER_JACOBIAN | HYCON_SHAPE_WARPED_FACE)
    );
    assert!(
        (report.corner_jacobian + 0.00158).abs() < 5e-6,
        "{report:?}"
    );
    assert!((report.integration_jacobian - 0.00634).abs() < 5e-6);
    assert!((report.warp_degrees - 48.0).abs() < 0.05);
    // SAFETY: `hycon_status_name` returns a static string.
    let name = unsafe { std::ffi::CStr::from_ptr(hycon_status_name(status)) };
    assert_eq!(name.to_str().unwrap(), "HYCON_WARNING_SHAPE");
    // strict: 0.8's error, report untouched
    let mut strict = unset;
    // SAFETY: as above.
    let status = unsafe {
        hycon_brick_shape(
            HYCON_BRICK_H8,
            FRONT.as_ptr(),
            HYCON_SHAPE_STRICT,
            &mut strict,
        )
    };
    assert_eq!(status, HYCON_ERROR_BAD_ELEMENT);
    assert!(
        last_error().starts_with("hycon_brick_shape: Jacobian not positive at local node 7 ("),
        "{}",
        last_error()
    );
    assert_eq!(strict.warnings, -1, "report untouched on error");
    // a clean brick: OK under both, no warnings, empty message
    for policy in [HYCON_SHAPE_INTEGRATION_POINTS, HYCON_SHAPE_STRICT] {
        // SAFETY: as above.
        let status =
            unsafe { hycon_brick_shape(HYCON_BRICK_HYBRID18, CUBE.as_ptr(), policy, &mut report) };
        assert_eq!(
            (status, report.warnings, last_error()),
            (HYCON_OK, 0, String::new())
        );
        assert!((report.warp_degrees).abs() < 1e-12 && report.corner_jacobian > 0.0);
    }
    // bad arguments: policy 0 (a zeroed value), a misaligned report, NULL coordinates; a NULL
    // report is allowed
    // SAFETY: as above.
    let status = unsafe { hycon_brick_shape(HYCON_BRICK_H8, CUBE.as_ptr(), 0, &mut report) };
    assert_eq!(status, HYCON_ERROR_INVALID_ARGUMENT);
    assert!(
        last_error().contains("unknown shape policy 0"),
        "{}",
        last_error()
    );
    let misaligned = std::ptr::from_mut(&mut report)
        .cast::<u8>()
        .wrapping_add(1)
        .cast::<HyconShapeReport>();
    // SAFETY: the misaligned pointer is refused before any write.
    let status = unsafe {
        hycon_brick_shape(
            HYCON_BRICK_H8,
            CUBE.as_ptr(),
            HYCON_SHAPE_STRICT,
            misaligned,
        )
    };
    assert_eq!(status, HYCON_ERROR_INVALID_ARGUMENT);
    // SAFETY: NULL coordinates are checked.
    let status =
        unsafe { hycon_brick_shape(HYCON_BRICK_H8, null(), HYCON_SHAPE_STRICT, &mut report) };
    assert_eq!(status, HYCON_ERROR_NULL_POINTER);
    // SAFETY: a NULL report is "not wanted".
    let status = unsafe {
        hycon_brick_shape(
            HYCON_BRICK_H8,
            FRONT.as_ptr(),
            HYCON_SHAPE_STRICT,
            null_mut(),
        )
    };
    assert_eq!(status, HYCON_ERROR_BAD_ELEMENT);
    // SAFETY: as above.
    let status = unsafe { hycon_brick_check(HYCON_BRICK_H8, FRONT.as_ptr()) };
    assert_eq!(status, HYCON_WARNING_SHAPE);
    assert!(
        last_error().starts_with("hycon_brick_check: warning: "),
        "{}",
        last_error()
    );

    // the element routines: the warning, and the kernel's numbers
    let m = HyconSolidMaterial {
        youngs: 1e6,
        poisson: 0.25,
    };
    let iso = Isotropic::new(1e6, 0.25).unwrap();
    let x: [[f64; 3]; 8] =
        std::array::from_fn(|k| [FRONT[3 * k], FRONT[3 * k + 1], FRONT[3 * k + 2]]);
    let mut q = [0.0; 24];
    for k in 0..8 {
        let [a, b, c] = x[k];
        q[3 * k..3 * k + 3].copy_from_slice(&[
            1e-3 * (2.0 * a + b + c) / 2.0,
            1e-3 * (a + 2.0 * b + c) / 2.0,
            1e-3 * (a + b + 2.0 * c) / 2.0,
        ]);
    }
    for (kind, f) in [
        (HYCON_BRICK_HYBRID18, BrickFormulation::Hybrid18),
        (HYCON_BRICK_H8, BrickFormulation::H8),
    ] {
        let mut k = vec![0.0; 576];
        // SAFETY: arrays of the documented sizes.
        let status =
            unsafe { hycon_brick_stiffness(kind, FRONT.as_ptr(), &m, k.as_mut_ptr(), 576) };
        assert_eq!(status, HYCON_WARNING_SHAPE, "{}", last_error());
        assert!(last_error().starts_with("hycon_brick_stiffness: warning: Jacobian"));
        let mut expect = solid::BrickMatrix::zeros();
        let shape = solid::stiffness_into(f, &x, &iso, &mut expect).unwrap();
        assert_eq!(shape.warnings().count(), 2);
        for i in 0..24 {
            for j in 0..24 {
                assert_eq!(k[i * 24 + j], expect[(i, j)]);
            }
        }
        // the patch field's stress, exact in this brick alone
        let mut s = [0.0; 6];
        // SAFETY: arrays of the documented sizes.
        let status = unsafe {
            hycon_brick_stress(
                kind,
                FRONT.as_ptr(),
                &m,
                q.as_ptr(),
                0.5,
                0.2,
                0.5,
                s.as_mut_ptr(),
            )
        };
        assert_eq!(status, HYCON_WARNING_SHAPE);
        for (got, want) in s.iter().zip([2000.0, 2000.0, 2000.0, 400.0, 400.0, 400.0]) {
            assert!((got - want).abs() < 1e-10 * 2000.0, "{s:?}");
        }
        let mut t = [0.0; 3];
        // SAFETY: arrays of the documented sizes.
        let status = unsafe {
            hycon_brick_face_traction(
                kind,
                FRONT.as_ptr(),
                &m,
                q.as_ptr(),
                4,
                0.0,
                0.0,
                t.as_mut_ptr(),
            )
        };
        assert_eq!(status, HYCON_WARNING_SHAPE);
        let mut beta = [0.0; HYCON_BRICK_MAX_BETA];
        let mut needed = 0;
        // SAFETY: a buffer of HYCON_BRICK_MAX_BETA doubles.
        let status = unsafe {
            hycon_brick_stress_params(
                kind,
                FRONT.as_ptr(),
                &m,
                q.as_ptr(),
                beta.as_mut_ptr(),
                18,
                &mut needed,
            )
        };
        assert_eq!(status, HYCON_WARNING_SHAPE);
        assert_eq!(needed, f.n_beta());
        // the load and check routines warn the same way, with their results written
        let mut s = [0.0; 6];
        // SAFETY: arrays of the documented sizes.
        let status = unsafe {
            hycon_brick_stress_natural(
                kind,
                FRONT.as_ptr(),
                &m,
                q.as_ptr(),
                0.1,
                -0.2,
                0.3,
                s.as_mut_ptr(),
            )
        };
        assert_eq!(status, HYCON_WARNING_SHAPE);
        assert!((s[0] - 2000.0).abs() < 1e-10 * 2000.0, "{s:?}");
        let (mut volume, mut quality) = (0.0, 1.0);
        // SAFETY: one writable double each.
        let status = unsafe { hycon_brick_volume(kind, FRONT.as_ptr(), &mut volume) };
        assert_eq!(status, HYCON_WARNING_SHAPE);
        assert_eq!(volume, solid::quality::volume(&x).unwrap());
        // SAFETY: as above.
        let status = unsafe { hycon_brick_quality(kind, FRONT.as_ptr(), &mut quality) };
        assert_eq!(status, HYCON_WARNING_SHAPE);
        assert!(quality <= 0.0, "a non-positive corner Jacobian: {quality}");
        let mut f24 = [0.0; 24];
        // SAFETY: a uniform pressure of 4 values, 24 writable doubles.
        let status = unsafe {
            hycon_brick_face_load(
                kind,
                FRONT.as_ptr(),
                0,
                [1.0; 4].as_ptr(),
                null(),
                f24.as_mut_ptr(),
                24,
            )
        };
        assert_eq!(status, HYCON_WARNING_SHAPE, "{}", last_error());
        assert!(last_error().starts_with("hycon_brick_face_load: warning: "));
    }
}
