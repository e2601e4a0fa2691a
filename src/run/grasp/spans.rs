//! When a hand is closed, by each signal a recording has, and the closings
//! they make together.
//!
//! Each signal is a series sampled at a fixed step (`None` where the hand
//! is not tracked). A signal's [`Span`] is one continuous closing by that
//! signal: entered and left with hysteresis, so that a flicker at one
//! threshold does not split it, with the firm part inside it where the
//! hand is closed by the stricter threshold. [`union`] merges every
//! signal's spans of a hand into its closings.

use serde::ser::{Serialize, SerializeSeq, Serializer};

/// A tracker's strength (grab or pinch, 0 to 1) at or above which its hand
/// is closed, and below which a closed one has opened: Ultraleap's own grab
/// detector's defaults (`GrabDetector.activateStrength` 0.8 and
/// `deactivateStrength` 0.6, Ultraleap Unity Plugin). The pinch strength is
/// on the same scale.
pub const STRENGTH_CLOSED: f32 = 0.8;
/// See [`STRENGTH_CLOSED`].
pub const STRENGTH_OPEN: f32 = 0.6;

/// How much a hand's curl ([`crate::hand::HandPose::curl`]) must rise above
/// its open level for it to close: a tenth of a fist, 23° of mean finger
/// flexion. Tracking jitter moves the curl by a few thousandths (the
/// bundled recordings' curl jitters by 0.001–0.008 rms), and a hand closing
/// around even a large ball flexes its fingers by more.
pub const CURL_RISE: f32 = 0.1;

/// The curl a closing hand must also reach: about that of fingers wrapped
/// round a 12 cm ball or cylinder, near the largest a hand closes its
/// fingers on. An average finger (8.5 cm from its knuckle, as in
/// [`crate::hand::rig::HandRig::adult`]) laid round a circle of 6.8 cm
/// radius at its axis turns by its length over that radius, 72°: 0.31 of a
/// fist. Below it, a hand that flexes a little while waving or clapping
/// does not close.
pub const CURL_CLOSED: f32 = 0.3;

/// The rise above an `open` curl at which a hand closes by its curl: at
/// least [`CURL_RISE`], and up to [`CURL_CLOSED`].
pub fn curl_rise(open: f32) -> f32 {
    CURL_RISE.max(CURL_CLOSED - open)
}

/// How far a hand's aperture (thumb tip to nearest fingertip) must shrink,
/// as a fraction of its width when open, for it to close: a hand that
/// never halves it (a clap, a wave, a resting hand) makes no closing by it,
/// however it wavers.
pub const CLOSES_TO: f32 = 0.5;

/// The parts of an excursion, from the open level (0) to the peak (1):
/// a closing by curl or aperture lasts while the hand stays above half of
/// it, and is firm above three quarters.
const HELD_ABOVE: f32 = 0.5;
const FIRM_ABOVE: f32 = 0.75;

/// A signal that tells when a hand is closed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Signal {
    /// The tracker's grab strength.
    Grab,
    /// The tracker's pinch strength.
    Pinch,
    /// The fingers' curl, from the joints.
    Curl,
    /// The thumb-to-fingertip aperture, from the joints.
    Aperture,
}

impl Signal {
    /// Every signal, in the order they are listed.
    pub const ALL: [Signal; 4] = [Signal::Grab, Signal::Pinch, Signal::Curl, Signal::Aperture];

    /// Its name, as the JSON and the summary give it.
    pub fn name(self) -> &'static str {
        match self {
            Signal::Grab => "grab",
            Signal::Pinch => "pinch",
            Signal::Curl => "curl",
            Signal::Aperture => "aperture",
        }
    }

    /// The tracker's own signals, which say when the hand opens.
    fn is_tracker(self) -> bool {
        matches!(self, Signal::Grab | Signal::Pinch)
    }
}

/// A set of [`Signal`]s: those that found a closing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Signals(u8);

impl Signals {
    /// With `signal` too.
    pub fn with(self, signal: Signal) -> Signals {
        Signals(self.0 | 1 << signal as u8)
    }

    /// Whether `signal` is in the set.
    pub fn contains(self, signal: Signal) -> bool {
        self.0 & 1 << signal as u8 != 0
    }

    /// The signals in the set, in [`Signal::ALL`]'s order.
    pub fn iter(self) -> impl Iterator<Item = Signal> {
        Signal::ALL.into_iter().filter(move |s| self.contains(*s))
    }
}

impl std::fmt::Display for Signals {
    /// `grab+curl`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let names: Vec<&str> = self.iter().map(Signal::name).collect();
        f.write_str(&names.join("+"))
    }
}

impl Serialize for Signals {
    /// A list of names: `["grab", "curl"]`.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(None)?;
        for s in self.iter() {
            seq.serialize_element(s.name())?;
        }
        seq.end()
    }
}

/// One continuous closing of a hand by one signal, in sample indices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Span {
    /// The signal.
    pub signal: Signal,
    /// The first sample closed by the lenient threshold.
    pub enter: usize,
    /// The first sample after it that is not (the end, exclusive).
    pub leave: usize,
    /// The first and last samples closed by the strict threshold.
    pub firm: (usize, usize),
}

impl Span {
    /// How long the firm part lasts, in samples.
    pub fn firm_len(&self) -> usize {
        self.firm.1 - self.firm.0
    }
}

/// The spans of a tracker strength: entered at [`STRENGTH_CLOSED`], left
/// below [`STRENGTH_OPEN`] or where the hand is lost; firm from entry to
/// the last sample still at [`STRENGTH_CLOSED`].
pub fn strength_spans(signal: Signal, xs: &[Option<f32>]) -> Vec<Span> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < xs.len() {
        if !xs[i].is_some_and(|x| x >= STRENGTH_CLOSED) {
            i += 1;
            continue;
        }
        let (enter, mut last) = (i, i);
        while let Some(x) = xs.get(i).copied().flatten().filter(|x| *x >= STRENGTH_OPEN) {
            if x >= STRENGTH_CLOSED {
                last = i;
            }
            i += 1;
        }
        out.push(Span { signal, enter, leave: i, firm: (enter, last) });
    }
    out
}

/// The spans of a closedness that has no fixed scale (the curl; the
/// aperture, negated): a closing begins once the value rises by
/// `rise(open)` above `open`, its lowest since the last closing (or since
/// the hand was found), so a hand that starts half closed still closes. It
/// lasts while the value stays above half the way from `open` to its peak
/// so far, and is firm above three quarters of the way to its final peak.
pub fn excursion_spans(signal: Signal, xs: &[Option<f32>], rise: impl Fn(f32) -> f32) -> Vec<Span> {
    let mut out = Vec::new();
    let mut open: Option<(usize, f32)> = None;
    let mut i = 0;
    while i < xs.len() {
        let Some(x) = xs[i] else {
            open = None;
            i += 1;
            continue;
        };
        let (from, low) = match open {
            Some((k, low)) if low <= x => (k, low),
            _ => (i, x),
        };
        open = Some((from, low));
        if x - low < rise(low) {
            i += 1;
            continue;
        }
        let mut peak = x;
        let mut end = i + 1;
        while let Some(y) = xs.get(end).copied().flatten() {
            peak = peak.max(y);
            if y <= low + HELD_ABOVE * (peak - low) {
                break;
            }
            end += 1;
        }
        let above = |k: usize, part: f32| xs[k].is_some_and(|v| v >= low + part * (peak - low));
        let enter = (from..end).find(|&k| above(k, HELD_ABOVE)).unwrap_or(i);
        let first = (enter..end).find(|&k| above(k, FIRM_ABOVE)).unwrap_or(i);
        let last = (enter..end).rfind(|&k| above(k, FIRM_ABOVE)).unwrap_or(first);
        out.push(Span { signal, enter, leave: end, firm: (first, last) });
        open = None;
        i = end;
    }
    out
}

/// The spans of one hand grouped into closings: spans that overlap, or
/// that are less than `bridge` samples apart, are one closing (one
/// continuous hold, whichever signals saw it). Groups come in time order.
pub fn union(mut spans: Vec<Span>, bridge: usize) -> Vec<Vec<Span>> {
    spans.sort_by_key(|s| (s.enter, s.leave));
    let mut groups: Vec<(Vec<Span>, usize)> = Vec::new();
    for span in spans {
        match groups.last_mut() {
            Some((group, end)) if span.enter <= *end + bridge => {
                group.push(span);
                *end = (*end).max(span.leave);
            }
            _ => groups.push((vec![span], span.leave)),
        }
    }
    groups.into_iter().map(|(group, _)| group).collect()
}

/// When a closing holds: from the first firm sample to the instant the hand
/// opens, by the tracker's strengths or the curl, whichever opens first,
/// among the signals that held for at least `min_len` samples; by the
/// aperture only when no other signal did. `None` when no signal held that
/// long: the closing is too short to judge.
pub fn hold(group: &[Span], min_len: usize) -> Option<(usize, usize)> {
    let sustained = |keep: &dyn Fn(Signal) -> bool| -> Option<(usize, usize)> {
        let mut hold: Option<(usize, usize)> = None;
        for signal in Signal::ALL.into_iter().filter(|s| keep(*s)) {
            let firm = group.iter().filter(|s| s.signal == signal && s.firm_len() >= min_len);
            let (first, last) =
                firm.fold((usize::MAX, 0), |(a, b), s| (a.min(s.firm.0), b.max(s.firm.1)));
            if first <= last {
                hold = Some(hold.map_or((first, last), |(a, b)| (a.min(first), b.min(last))));
            }
        }
        hold
    };
    sustained(&|s| s.is_tracker() || s == Signal::Curl)
        .or_else(|| sustained(&|s| s == Signal::Aperture))
}

/// The signals of a group.
pub fn signals(group: &[Span]) -> Signals {
    group.iter().fold(Signals::default(), |set, s| set.with(s.signal))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn series(values: &[f32]) -> Vec<Option<f32>> {
        values.iter().map(|v| Some(*v)).collect()
    }

    #[test]
    fn a_strength_closes_at_its_upper_threshold_and_opens_below_its_lower() {
        let xs = series(&[0.1, 0.5, 0.85, 0.9, 0.7, 0.82, 0.65, 0.55, 0.9, 0.3]);
        let spans = strength_spans(Signal::Grab, &xs);
        assert_eq!(spans.len(), 2);
        assert_eq!((spans[0].enter, spans[0].leave, spans[0].firm), (2, 7, (2, 5)));
        assert_eq!((spans[1].enter, spans[1].leave, spans[1].firm), (8, 9, (8, 8)));
        // A lost hand ends a span.
        let mut lost = series(&[0.9, 0.9, 0.9]);
        lost[1] = None;
        assert_eq!(strength_spans(Signal::Pinch, &lost).len(), 2);
    }

    #[test]
    fn a_hand_that_starts_half_closed_closes_by_its_own_excursion() {
        // Curl from 0.45 (half closed) up to 0.95 and back.
        let xs = series(&[0.45, 0.5, 0.6, 0.8, 0.9, 0.95, 0.93, 0.9, 0.69, 0.6, 0.5]);
        let spans = excursion_spans(Signal::Curl, &xs, curl_rise);
        assert_eq!(spans.len(), 1);
        // Held above 0.70, firm above 0.825.
        assert_eq!((spans[0].enter, spans[0].leave, spans[0].firm), (3, 8, (4, 7)));
        // A wobble smaller than the rise is no closing.
        let wobble = series(&[0.45, 0.5, 0.53, 0.47, 0.52, 0.46]);
        assert!(excursion_spans(Signal::Curl, &wobble, curl_rise).is_empty());
        // A flat hand that flexes by more than the rise but stays short of
        // a closed hand (a clap) does not close; one that reaches it does.
        let clap = series(&[0.05, 0.09, 0.21, 0.26, 0.12, 0.06]);
        assert!(excursion_spans(Signal::Curl, &clap, curl_rise).is_empty());
        let wrap = series(&[0.05, 0.09, 0.21, 0.33, 0.34, 0.12]);
        let spans = excursion_spans(Signal::Curl, &wrap, curl_rise);
        assert_eq!((spans.len(), spans[0].enter, spans[0].leave), (1, 2, 5));
    }

    #[test]
    fn an_aperture_must_halve_from_its_own_open_width() {
        // Apertures (m), negated: closedness.
        let closing = |a: &[f32]| -> Vec<Span> {
            let xs: Vec<Option<f32>> = a.iter().map(|a| Some(-a)).collect();
            excursion_spans(Signal::Aperture, &xs, |open| -CLOSES_TO * open)
        };
        assert!(closing(&[0.08, 0.06, 0.045, 0.05, 0.07]).is_empty(), "not halved");
        let spans = closing(&[0.08, 0.06, 0.039, 0.02, 0.021, 0.055, 0.07]);
        assert_eq!(spans.len(), 1);
        assert_eq!((spans[0].enter, spans[0].leave, spans[0].firm), (2, 5, (3, 4)));
    }

    #[test]
    fn overlapping_or_nearly_touching_spans_are_one_closing() {
        let span = |signal, enter, leave| Span { signal, enter, leave, firm: (enter, leave - 1) };
        let spans = vec![
            span(Signal::Aperture, 10, 14),
            span(Signal::Grab, 12, 60),
            span(Signal::Aperture, 20, 22),
            span(Signal::Curl, 15, 55),
            span(Signal::Aperture, 64, 70),
            span(Signal::Pinch, 90, 93),
        ];
        let groups = union(spans, 5);
        assert_eq!(groups.iter().map(Vec::len).collect::<Vec<_>>(), [5, 1]);
        assert_eq!(signals(&groups[0]).to_string(), "grab+curl+aperture");
        // Held from the grab's firm start until the curl opens (first).
        assert_eq!(hold(&groups[0], 30), Some((12, 54)));
        // The aperture alone holds only where nothing else did.
        assert_eq!(hold(&groups[0][..1], 3), Some((10, 13)));
        assert_eq!(hold(&groups[1], 3), None, "a 3-sample twitch");
    }
}
