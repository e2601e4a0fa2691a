use coulomb_hands::scenario::Scenario;
use coulomb_hands::WorldError;
fn main() {
    let file = std::env::args().nth(1).unwrap();
    let times: Vec<f64> = std::env::args().skip(2).map(|s| s.parse().unwrap()).collect();
    let s = Scenario::find(&file).unwrap();
    let r = s.run::<WorldError>(|w, line| {
        if times.iter().any(|t| (line.t - t).abs() < 0.0005) {
            println!("t {:.3} objs {:?}", line.t, line.objects.iter().map(|o| (o.name.clone(), o.pos)).collect::<Vec<_>>());
            for c in w.contacts() {
                println!("   {:?} {:?} fn {:.3} f {:?} n {:?} {:?}", c.hand, c.bone, c.normal_force, c.force, c.normal, c.state);
            }
        }
        Ok(())
    }).unwrap();
    for c in r.checks { println!("{} {} {} {}", c.passed, c.name, c.value, c.bound); }
}
