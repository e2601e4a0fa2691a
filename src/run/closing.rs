//! Verdicts for every closing of a recorded hand. An object appears where
//! each closing grasps ([`super::grasp::find_grasps`]), held by a fixture
//! until the hand grips it; then the replay judges, from physics alone,
//! whether the closed hand held it, when and how far it slipped, and
//! whether the hand let it go once it opened. A closing too short to mean
//! anything, or one whose hand never pressed its object, gets no verdict.

use super::RunError;
use super::drive::{Observer, StepView};
use super::grasp::spans::Signals;
use super::grasp::{GraspSite, MIN_HOLD, SAMPLE_STEP, find_grasps, site_at, tracker_holds};
use super::held::{GraspObject, is_gripped, is_squeezed};
use crate::friction::settling_time;
use crate::input::playback::Playback;
use crate::pipeline::{InteractionWorld, WorldError};
use crate::scene::ObjectId;
use glam::{Quat, Vec3};

/// How long after a hand opens its object must have stopped being gripped
/// (s), unless the hand closes again sooner. A hand opens in a few tenths
/// of a second; in this time an object let go falls 1.2 m.
pub const RELEASE_WINDOW: f64 = 0.5;

/// Whether a closing was judged.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Hold {
    /// The hand held for at least [`MIN_HOLD`] and pressed the object:
    /// held or slipped, and released or not, are judged.
    Judged,
    /// No signal kept the hand closed for [`MIN_HOLD`]: a twitch or a
    /// flicker. No object is put there.
    TooShort,
    /// The hand stayed closed but never pressed the object (it closed
    /// beside it, or short of it): nothing held it, so nothing is judged.
    NeverPressed,
    /// The hand opened before its grip on the object had settled (the
    /// object got free of its fixture too late in the hold): too soon to
    /// say where the grip held it.
    Unsettled,
}

/// What happened to the object at one closing of a hand.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ClosingVerdict {
    /// The object's name in the world: `closing-1`, `closing-2` … (a
    /// closing too short to judge gets the name but no object).
    pub object: String,
    /// The tracker's id of the closing hand.
    pub hand: i64,
    /// The signals that found the closing: `grab`, `pinch` (the tracker's
    /// strengths), `curl`, `aperture` (from the joints).
    pub signals: Signals,
    /// Whether it was judged, and if not, why.
    pub hold: Hold,
    /// Whether the tracker itself reports the hand holding in this
    /// closing: its grab or pinch strength at or above 0.8 for at least
    /// [`super::grasp::TRACKER_HOLD`] (0.2 s) within it.
    pub tracker_hold: bool,
    /// How long the hand held: `opening_at − closing_at` (s).
    pub hold_s: f64,
    /// When the hand was closed, from `closing_at` to `opening_at`, the last
    /// instant before it opened by the tracker's strengths or the curl,
    /// whichever first ([`GraspSite`]); its most closed instant, where the
    /// object sits, and when every signal had let it go (s).
    pub closing_at: f64,
    /// When the fixture let go at the latest, where the object sits: the
    /// most closed instant of the hold that leaves the grip its settling
    /// time and then [`fall_time`] before the hand opens (s).
    pub closed_at: f64,
    /// See `closing_at` (s).
    pub opening_at: f64,
    /// See `closing_at` (s).
    pub open_at: f64,
    /// Where the object appeared (m), at `appeared_at` (s): the hand's most
    /// open instant before this closing.
    pub site: [f32; 3],
    /// See `site` (s).
    pub appeared_at: f64,
    /// When the fixture let the object go because the hand gripped it
    /// ([`is_gripped`]), or `None` if the hand had not gripped it by its
    /// most closed instant, when the fixture let go anyway.
    pub gripped_at: Option<f64>,
    /// When the object's place in the hand is taken as the reference for
    /// the drift (s): the grip's settling time ([`settling_time`], for the
    /// object's γ and mass and the contacts' damping) after the fixture let
    /// it go. Later than `opening_at`: [`Hold::Unsettled`].
    pub settled_at: Option<f64>,
    /// The largest distance the object moved in the palm's frame from
    /// `settled_at` to `opening_at` (m): the palm of the hand that acts,
    /// which holds the object, so the tracking filter's lag is not a slip.
    pub drift: f32,
    /// The drift that is a slip: the closing hand's finger width (twice
    /// its index fingertip's radius, m). An object that moved farther
    /// than that against the palm is no longer under the pads that held
    /// it.
    pub slip_bound: f32,
    /// When the drift first exceeded `slip_bound` (s), if it did.
    pub slipped_at: Option<f64>,
    /// Whether the hand let the object go after opening: from some instant
    /// after `opening_at`, and within [`RELEASE_WINDOW`] of `open_at` (or
    /// before the hand's next closing begins), no hand squeezed it any more
    /// ([`is_squeezed`]). `None` when the closing was not judged, or when
    /// the recording ends before that window does with the object still
    /// gripped.
    pub released: Option<bool>,
    /// From when the object stayed let go (s), if it was.
    pub released_at: Option<f64>,
    /// The end of the window in which it must have been let go (s):
    /// [`RELEASE_WINDOW`] after `open_at`, or the hand's next closing if
    /// that begins sooner.
    pub release_by: f64,
    /// The object's largest speed from `opening_at` to the window's end
    /// (m/s).
    pub speed_after_open: f32,
}

impl ClosingVerdict {
    /// Held: judged, and the object stayed under the pads while the hand
    /// was closed.
    pub fn held(&self) -> bool {
        self.hold == Hold::Judged && self.slipped_at.is_none()
    }

    /// Which closing this is: `closing-1 (hand 31, closed 1.02-2.06 s, by
    /// pinch+aperture)`, as the summary line and the report name it.
    pub fn label(&self) -> String {
        format!(
            "{} (hand {}, closed {:.2}-{:.2} s, by {})",
            self.object, self.hand, self.closing_at, self.opening_at, self.signals
        )
    }
}

impl std::fmt::Display for ClosingVerdict {
    /// One line, e.g. `closing-1 (hand 31, closed 1.02-2.06 s, by
    /// pinch+aperture): held, drift 7.3 mm (a slip is 18.7); released at
    /// 2.06 s`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: ", self.label())?;
        match self.hold {
            Hold::TooShort => {
                return write!(
                    f,
                    "too short to judge ({:.2} s; a hold is {MIN_HOLD} s)",
                    self.hold_s.max(0.0)
                );
            }
            Hold::NeverPressed => return write!(f, "never pressed the object, not judged"),
            Hold::Unsettled => {
                return write!(f, "opened before the grip settled on the object, not judged");
            }
            Hold::Judged => {}
        }
        let (drift, bound) = (self.drift * 1e3, self.slip_bound * 1e3);
        match self.slipped_at {
            None => write!(f, "held, drift {drift:.1} mm (a slip is {bound:.1})")?,
            Some(t) => write!(f, "slipped at {t:.2} s, {drift:.1} mm (a slip is {bound:.1})")?,
        }
        match (self.released, self.released_at) {
            (Some(true), Some(t)) => write!(f, "; released at {t:.2} s"),
            (Some(false), _) => write!(f, "; NOT released after opening"),
            _ => write!(f, "; still gripped when the recording ends"),
        }
    }
}

/// One closing being judged.
#[derive(Debug, Clone)]
struct Judged {
    site: GraspSite,
    verdict: ClosingVerdict,
    id: Option<ObjectId>,
    /// Still held by its fixture.
    fixed: bool,
    /// The grip's settling time for this object (s).
    settle: f64,
    /// Whether a hand has pressed the object while closed.
    pressed: bool,
    /// The object in the palm frame once the grip settled.
    reference: Option<Vec3>,
    /// The hold's sites, one per [`SAMPLE_STEP`] from `closing_at` to
    /// `opening_at`: where the fixture's release is chosen.
    sites: Vec<HoldSite>,
}

/// The site the hand has at one instant of a hold ([`site_at`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct HoldSite {
    t: f64,
    point: Vec3,
    rotation: Quat,
    aperture: f32,
}

/// How long an object that nothing holds takes to fall `distance` (m)
/// from rest under `gravity` (m/s²) (s): a judged window at least this
/// long sees an object the hand does not hold slip.
pub fn fall_time(distance: f32, gravity: f32) -> f64 {
    f64::from(2.0 * distance / gravity).sqrt()
}

/// The site at which the fixture lets go: the most closed of `sites` no
/// later than `latest`, or the first if none is (a hold too short for
/// this object's grip to settle and be judged).
fn release_site(sites: &[HoldSite], latest: f64) -> Option<HoldSite> {
    let judgeable = sites.iter().filter(|s| s.t <= latest + 1e-9);
    judgeable.min_by(|a, b| a.aperture.total_cmp(&b.aperture)).or(sites.first()).copied()
}

/// `site` with its fixture's release (`closed_at`) and its object's place
/// (`point`, `rotation`) moved to the latest instant that leaves a grip on
/// the object time to be judged: the most closed instant of the hold at
/// least the grip's `settle` time (s) and then the [`fall_time`] of the
/// hand's `slip_bound` (m) under `gravity` (m/s²) before the hand opens,
/// or the hold's first instant if none is. Unchanged where that is its
/// most closed instant.
/// `sites` are the hold's ([`hold_sites`]).
fn let_go_site(
    sites: &[HoldSite],
    site: &GraspSite,
    settle: f64,
    (slip_bound, gravity): (f32, f32),
) -> GraspSite {
    let latest = site.opening_at - settle - fall_time(slip_bound, gravity);
    match release_site(sites, latest) {
        Some(at) if at.t != site.closed_at => {
            GraspSite { closed_at: at.t, point: at.point, rotation: at.rotation, ..*site }
        }
        _ => *site,
    }
}

/// Moves object `id`, fixed at `site` with a grip that settles in `settle`
/// (s), to where its fixture lets go at the latest ([`let_go_site`] of the
/// hold's `sites` and the hand's `slip_bound`, m); returns that site.
pub(crate) fn seat_for_judging(
    world: &mut InteractionWorld,
    id: ObjectId,
    (sites, site): (&[HoldSite], &GraspSite),
    settle: f64,
    slip_bound: f32,
) -> Result<GraspSite, RunError> {
    let at = let_go_site(sites, site, settle, (slip_bound, world.config().gravity.length()));
    if at.closed_at != site.closed_at {
        world.place_object(id, at.point, at.rotation)?;
    }
    Ok(at)
}

/// The drift that is a slip at `site` (m): twice the closing hand's index
/// fingertip radius, a finger's width.
pub(crate) fn slip_bound(playback: &Playback, site: &GraspSite) -> f32 {
    let finger = playback.sample(site.track, site.closed_at);
    finger.map_or(0.0, |h| 2.0 * h.pose.fingers[1][2].radius)
}

/// The sites of `site`'s hold, one per [`SAMPLE_STEP`].
pub(crate) fn hold_sites(playback: &Playback, site: &GraspSite) -> Vec<HoldSite> {
    let first = (site.closing_at / SAMPLE_STEP).round() as usize;
    let last = (site.opening_at / SAMPLE_STEP).round() as usize;
    (first..=last)
        .filter_map(|k| {
            let t = k as f64 * SAMPLE_STEP;
            let (point, rotation, aperture) = site_at(playback, site.track, t)?;
            Some(HoldSite { t, point, rotation, aperture })
        })
        .collect()
}

/// The [`Observer`] that puts an object at every closing of a recording's
/// hands and judges each ([`ClosingVerdict`]). The hands must be driven in
/// track order, as [`super::replay::replay`] does.
#[derive(Debug, Clone)]
pub struct Closings {
    object: GraspObject,
    judged: Vec<Judged>,
    /// The recording's end (s).
    end: f64,
}

impl Closings {
    /// The closings of `playback`, each to get an `object`; an object that
    /// could not be added is an error now, before any step.
    pub fn new(playback: &Playback, object: GraspObject) -> Result<Closings, WorldError> {
        let origin =
            GraspSite { point: Vec3::ZERO, rotation: Quat::IDENTITY, ..Default::default() };
        object.at(&origin, "closing-1").validate()?;
        let sites = find_grasps(playback, SAMPLE_STEP);
        let holds: Vec<Vec<(f64, f64)>> =
            (0..playback.tracks.len()).map(|track| tracker_holds(playback, track)).collect();
        let judged = sites
            .iter()
            .enumerate()
            .map(|(k, site)| {
                let next = sites[k + 1..].iter().find(|s| s.track == site.track);
                let window_end = (site.open_at + RELEASE_WINDOW)
                    .min(next.map_or(f64::INFINITY, |n| n.widest_before));
                let slip_bound = slip_bound(playback, site);
                Judged {
                    site: *site,
                    verdict: ClosingVerdict {
                        object: format!("closing-{}", k + 1),
                        hand: playback.tracks[site.track].id,
                        signals: site.signals,
                        hold: if site.sustained { Hold::Judged } else { Hold::TooShort },
                        tracker_hold: holds[site.track]
                            .iter()
                            .any(|&(a, b)| a <= site.open_at && b >= site.closing_at),
                        hold_s: site.hold(),
                        closing_at: site.closing_at,
                        closed_at: site.closed_at,
                        opening_at: site.opening_at,
                        open_at: site.open_at,
                        site: site.point.to_array(),
                        appeared_at: site.widest_before,
                        gripped_at: None,
                        settled_at: None,
                        drift: 0.0,
                        slip_bound,
                        slipped_at: None,
                        released: None,
                        released_at: None,
                        release_by: window_end,
                        speed_after_open: 0.0,
                    },
                    id: None,
                    fixed: true,
                    settle: 0.0,
                    pressed: false,
                    reference: None,
                    sites: hold_sites(playback, site),
                }
            })
            .collect();
        Ok(Closings { object, judged, end: playback.duration })
    }

    /// The verdicts so far, in the closings' time order.
    pub fn verdicts(&self) -> Vec<ClosingVerdict> {
        let verdict = |j: &Judged| ClosingVerdict { hold: j.hold(), ..j.verdict.clone() };
        self.judged.iter().map(verdict).collect()
    }
}

/// The settling time of the grip on object `id` ([`settling_time`]): its
/// γ and mass, and the contacts' damping ratio (none without a damper).
pub(crate) fn grip_settling(world: &InteractionWorld, id: ObjectId) -> f64 {
    let (gamma, mass) = (world.object_gamma(id), world.object_mass(id));
    let zeta = world.config().damping_ratio.unwrap_or(0.0);
    let settle = gamma.zip(mass).and_then(|(k, m)| settling_time(k, m, zeta));
    settle.map_or(0.0, f64::from)
}

impl Observer for Closings {
    /// Adds each object when its time comes (none for a closing too short
    /// to judge), at the site the hand has when its fixture lets go at the
    /// latest (the grip's settling time and then the object's fall time
    /// before the hand opens), and lets each fixture go when
    /// the hand grips the object or at that instant (re-seating the
    /// contacts then, as [`super::replay::Fixtures`] does).
    fn before_step(&mut self, world: &mut InteractionWorld, t: f64) -> Result<(), RunError> {
        for j in &mut self.judged {
            if j.verdict.hold == Hold::TooShort {
                continue;
            }
            if j.id.is_none() && j.verdict.appeared_at <= t {
                let id = world.add_object(&self.object.at(&j.site, &j.verdict.object))?;
                world.set_object_locked(id, true)?;
                j.settle = grip_settling(world, id);
                j.id = Some(id);
                let hold = (&j.sites[..], &j.site);
                j.site = seat_for_judging(world, id, hold, j.settle, j.verdict.slip_bound)?;
                (j.verdict.closed_at, j.verdict.site) = (j.site.closed_at, j.site.point.to_array());
            }
            let Some(id) = j.id.filter(|_| j.fixed) else { continue };
            let gripped = is_gripped(world, id);
            if gripped || j.site.closed_at <= t {
                world.set_object_locked(id, false)?;
                if gripped {
                    j.verdict.gripped_at = Some(t);
                } else {
                    world.reseat_contacts(id)?;
                }
                j.verdict.settled_at = Some(t + j.settle);
                j.fixed = false;
            }
        }
        Ok(())
    }

    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let t = step.t;
        let end = self.end;
        for j in &mut self.judged {
            let Some(id) = j.id.filter(|_| !j.fixed) else { continue };
            if t <= j.site.opening_at {
                j.hold_step(step, id)?;
            } else {
                j.release_step(step, id, end)?;
            }
        }
        Ok(())
    }
}

impl Judged {
    /// Whether the closing can be judged, from what the hold has shown so
    /// far: not if no hand has pressed the object, or if the grip has not
    /// settled on it.
    fn hold(&self) -> Hold {
        match self.verdict.hold {
            Hold::Judged if !self.pressed => Hold::NeverPressed,
            Hold::Judged if self.reference.is_none() => Hold::Unsettled,
            hold => hold,
        }
    }

    /// While the hand is closed: whether a hand presses the object, and,
    /// once the grip has settled, how far it moves in the palm's frame.
    fn hold_step(&mut self, step: &StepView, id: ObjectId) -> Result<(), RunError> {
        let t = step.t;
        self.pressed |= step.world.contacts_on(id).iter().any(|c| c.normal_force > 0.0);
        if self.verdict.settled_at.is_none_or(|s| t < s) {
            return Ok(());
        }
        let state = step.world.object_state(id)?;
        // The hand that holds the object is the one that acts: against the
        // tracked hand, a filtered hand's lag would read as a slip.
        let frame = step.hands.get(self.site.track).filter(|h| h.sample.is_some());
        if let Some(hand) = frame.and_then(|h| step.world.hand_pose(h.id)) {
            let v = &mut self.verdict;
            let local = hand.palm.to_local(state.position);
            let reference = *self.reference.get_or_insert(local);
            v.drift = v.drift.max(local.distance(reference));
            if v.drift > v.slip_bound && v.slipped_at.is_none() {
                v.slipped_at = Some(t);
            }
        }
        Ok(())
    }

    /// After the hand opened: settles the hold's verdict, then watches for
    /// the release until its window ends (`end`: the recording's).
    fn release_step(&mut self, step: &StepView, id: ObjectId, end: f64) -> Result<(), RunError> {
        let t = step.t;
        self.verdict.hold = self.hold();
        let v = &mut self.verdict;
        if v.hold != Hold::Judged || v.released.is_some() {
            return Ok(());
        }
        let state = step.world.object_state(id)?;
        if t <= v.release_by {
            v.speed_after_open = v.speed_after_open.max(state.linvel.length());
            if is_squeezed(step.world, id) {
                v.released_at = None;
            } else {
                v.released_at.get_or_insert(t);
            }
        }
        let next = t + f64::from(step.world.config().dt);
        if next > v.release_by {
            v.released = Some(v.released_at.is_some());
        } else if next > end && v.released_at.is_some() {
            v.released = Some(true);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn site(t: f64, aperture: f32) -> HoldSite {
        HoldSite { t, point: Vec3::splat(t as f32), rotation: Quat::IDENTITY, aperture }
    }

    #[test]
    fn an_unheld_object_falls_a_finger_width_in_about_sixty_milliseconds() {
        assert!((fall_time(0.0188, 9.81) - 0.0619).abs() < 1e-3);
    }

    #[test]
    fn the_fixture_lets_go_at_the_most_closed_instant_that_leaves_time_to_judge() {
        // Most closed at 0.9 s, but the hold must be judged by 0.8 s.
        let sites = [site(0.5, 0.05), site(0.6, 0.03), site(0.7, 0.04), site(0.9, 0.01)];
        assert_eq!(release_site(&sites, 0.8).unwrap().t, 0.6);
        assert_eq!(release_site(&sites, 1.0).unwrap().t, 0.9, "time enough: as before");
        // A hold too short for any: its first instant.
        assert_eq!(release_site(&sites, 0.4).unwrap().t, 0.5);
        assert!(release_site(&[], 1.0).is_none());
    }
}
