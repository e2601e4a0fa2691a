//! The per-step trace: one JSON line per physics step, in world metres
//! (y up). `replay --trace` and `scenario --trace` write it.

use crate::hand::{HandPose, HandSample, Phalanx, Side};
use crate::pipeline::InteractionWorld;
use std::io::Write;

/// One line of a trace.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TraceLine {
    /// Simulated time (s).
    pub t: f64,
    /// The tracked hands.
    pub hands: Vec<TraceHand>,
    /// Every object, in id order.
    pub objects: Vec<TraceObject>,
    /// Active hand–object contacts.
    pub contacts: usize,
}

/// A tracked hand on a trace line.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TraceHand {
    /// The tracker's hand id, or the hand's index for a scripted hand.
    pub id: i64,
    /// Which hand.
    pub side: Side,
    /// The hand as tracked.
    #[serde(flatten)]
    pub tracked: TracePose,
    /// The hand that acts after the step: the tracked hand through the
    /// config's tracking filter (`hand::acting`), the tracked hand itself
    /// without one. Beside `tracked`, it tells the filter's lag from a
    /// slip: an object that keeps its place on the acting hand did not slip.
    pub acting: Option<TracePose>,
    /// The tracker's grab strength (0..1), if it reports one.
    pub grab: Option<f32>,
    /// The tracker's pinch strength (0..1), if it reports one.
    pub pinch: Option<f32>,
    /// The tracker's confidence in the pose (0..1), if it reports one:
    /// beside a slip, whether the tracker was guessing.
    pub confidence: Option<f32>,
}

/// Where a hand is on a trace line (m).
#[derive(Debug, Clone, serde::Serialize)]
pub struct TracePose {
    /// The centre of the palm's grasping face (m).
    pub palm: [f32; 3],
    /// The palm's orientation, a unit quaternion x y z w: its local y is
    /// the grasping face's normal, its local z points to the fingers. With
    /// `palm` it gives an object's pose in the hand's frame.
    pub palm_rot: [f32; 4],
    /// The fingertips, thumb first: each distal phalanx's far end (m),
    /// which shows the grip's aperture and which finger a glitch threw.
    pub tips: [[f32; 3]; 5],
}

impl TracePose {
    /// The entry of `pose`.
    pub fn of(pose: &HandPose) -> TracePose {
        TracePose {
            palm: pose.palm_surface().to_array(),
            palm_rot: pose.palm.rotation.to_array(),
            tips: pose.fingers.map(|f| f[Phalanx::Distal as usize].b.to_array()),
        }
    }

    /// Every number of the entry.
    fn values(&self) -> impl Iterator<Item = &f32> {
        self.palm.iter().chain(&self.palm_rot).chain(self.tips.iter().flatten())
    }
}

/// An object on a trace line.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TraceObject {
    /// Its name in the scene.
    pub name: String,
    /// Body origin (m).
    pub pos: [f32; 3],
    /// Unit quaternion, x y z w.
    pub rot: [f32; 4],
    /// Linear velocity (m/s).
    pub linvel: [f32; 3],
}

impl TraceHand {
    /// A hand's entry, from its label, this step's sample and the pose
    /// that acted in the step, if the hand acted.
    pub fn of(id: i64, side: Side, sample: &HandSample, acting: Option<&HandPose>) -> TraceHand {
        TraceHand {
            id,
            side,
            tracked: TracePose::of(&sample.pose),
            acting: acting.map(TracePose::of),
            grab: sample.grab,
            pinch: sample.pinch,
            confidence: sample.confidence,
        }
    }
}

impl TraceLine {
    /// The line for `world` after a step, with the given hands.
    pub fn of(world: &InteractionWorld, hands: Vec<TraceHand>) -> TraceLine {
        let objects = world
            .object_ids()
            .filter_map(|id| {
                let s = world.object_state(id).ok()?;
                Some(TraceObject {
                    name: world.object_name(id).unwrap_or("").to_string(),
                    pos: s.position.to_array(),
                    rot: s.rotation.to_array(),
                    linvel: s.linvel.to_array(),
                })
            })
            .collect();
        TraceLine { t: world.time(), hands, objects, contacts: world.contacts().len() }
    }

    /// Whether every number on the line is finite.
    pub fn is_finite(&self) -> bool {
        let poses = self.hands.iter().flat_map(|h| std::iter::once(&h.tracked).chain(&h.acting));
        let hands = poses.flat_map(TracePose::values);
        let objects = self.objects.iter().flat_map(|o| o.pos.iter().chain(&o.rot).chain(&o.linvel));
        hands.chain(objects).all(|v| v.is_finite())
    }

    /// Writes the line as JSON Lines.
    pub fn write(&self, out: &mut impl Write) -> std::io::Result<()> {
        serde_json::to_writer(&mut *out, self).map_err(std::io::Error::other)?;
        out.write_all(b"\n")
    }
}

/// A trace file: buffered, and every error writing it names the file.
///
/// The file is created (or truncated) at its first line, or when flushed:
/// a run that fails before its first step leaves no file behind, and an
/// earlier trace at the same path as it was. A run that fails later keeps
/// the steps it traced.
pub struct TraceFile {
    path: std::path::PathBuf,
    out: Option<std::io::BufWriter<std::fs::File>>,
}

impl TraceFile {
    /// A trace to be written at `path`. Its folder is checked now, so a
    /// path that cannot be written is named before a run starts.
    pub fn at(path: &std::path::Path) -> std::io::Result<TraceFile> {
        use std::io::{Error, ErrorKind};
        let folder = path.parent().filter(|f| !f.as_os_str().is_empty());
        let folder = std::fs::metadata(folder.unwrap_or(std::path::Path::new(".")));
        let problem = match folder {
            Err(e) => Some(e),
            Ok(f) if !f.is_dir() => {
                Some(Error::new(ErrorKind::NotADirectory, "its parent is not a directory"))
            }
            Ok(_) if path.is_dir() => Some(Error::new(ErrorKind::IsADirectory, "is a directory")),
            Ok(_) => None,
        };
        match problem {
            Some(e) => Err(named(path, e)),
            None => Ok(TraceFile { path: path.to_path_buf(), out: None }),
        }
    }

    /// The file, created at the first call.
    fn file(&mut self) -> std::io::Result<&mut std::io::BufWriter<std::fs::File>> {
        match &mut self.out {
            Some(out) => Ok(out),
            none => {
                let file = std::fs::File::create(&self.path).map_err(|e| named(&self.path, e))?;
                Ok(none.insert(std::io::BufWriter::new(file)))
            }
        }
    }
}

/// `e` with the file's path in front of its message.
fn named(path: &std::path::Path, e: std::io::Error) -> std::io::Error {
    std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
}

impl Write for TraceFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let written = self.file()?.write(buf);
        written.map_err(|e| named(&self.path, e))
    }

    fn flush(&mut self) -> std::io::Result<()> {
        let flushed = self.file()?.flush();
        flushed.map_err(|e| named(&self.path, e))
    }
}
