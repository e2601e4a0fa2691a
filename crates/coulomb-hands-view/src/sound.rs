//! A subtle tap when a bone begins to touch an object, louder for a harder
//! contact: its volume grows with the speed at which the bone was closing
//! on the object's surface when the contact began, over the last
//! [`SPEED_WINDOW`] (a tracker's or the mouse hand's poses arrive in
//! steps, so one physics step's motion would be all or nothing).
//!
//! With no audio device the viewer is silent, and says nothing about it.
//! Bevy's audio output is never opened then, so the system's audio library
//! prints nothing either. The taps are still worked out ([`ContactSound::taps`]),
//! so what would have sounded can be checked.

use bevy::audio::{AudioPlayer, AudioPlugin, AudioSink, AudioSource, PlaybackSettings, Volume};
use bevy::prelude::*;
use coulomb_hands::contact::ContactEventKind;
use coulomb_hands::hand::{BoneShape, HandId, HandPose};
use coulomb_hands::pipeline::InteractionWorld;
use coulomb_hands_bevy::prelude::*;
use std::collections::VecDeque;
use std::path::Path;

/// The approach speed that gives the loudest tap (m/s): a brisk slap.
pub const LOUDEST_SPEED: f32 = 0.6;
/// The quietest tap's volume, for a touch at no speed: still audible.
pub const QUIETEST: f32 = 0.08;
/// The loudest tap's volume (linear): subtle, under Bevy's full scale.
pub const LOUDEST: f32 = 0.5;
/// The time over which a bone's closing speed is measured (s): two frames
/// of a 100 Hz tracker.
pub const SPEED_WINDOW: f32 = 0.02;
/// At most this many taps waiting to start; more are dropped, so an
/// output that never plays cannot pile up entities.
const MAX_PENDING: usize = 16;

/// The tap's volume (linear gain) for a contact that began with the bone
/// closing at `speed` (m/s).
pub fn loudness(speed: f32) -> f32 {
    let t = (speed / LOUDEST_SPEED).clamp(0.0, 1.0);
    if t.is_nan() {
        return QUIETEST;
    }
    QUIETEST + (LOUDEST - QUIETEST) * t
}

/// Whether this machine has somewhere to play sound: on Linux, a sound card
/// in `/proc/asound/cards`, or a PulseAudio or PipeWire server. (Asking the
/// audio library instead makes ALSA print errors when there is none.)
pub fn audio_device_present() -> bool {
    if !cfg!(target_os = "linux") {
        return true;
    }
    let runtime = std::env::var_os("XDG_RUNTIME_DIR").map(std::path::PathBuf::from);
    has_sound_card(Path::new("/proc/asound/cards"))
        || std::env::var_os("PULSE_SERVER").is_some()
        || runtime.is_some_and(|r| r.join("pulse/native").exists() || r.join("pipewire-0").exists())
}

/// Whether an ALSA card list (`/proc/asound/cards`) names a card.
fn has_sound_card(cards: &Path) -> bool {
    let text = std::fs::read_to_string(cards).unwrap_or_default();
    !text.trim().is_empty() && !text.contains("no soundcards")
}

/// The taps: the sound, if there is an output to play it on, and every tap
/// worked out so far.
#[derive(Resource, Debug, Default)]
pub struct ContactSound {
    /// The tap's sound; `None` when silent.
    tap: Option<Handle<AudioSource>>,
    /// Each tap's volume, in the order the contacts began.
    pub taps: Vec<f32>,
    /// Every hand's pose in each of the last steps, oldest first, for the
    /// bones' speeds.
    history: VecDeque<Vec<Option<HandPose>>>,
    /// The world's step count when last heard: the events are the last step's, so
    /// a tick with no step (paused, held at a screenshot) has none new.
    steps: Option<usize>,
}

/// Contact taps: played when `play` and an audio device is present, worked
/// out in any case. It adds Bevy's [`AudioPlugin`] only when it will play.
#[derive(Debug, Clone, Copy)]
pub struct SoundPlugin {
    /// Play the taps (false: `--mute`, or no audio device).
    pub play: bool,
}

impl Plugin for SoundPlugin {
    fn build(&self, app: &mut App) {
        let mut sound = ContactSound::default();
        if self.play {
            if !app.is_plugin_added::<AudioPlugin>() {
                app.add_plugins(AudioPlugin::default());
            }
            let bytes = tap_wav();
            let mut sources = app.world_mut().resource_mut::<Assets<AudioSource>>();
            sound.tap = Some(sources.add(AudioSource { bytes: bytes.into() }));
        }
        app.insert_resource(sound).add_systems(HandPhysicsStep, listen.after(WorldStep));
    }
}

/// After each physics step: a tap for each contact that began in it.
fn listen(
    physics: Option<Res<HandPhysics>>,
    mut replaced: MessageReader<HandPhysicsReplaced>,
    mut sound: ResMut<ContactSound>,
    pending: Query<(), (With<AudioPlayer>, Without<AudioSink>)>,
    mut commands: Commands,
) {
    let Some(physics) = physics else { return };
    let world = physics.world();
    if replaced.read().last().is_some() {
        sound.history = VecDeque::new();
    }
    let steps = physics.steps();
    match sound.steps.replace(steps) {
        Some(last) if last == steps => return,
        // Steps the viewer took itself (a seek): no speeds across that jump.
        Some(last) if steps != last + 1 => sound.history.clear(),
        _ => {}
    }
    let mut waiting = pending.iter().count();
    for e in world.events().iter().filter(|e| e.kind == ContactEventKind::Began) {
        let steps = sound.history.len();
        let oldest = sound.history.front().and_then(|h| h.get(e.hand.0 as usize)?.as_ref());
        let then = oldest.map(|pose| (pose, steps as f32 * world.config().dt));
        let speed = closing_speed(world, then, e.hand, e.bone, e.object);
        let volume = loudness(speed.unwrap_or(0.0));
        sound.taps.push(volume);
        if let Some(tap) = sound.tap.clone().filter(|_| waiting < MAX_PENDING) {
            let settings = PlaybackSettings::DESPAWN.with_volume(Volume::Linear(volume));
            commands.spawn((AudioPlayer(tap), settings));
            waiting += 1;
        }
    }
    let poses = (0..world.hand_count()).map(|i| world.hand_pose(HandId(i as u32)).cloned());
    sound.history.push_back(poses.collect());
    let window = (SPEED_WINDOW / world.config().dt).round().max(1.0) as usize;
    while sound.history.len() > window {
        sound.history.pop_front();
    }
}

/// How fast the bone closed on the object's surface (m/s), relative to the
/// object: its centre's motion since `then` (a pose and how long ago, s)
/// against the contact normal.
fn closing_speed(
    world: &InteractionWorld,
    then: Option<(&HandPose, f32)>,
    hand: HandId,
    bone: coulomb_hands::hand::Bone,
    object: coulomb_hands::scene::ObjectId,
) -> Option<f32> {
    let now = world.hand_pose(hand)?;
    let contact =
        world.contacts().iter().find(|c| c.hand == hand && c.bone == bone && c.object == object)?;
    let centre = |shape: BoneShape| match shape {
        BoneShape::Palm(p) => p.center,
        BoneShape::Capsule(c) => c.centroid(),
    };
    let (before, elapsed) = then?;
    let bone_velocity = (centre(now.bone(bone)) - centre(before.bone(bone))) / elapsed;
    let state = world.object_state(object).ok()?;
    let at = contact.point - state.position;
    let object_velocity = state.linvel + state.angvel.cross(at);
    let speed = -(bone_velocity - object_velocity).dot(contact.normal);
    speed.is_finite().then_some(speed.max(0.0))
}

/// The tap as a WAV file: 60 ms of a damped 1.1 kHz tone with a softer
/// octave, 44.1 kHz mono 16-bit, with a 1 ms rise so it does not click.
fn tap_wav() -> Vec<u8> {
    const RATE: u32 = 44_100;
    let samples: Vec<i16> = (0..RATE * 60 / 1000)
        .map(|i| {
            let t = i as f32 / RATE as f32;
            let tone = (std::f32::consts::TAU * 1100.0 * t).sin()
                + 0.35 * (std::f32::consts::TAU * 2200.0 * t).sin();
            let envelope = (t / 0.001).min(1.0) * (-t / 0.010).exp();
            (tone * envelope * 0.7 * f32::from(i16::MAX)) as i16
        })
        .collect();
    let data_len = (samples.len() * 2) as u32;
    let mut wav = Vec::with_capacity(44 + data_len as usize);
    wav.extend_from_slice(b"RIFF");
    wav.extend_from_slice(&(36 + data_len).to_le_bytes());
    wav.extend_from_slice(b"WAVEfmt ");
    // PCM, mono, the rate, bytes per second, block align 2, 16 bits.
    for field in [16u32, 1 | (1 << 16), RATE, RATE * 2, 2 | (16 << 16)] {
        wav.extend_from_slice(&field.to_le_bytes());
    }
    wav.extend_from_slice(b"data");
    wav.extend_from_slice(&data_len.to_le_bytes());
    samples.iter().for_each(|s| wav.extend_from_slice(&s.to_le_bytes()));
    wav
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_harder_contact_is_louder_within_subtle_bounds() {
        assert_eq!(loudness(0.0), QUIETEST);
        assert!(loudness(0.05) < loudness(0.2) && loudness(0.2) < loudness(0.5));
        assert_eq!(loudness(3.0), LOUDEST);
        assert_eq!(loudness(f32::NAN), QUIETEST);
    }

    #[test]
    fn the_tap_is_a_well_formed_pcm_wav() {
        let wav = tap_wav();
        assert_eq!(&wav[0..4], b"RIFF");
        assert_eq!(u32::from_le_bytes(wav[4..8].try_into().unwrap()) as usize, wav.len() - 8);
        assert_eq!(&wav[8..16], b"WAVEfmt ");
        assert_eq!(u32::from_le_bytes(wav[24..28].try_into().unwrap()), 44_100);
        assert_eq!(&wav[36..40], b"data");
        assert_eq!(u32::from_le_bytes(wav[40..44].try_into().unwrap()) as usize, 2 * 2646);
        // It fades out: the last millisecond is near silence.
        let last = wav[wav.len() - 88..].chunks(2).map(|b| i16::from_le_bytes([b[0], b[1]]));
        assert!(last.map(i16::unsigned_abs).max().unwrap_or(0) < 200);
    }

    #[test]
    fn an_empty_or_cardless_alsa_list_has_no_device() {
        let dir = std::env::temp_dir().join(format!("coulomb-hands-asound-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary directory");
        let cards = dir.join("cards");
        std::fs::write(&cards, "--- no soundcards ---\n").expect("written");
        assert!(!has_sound_card(&cards));
        std::fs::write(&cards, " 0 [PCH            ]: HDA-Intel - HDA Intel PCH\n").expect("ok");
        assert!(has_sound_card(&cards));
        assert!(!has_sound_card(&dir.join("missing")));
        std::fs::remove_dir_all(&dir).ok();
    }
}
