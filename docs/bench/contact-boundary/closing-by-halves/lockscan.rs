use hycon::contact::iteration::{ContactOptions, Kinematics};
use hycon_lab::scene::DiskOnBlock;
fn main() {
    for kin in [Kinematics::Finite] {
        for n in [8, 16, 32] {
            for bl in [4, 8, 16] {
                for frac in [0.05, 0.1, 0.2] {
                    for mu in [0.3, 0.5] {
                        let scene = DiskOnBlock {
                            elements_per_half_width: n,
                            friction: mu,
                            travel: 2.5,
                            band_layers: bl,
                            ..Default::default()
                        }
                        .build()
                        .unwrap();
                        let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
                        let run = |lock_rounds: usize| -> Result<(), String> {
                            let options = ContactOptions {
                                lock_rounds,
                                kinematics: kin,
                                ..ContactOptions::default()
                            };
                            let mut analysis = scene.analysis(options).unwrap();
                            let approach = scene.calibrated_approach(&mut analysis).unwrap();
                            analysis
                                .increment(&f, &scene.prescribed(approach, 0.0))
                                .map_err(|e| e.to_string())?;
                            let step = frac * scene.half_width;
                            let steps = (2.0 / frac) as usize;
                            for k in 1..=steps {
                                analysis
                                    .increment(&f, &scene.prescribed(approach, k as f64 * step))
                                    .map_err(|e| e.to_string())?;
                            }
                            Ok(())
                        };
                        let with = run(4);
                        let without = run(0);
                        println!(
                            "{kin:?} n {n} bl {bl} frac {frac} mu {mu}: locks {:?} / none {:?}",
                            with.err(),
                            without
                                .err()
                                .map(|e| e.chars().take(90).collect::<String>())
                        );
                    }
                }
            }
        }
    }
}
