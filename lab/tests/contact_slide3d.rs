//! Sliding at an angle in 3D (issue #43): a block dragged over a flat at 0, 15, 30, 45, 60 and
//! 90 degrees to the flat's mesh lines (`hycon_lab::slide3d`, the block turned with the drag),
//! `mu = 0.3`, small kinematics: pressed, then dragged by `0.1` (100 times the press) in each
//! of four increments. From the first drag increment on every A node slips; from the second
//! (steady sliding: the elastic state no longer changes) the total friction force opposes the
//! drag within `1e-6` rad and its magnitude is `mu P` to `1e-8`, at every angle. A pyramid
//! cone errs by tens of percent off its facets; a slip direction kept from the press (radial:
//! 20 of the 25 nodes slip outward under the press) errs by 12% in magnitude at 0 degrees and
//! by 0.03 to 0.07 rad in direction at 15 to 60 (measured before slip directions followed the
//! slip).
//!
//! Node by node, from the third drag increment on every slip node's direction is the drag's
//! within `1.5e-6` rad: an increment converges only when no slip node's direction turns by
//! more than `SlipDirection::same_as` tells apart, a cosine of `1 - 1e-12` (`1.41e-6` rad). In
//! the second the nodes' slips still differ from the drag by the last change of the elastic
//! state (measured up to `6.8e-6` rad); the totals average it out. Measured in the second
//! drag increment: angle at most `6.3e-8` rad, `|F_t| / (mu P) - 1` at most `7.8e-12`; in the
//! later ones round-off (`cargo test -p hycon-lab --test lab contact_slide3d:: --
//! --nocapture`).

use hycon_lab::slide3d::Slide;

const ANGLES: [f64; 6] = [0.0, 15.0, 30.0, 45.0, 60.0, 90.0];

/// The angle `SlipDirection::same_as` tells apart: `acos(1 - 1e-12)`.
const DIRECTION: f64 = 1.5e-6;

#[test]
fn a_block_dragged_at_any_angle_feels_mu_p_against_its_slip() {
    for theta in ANGLES {
        let slide = Slide::small(theta);
        let increments = slide.run().unwrap();
        assert_eq!(increments.len(), 5);
        for (i, inc) in increments.iter().enumerate() {
            println!(
                "theta {theta:>2}: drag {:.1}, P {:.6e}, F_t {:+.6e} {:+.6e}, angle {:.2e} rad, \
                 |F_t|/(mu P) - 1 {:+.2e}, slip spread {:.2e} rad, active/stick/slip {:?}, \
                 {} iterations",
                inc.drag,
                inc.normal,
                inc.friction[0],
                inc.friction[1],
                inc.angle,
                inc.magnitude,
                inc.spread,
                inc.states,
                inc.iterations
            );
            assert_eq!(inc.states[0], 25, "the whole bottom presses: {inc:?}");
            assert!(inc.normal > 0.0);
            if i == 0 {
                continue;
            }
            assert_eq!(inc.states[2], 25, "every node slips: {inc:?}");
            if i >= 2 {
                assert!(i < 3 || inc.spread <= DIRECTION, "theta {theta}: {inc:?}");
                assert!(inc.angle <= 1e-6, "theta {theta}: {inc:?}");
                assert!(inc.magnitude.abs() <= 1e-8, "theta {theta}: {inc:?}");
            }
        }
    }
}

/// Finite kinematics: the block starts `1` behind the flat's centre and is dragged by `0.25`
/// eight times, over four of the flat's faces (`0.5` wide), re-paired as it goes; the same
/// totals asserted from the second drag increment on.
///
/// Fails today (`cargo test -p hycon-lab --test lab contact_slide3d:: -- --ignored
/// --nocapture`): the press increment does not converge (60 iterations, last `R` 0.15 to
/// 0.33; from the fallback's states the stick/slip states of some 20 of the 25 nodes churn
/// again): the slip directions' fixed-point iteration (a slip node's direction following its
/// slip, which small kinematics needs) does not settle while the geometry follows the
/// iterate. With the directions kept from stick -> slip instead (as before), the press
/// converges in 6 to 8 iterations.
///
/// A second failure followed, in the first drag increment: an A node refused as covered more
/// than `1 + 1e-10` times over, by `1.5e-7` to `2.8e-7`, the triangle rule's error on the
/// deformed (no longer parallelogram) faces of an iterate (the covered weight integrating
/// `N_k` through the inverse bilinear map, the whole weight by Gauss's rule), not B's faces
/// overlapping. Coverage is now judged by the exact projected areas of the overlap polygons
/// (`SurfaceMortar::coverage`, `src/contact/faces/surface.rs`), which that error does not
/// reach; not yet seen on this run, which stops at the press. Without friction (`mu = 0`)
/// the finite run presses and drags over the four faces at all six angles, 24 or 25 nodes in
/// contact, in 3 to 8 iterations per increment (as it did with the judgement by weights).
///
/// With the directions sidestepped by hand (kept from stick -> slip) and the coverage
/// tolerance loosened (`1e-5`, before the judgement by areas) the
/// block slides over the four faces at all six angles, re-paired as it goes, in 4 iterations
/// per drag increment, 24 or 25 of the 25 nodes slipping; the totals then show the frozen
/// directions: `|F_t| / (mu P) - 1` from `-1.9e-2` to `-2.8e-2`, the angle up to `2.3e-2` rad
/// at 30 and 60 degrees.
#[test]
#[ignore = "finite kinematics does not yet slide the block: see the doc comment"]
fn a_block_dragged_over_four_faces_with_finite_kinematics() {
    for theta in ANGLES {
        let increments = Slide::finite(theta).run().unwrap();
        for inc in &increments[2..] {
            assert_eq!(inc.states[2], 25, "every node slips: {inc:?}");
            assert!(inc.angle <= 1e-6, "theta {theta}: {inc:?}");
            assert!(inc.magnitude.abs() <= 1e-8, "theta {theta}: {inc:?}");
        }
    }
}
