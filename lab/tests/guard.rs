//! The accuracy regression guard: the Hertz scene at 8, 16 and 64 elements per half-width and
//! Cook's membrane at 8 x 8 no worse than the values committed in `docs/bench/guard.csv`
//! (`hycon bench guard` prints the same comparison; `--write` records new values).

use std::path::Path;

#[test]
fn accuracy_no_worse_than_committed() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/bench/guard.csv");
    let committed = std::fs::read_to_string(&path).expect("docs/bench/guard.csv");
    let values = hycon_lab::bench::guard_values().expect("the guard's scenes solve");
    assert_eq!(
        values.len(),
        committed.lines().count(),
        "one value per committed line"
    );
    let verdicts = hycon_lab::bench::guard_verdicts(values, &committed).unwrap();
    let worse: Vec<_> = verdicts.iter().filter(|v| v.worse()).collect();
    assert!(worse.is_empty(), "worse than committed: {worse:#?}");
}
