//! The automatic cutback (`ContactOptions::cutback_depth`) and the promise that a surface pushed
//! through the other is an error at any depth (issue 33).
//!
//! The scene (the distribution of `hycon bench presses`): a lower block `[0, 2] x [0, 1]` held
//! at its bottom (`E = 1`), an upper block of width `w` from `x = left`, `gap` above it, pressed
//! down through its top by `gap + depth` and then moved sideways by `slide`; A = the upper
//! block's bottom, B = the lower block's top.

use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, IncrementInfo, Kinematics,
};
use hycon::element::Formulation;
use hycon::error::{ContactError, Error};
use hycon::material::{Analysis, Material};
use hycon::mesh::Mesh;
use hycon::model::Model;

use crate::common::block;

/// One two-block problem.
#[derive(Debug, Clone, Copy)]
struct Press {
    lower: [usize; 2],
    upper: [usize; 2],
    left: f64,
    width: f64,
    gap: f64,
    depth: f64,
    upper_modulus: f64,
    poisson: [f64; 2],
    friction: f64,
    kinematics: Kinematics,
}

/// The analysis of a press with `options`, and the upper block's top nodes. It runs the
/// paper's rules alone (`set_fallback(false)`): 0.7.0's fallback settles the slides below in
/// one step, so the cutback is tested here as the mechanism it is, on increments the rules
/// fail (a_large_frictional_slide_converges_in_sub_increments checks the fallback settles
/// them too).
struct Scene {
    analysis: ContactAnalysis,
    top: Vec<usize>,
    n: usize,
    press: Press,
}

impl Scene {
    fn new(press: Press, options: ContactOptions) -> hycon::Result<Scene> {
        Scene::build(press, options, false)
    }

    /// As [`new`](Self::new), with the upper block's top tied to a rigid plate.
    fn with_plate(press: Press, options: ContactOptions) -> hycon::Result<Scene> {
        Scene::build(press, options, true)
    }

    fn build(press: Press, options: ContactOptions, plate: bool) -> hycon::Result<Scene> {
        let mut mesh = Mesh::new();
        let lower = block(&mut mesh, [0.0, 0.0], [2.0, 1.0], press.lower, 0);
        let upper = block(
            &mut mesh,
            [press.left, 1.0 + press.gap],
            [press.width, 1.0],
            press.upper,
            1,
        );
        let row = |ids: &[usize], n: [usize; 2], j: usize| {
            ids[j * (n[0] + 1)..(j + 1) * (n[0] + 1)].to_vec()
        };
        let a = row(&upper, press.upper, 0);
        let mut b = row(&lower, press.lower, press.lower[1]);
        b.reverse();
        let top = row(&upper, press.upper, press.upper[1]);
        let n = mesh.n_nodes();
        let materials = vec![
            Material::new(1.0, press.poisson[0], 1.0, Analysis::PlaneStrain)?,
            Material::new(
                press.upper_modulus,
                press.poisson[1],
                1.0,
                Analysis::PlaneStrain,
            )?,
        ];
        let mut model = Model::new(mesh, materials, Formulation::Hybrid);
        model.fix(&row(&lower, press.lower, 0), [0.0, 0.0])?;
        model.fix(&top, [0.0, 0.0])?;
        let pair = ContactPair {
            a,
            b,
            friction: press.friction,
        };
        let options = ContactOptions {
            kinematics: press.kinematics,
            ..options
        };
        let mut analysis = if plate {
            ContactAnalysis::with_plate(model, vec![pair], options, top.clone())?
        } else {
            ContactAnalysis::new(model, vec![pair], options)?
        };
        analysis.set_fallback(false);
        Ok(Scene {
            analysis,
            top,
            n,
            press,
        })
    }

    /// The top pressed down by `gap + depth` and moved sideways by `slide`.
    fn step(&mut self, depth: f64, slide: f64) -> hycon::Result<IncrementInfo> {
        let mut qp = vec![0.0; 2 * self.n];
        for &node in &self.top {
            qp[2 * node] = slide;
            qp[2 * node + 1] = -(self.press.gap + depth);
        }
        self.analysis.increment(&vec![0.0; 2 * self.n], &qp)
    }
}

/// Everything a result query returns after the last converged increment, as bits.
fn state_bits(a: &ContactAnalysis) -> Vec<u64> {
    let mut bits: Vec<u64> = a
        .displacement()
        .unwrap()
        .iter()
        .map(|v| v.to_bits())
        .collect();
    for r in a.node_results(0).unwrap() {
        bits.extend(
            [
                r.tn,
                r.ts.components()[0],
                r.gap,
                r.weight,
                r.position[0],
                r.position[1],
            ]
            .map(f64::to_bits),
        );
        bits.push(r.state.name().len() as u64);
    }
    bits.extend(a.contact_forces().iter().map(|v| v.to_bits()));
    bits.push(a.records().len() as u64);
    bits
}

fn off() -> ContactOptions {
    ContactOptions {
        cutback_depth: 0,
        ..ContactOptions::default()
    }
}

/// xorshift64 draws.
struct Draws(u64);

impl Draws {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + ((self.unit() * (hi - lo + 1) as f64) as usize).min(hi - lo)
    }
}

/// Found by `search` (seed 0x9e3779b97f4a7c15, problem 2556): pressed in one increment, the
/// upper block (`mu = 0.746`, small kinematics) slides `-0.46 depth` in one increment. Without
/// cutback the slide fails (node 12 alternates between stick and slip and, locked in slip,
/// slides against its friction by 6.6e-2 of the motion); with it the slide converges in 7
/// sub-increments (4 of them halved).
const SLIDE: (Press, f64) = (
    Press {
        lower: [3, 2],
        upper: [3, 1],
        left: 0.13375962197131824,
        width: 0.5792129221738916,
        gap: 0.00020495499713774645,
        depth: 0.0061745374110939374,
        upper_modulus: 0.27052693094061236,
        poisson: [0.12422641974817228, 0.35274600020744346],
        friction: 0.7457386425405506,
        kinematics: Kinematics::Small,
    },
    -2.8382683472792424e-3,
);

/// The same search, problem 467: `mu = 0.715`, a slide of 1.3 depths; 2 sub-increments.
const LONG_SLIDE: (Press, f64) = (
    Press {
        lower: [6, 1],
        upper: [3, 3],
        left: 0.12521875688109207,
        width: 0.5996119747172998,
        gap: 0.0008865864141073593,
        depth: 0.00978218990393636,
        upper_modulus: 10.863685597075495,
        poisson: [0.4035559225313797, -0.016788297495953702],
        friction: 0.7148993743348729,
        kinematics: Kinematics::Small,
    },
    -1.25770690002037e-2,
);

/// A frictional slide that fails in one step converges with the cutback, as one increment of
/// the host: one increment number, records indexed by sub-increment, the displacement
/// increment over the whole step; and the converged state satisfies Coulomb's law node by node.
#[test]
fn a_large_frictional_slide_converges_in_sub_increments() {
    for (press, slide) in [SLIDE, LONG_SLIDE] {
        let mut plain = Scene::new(press, off()).unwrap();
        plain.step(press.depth, 0.0).unwrap();
        let e = plain.step(press.depth, slide).unwrap_err();
        assert!(
            matches!(e, Error::Contact(ContactError::SlipReversal { .. })),
            "{e}"
        );
        // 0.7.0's rules (the fallback on) settle the same slide without cutting back
        let mut settled = Scene::new(press, off()).unwrap();
        settled.analysis.set_fallback(true);
        settled.step(press.depth, 0.0).unwrap();
        let info = settled.step(press.depth, slide).unwrap();
        assert_eq!((info.sub_increments, info.cutbacks), (1, 0));
        assert_eq!(settled.analysis.fallbacks(), 1);

        let mut cut = Scene::new(press, ContactOptions::default()).unwrap();
        let first = cut.step(press.depth, 0.0).unwrap();
        assert_eq!((first.sub_increments, first.cutbacks), (1, 0));
        let before = cut.analysis.displacement().unwrap().to_vec();
        let kept = cut.analysis.records().len();
        let info = cut.step(press.depth, slide).unwrap();
        assert_eq!(info.increment, 2);
        assert!(info.sub_increments >= 2 && info.cutbacks >= 1, "{info:?}");
        // `K` was factored once, for the whole analysis
        assert_eq!(cut.analysis.factorizations(), 1);
        // records: increment 2 throughout, sub-increments 1..=n in order, each ending converged
        let records = &cut.analysis.records()[kept..];
        assert_eq!(records.len(), info.iterations);
        assert!(records.iter().all(|r| r.increment == 2));
        assert!(
            records
                .windows(2)
                .all(|w| w[1].sub_increment >= w[0].sub_increment)
        );
        assert_eq!(records[0].sub_increment, 1);
        assert_eq!(records.last().unwrap().sub_increment, info.sub_increments);
        // the displacement increment spans the host's increment
        let after = cut.analysis.displacement().unwrap().to_vec();
        let du = cut.analysis.displacement_increment().unwrap();
        let scale = after.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for ((a, b), d) in after.iter().zip(&before).zip(&du) {
            assert!((a - b - d).abs() <= 1e-12 * scale);
        }
        // the top slid by `slide` and Coulomb's law holds at every contact node
        let results = cut.analysis.node_results(0).unwrap();
        let peak = results.iter().fold(0.0f64, |m, r| m.max(r.tn.abs()));
        assert!(peak > 0.0);
        for r in &results {
            assert!(r.tn <= 1e-9 * peak, "{r:?}");
            assert!(r.ts.norm() <= press.friction * r.tn.abs() * (1.0 + 1e-8) + 1e-12 * peak);
        }
    }
}

/// The same slide driven through a rigid plate tied to the upper block's top: displacement
/// control in both directions gives the prescribed-top results bit for bit (sub-increments
/// included); with the press force-controlled (the force of the pressed state) and the slide
/// displacement-controlled, the plate's force-controlled direction is interpolated as a force
/// (its motion solved for in every sub-increment), and the plate ends carrying the force and
/// moved by the slide.
#[test]
fn a_plate_slide_is_cut_back_with_its_controls() {
    use hycon::contact::iteration::PlateControl::{Displacement, Force};
    let (press, slide) = SLIDE;
    let mut prescribed = Scene::new(press, ContactOptions::default()).unwrap();
    prescribed.step(press.depth, 0.0).unwrap();
    let want = prescribed.step(press.depth, slide).unwrap();
    let mut plate = Scene::with_plate(press, ContactOptions::default()).unwrap();
    let n = plate.n;
    let (f, qp) = (vec![0.0; 2 * n], vec![0.0; 2 * n]);
    let down = -(press.gap + press.depth);
    plate
        .analysis
        .increment_with_plate(&f, &qp, &[Displacement(0.0), Displacement(down)])
        .unwrap();
    let (_, pressed) = plate.analysis.plate().unwrap();
    let got = plate
        .analysis
        .increment_with_plate(&f, &qp, &[Displacement(slide), Displacement(down)])
        .unwrap();
    assert_eq!(got, want);
    let bits = |a: &ContactAnalysis| -> Vec<u64> {
        let r = a.node_results(0).unwrap();
        r.iter()
            .flat_map(|n| [n.tn.to_bits(), n.ts.components()[0].to_bits()])
            .collect()
    };
    assert_eq!(bits(&plate.analysis), bits(&prescribed.analysis));

    let mut forced = Scene::with_plate(press, ContactOptions::default()).unwrap();
    let load = [Displacement(0.0), Force(pressed[1])];
    forced
        .analysis
        .increment_with_plate(&f, &qp, &load)
        .unwrap();
    let info = forced
        .analysis
        .increment_with_plate(&f, &qp, &[Displacement(slide), Force(pressed[1])])
        .unwrap();
    let (u, force) = forced.analysis.plate().unwrap();
    assert_eq!(u[0], slide);
    assert!(
        (force[1] / pressed[1] - 1.0).abs() < 1e-9,
        "{force:?} vs {pressed:?}"
    );
    let top = forced.top[0];
    let field = forced.analysis.displacement().unwrap();
    assert_eq!((field[2 * top], field[2 * top + 1]), (u[0], u[1]));
    eprintln!("force-controlled slide: {info:?}");
}

/// Press 1599 of `hycon bench presses --count 2000 --seed 1` (wide ranges): body A (the upper
/// block) 33 times stiffer than B, B's segments (0.22) longer than A's (0.088). A B node
/// (x = 0.889) lies over A's segment 2 beside its node 2 (x = 0.885); closing node 2 puts it in
/// tension, leaving it open lets the B node through.
const STIFF_A: Press = Press {
    lower: [9, 8],
    upper: [5, 1],
    left: 0.7088685647274104,
    width: 0.44152234677896096,
    gap: 0.00011799861604332307,
    depth: 0.0015049624104232337,
    upper_modulus: 33.324757153579384,
    poisson: [0.4312771763132675, 0.22256492195716926],
    friction: 0.5719566768598076,
    kinematics: Kinematics::Small,
};

/// The stiff-A class has no state that satisfies the conditions, and its error says what to
/// do: pressed in one increment, press `STIFF_A` fails with a B node through A's segment
/// beside open A nodes (`1.4e-4` of the problem's scale); with B's segments quartered it
/// settles in one increment.
#[test]
fn a_b_node_between_open_a_nodes_says_refine_b() {
    let mut scene = Scene::new(STIFF_A, ContactOptions::default()).unwrap();
    scene.analysis.set_fallback(true);
    let e = scene.step(STIFF_A.depth, 0.0).unwrap_err();
    match &e {
        Error::Contact(ContactError::ConditionViolated { condition, .. }) => assert!(
            condition.starts_with("a B node penetrates between two open A nodes"),
            "{e}"
        ),
        _ => panic!("{e}"),
    }
    assert!(e.to_string().contains("refine the B surface"), "{e}");
    let refined = Press {
        lower: [36, 8],
        ..STIFF_A
    };
    let mut scene = Scene::new(refined, ContactOptions::default()).unwrap();
    scene.analysis.set_fallback(true);
    scene.step(refined.depth, 0.0).unwrap();
}

/// Press 1076 of `hycon bench presses --count 2000 --seed 4` (wide ranges): body A 3,046 times
/// stiffer than B, `mu = 0.40`. The paper's rules wander at the first touch, and the
/// fallback's projected Gauss-Seidel needs 826,000 sweeps on its small system (`cond(S)` about
/// `5e6`); 0.7.0 stopped it after 20,000, far from the solution, and every increment and
/// sub-increment through the first touch failed (here: no convergence). The converged
/// solution's states settle the press in one increment, without the cutback.
#[test]
fn a_stiff_a_press_settles_from_the_converged_fallback() {
    let press = Press {
        lower: [19, 8],
        upper: [18, 4],
        left: 0.4487646496524075,
        width: 0.8125828665556429,
        gap: 0.0003524483938569546,
        depth: 0.008065305138413898,
        upper_modulus: 3046.4420012998094,
        poisson: [0.1076622284683112, 0.3604159420724465],
        friction: 0.39849984348002143,
        kinematics: Kinematics::Small,
    };
    let mut scene = Scene::new(press, off()).unwrap();
    scene.analysis.set_fallback(true);
    let info = scene.step(press.depth, 0.0).unwrap();
    assert_eq!((info.sub_increments, info.cutbacks), (1, 0));
    assert_eq!(scene.analysis.fallbacks(), 1);
}

/// Press 15241 of `hycon bench presses --count 20000 --seed 1` (wide ranges): A (the upper
/// block) 23 times softer than B, `mu = 0.74`. The paper's rules cycle at the first touch and
/// the fallback's projected Gauss-Seidel cycles too (the friction bounds follow `tn`), so
/// 0.8.0 failed the press at every sub-increment with a slip reversal, while a reference run in
/// 50 sub-increments per phase settles it. The semi-smooth Newton method solves the fallback's
/// conditions exactly, and the press, the slide and the repeated totals converge.
#[test]
fn a_large_friction_press_settles_from_the_newton_fallback() {
    let press = Press {
        lower: [3, 8],
        upper: [7, 1],
        left: 0.7822626245848971,
        width: 0.5787596818436164,
        gap: 0.00030957028830917553,
        depth: 0.004859937609864019,
        upper_modulus: 0.04434548466332618,
        poisson: [0.04661349026082093, 0.39657957455409115],
        friction: 0.742198216879413,
        kinematics: Kinematics::Small,
    };
    let slide = -5.601311985322515e-5;
    let mut scene = Scene::new(press, ContactOptions::default()).unwrap();
    scene.analysis.set_fallback(true);
    for slide in [0.0, slide, slide] {
        scene.step(press.depth, slide).unwrap();
    }
    assert!(scene.analysis.fallbacks() >= 1);
    // the converged iterate of each increment (its last record) meets the conditions
    let records = scene.analysis.records();
    let converged = (records.iter().enumerate()).filter(|&(i, r)| {
        records
            .get(i + 1)
            .is_none_or(|n| n.increment != r.increment)
    });
    for (_, r) in converged {
        assert!(
            r.violation <= hycon::contact::iteration::CONDITION_LIMIT,
            "{r:?}"
        );
    }
}

/// Round 96488 of `contact_randomized 1000 1` (A 74 times stiffer than B, `mu = 0.09`): the
/// press converges only in the fallback's last attempt, where B nodes are judged at
/// convergence (one is `6.7e-5` of the scale through A's segment beside open A nodes). The
/// same totals again then took 11 iterations (the C test allows 3): the rules, judging B nodes
/// pointwise again, closed the nearer A node, cycled and needed the fallback once more. A
/// repeated increment now resumes with the last one's locks and its way of judging B nodes,
/// and settles at once on the same state.
#[test]
fn a_repeated_increment_settles_at_once_after_the_fallback() {
    let press = Press {
        lower: [6, 3],
        upper: [6, 1],
        left: 0.7734874600043844,
        width: 0.6598804584303706,
        gap: 0.0,
        depth: 0.009528844230677902,
        upper_modulus: 73.61722819860161,
        poisson: [0.22359121202061955, 0.08649439256348629],
        friction: 0.09326802011067681,
        kinematics: Kinematics::Small,
    };
    let mut scene = Scene::new(press, ContactOptions::default()).unwrap();
    scene.analysis.set_fallback(true);
    scene.step(press.depth, 0.0).unwrap();
    assert_eq!(scene.analysis.fallbacks(), 1);
    let before = scene.analysis.node_results(0).unwrap();
    let again = scene.step(press.depth, 0.0).unwrap();
    assert_eq!((again.iterations, scene.analysis.fallbacks()), (1, 1));
    assert_eq!(scene.analysis.node_results(0).unwrap(), before);
}

/// With `cutback_depth = 0` the increment fails at once, as before 0.7.0: the monitor sees one
/// try, and the state is the one before the call.
#[test]
fn cutback_off_is_the_old_behaviour() {
    let (press, slide) = SLIDE;
    let mut plain = Scene::new(press, off()).unwrap();
    plain.step(press.depth, 0.0).unwrap();
    let seen = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
    let log = seen.clone();
    plain.analysis.set_monitor(Some(Box::new(move |r| {
        log.lock().unwrap().push(*r);
        true
    })));
    let before = state_bits(&plain.analysis);
    plain.step(press.depth, slide).unwrap_err();
    let seen = seen.lock().unwrap();
    assert!(!seen.is_empty() && seen.iter().all(|r| r.sub_increment == 1));
    assert!(
        seen.windows(2)
            .all(|w| w[1].iteration == w[0].iteration + 1)
    );
    assert_eq!(state_bits(&plain.analysis), before);
}

/// A failure after sub-increments have converged (here the monitor stops the iteration in the
/// third sub-increment: a callback's failure, not retried) restores everything: every result
/// query returns the bits it returned before the call, and the next increment runs as if the
/// failed one had never been tried.
#[test]
fn a_failed_cut_back_increment_leaves_the_state_exactly_as_before() {
    let (press, slide) = SLIDE;
    let mut scene = Scene::new(press, ContactOptions::default()).unwrap();
    scene.step(press.depth, 0.0).unwrap();
    let before = state_bits(&scene.analysis);
    let seen = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
    let log = seen.clone();
    scene.analysis.set_monitor(Some(Box::new(move |r| {
        log.lock().unwrap().push(*r);
        r.sub_increment < 3
    })));
    let e = scene.step(press.depth, slide).unwrap_err();
    assert!(matches!(e, Error::Callback(_)), "{e}");
    assert!(seen.lock().unwrap().iter().any(|r| r.sub_increment == 2));
    assert_eq!(state_bits(&scene.analysis), before);
    // the same slide again, without the monitor, gives what a fresh analysis gives
    scene.analysis.set_monitor(None);
    let again = scene.step(press.depth, slide).unwrap();
    let mut fresh = Scene::new(press, ContactOptions::default()).unwrap();
    fresh.step(press.depth, 0.0).unwrap();
    let want = fresh.step(press.depth, slide).unwrap();
    assert_eq!(again, want);
    let tractions = |a: &ContactAnalysis| -> Vec<(u64, u64)> {
        let r = a.node_results(0).unwrap();
        r.iter()
            .map(|n| (n.tn.to_bits(), n.ts.components()[0].to_bits()))
            .collect()
    };
    assert_eq!(tractions(&scene.analysis), tractions(&fresh.analysis));
}

/// Beyond the cutback's limit the increment fails with the iteration's error and the state is
/// bit for bit the one before the call; so it is with a limit of one halving.
#[test]
fn beyond_the_limit_the_increment_fails_and_keeps_the_state() {
    let (press, slide) = SLIDE;
    let shallow = ContactOptions {
        cutback_depth: 1,
        ..ContactOptions::default()
    };
    let coarse = ContactOptions {
        cutback_min_fraction: 0.75,
        ..ContactOptions::default()
    };
    for options in [shallow, coarse] {
        let mut scene = Scene::new(press, options).unwrap();
        scene.step(press.depth, 0.0).unwrap();
        let before = state_bits(&scene.analysis);
        let e = scene.step(press.depth, slide).unwrap_err();
        assert!(matches!(e, Error::Contact(_)), "{e}");
        assert_eq!(state_bits(&scene.analysis), before);
    }
}

/// The cutback's options are checked in the core.
#[test]
fn cutback_options_are_checked() {
    let d = ContactOptions::default();
    assert_eq!((d.cutback_depth, d.cutback_min_fraction), (8, 1.0 / 256.0));
    for (options, what) in [
        (
            ContactOptions {
                cutback_depth: hycon::contact::iteration::MAX_CUTBACK_DEPTH + 1,
                ..d
            },
            "options.cutback_depth = 53",
        ),
        (
            ContactOptions {
                cutback_min_fraction: 0.0,
                ..d
            },
            "options.cutback_min_fraction = 0",
        ),
        (
            ContactOptions {
                cutback_min_fraction: f64::NAN,
                ..d
            },
            "options.cutback_min_fraction = NaN",
        ),
        (
            ContactOptions {
                cutback_min_fraction: 1.5,
                ..d
            },
            "options.cutback_min_fraction = 1.5",
        ),
    ] {
        let e = options.validate().unwrap_err().to_string();
        assert!(e.contains(what), "{e}");
        let e = Scene::new(SLIDE.0, options).err().unwrap().to_string();
        assert!(e.contains(what), "{e}");
    }
}

/// Issue 33, item 4: under finite kinematics a press of `1e16` body sizes or more in one
/// increment returned `Ok` with every A node open below the held bottom of the lower block
/// (and at `1e66` an invalid-input error, "zero-length segment"). At every magnitude it must
/// be a contact error, the state kept; under small kinematics the contact holds (the problem
/// is linear).
#[test]
fn a_press_through_the_other_body_is_an_error_at_any_magnitude() {
    let press = Press {
        lower: [4, 2],
        upper: [2, 2],
        left: 0.5,
        width: 1.0,
        gap: 0.0,
        depth: 0.0,
        upper_modulus: 1.0,
        poisson: [0.3, 0.3],
        friction: 0.0,
        kinematics: Kinematics::Finite,
    };
    for depth in [1e10, 1e15, 1e16, 1e17, 1e50, 1e66, 1e100, 1e300] {
        for options in [off(), ContactOptions::default()] {
            let mut scene = Scene::new(press, options).unwrap();
            scene.step(1e-3, 0.0).unwrap();
            let before = state_bits(&scene.analysis);
            match scene.step(depth, 0.0) {
                Err(Error::Contact(_)) => {}
                other => panic!("a press of {depth:e}: {other:?}"),
            }
            assert_eq!(state_bits(&scene.analysis), before, "a press of {depth:e}");
        }
    }
    let small = Press {
        kinematics: Kinematics::Small,
        ..press
    };
    let mut scene = Scene::new(small, ContactOptions::default()).unwrap();
    scene.step(1e16, 0.0).unwrap();
    let results = scene.analysis.node_results(0).unwrap();
    assert!(
        results
            .iter()
            .all(|r| r.state.name() != "open" && r.tn < 0.0)
    );
}

fn draw(d: &mut Draws) -> Press {
    Press {
        lower: [d.int(2, 6), d.int(1, 3)],
        upper: [d.int(1, 4), d.int(1, 3)],
        left: d.range(0.1, 0.8),
        width: d.range(0.4, 1.0),
        gap: d.range(0.0, 1e-3),
        depth: d.range(1e-4, 1e-2),
        upper_modulus: 10f64.powf(d.range(-2.0, 2.0)),
        poisson: [d.range(-0.2, 0.45), d.range(-0.2, 0.45)],
        friction: d.range(0.05, 1.0),
        kinematics: if d.unit() < 0.5 {
            Kinematics::Small
        } else {
            Kinematics::Finite
        },
    }
}

/// Search for frictional slides that fail in one step without cutback after a press that
/// converges (run by hand: `cargo test --test integration -- --ignored --nocapture contact_cutback::search`).
#[test]
#[ignore]
fn search() {
    let mut d = Draws(0x9e37_79b9_7f4a_7c15);
    let (mut failed, mut rescued) = (0, 0);
    for i in 0..3000 {
        let press = draw(&mut d);
        let slide = d.range(-2.0, 2.0) * press.depth;
        let Ok(mut plain) = Scene::new(press, off()) else {
            continue;
        };
        if plain.step(press.depth, 0.0).is_err() {
            continue;
        }
        let Err(e) = plain.step(press.depth, slide) else {
            continue;
        };
        failed += 1;
        let mut cut = Scene::new(press, ContactOptions::default()).unwrap();
        cut.step(press.depth, 0.0).unwrap();
        let with = cut.step(press.depth, slide);
        if with.is_ok() {
            rescued += 1;
        }
        println!("{i}: {press:?} slide {slide:e}\n   off: {e}\n   on: {with:?}");
    }
    println!("{failed} slides failed without cutback, {rescued} of them converge with it");
}

// ------------------------------------------------------------------------------------------
// A pair lying back to back on the host API (issue 33, item 4)

/// A host pair: A = 5 nodes along `y = gap` from `x = 0` to 1 (the bottom of an upper body, left
/// to right), B = 5 nodes along `y = 0` from `x = 1.1` to -0.1 (the top of a lower body, right to
/// left); both reversed when `reversed`. Every dof a unit spring to the ground (CSR, diagonal):
/// the system the host API sees is all a host gives, and with surfaces this close the
/// polylines alone cannot tell which side each body is on.
fn host_pair(
    gap: f64,
    reversed: bool,
    a_inside: Vec<Option<[f64; 2]>>,
) -> hycon::Result<ContactAnalysis> {
    host_pair_with(gap, reversed, a_inside, None)
}

/// As [`host_pair`], with the host's elements of body A: one square on A's first segment (its
/// other two nodes held), which tells the side of body A without a point.
fn host_pair_with_element(gap: f64, reversed: bool) -> hycon::Result<ContactAnalysis> {
    use hycon::contact::bodies::{HostElements, HostNode};
    let node = |id: usize, position: [f64; 2], equations: [Option<usize>; 2]| HostNode {
        id,
        position: position.into(),
        equations: equations.into(),
    };
    let elements = HostElements {
        formulation: Formulation::Hybrid,
        materials: vec![Material::new(1.0, 0.3, 1.0, Analysis::PlaneStrain)?],
        element_material: vec![0],
        offsets: vec![0, 4],
        nodes: vec![0, 1, 100, 101],
        node_table: vec![
            node(0, [0.0, gap], [Some(0), Some(1)]),
            node(1, [0.25, gap], [Some(2), Some(3)]),
            node(100, [0.25, gap + 0.25], [None, None]),
            node(101, [0.0, gap + 0.25], [None, None]),
        ],
    };
    host_pair_with(gap, reversed, vec![], Some(elements))
}

fn host_pair_with(
    gap: f64,
    reversed: bool,
    a_inside: Vec<Option<[f64; 2]>>,
    elements: Option<hycon::contact::bodies::HostElements>,
) -> hycon::Result<ContactAnalysis> {
    use hycon::contact::bodies::{Csr, HostNode, HostStiffness, HostSystem, Triangle};
    let mut nodes = Vec::new();
    for i in 0..5 {
        nodes.push([0.25 * i as f64, gap]);
    }
    for i in 0..5 {
        nodes.push([1.1 - 0.3 * i as f64, 0.0]);
    }
    let n = 2 * nodes.len();
    let system = HostSystem {
        equations: n,
        nodes: nodes
            .iter()
            .enumerate()
            .map(|(i, &position)| HostNode {
                id: i,
                position: position.into(),
                equations: [Some(2 * i), Some(2 * i + 1)].into(),
            })
            .collect(),
        stiffness: HostStiffness::Csr(Csr {
            n,
            row_ptr: (0..=n).collect(),
            columns: (0..n).collect(),
            values: vec![1.0; n],
            triangle: Triangle::Full,
        }),
        elements,
        a_inside: a_inside.into_iter().map(|p| p.map(Into::into)).collect(),
        sections: vec![hycon::contact::handover::Section::new(
            Analysis::PlaneStrain,
            1.0,
        )?],
    };
    let (mut a, mut b): (Vec<usize>, Vec<usize>) = ((0..5).collect(), (5..10).collect());
    if reversed {
        a.reverse();
        b.reverse();
    }
    let pair = ContactPair {
        a,
        b,
        friction: 0.0,
    };
    ContactAnalysis::host(system, vec![pair], ContactOptions::default())
}

/// Before 0.7.0 the host API accepted a pair whose A and B were both reversed when the
/// surfaces lay within about half a segment of each other (touching, or 0.01 apart), and
/// pressing A into B returned `Ok` with every A node open (at 0.2 apart it was rejected, "B
/// lies behind A"). Now such a pair is rejected when the analysis is created: with a point
/// inside body A, by its orientation; without one, because nothing tells the sides.
#[test]
fn a_host_pair_lying_back_to_back_is_rejected() {
    let message = |r: hycon::Result<ContactAnalysis>| r.err().map(|e| e.to_string());
    for gap in [0.0, 0.01, 0.2] {
        let above = Some([0.5, gap + 0.1]);
        // both reversed: rejected, whatever the host says
        let e = message(host_pair(gap, true, vec![])).unwrap();
        assert!(
            e.contains("B lies behind A") || e.contains("A and B touch"),
            "{gap}: {e}"
        );
        let e = message(host_pair(gap, true, vec![above])).unwrap();
        assert!(
            e.contains("B lies behind A") || e.contains("A has its body on its right"),
            "{gap}: {e}"
        );
        // facing each other: accepted with the point inside the upper body
        host_pair(gap, false, vec![above]).unwrap();
        // and a point on the wrong side or beyond the ends is rejected
        let e = message(host_pair(gap, false, vec![Some([0.5, gap - 0.1])])).unwrap();
        assert!(e.contains("A has its body on its right"), "{gap}: {e}");
        let e = message(host_pair(gap, false, vec![Some([-1.0, gap + 0.1])])).unwrap();
        assert!(e.contains("beyond an end of the A polyline"), "{gap}: {e}");
    }
    // touching and facing, without the point: the geometry cannot tell, so it is asked for
    for gap in [0.0, 0.01] {
        let e = message(host_pair(gap, false, vec![])).unwrap();
        assert!(
            e.contains("A and B touch") && e.contains("a point inside it"),
            "{e}"
        );
    }
    // apart, the geometry tells: no point needed
    host_pair(0.2, false, vec![]).unwrap();
    // the host's elements tell the side too (the centroid of the element with A's first
    // segment)
    for gap in [0.0, 0.01] {
        host_pair_with_element(gap, false).unwrap();
        let e = message(host_pair_with_element(gap, true)).unwrap();
        assert!(e.contains("A has its body on its right"), "{gap}: {e}");
    }
    // a pair accepted with its point presses as it should: A pushed down closes (the springs
    // let the nodes alternate: 3 of 5 carry it) and nothing penetrates
    let above = Some([0.5, 0.1]);
    let mut ok = host_pair(0.0, false, vec![above]).unwrap();
    let mut f = vec![0.0; 20];
    for i in 0..5 {
        f[2 * i + 1] = -1e-3;
    }
    ok.increment(&f, &[]).unwrap();
    let results = ok.node_results(0).unwrap();
    assert!(results.iter().filter(|r| r.state.name() != "open").count() >= 3);
    assert!(results.iter().all(|r| r.gap >= -1e-12), "{results:?}");
    let e = message(host_pair(0.0, false, vec![above, above])).unwrap();
    assert!(e.contains("a_inside has 2 entries for 1 pairs"), "{e}");
}
