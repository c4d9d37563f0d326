//! Instruction counts of `antipodal` runs, for callgrind: the machine's timings are noisy, the
//! number of instructions one run executes is not. `count-instructions.sh` (beside this file)
//! runs it under callgrind and prints instructions per run; run alone (`cargo bench --bench
//! instructions`) it times the same runs.
//!
//! `instructions FILE MODE N`: `N` runs of `antipodal` on the curve of `FILE`, either `warm`
//! (on one prepared curve, after a first run) or `cold` (preparing the curve read and answering
//! once, each time). The runs are in the function `measured`, which callgrind's
//! `--toggle-collect` isolates.
#![allow(missing_docs, clippy::unwrap_used)]

use antipodal::{prepare, Options, PlaneCurve};
use std::hint::black_box;
use std::time::Instant;

#[inline(never)]
fn measured(curve: &dyn PlaneCurve, warm: bool, n: usize) {
    let opts = Options::default();
    if warm {
        let p = prepare(curve);
        black_box(p.antipodal(&opts).unwrap());
        for _ in 0..n {
            black_box(p.antipodal(black_box(&opts)).unwrap());
        }
    } else {
        for _ in 0..n {
            black_box(prepare(black_box(curve)).antipodal(&opts).unwrap());
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let [file, mode, n] = args.as_slice() else {
        // (`cargo bench` runs every bench target without arguments: nothing to do.)
        eprintln!("usage: instructions FILE warm|cold N");
        return;
    };
    let text = std::fs::read_to_string(file).unwrap();
    let curve = curvekit::io::parse_curve(file, &text).unwrap();
    let n: usize = n.parse().unwrap();
    let t = Instant::now();
    measured(curve.plane_curve(), mode == "warm", n);
    eprintln!(
        "{mode}: {:.2} µs per run",
        t.elapsed().as_secs_f64() * 1e6 / n as f64
    );
}
