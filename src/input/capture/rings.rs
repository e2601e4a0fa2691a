//! A hand given by points on its surface, as a MANO fit's 778 vertices,
//! made into the 21 keypoints and finger widths of the skeletal hand.
//!
//! Each keypoint is the centroid of a ring of surface points around a
//! joint (a fingertip is its one published tip point, as MediaPipe's tip
//! landmark is on the skin). The rings are lists of vertex indices in the
//! topology every MANO fit shares; they were cut from the points of TACO
//! sequence 20231104_017 alone (no MANO model file), so that each bone's
//! length stays within 0.2-1.8 mm (standard deviation) over its 146 frames
//! while the fingers flex. The book's `captures.md` gives the method.

use glam::Vec3;

/// Points on a MANO-topology hand surface.
pub const POINTS: usize = 778;

/// The ring of surface points around each keypoint, in MediaPipe Hands'
/// order (wrist, then each finger's four landmarks, thumb first).
pub const RINGS: [&[u16]; 21] = [
    &[37, 38, 39, 78, 79, 91, 92, 107, 108, 116, 117, 118, 119, 120, 122, 234], // WRIST
    &[1, 26, 40, 42, 88, 113, 114, 219, 230, 231, 233, 236],                    // THUMB_CMC
    &[9, 28, 31, 124, 125, 126, 249, 250, 266, 697, 702, 703, 705],             // THUMB_MCP
    &[715, 716, 721, 731, 732, 739, 756, 760],                                  // THUMB_IP
    &[745],                                                                     // THUMB_TIP
    &[65, 93, 127, 143, 151, 186, 258, 259, 260, 261, 263, 274],                // INDEX_FINGER_MCP
    &[56, 86, 87, 134, 166, 195, 222, 223, 225, 226],                           // INDEX_FINGER_PIP
    &[272, 273, 281, 294, 295, 299, 300, 302, 340, 342],                        // INDEX_FINGER_DIP
    &[317],                                                                     // INDEX_FINGER_TIP
    &[141, 185, 187, 262, 270, 271, 277, 383, 399],                             // MIDDLE_FINGER_MCP
    &[358, 363, 365, 367, 377, 382, 385, 387, 389, 394, 395],                   // MIDDLE_FINGER_PIP
    &[390, 401, 406, 407, 408, 409, 411, 412, 440, 453],                        // MIDDLE_FINGER_DIP
    &[444],                                                                     // MIDDLE_FINGER_TIP
    &[74, 76, 142, 182, 206, 269, 276, 290, 291, 292, 293],                     // RING_FINGER_MCP
    &[470, 475, 477, 478, 479, 484, 487, 495, 497, 499, 504],                   // RING_FINGER_PIP
    &[503, 508, 512, 517, 518, 519, 522, 526, 541, 564],                        // RING_FINGER_DIP
    &[556],                                                                     // RING_FINGER_TIP
    &[82, 83, 183, 201, 202, 593, 597, 611, 612, 627, 776],                     // PINKY_MCP
    &[582, 584, 585, 587, 588, 589, 590, 591, 599, 602, 609, 610, 616],         // PINKY_PIP
    &[621, 624, 625, 631, 634, 643, 648, 650, 658, 659],                        // PINKY_DIP
    &[673],                                                                     // PINKY_TIP
];

/// The 21 keypoints (MediaPipe order) of one frame of surface points, in
/// their frame and units. `points` must hold [`POINTS`] points.
pub fn keypoints(points: &[Vec3]) -> [Vec3; 21] {
    RINGS.map(|ring| centroid(points, ring))
}

/// The mean of the ring's points.
fn centroid(points: &[Vec3], ring: &[u16]) -> Vec3 {
    ring.iter().map(|&i| points[usize::from(i)]).sum::<Vec3>() / ring.len() as f32
}

/// Each finger's width (diameter, in the points' units), thumb first: twice
/// the mean distance of its two middle rings' points (a finger's PIP and
/// DIP, the thumb's MCP and IP) from the bone that starts there, over all
/// `frames`. Those rings circle a phalanx, not the palm, so their radius is
/// the finger's own; a capsule that wide lies on the captured skin.
pub fn widths(frames: &[Vec<Vec3>], keypoints: &[[Vec3; 21]]) -> [f32; 5] {
    std::array::from_fn(|finger| {
        let (mut sum, mut n) = (0.0f64, 0usize);
        for (points, keys) in frames.iter().zip(keypoints) {
            for joint in [2 + 4 * finger, 3 + 4 * finger] {
                let axis = (keys[joint + 1] - keys[joint]).normalize_or_zero();
                for &i in RINGS[joint] {
                    let offset = points[usize::from(i)] - keys[joint];
                    sum += f64::from(offset.reject_from_normalized(axis).length());
                    n += 1;
                }
            }
        }
        (2.0 * sum / n.max(1) as f64) as f32
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rings_are_disjoint_and_on_the_surface() {
        let mut seen = [false; POINTS];
        for ring in RINGS {
            for &i in ring {
                assert!(usize::from(i) < POINTS && !seen[usize::from(i)], "vertex {i}");
                seen[usize::from(i)] = true;
            }
        }
    }

    #[test]
    fn a_ring_of_a_cylinder_gives_its_axis_and_its_width() {
        // Every point on a cylinder of radius 8.5 mm along +x through the
        // origin, each ring's points at the same x as its keypoint's.
        let mut points = vec![Vec3::ZERO; POINTS];
        for (k, ring) in RINGS.iter().enumerate() {
            for (j, &i) in ring.iter().enumerate() {
                let a = j as f32 * std::f32::consts::TAU / ring.len() as f32;
                let r = if ring.len() == 1 { 0.0 } else { 8.5 };
                points[usize::from(i)] = Vec3::new(10.0 * k as f32, r * a.cos(), r * a.sin());
            }
        }
        let keys = keypoints(&points);
        for (k, key) in keys.iter().enumerate() {
            assert!((*key - Vec3::X * 10.0 * k as f32).length() < 1e-4, "{k}: {key}");
        }
        for w in widths(&[points], &[keys]) {
            assert!((w - 17.0).abs() < 1e-3, "{w}");
        }
    }
}
