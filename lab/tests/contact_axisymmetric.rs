//! Axisymmetric contact (`x = r`, `y = z`, measure `2 pi r`, tractions as pressures) against
//! closed forms: two cylinders stacked on the axis (a contact zone centred on the axis: no
//! spurious pressure at `r = 0`), the shrink fit of two thick tubes (Lamé; docs/validation.md's
//! data), and pushing the fit out (gross slip: axial force = mu times the normal force). Scenes
//! and closed forms in `hycon_lab::axisymmetric`.

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, Kinematics, NodeState};
use hycon_lab::axisymmetric::{ShrinkFit, StackedCylinders, shrink_fit_pressure};

/// Stacked cylinders: the exact contact pressure is the applied `p` at every A node, the node
/// on the axis included (its weight `integral M 2 pi r ds > 0`, its rows regular: the small
/// system's condition estimate stays moderate). Non-matching meshes (A finer, coarser, equal),
/// both kinematics. Tolerance: 1e-9 of `p` (round-off of a linear solve; measured below 1e-12).
#[test]
fn stacked_cylinders_carry_the_pressure_through_the_axis() {
    for (n_lower, n_upper) in [(8, 5), (5, 8), (6, 6)] {
        for kinematics in [Kinematics::Small, Kinematics::Finite] {
            let p = 1e-3;
            let scene = StackedCylinders {
                radius: 1.0,
                n_lower,
                n_upper,
                pressure: p,
                gap: 1e-4,
            }
            .build()
            .unwrap();
            let options = ContactOptions {
                kinematics,
                tolerance: 1e-10,
                ..Default::default()
            };
            let mut analysis =
                ContactAnalysis::new(scene.model.clone(), vec![scene.pair.clone()], options)
                    .unwrap();
            analysis
                .increment(
                    &scene.model.external_forces(),
                    &scene.model.prescribed_values(),
                )
                .unwrap();
            let nodes = analysis.node_results(0).unwrap();
            // under finite kinematics the tractions are per current area: the interface
            // widened by eps_r = nu p / E (uniaxial), its area by (1 + eps_r)^2
            let expected = match kinematics {
                Kinematics::Small => p,
                Kinematics::Finite => p / (1.0 + 0.3 * p).powi(2),
            };
            let worst = nodes
                .iter()
                .map(|n| (-n.tn / expected - 1.0).abs())
                .fold(0.0, f64::max);
            let axis = nodes.iter().find(|n| n.position[0].abs() < 1e-12).unwrap();
            let condition = analysis
                .records()
                .iter()
                .map(|r| r.condition)
                .fold(1.0, f64::max);
            println!(
                "{n_lower}/{n_upper} {kinematics:?}: max |p_h/p - 1| = {worst:.1e}, axis node p = {:.12e} weight {:.3e}, condition {condition:.1e}",
                -axis.tn, axis.weight
            );
            assert!(nodes.iter().all(|n| n.state != NodeState::Open));
            assert!(
                worst < 1e-9,
                "{n_lower}/{n_upper} {kinematics:?}: {worst:e}"
            );
            assert!(axis.weight > 0.0);
            assert!(condition < 1e8, "{condition:e}");
        }
    }
}

/// The shrink fit (docs/validation.md, "Shrink fit of two tubes": a = 0.5, b = 1, c = 2, E = 1, nu = 0.3, delta = 1e-3, ends
/// held axially, frictionless, small kinematics). The interface pressure on the outer bore (A,
/// the multiplier side) against Lamé's for the radii modelled (the inner tube's outside at
/// b + delta) within 1e-6 at every node and every mesh; against the textbook formula (p =
/// 3.2967032967e-4, the limit delta -> 0) within 0.1% (it differs from the modelled radii's by
/// O(delta / b)); with delta = 1e-6 (scaled back by 1e3) within 1e-5 of the textbook value.
/// Hoop stresses at the element centres converge to Lamé's: the largest error (relative to p)
/// falls with nr = 4, 8, 16 and is below 2% at 16.
#[test]
fn shrink_fit_against_lame() {
    let p_book = 3.2967032967e-4;
    assert!((shrink_fit_pressure(0.5, 1.0, 2.0, 1.0, 0.3, 1e-3) / p_book - 1.0).abs() < 1e-10);
    let mut hoop = Vec::new();
    for nr in [4, 8, 16] {
        let def = ShrinkFit {
            nr,
            ..Default::default()
        };
        let scene = def.build().unwrap();
        let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
        let f = vec![0.0; scene.model.external_forces().len()];
        let info = analysis
            .increment(&f, &scene.model.prescribed_values())
            .unwrap();
        let nodes = analysis.node_results(0).unwrap();
        let exact = scene.exact.outer;
        let (lo, hi) = nodes.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), n| {
            (lo.min(-n.tn), hi.max(-n.tn))
        });
        let worst = nodes
            .iter()
            .map(|n| (-n.tn / exact - 1.0).abs())
            .fold(0.0, f64::max);
        let q = analysis.displacement().unwrap().to_vec();
        let h = scene.hoop_error(&q).unwrap();
        hoop.push(h);
        println!(
            "nr {nr}: p in [{lo:.10e}, {hi:.10e}], Lame (modelled radii) {exact:.10e}, max rel {worst:.1e}, vs book {:+.3e}, hoop err/p {h:.2e}, it {}",
            hi / p_book - 1.0,
            info.iterations
        );
        assert!(worst < 1e-6, "nr {nr}: {worst:e}");
        assert!((hi / p_book - 1.0).abs() < 1e-3 && (lo / p_book - 1.0).abs() < 1e-3);
    }
    assert!(hoop[1] < hoop[0] && hoop[2] < hoop[1], "{hoop:?}");
    assert!(hoop[2] < 0.02, "{hoop:?}");
    // a tiny interference: the textbook value itself
    let scene = ShrinkFit {
        interference: 1e-6,
        ..Default::default()
    }
    .build()
    .unwrap();
    let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
    let f = vec![0.0; scene.model.external_forces().len()];
    analysis
        .increment(&f, &scene.model.prescribed_values())
        .unwrap();
    for n in analysis.node_results(0).unwrap() {
        let p = -n.tn * 1e3;
        assert!((p / p_book - 1.0).abs() < 1e-5, "{p:e}");
    }
}

/// Pushing the fit out: after the shrink fit (mu = 0.2), the inner tube's ends move axially
/// (the outer's stay held) in increments; once every node slips (gross slip) the axial force
/// on the inner tube (its end reactions) is mu times the total normal force, to round-off
/// (1e-9), and the friction tractions are mu times the pressures node by node.
#[test]
fn push_out_at_gross_slip() {
    let mu = 0.2;
    let scene = ShrinkFit {
        friction: mu,
        ..Default::default()
    }
    .build()
    .unwrap();
    let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
    let f = vec![0.0; scene.model.external_forces().len()];
    analysis
        .increment(&f, &scene.model.prescribed_values())
        .unwrap();
    let mut slipping = false;
    for step in 1..=4 {
        let push = 2.5e-4 * step as f64;
        let info = analysis.increment(&f, &scene.pushed(push)).unwrap();
        let nodes = analysis.node_results(0).unwrap();
        let normal: f64 = nodes
            .iter()
            .map(|n| -(n.frame.normal().dot(&n.force)))
            .sum();
        let q = analysis.displacement().unwrap().to_vec();
        // the end reactions: K q minus the contact forces at the (contact) end nodes
        let kq = scene.model.internal_forces(&q).unwrap();
        let fc = analysis.contact_forces();
        let axial: f64 = scene
            .inner_ends
            .iter()
            .map(|&i| kq[2 * i + 1] - fc[2 * i + 1])
            .sum();
        let slip = nodes
            .iter()
            .filter(|n| matches!(n.state, NodeState::Slip { .. }))
            .count();
        println!(
            "push {push:.1e}: slip {slip}/{}, axial {axial:.10e}, mu N {:.10e}, ratio - 1 = {:+.1e}, it {}",
            nodes.len(),
            mu * normal,
            axial.abs() / (mu * normal) - 1.0,
            info.iterations
        );
        if slip == nodes.len() {
            slipping = true;
            assert!((axial.abs() / (mu * normal) - 1.0).abs() < 1e-9);
            for n in &nodes {
                assert!((n.ts.norm() - mu * n.tn.abs()).abs() <= 1e-12 * n.tn.abs());
            }
        }
    }
    assert!(slipping, "the fit never slipped as a whole");
}

/// Hertz, sphere on a half-space (`SphereOnBlock`: R/a = 32, block 4R, graded quads, 16
/// cells per size band, approach `a^2 / R` in one increment, small kinematics, frictionless),
/// compared with Hertz at the computed load P (full circle):
/// * `a` from the pressure's moments on `r dr` (`a^2 = 5 M3 / (2 M1)`) and `p0` from them
///   (`p0 = 6 M1^2 / (5 M3) = 3 P / (2 pi a^2)`): within 0.1% at n = 64 for modulus ratios 1,
///   1e-2, 1e-4;
/// * `p(0)`, the multiplier of the node on the axis (zero-slope shapes on the axis segment:
///   `hycon::contact::plane::mortar`, "Nodes on the axis"): within 0.45% at n = 64 (measured
///   -0.39%, -0.43%, -0.44% for the three ratios; the linear hats gave -0.52%, -0.54%,
///   -0.54%) and falling with n. It still lags its neighbours (within 0.1%): the axis node's
///   equivalent nodal force, Q4 and hybrid alike, is low by O(h) against theirs;
/// * the L2 error over `r dr` falls with n (16 -> 32 -> 64) and is below 1.5% at n = 64.
#[test]
fn sphere_hertz() {
    use hycon_lab::axisymmetric::SphereOnBlock;
    for ratio in [1.0, 1e-2, 1e-4] {
        let mut l2 = Vec::new();
        let mut axis = Vec::new();
        for n in [16, 32, 64] {
            let scene = SphereOnBlock {
                elements_per_radius: n,
                radius_over_contact: 32.0,
                modulus_ratio: ratio,
            }
            .build()
            .unwrap();
            let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
            let f = vec![0.0; scene.model.external_forces().len()];
            let info = analysis
                .increment(&f, &scene.prescribed(scene.hertz_approach()))
                .unwrap();
            let c = scene.compare(&analysis).unwrap();
            let rel = |u: f64, v: f64| u / v - 1.0;
            println!(
                "E ratio {ratio:e}, n {n}: elements {} a/a_target {:.3} | a {:+.3}% | p0 (moments) {:+.3}% | p(0) {:+.3}% | L2 {:.3}% | active {} | it {}",
                scene.model.mesh.n_elements(),
                c.hertz.radius / scene.target,
                100.0 * rel(c.radius, c.hertz.radius),
                100.0 * rel(c.peak_from_moments, c.hertz.peak),
                100.0 * rel(c.peak, c.hertz.peak),
                100.0 * c.l2_error,
                c.active,
                info.iterations
            );
            l2.push(c.l2_error);
            axis.push(rel(c.peak, c.hertz.peak).abs());
            if n == 64 {
                assert!(rel(c.radius, c.hertz.radius).abs() < 1e-3, "{c:?}");
                assert!(rel(c.peak_from_moments, c.hertz.peak).abs() < 1e-3, "{c:?}");
                assert!(axis[2] < 4.5e-3, "{c:?}");
                assert!(c.l2_error < 0.015, "{c:?}");
            }
        }
        assert!(l2[1] < l2[0] && l2[2] < l2[1], "{l2:?}");
        assert!(axis[1] < axis[0] && axis[2] < axis[1], "{axis:?}");
    }
}

/// Hertz's sphere, the L2 error over `r dr` averaged over where the contact edge falls
/// between two nodes (`SphereOnBlock::edge_sweep`, 4 places per element, equal moduli; as
/// `hycon bench edge` does for the plane scene; `hycon bench sphere-edge` prints 8 places):
/// the mean falls with n = 16, 32, 64 at a least-squares rate of at least 0.9 (measured 0.98
/// with 8 places), and R/a = 32 and 64 are within 0.05 points of L2 of each other at n = 64
/// (measured 0.001 with 8 places; a single edge position differs by up to 0.05 points).
#[test]
fn sphere_l2_over_edge_positions() {
    use hycon_lab::axisymmetric::SphereOnBlock;
    let mut at_64 = Vec::new();
    for r_over_a in [32.0, 64.0] {
        let mut means = Vec::new();
        for n in [16, 32, 64] {
            let runs = SphereOnBlock {
                elements_per_radius: n,
                radius_over_contact: r_over_a,
                modulus_ratio: 1.0,
            }
            .edge_sweep(4)
            .unwrap();
            let l2: Vec<f64> = runs.iter().map(|r| r.comparison.l2_error).collect();
            let edges: Vec<f64> = runs.iter().map(|r| r.edge_position()).collect();
            // the places asked for: (j + 1/2) / 4, to the load's round-off
            for (j, e) in edges.iter().enumerate() {
                assert!((e - (j as f64 + 0.5) / 4.0).abs() < 0.02, "{edges:?}");
            }
            let mean = l2.iter().sum::<f64>() / l2.len() as f64;
            println!(
                "R/a {r_over_a}, n {n}: L2 {l2:.5?}, mean {:.3}%",
                100.0 * mean
            );
            means.push((n as f64, mean));
        }
        let (rate, _, _) = hycon_lab::bench::fit_power(&means).unwrap();
        println!("R/a {r_over_a}: rate {:.3}", -rate);
        assert!(-rate >= 0.9, "R/a {r_over_a}: rate {}", -rate);
        at_64.push(means[2].1);
    }
    assert!(
        (at_64[0] - at_64[1]).abs() < 5e-4,
        "R/a 32 and 64 at n = 64: {at_64:?}"
    );
}

/// The Hertz sphere with friction (`mu = 0.3`, n = 16, approach `a^2 / R`, small
/// kinematics, modulus ratios 1 and 1e-2): it converges, the node on the axis closes
/// frictionless (`tau_rz(0) = 0` by symmetry, `ts = 0`; 0.7.0 gave it a stick row, which
/// this mesh survived, B being as fine as A there, but the random problems' coarser B did
/// not: a singular contact system) and every other closed node keeps the friction law. With
/// equal moduli (Dundurs' `beta = 0`: the shear does not couple into the normal problem) `a`
/// and `p0` are those of the frictionless sphere to 1e-4 (measured 3e-7 and 2e-6; the two
/// meshes differ, so not exactly); at ratio 1e-2 (`beta = 0.28`) friction lowers `a` by 2.2%
/// and raises `p0` by 6.4% (2.4% and 6.7% at n = 64: not the discretisation; printed).
#[test]
fn frictional_sphere() {
    use hycon_lab::axisymmetric::SphereOnBlock;
    for ratio in [1.0, 1e-2] {
        let base = SphereOnBlock {
            elements_per_radius: 16,
            radius_over_contact: 32.0,
            modulus_ratio: ratio,
        }
        .build()
        .unwrap();
        let mut results = Vec::new();
        for mu in [0.0, 0.3] {
            let mut scene = base.clone();
            scene.pair.friction = mu;
            let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
            let f = vec![0.0; scene.model.external_forces().len()];
            let info = analysis
                .increment(&f, &scene.prescribed(scene.hertz_approach()))
                .unwrap();
            let c = scene.compare(&analysis).unwrap();
            let nodes = analysis.node_results(0).unwrap();
            let (stick, slip) = nodes.iter().fold((0, 0), |(st, sl), n| match n.state {
                NodeState::Stick => (st + 1, sl),
                NodeState::Slip { .. } => (st, sl + 1),
                _ => (st, sl),
            });
            println!(
                "E ratio {ratio:e}, mu {mu}: P {:.6e} a/a_H {:.6} p0/p0_H {:.6} p(0)/p0_H {:.6} | stick {stick} slip {slip} active {} | max |ts|/p0 {:.2e} | it {}",
                c.load,
                c.radius / c.hertz.radius,
                c.peak_from_moments / c.hertz.peak,
                c.peak / c.hertz.peak,
                c.active,
                nodes.iter().fold(0.0f64, |m, n| m.max(n.ts.norm())) / c.hertz.peak,
                info.iterations
            );
            if mu > 0.0 {
                let axis = nodes
                    .iter()
                    .find(|n| scene.model.mesh.nodes[n.node][0] == 0.0);
                let axis = axis.unwrap();
                assert_eq!(axis.state, NodeState::Frictionless, "{axis:?}");
                assert!(axis.tn < 0.0 && axis.ts.norm() == 0.0, "{axis:?}");
                assert!(stick > 0, "{nodes:?}");
                for n in &nodes {
                    assert!(n.ts.norm() <= mu * n.tn.abs() * (1.0 + 1e-9), "{n:?}");
                }
            }
            results.push(c);
        }
        let rel = |u: f64, v: f64| (u / v - 1.0).abs();
        let (a, p0) = (
            rel(results[1].radius, results[0].radius),
            rel(results[1].peak_from_moments, results[0].peak_from_moments),
        );
        println!("E ratio {ratio:e}: friction changes a by {a:.2e}, p0 by {p0:.2e}");
        if ratio == 1.0 {
            assert!(a < 1e-4 && p0 < 1e-4, "{results:?}");
        }
    }
}
