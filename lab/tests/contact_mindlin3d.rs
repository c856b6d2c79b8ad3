//! Cattaneo-Mindlin in 3D (issue #43): `hycon_lab::mindlin3d`'s half cap on its mirror block,
//! both bodies of `E = 1` and the same `nu`, `R / a = 256`, `mu = 0.3`, pressed by Hertz's
//! approach and then pulled along `x` until `Q / (mu P)` reaches 0.5 and then 0.875 (forward
//! increments, a secant on Mindlin's compliance), the stick radius read off the node states
//! along `Q` on the leading (`+x`) and the trailing (`-x`) side and across `Q` (`+y`) against
//! Mindlin's `c = a (1 - Q / (mu P))^(1/3)` (`a` from the moments of the normal forces).
//!
//! Measured (`cargo test -p hycon-lab --test lab contact_mindlin3d:: -- --nocapture
//! --include-ignored --test-threads 1`); radii in node spacings `h`, "3-4 (3.5)" the last
//! stick node, the first node beyond it that does not stick, and their midpoint (the measured
//! stick radius); Mindlin's `c` at the reached `Q / (mu P)` and the measured `a`:
//!
//! | a/h | nu | Q/(mu P) | a / h | Mindlin c / h (c/a) | leading `+x` | trailing `-x` | across `+y` |
//! |---|---|---|---|---|---|---|---|
//! | 4 | 0 | 0.5003 | 4.170 | 3.309 (0.794) | 3-4 (3.5) | 3-4 (3.5) | 3-4 (3.5) |
//! | 4 | 0 | 0.8729 | 4.170 | 2.097 (0.503) | 1-2 (1.5) | 1-2 (1.5) | 1-2 (1.5) |
//! | 8 | 0 | 0.4999 | 8.270 | 6.565 (0.794) | 6-7 (6.5) | 6-7 (6.5) | 6-7 (6.5) |
//! | 8 | 0 | 0.8773 | 8.270 | 4.110 (0.497) | 3-4 (3.5) | 3-4 (3.5) | 3-4 (3.5) |
//! | 4 | 0.3 | 0.5006 | 4.188 | 3.323 (0.793) | 3-4 (3.5) | 3-4 (3.5) | 3-4 (3.5) |
//! | 4 | 0.3 | 0.8739 | 4.188 | 2.100 (0.501) | 1-2 (1.5) | 1-2 (1.5) | 1-2 (1.5) |
//! | 8 | 0.3 | 0.5000 | 8.314 | 6.599 (0.794) | 6-7 (6.5) | 6-7 (6.5) | 6-7 (6.5) |
//! | 8 | 0.3 | 0.8777 | 8.314 | 4.127 (0.496) | 3-4 (3.5) | 3-4 (3.5) | 3-4 (3.5) |
//!
//! Every measured radius is within one node spacing of Mindlin's (the largest miss 0.63 h, at
//! `a/h = 8`, `Q / (mu P) = 0.875`), along and across `Q` alike, and leading and trailing
//! alike: at `nu = 0.3` the non-circularity of the stick zone is below the node spacing. The
//! press slips nowhere. Slip directions lie within 1.7 degrees of Mindlin's at `a/h = 4` and
//! 6.0 at `a/h = 8` (`nu = 0`; 3.2 and 11.8 at `nu = 0.3`). One increment from the press to
//! the same displacement gives the same stick nodes and `Q / (mu P)` within 0.001 (measured
//! with multipliers on the cap): the forward path and the single step agree.
//!
//! What the checks catch: the stick radius at two loads on three rays, each within `h` of
//! Mindlin's, the stick nodes forming a disk, leading and trailing alike, the slip along `Q`.
//! The unlike bodies of `contact_friction3d` (slip in the press) and the multipliers on the
//! curved cap (at `a/h = 4`, `Q / (mu P) = 0.5`: trailing 2-3, leading 3-4) break them, as
//! would a tangential load off by the half model's factor 2 (the pull then aiming at twice the
//! target). The tolerance `h` is a quarter of `a` at `a/h = 4`: the stick radius's exponent 1/3
//! against, say, 1/2 (`c/a` 0.707 and 0.354 at the two loads) moves `c` by 0.36 h and 0.6 h,
//! inside it; the finer `a/h = 8` pins `c` to an eighth of `a`.

use hycon_lab::mindlin3d::{HalfCap, Pull, Ray};

const MU: f64 = 0.3;

/// The targets of `Q / (mu P)`, and how close the pull must come to them.
const TARGETS: [f64; 2] = [0.5, 0.875];
const TOLERANCE: f64 = 0.005;

/// Press and pull the half cap at `a_over_h` and `nu`; print each state; return the press and
/// the two pulls, and the face size `h`.
fn measure(a_over_h: usize, nu: f64) -> (Pull, Vec<Pull>, f64) {
    let mut cap = HalfCap::new(a_over_h, nu, MU).unwrap();
    let h = cap.scene.mesh.h;
    let pressed = cap.press().unwrap();
    let mut pulls: Vec<Pull> = Vec::new();
    for target in TARGETS {
        let from = *pulls.last().unwrap_or(&pressed);
        pulls.push(cap.pull_to(&from, target, TOLERANCE, 6).unwrap());
    }
    let ray = |r: &Ray| {
        format!(
            "{:.1}-{:.1} ({:.2})",
            r.stick / h,
            r.beyond / h,
            r.radius() / h
        )
    };
    for p in std::iter::once(&pressed).chain(&pulls) {
        println!(
            "a/h {a_over_h} nu {nu}: P {:.5e} Q/(mu P) {:.4} a/h {:.3} c_M/h {:.3} (c_M/a {:.4}) \
             leading {} trailing {} across {} (in h) spread {:.2} deg, {} active {} slip, {} \
             iterations",
            p.load,
            p.ratio(MU),
            p.radius / h,
            p.mindlin_stick(MU) / h,
            p.mindlin_stick(MU) / p.radius,
            ray(&p.leading),
            ray(&p.trailing),
            ray(&p.across),
            p.spread,
            p.info.active,
            p.info.slip,
            p.info.iterations
        );
    }
    (pressed, pulls, h)
}

/// The press slips nowhere; each pull reaches its target; on each ray the stick nodes form
/// one disk whose edge is within one node spacing `h` of Mindlin's `c`, the same on the leading
/// and the trailing side; every slip node slips within 15 degrees of `Q`.
fn check(pressed: &Pull, pulls: &[Pull], h: f64) {
    assert_eq!(pressed.info.slip, 0, "{pressed:?}");
    for (p, target) in pulls.iter().zip(TARGETS) {
        assert!((p.ratio(MU) - target).abs() <= TOLERANCE, "{p:?}");
        assert_eq!(p.leading, p.trailing, "{p:?}");
        assert!(p.spread < 15.0, "{p:?}");
        let c = p.mindlin_stick(MU);
        for ray in [p.leading, p.trailing, p.across] {
            assert!(ray.is_stick_disk(), "{ray:?} {p:?}");
            assert!((ray.radius() - c).abs() <= h, "c = {c}, {ray:?}, h = {h}");
        }
    }
}

#[test]
fn the_stick_radius_is_mindlins_at_nu_0() {
    let (pressed, pulls, h) = measure(4, 0.0);
    check(&pressed, &pulls, h);
}

/// At `a/h = 8` and `nu = 0`, and at `nu = 0.3` (where Mindlin's circular stick zone is
/// an approximation) at `a/h = 4` and 8: the same checks (some 80 s).
#[test]
#[ignore = "some 80 s: a/h = 8, and nu = 0.3"]
fn the_stick_radius_is_mindlins_finer_and_at_nu_0_3() {
    for (a_over_h, nu) in [(8, 0.0), (4, 0.3), (8, 0.3)] {
        let (pressed, pulls, h) = measure(a_over_h, nu);
        check(&pressed, &pulls, h);
    }
}
