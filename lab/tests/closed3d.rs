//! The closed forms of the 3D contact validation (`hycon_lab::closed3d`) against independent
//! values: published numbers, quadratures of the tractions, Mindlin's full-stick stiffness, and
//! the axisymmetric finite-element sphere.

use hycon::contact::iteration::ContactOptions;
use hycon_lab::axisymmetric::SphereOnBlock;
use hycon_lab::closed3d::{HertzSphere, Mindlin, hertz_approach, hertz_load};
use std::f64::consts::PI;

fn rel(u: f64, v: f64) -> f64 {
    (u / v - 1.0).abs()
}

/// `integral_0^1 f(t) dt` by composite Simpson on 2000 intervals (smooth `f`).
fn simpson(f: impl Fn(f64) -> f64) -> f64 {
    let n = 2000;
    let h = 1.0 / n as f64;
    (0..=n)
        .map(|i| {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * f(i as f64 * h)
        })
        .sum::<f64>()
        * h
        / 3.0
}

/// `integral_0^outer f(r) 2 pi r dr = pi integral f(sqrt s) ds` (`s = r^2`), split at
/// `inner`, with `s = top^2 (1 - t^2)` on each piece (`top` its end): a factor
/// `sqrt(1 - r^2/top^2) = t` becomes smooth, so Simpson converges fast.
fn over_disk(f: &dyn Fn(f64) -> f64, inner: f64, outer: f64) -> f64 {
    // [0, inner]: t in [0, 1]; [inner, outer]: t in [0, t0], t0 = sqrt(1 - inner^2/outer^2)
    let piece = |top: f64, t0: f64| {
        simpson(|u| {
            let t = t0 * u;
            let s = top * top * (1.0 - t * t);
            f(s.sqrt()) * 2.0 * top * top * t * t0
        })
    };
    let t0 = (1.0 - (inner / outer).powi(2)).sqrt();
    PI * (piece(inner, 1.0) + piece(outer, t0))
}

#[test]
fn hertz_matches_the_published_values() {
    // R = 1, E1 = E2 = 1, nu = 0.3 (docs/validation.md): P, p0 and the approach at R/a = 32, 64
    let e_star = 1.0 / (2.0 * (1.0 - 0.09));
    for (r_over_a, p, p0, delta) in [
        (32.0, 2.2357200092e-5, 1.0930971366e-2, 9.765625e-4),
        (64.0, 2.7946500114e-6, 5.4654856831e-3, 2.44140625e-4),
    ] {
        let a = 1.0 / r_over_a;
        assert!(rel(hertz_load(a, 1.0, e_star), p) < 1e-10);
        let h = HertzSphere::new(p, 1.0, e_star);
        assert!(rel(h.radius, a) < 1e-10 && rel(h.peak, p0) < 1e-10);
        assert_eq!(hertz_approach(a, 1.0), delta);
    }
    // CalculiX's Contact/Hertz_axi: R = 50, steel on steel (E = 210000, nu = 0.3),
    // P = 78540: a = 2.944, p0 = 4326, approach 0.173 (as printed, to their last digit)
    let e_star = 210_000.0 / (2.0 * (1.0 - 0.09));
    let h = HertzSphere::new(78_540.0, 50.0, e_star);
    assert!((h.radius - 2.944).abs() < 5e-4, "{}", h.radius);
    assert!((h.peak - 4326.0).abs() < 0.5, "{}", h.peak);
    assert!((hertz_approach(h.radius, 50.0) - 0.173).abs() < 5e-4);
}

#[test]
fn the_tractions_integrate_to_the_loads() {
    let (p, r, e_star, mu) = (2.0, 1.5, 0.7, 0.3);
    let h = HertzSphere::new(p, r, e_star);
    let a = h.radius;
    let normal = over_disk(&|x| h.pressure(x), 0.5 * a, a);
    assert!(rel(normal, p) < 1e-9, "{normal} vs {p}");
    for ratio in [0.0, 0.1, 0.5, 0.9] {
        let m = Mindlin::new(p, r, e_star, mu, ratio * mu * p).unwrap();
        assert!(rel(m.stick / a, (1.0 - ratio).cbrt()) < 1e-15);
        let q = over_disk(&|x| m.traction(x), m.stick.max(1e-3 * a), a);
        assert!(
            (q - ratio * mu * p).abs() < 1e-9 * mu * p,
            "Q/muP {ratio}: {q}"
        );
        // full slip in the annulus, q below mu p in the stick disk
        assert!(
            (m.traction(0.5 * (m.stick + a)) - mu * h.pressure(0.5 * (m.stick + a))).abs() < 1e-15
        );
        if ratio > 0.0 {
            assert!(m.traction(0.5 * m.stick) < mu * h.pressure(0.5 * m.stick));
        }
    }
    assert!(Mindlin::new(p, r, e_star, mu, mu * p).is_err());
    assert!(Mindlin::new(p, r, e_star, 0.0, 0.0).is_err());
}

#[test]
fn mindlins_compliance_starts_at_the_full_stick_stiffness() {
    // Mindlin (1949): a circular contact that sticks everywhere has the tangential stiffness
    // 8 G* a, 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2
    let (p, r, e_star, mu) = (1.0, 1.0, 0.55, 0.4);
    let (g, nu) = ([0.4, 0.9], [0.3, 0.2]);
    let g_star = 1.0 / ((2.0 - nu[0]) / g[0] + (2.0 - nu[1]) / g[1]);
    let q = 1e-6 * mu * p;
    let m = Mindlin::new(p, r, e_star, mu, q).unwrap();
    let stiffness = q / m.compliance_displacement(g, nu);
    assert!(
        rel(stiffness, 8.0 * g_star * m.hertz.radius) < 1e-6,
        "{stiffness}"
    );
    // at the onset of gross slip, 3 mu P / (16 a G*)
    let m = Mindlin::new(p, r, e_star, mu, (1.0 - 1e-12) * mu * p).unwrap();
    let full = 3.0 * mu * p / (16.0 * m.hertz.radius * g_star);
    assert!(rel(m.compliance_displacement(g, nu), full) < 1e-7);
}

/// The approach `a^2 / R` of a target radius applied to the axisymmetric finite-element sphere
/// (`SphereOnBlock`, n = 16 elements per radius, R/a = 32, equal moduli): the load it carries
/// is `hertz_load` of that radius within 1.5% (measured +0.95%: the block of 4R and the mesh),
/// and Hertz's radius at that load the target within 0.5% (measured +0.32%). Half the
/// approach, or `R` for `2R`, would be off by a factor 2^(3/2) in the load.
#[test]
fn the_approach_matches_the_axisymmetric_sphere() {
    let scene = SphereOnBlock {
        elements_per_radius: 16,
        radius_over_contact: 32.0,
        modulus_ratio: 1.0,
    }
    .build()
    .unwrap();
    let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
    let f = vec![0.0; scene.model.external_forces().len()];
    let delta = hertz_approach(scene.target, 1.0);
    analysis.increment(&f, &scene.prescribed(delta)).unwrap();
    let c = scene.compare(&analysis).unwrap();
    let load = hertz_load(scene.target, 1.0, scene.e_star);
    println!(
        "approach {delta:e}: load {:e} vs Hertz {load:e} ({:+.3}%), a {:+.3}%",
        c.load,
        100.0 * (c.load / load - 1.0),
        100.0 * (c.hertz.radius / scene.target - 1.0)
    );
    assert!(rel(c.load, load) < 0.015);
    assert!(rel(c.hertz.radius, scene.target) < 0.005);
}
