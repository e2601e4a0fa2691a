//! README's "In a Bevy app": a shipped scenario in a headless app, printing
//! each contact that begins, until the scenario's time is up.

use bevy::prelude::*;
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands_bevy::{CoulombHandsPlugin, contacts::ContactBegan, interaction::Interaction};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let scenario = Scenario::find("grasp-lift")?; // or a world and hands of your own:
    let interaction = Interaction::of_scenario(&scenario)?; // interaction.add_hand(source)
    let steps = (scenario.duration / scenario.config.dt).round() as usize;
    App::new()
        .add_plugins((MinimalPlugins, CoulombHandsPlugin)) // DefaultPlugins to draw it
        .insert_non_send(interaction)
        .add_systems(Update, move |mut began: MessageReader<ContactBegan>| {
            for b in began.read() {
                println!("{:.3} s: {} touched {}", b.0.time, b.0.bone, b.0.object);
            }
        })
        .add_systems(Update, move |i: NonSend<Interaction>, mut exit: MessageWriter<AppExit>| {
            if i.steps() >= steps {
                exit.write(AppExit::Success);
            }
        })
        .run();
    Ok(())
}
