//! The native side of the page's step budget (`web/bench/bench.mjs`, which runs this): the
//! demo's steps timed natively, the mean step of the best of 5 whole runs, as JSON.
//!
//!   cargo run --release -p coulomb-hands-web [--features enhanced-determinism] --example bench

use coulomb_hands_web::sim::{self, Sim};
use std::time::Instant;

fn main() -> Result<(), sim::Error> {
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let mut demo = Sim::demo()?;
        let start = Instant::now();
        while !demo.finished() {
            demo.step(1000)?;
        }
        best = best.min(start.elapsed().as_secs_f64() / demo.steps() as f64);
    }
    let determinism = cfg!(feature = "enhanced-determinism");
    println!("{{\"demo_step_us\": {:.3}, \"enhanced_determinism\": {determinism}}}", best * 1e6);
    Ok(())
}
