//! Force control in 3D (issue #43): the cap's top tied to a rigid plate
//! (`hycon_lab::plate3d`), Hertz's quarter cap pressed by a given force `P` and Mindlin's half
//! cap pressed by `P` and then sheared by a given `Q`, each force-controlled through the
//! plate's bordered small system; against the closed forms and against displacement control.

use hycon::contact::iteration::{FacePair, PlateControl};
use hycon_lab::closed3d::{hertz_approach, hertz_load};
use hycon_lab::hertz3d::e_star;
use hycon_lab::mindlin3d::{HalfCap, Pull, Ray};
use hycon_lab::plate3d::{PlateCap, press, tied_cap};

/// `|a / b - 1|`.
fn relative(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// The quarter cap at `a/h = 4` pressed by Hertz's load `P` of the target radius `a = R / 16`:
/// the plate's force and the contact forces reach `P` to round-off, the contact radius and the
/// peak pressure meet Hertz at `P` within the tolerances the displacement-controlled press of
/// `contact_hertz3d` meets (3% and 2%), and the approach lies below Hertz's `a^2 / R` (the
/// finite bodies are stiffer than half-spaces: about 6% more load at that approach, so some 4%
/// less approach at Hertz's load). Then displacement control at the approach the force control
/// found, on a fresh analysis: the same load to `1e-10` and the same active set. A plate force
/// taken as the full model's on the quarter (a factor 4), a wrong sign of the border or of the
/// plate's stiffness breaks them.
#[test]
fn hertz_at_a_given_force_agrees_with_displacement_control() {
    let mut cap = PlateCap::quarter(4).unwrap();
    let a = 1.0 / 16.0;
    let p = hertz_load(a, 1.0, e_star());
    let forced = cap.press(PlateControl::Force(-p)).unwrap();
    println!("force control at P = {p:.6e}: {forced:?}");
    assert!(relative(forced.plate_load, p) < 1e-12, "{forced:?}");
    assert!(relative(forced.load, p) < 1e-10, "{forced:?}");
    assert!(
        relative(forced.radius, forced.hertz.radius) < 0.03,
        "{forced:?}"
    );
    assert!(
        relative(forced.peak, forced.hertz.peak) < 0.02,
        "{forced:?}"
    );
    let ratio = forced.approach / hertz_approach(a, 1.0);
    assert!(ratio > 0.9 && ratio < 1.0, "approach / Hertz's {ratio}");

    let mut again = PlateCap::quarter(4).unwrap();
    let pressed = again
        .press(PlateControl::Displacement(-forced.approach))
        .unwrap();
    println!(
        "displacement control at {:.6e}: {pressed:?}",
        forced.approach
    );
    assert!(relative(pressed.plate_load, p) < 1e-10, "{pressed:?}");
    assert!(relative(pressed.load, p) < 1e-10, "{pressed:?}");
    assert_eq!(pressed.info.active, forced.info.active);
}

const MU: f64 = 0.3;
const NU: f64 = 0.3;

/// Mindlin's half cap at `a/h = 4`, `nu = 0.3`, `mu = 0.3` (`hycon_lab::mindlin3d`, the
/// multipliers on the flat block), the cap's top tied to the plate: pressed by the load `P`
/// that `HalfCap::press` reaches at Hertz's approach (x held), then sheared along `x` by
/// `Q / (mu P) = 0.05, 0.10, 0.15, 0.5, 0.875` (force-controlled; z held at the approach the
/// press found, y by the symmetry plane). The force-controlled press reaches `P` to round-off
/// at the displacement-controlled press's approach (`1e-12`) with the same stick radii; each
/// shear makes the total friction force `Q` to round-off, leaves `P` within `1e-6` (the
/// approach is held, normal and tangential barely couple), and keeps the stick radius on the
/// three rays (leading, trailing, across `Q`) a disk within one node spacing of Mindlin's
/// `a (1 - Q / (mu P))^(1/3)`. The plate's x displacement grows in proportion to `Q` while
/// nothing slips (the first three shears: 2 iterations each).
///
/// Beyond `Q / (mu P) = 0.15` nodes slip: the shear is solved with the contact conditions
/// linearized at each iterate and bordered by the plate's force-controlled x translation (the
/// cap is held in x only by the plate and by contact: `D = 0`). Measured: at 0.5 the stick
/// radius 3.5 h against Mindlin's 3.32 h (3 iterations), at 0.875 1.5 h against 2.09 h
/// (6 iterations).
#[test]
fn mindlin_at_a_given_shear() {
    let mut cap = HalfCap::new(4, NU, MU).unwrap();
    let h = cap.scene.mesh.h;
    let displaced = cap.press().unwrap();
    let p = displaced.load;
    let pair = FacePair {
        a: cap.scene.mesh.b_faces.clone(),
        b: cap.scene.mesh.a_faces.clone(),
        friction: MU,
    };
    cap.analysis = tied_cap(&cap.scene.mesh, NU, pair).unwrap();
    let held = PlateControl::Displacement(0.0);
    // the half model carries half of each load
    let info = press(
        &mut cap.analysis,
        [held, held, PlateControl::Force(-p / 2.0)],
    )
    .unwrap();
    let pressed = cap.results(info).unwrap();
    show("pressed", &pressed, h);
    let (u, force) = cap.analysis.plate().unwrap();
    let approach = hertz_approach(cap.spec.contact_radius(), 1.0);
    assert!(relative(-u.components()[2], approach) < 1e-12, "{u:?}");
    assert!(
        relative(force.components()[2], -p / 2.0) < 1e-12,
        "{force:?}"
    );
    assert!(relative(pressed.load, p) < 1e-10, "{pressed:?}");
    assert_eq!(rays(&pressed), rays(&displaced));
    let w = PlateControl::Displacement(u.components()[2]);
    let mut slope = None;
    for ratio in [0.05, 0.10, 0.15, 0.5, 0.875] {
        let q = ratio * MU * p;
        let info = press(&mut cap.analysis, [PlateControl::Force(q / 2.0), held, w]).unwrap();
        let pulled = cap.results(info).unwrap();
        show("sheared", &pulled, h);
        let (u, force) = cap.analysis.plate().unwrap();
        assert!(
            relative(force.components()[0], q / 2.0) < 1e-12,
            "{force:?}"
        );
        assert!(relative(pulled.tangential, q) < 1e-10, "{pulled:?}");
        assert!(relative(pulled.load, p) < 1e-6, "{pulled:?}");
        let c = pulled.mindlin_stick(MU);
        for ray in rays(&pulled) {
            assert!(ray.is_stick_disk(), "{pulled:?}");
            assert!((ray.radius() - c).abs() < h, "{ray:?}, Mindlin {c}, h {h}");
        }
        if ratio <= 0.15 {
            let s = *slope.get_or_insert(u.components()[0] / q);
            assert!(relative(u.components()[0] / q, s) < 1e-9, "{u:?}");
        }
    }
}

/// Leading, trailing, across.
fn rays(p: &Pull) -> [Ray; 3] {
    [p.leading, p.trailing, p.across]
}

fn show(what: &str, p: &Pull, h: f64) {
    let r = |ray: Ray| {
        format!(
            "{}-{} ({})",
            ray.stick / h,
            ray.beyond / h,
            ray.radius() / h
        )
    };
    println!(
        "{what}: P = {:.6e}, Q = {:.6e}, Q / (mu P) = {:.6}, a / h = {:.3}, Mindlin c / h = \
         {:.3}, leading {}, trailing {}, across {}, {} iterations",
        p.load,
        p.tangential,
        p.ratio(MU),
        p.radius / h,
        p.mindlin_stick(MU) / h,
        r(p.leading),
        r(p.trailing),
        r(p.across),
        p.info.iterations
    );
}
