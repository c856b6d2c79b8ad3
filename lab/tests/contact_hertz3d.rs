//! Hertz's sphere in 3D, the first 3D contact analysis end to end (issue #43): the quarter cap
//! on the block of `hycon_lab::hertz3d` (frictionless, small kinematics, one increment by
//! Hertz's approach of the target radius), compared with `hycon_lab::closed3d` at the
//! computed load, with the finite bodies' reference load of the approach, and with hycon's
//! axisymmetric sphere.
//!
//! Measured (`cargo test -p hycon-lab --test lab contact_hertz3d:: -- --nocapture
//! --include-ignored`, or `hycon bench hertz3d --radial`), relative to Hertz at the computed
//! load (`a`, `p0` from the pressure's moments, `p(0)` the centre node's), the load against
//! Hertz's of the approach and against the finite bodies' reference `P*`:
//!
//! | E_cap/E_block | a/h | a | p0 | p(0) | L2 of p | P / P_H - 1 | P / P* - 1 | active A nodes | iterations |
//! |---|---|---|---|---|---|---|---|---|---|
//! | 1 | 4 | -1.00% | +1.95% | +0.58% | 11.1% | +5.79% | -0.32% | 15 | 6 |
//! | 1 | 8 | -0.47% | +0.86% | +0.49% | 6.54% | +6.53% | +0.34% | 58 | 6 |
//! | 1e-2 | 4 | -1.01% | +1.97% | +0.64% | 11.1% | +5.79% | -0.83% | 15 | 6 |
//! | 1e-2 | 8 | -0.44% | +0.80% | +0.45% | 6.49% | +6.50% | -0.22% | 58 | 6 |
//!
//! The radius and the pressure converge; the load of the approach stays some 6% above Hertz's,
//! the finite bodies' stiffening (`hycon_lab::hertz3d`'s module docs), and within 1% of the
//! finite bodies' reference. Finite kinematics (the geometry at the current positions in
//! every iteration, tractions per current area) adds effects of the order of the surface
//! strain `a / R = 1/16` to the small-strain model.

use hycon::contact::iteration::{ContactOptions, Kinematics};
use hycon::contact::space::Vector;
use hycon::solid::contact_meshes::{CapModel, CapOnBlock};
use hycon_lab::hertz3d::{CapComparison, QuarterCap};

/// Press the quarter cap at `a_over_h`, `E_cap / E_block = ratio` (small kinematics), check
/// that B's forces balance A's (the patch-test condition `sum_b M_kb = sum_j D_kj` of every
/// covered node), print the comparison.
fn press(a_over_h: usize, ratio: f64) -> (QuarterCap, CapComparison) {
    let spec = CapOnBlock::new(CapModel::Quarter, a_over_h);
    press_with(spec, ratio, ContactOptions::default())
}

fn press_with(
    spec: CapOnBlock,
    ratio: f64,
    options: ContactOptions,
) -> (QuarterCap, CapComparison) {
    let mut cap = QuarterCap::with(spec, ratio, options).unwrap();
    let c = cap.press().unwrap();
    let total = |forces: &mut dyn Iterator<Item = Vector>| {
        forces.fold([0.0; 3], |s, f| {
            std::array::from_fn(|i| s[i] + f.components()[i])
        })
    };
    let a = cap.analysis.node_results(0).unwrap();
    let b = cap.analysis.b_node_results(0).unwrap();
    let on_a = total(&mut a.iter().map(|r| r.force));
    let on_b = total(&mut b.iter().map(|r| r.force));
    for i in 0..3 {
        assert!(
            (on_a[i] + on_b[i]).abs() < 1e-12 * c.load,
            "{on_a:?} {on_b:?}"
        );
    }
    let e = c.errors();
    println!(
        "{} a/h = {}, E_cap/E_block = {ratio:e}, block {} a: P = {:.6e} (Hertz {:.6e} at the \
         approach, {:+.4}), a = {:.6e} (Hertz {:.6e} at P, {:+.4}), p0 {:+.4} from the \
         moments, {:+.4} at the centre, L2 {:.4}, |p - p_H| / p0 within a/2 {:.4}, {} active A \
         nodes, {} iterations",
        options.kinematics.name(),
        spec.a_over_h,
        spec.block_extent,
        c.load,
        c.hertz_load,
        e[2],
        c.radius,
        c.hertz.radius,
        e[0],
        c.peak_error(),
        e[1],
        c.l2_error,
        c.interior,
        c.active,
        c.iterations
    );
    (cap, c)
}

/// `P / P* - 1` and `c P / delta` of a pressed cap (`hycon_lab::hertz3d::QuarterCap::load_check`).
fn load_check(cap: &QuarterCap, c: &CapComparison) -> (f64, f64) {
    let check = cap.load_check(c, &cap.linear(c.load).unwrap());
    println!(
        "P / P* - 1 = {:+.4}, c P / delta = {:+.4}",
        check.error(),
        check.finite_share / check.approach
    );
    (check.error(), check.finite_share / check.approach)
}

/// At `a/h = 4` (a few seconds each), identical materials and a cap 100 times softer than the
/// block: the radius from the moments within 2% and the peak within 3% of Hertz at the
/// computed load (measured -1.0% and +2.0%), the centre node's pressure within 1.5% (+0.6%),
/// the L2 error within 13% (11.1%), the pressure within `a / 2` within 6% of `p0` node by node
/// (4.3%); the load above Hertz's for the approach by less than the finite bodies' 10%
/// (+5.8%), and within 1.5% of the finite bodies' reference `P*` (-0.3% and -0.8%), their
/// share of the approach between -2% and -8% (-4.0%, -4.4%). A missing symmetry factor (the
/// quarter's load taken as the whole: Hertz's radius 37% smaller), `E*` of the wrong bodies
/// (a radius 3.7 times off), a wrong weight or normal breaks them.
#[test]
fn the_quarter_cap_matches_hertz() {
    for ratio in [1.0, 1e-2] {
        let (cap, c) = press(4, ratio);
        let [radius, peak, load] = c.errors();
        assert!(radius.abs() < 0.02, "{c:?}");
        assert!(c.peak_error().abs() < 0.03, "{c:?}");
        assert!(peak.abs() < 0.015, "{c:?}");
        assert!(c.l2_error < 0.13, "{c:?}");
        assert!(c.interior < 0.06, "{c:?}");
        assert!(load > 0.0 && load < 0.10, "{c:?}");
        assert!(c.iterations <= 10, "{c:?}");
        let (error, share) = load_check(&cap, &c);
        assert!(error.abs() < 0.015, "{c:?}: P / P* - 1 = {error}");
        assert!(
            (-0.08..-0.02).contains(&share),
            "{c:?}: c P / delta = {share}"
        );
    }
}

/// The pressure at the cap's nodes along `x` against hycon's axisymmetric sphere (same `R/a`,
/// `a/h`, moduli) pressed to the same load: its nodes at the same radii, its load matched to
/// 1e-3, the pressures within 0.15 p0 at `a/h = 4` (measured 0.10: the axisymmetric pressure
/// oscillates about Hertz's by that much at 4 nodes per radius, its axis node 8% low).
#[test]
fn the_pressure_along_a_radius_matches_the_axisymmetric_sphere() {
    let (cap, c) = press(4, 1.0);
    let radial = cap.radial_comparison(&c).unwrap();
    println!("{:?}", radial.rows);
    assert_eq!(radial.offset, 0.0);
    assert!(radial.load_mismatch().abs() < 1e-3, "{radial:?}");
    assert_eq!(radial.rows.len(), 4, "{radial:?}");
    let diff = radial.max_difference(c.hertz.peak);
    assert!(diff < 0.15, "{diff}: {radial:?}");
}

/// A block twice as wide and deep (32 a) takes away part of the finite bodies' stiffening:
/// the load of the approach comes nearer to Hertz's (measured +5.8% to +4.4%) and the finite
/// bodies' share of the approach shrinks (-4.0% to -3.1%: the block's half of it halves,
/// Boussinesq's `1 / z`), while `P*` still holds within 1.5% (measured -0.30%).
#[test]
fn a_larger_block_brings_the_load_nearer_to_hertz() {
    let (_, small) = press(4, 1.0);
    let spec = CapOnBlock {
        block_extent: 32.0,
        ..CapOnBlock::new(CapModel::Quarter, 4)
    };
    let (cap, large) = press_with(spec, 1.0, ContactOptions::default());
    assert!(
        large.errors()[2] < small.errors()[2] - 0.005,
        "{small:?} {large:?}"
    );
    assert!(large.errors()[2] > 0.0, "{large:?}");
    let (error, _) = load_check(&cap, &large);
    assert!(error.abs() < 0.015, "{large:?}: P / P* - 1 = {error}");
}

/// Finite kinematics on the same cap (its symmetry planes included: A's faces there are
/// projected along their normals turned into the planes, `FaceGeometry`): it converges, and
/// differs from small kinematics by less than `a / R = 6%`: all within 2% here.
#[test]
fn finite_kinematics_agrees_with_small() {
    let (_, small) = press(4, 1.0);
    let (_, finite) = press_with(
        CapOnBlock::new(CapModel::Quarter, 4),
        1.0,
        ContactOptions {
            kinematics: Kinematics::Finite,
            ..ContactOptions::default()
        },
    );
    for (f, s) in [
        (finite.radius, small.radius),
        (finite.peak, small.peak),
        (finite.load, small.load),
    ] {
        assert!(
            (f / s - 1.0).abs() < 0.02,
            "small {small:?}, finite {finite:?}"
        );
    }
    assert_eq!(finite.active, small.active);
}

/// Refined to `a/h = 8` the radius within 1% and the peak within 1.5% of Hertz (issue #43;
/// measured -0.47% and +0.86%), every error smaller than at 4 (the radius, the peak from the
/// moments and at the centre, the L2 error, the pressure within `a / 2`), the load of the
/// approach within 1% of the coarse one (it is the finite bodies', not the mesh's), and the
/// pressure along `x` within 0.04 p0 of the axisymmetric sphere's (measured 0.026, at the
/// axis node). Ignored: 30 s in the test profile; run with `--include-ignored`.
#[test]
#[ignore = "30 s in the test profile"]
fn the_quarter_cap_converges_to_hertz() {
    let ((_, coarse), (cap, fine)) = (press(4, 1.0), press(8, 1.0));
    let [c, f] = [coarse, fine].map(|p| p.errors());
    let pair = format!("a/h 4: {coarse:?}, a/h 8: {fine:?}");
    assert!(
        f[0].abs() < 0.01 && fine.peak_error().abs() < 0.015,
        "{pair}"
    );
    assert!(f[0].abs() < c[0].abs() && f[1].abs() < c[1].abs(), "{pair}");
    assert!(
        fine.peak_error().abs() < coarse.peak_error().abs(),
        "{pair}"
    );
    assert!(fine.l2_error < coarse.l2_error, "{pair}");
    assert!(fine.interior < coarse.interior, "{pair}");
    assert!((fine.load / coarse.load - 1.0).abs() < 0.01, "{pair}");
    let radial = cap.radial_comparison(&fine).unwrap();
    let diff = radial.max_difference(fine.hertz.peak);
    assert!(diff < 0.04, "{diff}: {radial:?}");
}
