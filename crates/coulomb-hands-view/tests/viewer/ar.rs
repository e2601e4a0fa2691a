//! AR mode (§3.6) in a real window: over a background image, the hand is an
//! occlusion mask, so the virtual object behind it is hidden where the hand
//! is (the background shows) and drawn everywhere else.

use super::window::{any_skin, count, fresh, hsv, is_teal, out_dir, refused, teal, view};
use image::{Rgb, RgbImage};

/// The background's colour, which nothing virtual has.
const MAGENTA: Rgb<u8> = Rgb([230, 20, 200]);

fn is_magenta(h: f32, s: f32, v: f32) -> bool {
    (290.0..330.0).contains(&h) && s > 0.8 && v > 0.8
}

/// Background pixels inside the object's silhouette: in each row, between
/// the first and last teal pixel. A box's silhouette has no holes, so these
/// are where something in front of it shows the background.
fn holes(img: &RgbImage) -> usize {
    let mut n = 0;
    for y in 0..img.height() {
        let row: Vec<&Rgb<u8>> = (0..img.width()).map(|x| img.get_pixel(x, y)).collect();
        let (Some(first), Some(last)) =
            (row.iter().position(|p| is_teal(p)), row.iter().rposition(|p| is_teal(p)))
        else {
            continue;
        };
        let inside = row[first..last].iter().map(|p| hsv(p));
        n += inside.filter(|&(h, s, v)| is_magenta(h, s, v)).count();
    }
    n
}

#[test]
fn in_ar_mode_the_hand_masks_the_object_behind_it_with_the_background() {
    let dir = out_dir();
    let background = dir.join("magenta.png");
    RgbImage::from_pixel(64, 36, MAGENTA).save(&background).expect("written");
    // A teal slab standing on the ground, 26 cm behind where the mouse hand starts
    // (palm at (0, 0.15, -0.2)), seen from behind the hand, nearly level.
    let scene = dir.join("slab-behind-the-hand.json");
    let slab = r#"{"name": "slab", "shape": {"Box": {"half_extents": [0.15, 0.12, 0.02]}},
        "mass": 0.5, "material": "wood", "position": [0, 0.12, 0.06]}"#;
    let text = format!(r#"{{"ground": {{"height": 0, "friction": 0.5}}, "objects": [{slab}]}}"#);
    std::fs::write(&scene, text).expect("written");
    let shot = dir.join("ar-slab.png");
    fresh(&[&shot]);
    let (ok, stderr) = view(&[
        scene.to_str().expect("a UTF-8 path"),
        "--background",
        background.to_str().expect("a UTF-8 path"),
        "--view=0,5,0.7",
        "--screenshot",
        &format!("0.3={}", shot.display()),
        "--exit-after",
        "0.3",
    ]);
    assert!(ok, "the viewer failed:\n{stderr}");
    let img = image::open(&shot).expect("the screenshot").to_rgb8();
    let total = (img.width() * img.height()) as usize;
    let (slab, background, hand) = (teal(&img), count(&img, is_magenta), any_skin(&img));
    // The slab is drawn where nothing real is in front of it.
    assert!(slab > 20_000, "the slab is visible: {slab} teal pixels");
    // The hand masks it: the background shows through the slab's silhouette.
    let masked = holes(&img);
    assert!(masked > 2_000, "the hand hides the slab behind it: {masked} background pixels");
    // The hand itself is not drawn, and the background shows everywhere else, through
    // the ground too (a real surface).
    assert!(hand < 50, "no skin-coloured hand in AR mode: {hand} pixels");
    assert!(background > total / 3, "the background shows: {background} of {total} pixels");
}

#[test]
fn a_background_that_cannot_be_read_is_an_error_naming_it() {
    let dir = out_dir();
    let not_an_image = dir.join("not-an-image.png");
    std::fs::write(&not_an_image, "plain text").expect("written");
    for path in [std::path::Path::new("no/such/frame.png"), &not_an_image] {
        let stderr =
            refused(&["grasp-lift".as_ref(), "--background".as_ref(), path.as_os_str()], None);
        let expected = format!("error: {}: cannot read the background image: ", path.display());
        assert!(stderr.starts_with(&expected), "{stderr}");
    }
}
