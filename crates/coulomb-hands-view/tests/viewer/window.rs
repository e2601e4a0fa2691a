//! The viewer in a real window: under Xvfb with Mesa's software renderer
//! (lavapipe), `grasp-lift` is shown and screenshots are saved at chosen
//! simulated times, then read back:
//!
//! - at 0.5 s the hand is still coming down: no contact, so no red arrow
//!   pixels, and the hand is drawn see-through;
//! - at 2.5 s the hand holds the lifted cube: red force arrows, and the
//!   hand drawn opaque.
//!
//! Pixels are told apart by colour: the hand is a light skin tone, the
//! cube teal, the force arrows pure red, over a dark blue-grey scene.
//!
//! It needs `xvfb-run` and `mesa-vulkan-drivers` (README's set-up line).

use image::RgbImage;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Where the screenshots go (kept for a look after the test).
pub fn out_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("window");
    std::fs::create_dir_all(&dir).expect("a directory for screenshots");
    dir
}

/// One Xvfb at a time: two software renderers on two cores would each run
/// at half speed, and their servers' start-up would overlap.
static XVFB: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Runs the viewer under `xvfb-run` with `args`; returns whether it
/// succeeded, and its stderr. Each run gets a display number of its own
/// (a number just freed can still have a dying server's socket), and a run
/// whose X server could not be opened at all is retried twice: that is
/// Xvfb starting, not the viewer.
pub fn view(args: &[&str]) -> (bool, String) {
    use std::sync::atomic::{AtomicU32, Ordering};
    static NEXT: AtomicU32 = AtomicU32::new(0);
    let _one_at_a_time = XVFB.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let found = Command::new("xvfb-run").arg("--help").output().is_ok();
    assert!(found, "xvfb-run is missing: install README's apt packages (xvfb mesa-vulkan-drivers)");
    let mut last = String::new();
    for _ in 0..3 {
        let display = 100 + (std::process::id() % 200) * 20 + NEXT.fetch_add(1, Ordering::Relaxed);
        let out = Command::new("xvfb-run")
            .args(["-n", &display.to_string(), "-s", "-screen 0 1280x720x24"])
            .arg(env!("CARGO_BIN_EXE_coulomb-hands-view"))
            .args(args)
            .output()
            .expect("xvfb-run runs");
        last = String::from_utf8_lossy(&out.stderr).into_owned();
        let no_server =
            last.contains("XOpenDisplayFailed") || last.contains("Xvfb failed to start");
        if out.status.success() || !no_server {
            return (out.status.success(), last);
        }
        std::thread::sleep(std::time::Duration::from_secs(1));
    }
    (false, last)
}

/// Removes a previous run's screenshots, so only this run's can be read.
pub fn fresh(paths: &[&Path]) {
    for path in paths {
        match std::fs::remove_file(path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => panic!("{path:?}: {e}"),
            _ => {}
        }
    }
}

/// Hue (degrees), saturation and value of a pixel, each of s and v in [0, 1].
pub fn hsv(p: &image::Rgb<u8>) -> (f32, f32, f32) {
    let [r, g, b] = p.0.map(|c| f32::from(c) / 255.0);
    let (max, min) = (r.max(g).max(b), r.min(g).min(b));
    let d = max - min;
    let h = if d == 0.0 {
        0.0
    } else if max == r {
        60.0 * ((g - b) / d).rem_euclid(6.0)
    } else if max == g {
        60.0 * ((b - r) / d + 2.0)
    } else {
        60.0 * ((r - g) / d + 4.0)
    };
    (h, if max == 0.0 { 0.0 } else { d / max }, max)
}

/// Pixels whose hue (degrees), saturation and value pass `test`.
pub fn count(img: &RgbImage, test: impl Fn(f32, f32, f32) -> bool) -> usize {
    img.pixels().filter(|p| matches!(hsv(p), (h, s, v) if test(h, s, v))).count()
}

/// Pixels the force arrows' pure red: saturated, hue within 10° of red.
fn red(img: &RgbImage) -> usize {
    count(img, |h, s, v| !(10.0..=350.0).contains(&h) && s > 0.85 && v > 0.6)
}

/// The skin tone's hues (the drawn hand's colour is orange-ish).
const SKIN_HUES: std::ops::Range<f32> = 12.0..45.0;

/// Pixels of the opaque skin-toned hand: skin hues more saturated than the
/// see-through hand can show. The skin is 0.38 saturated where lit head-on
/// and more (about 0.5) on its shaded faces, whichever way the hand turns;
/// the see-through hand, 40 % skin over the blue-grey scene, stays below
/// 0.3 on nine pixels in ten, and below 0.4 on all but a handful.
fn opaque_skin(img: &RgbImage) -> usize {
    count(img, |h, s, v| is_skin(h, s, v) && s > 0.4)
}

/// Whether a pixel's hue, saturation and value are the hand's skin tone,
/// see-through or not.
fn is_skin(h: f32, s: f32, v: f32) -> bool {
    SKIN_HUES.contains(&h) && s > 0.12 && v > 0.2
}

/// Pixels of any skin-toned hue, see-through or not.
pub fn any_skin(img: &RgbImage) -> usize {
    count(img, is_skin)
}

/// Pixels of the teal cube.
pub fn teal(img: &RgbImage) -> usize {
    img.pixels().filter(|p| is_teal(p)).count()
}

/// Whether a pixel is the teal cube's.
pub fn is_teal(p: &image::Rgb<u8>) -> bool {
    matches!(hsv(p), (h, s, v) if (170.0..200.0).contains(&h) && s > 0.4 && v > 0.25)
}

/// Distinct colours, a blank image having one or two.
fn colours(img: &RgbImage) -> usize {
    let mut seen: Vec<[u8; 3]> = img.pixels().map(|p| p.0).collect();
    seen.sort_unstable();
    seen.dedup();
    seen.len()
}

/// The bounding box of the pixels that pass `test`: (left, top, right,
/// bottom), or `None` if there are none.
fn bounding_box(img: &RgbImage, test: impl Fn(&image::Rgb<u8>) -> bool) -> Option<[u32; 4]> {
    let mut hits = img.enumerate_pixels().filter(|(_, _, p)| test(p));
    let (x, y, _) = hits.next()?;
    let grow = |[l, t, r, b]: [u32; 4], (x, y, _)| [l.min(x), t.min(y), r.max(x), b.max(y)];
    Some(hits.fold([x, y, x, y], grow))
}

/// grasp-lift from the front left (where the hand does not hide the cube),
/// at the distance that frames the whole run: the camera keeps the cube in
/// the window, clear of its edges, from the approach through the lift (it
/// ends 20 cm up) to the end; before contact the hand is see-through with
/// no force arrow, while holding it is opaque with red force arrows.
#[test]
fn grasp_lift_stays_in_frame_see_through_then_opaque_with_force_arrows() {
    let dir = out_dir();
    let times = ["0.3", "0.5", "1.2", "2.1", "2.5", "3.0", "3.9", "4.3"];
    let paths: Vec<PathBuf> =
        times.iter().map(|t| dir.join(format!("grasp-lift-{t}s.png"))).collect();
    fresh(&paths.iter().map(PathBuf::as_path).collect::<Vec<_>>());
    let mut args = vec!["grasp-lift".to_string(), "--view=60,25".into(), "--exit-after=4.3".into()];
    for (t, path) in times.iter().zip(&paths) {
        args.push(format!("--screenshot={t}={}", path.display()));
    }
    let (ok, stderr) = view(&args.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(ok, "the viewer failed:\n{stderr}");
    // With no audio device (as under CI) it is silent without a word: neither ALSA's
    // complaints nor Bevy's warning, since the audio output is never opened.
    let device = coulomb_hands_view::sound::audio_device_present();
    let quiet = !stderr.contains("ALSA") && !stderr.contains("No audio device");
    assert!(device || quiet, "no audio device, yet:\n{stderr}");
    let shots: Vec<RgbImage> =
        paths.iter().map(|p| image::open(p).expect("a screenshot").to_rgb8()).collect();
    for (t, img) in times.iter().zip(&shots) {
        let (w, h) = img.dimensions();
        assert!(colours(img) > 500, "{t} s: not blank: {} colours", colours(img));
        assert!(any_skin(img) > 1000, "{t} s: the hand is visible: {} skin pixels", any_skin(img));
        // The cube, where it is not behind the hand, and the hand that holds
        // it, clear of the window's edges (the timeline along the foot is 14 px).
        let clear = |[l, top, r, b]: [u32; 4]| l > 4 && top > 4 && r < w - 5 && b < h - 20;
        let cube = bounding_box(img, is_teal).unwrap_or_else(|| panic!("{t} s: no cube"));
        assert!(clear(cube), "{t} s: the cube at {cube:?}");
        let skin = |p: &image::Rgb<u8>| matches!(hsv(p), (h, s, v) if is_skin(h, s, v));
        let hand = bounding_box(img, skin).unwrap_or_else(|| panic!("{t} s: no hand"));
        assert!(clear(hand), "{t} s: the hand at {hand:?}");
    }
    // Before the grasp, nothing hides the cube: all its lit faces show.
    assert!(teal(&shots[0]) > 400, "the cube is visible: {} teal pixels", teal(&shots[0]));
    let (before, holding) = (&shots[1], &shots[4]);
    assert_eq!(red(before), 0, "no contact yet, no force arrow");
    assert!(red(holding) > 30, "force arrows while holding: {} red pixels", red(holding));
    let (free, held) = (opaque_skin(before), opaque_skin(holding));
    assert!(
        held > 1000 && held > 10 * free,
        "opaque in contact: {held} vs {free} opaque skin pixels"
    );
}

/// grasp-lift from its default view, the one that shows the grasp: while
/// the hand holds the lifted cube, the cube shows between the fingers
/// (teal pixels) with the red force arrows. From the fixed view it had
/// before (behind and above), the palm covered the cube.
#[test]
fn grasp_lift_s_default_view_shows_the_held_cube() {
    let dir = out_dir();
    let (shown, fixed) = (dir.join("grasp-lift-default.png"), dir.join("grasp-lift-fixed.png"));
    fresh(&[&shown, &fixed]);
    for (path, view) in [(&shown, None), (&fixed, Some("--view=0,32"))] {
        let shot = format!("--screenshot=2.5={}", path.display());
        let mut args = vec!["grasp-lift", "--exit-after=2.5", &shot];
        args.extend(view);
        let (ok, stderr) = super::window::view(&args);
        assert!(ok, "the viewer failed:\n{stderr}");
    }
    let read = |p: &Path| image::open(p).expect("a screenshot").to_rgb8();
    let (shown, fixed) = (read(&shown), read(&fixed));
    assert!(teal(&shown) > 1000, "the held cube shows: {} teal pixels", teal(&shown));
    assert!(red(&shown) > 30, "with its force arrows: {} red pixels", red(&shown));
    assert!(teal(&fixed) * 2 < teal(&shown), "{} teal pixels from behind", teal(&fixed));
}

/// The viewer's stderr and exit status for `args`, without a window.
/// `display` is the `DISPLAY` to set, or none.
pub fn refused(args: &[&std::ffi::OsStr], display: Option<&str>) -> String {
    let mut command = Command::new(env!("CARGO_BIN_EXE_coulomb-hands-view"));
    command.args(args).env_remove("WAYLAND_DISPLAY");
    match display {
        Some(d) => command.env("DISPLAY", d),
        None => command.env_remove("DISPLAY"),
    };
    let out = command.output().expect("the viewer runs");
    assert!(!out.status.success(), "{args:?} must fail");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!stderr.contains("panicked"), "an error, not a panic: {stderr}");
    stderr
}

#[test]
fn a_missing_or_invalid_file_is_the_clis_error() {
    let missing = "no/such/recording.json.lz";
    let stderr = refused(&[missing.as_ref()], None);
    let cli = coulomb_hands::run::scenario::Scenario::find(missing).expect_err("missing");
    assert_eq!(stderr, format!("error: {cli}\n"), "as the CLI prints it");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let scene = dir.join("negative-size.json");
    let object = r#"{"name": "x", "shape": {"Box": {"half_extents": [0.1, -1, 0.1]}},
        "mass": 1, "material": "wood", "position": [0, 1, 0]}"#;
    std::fs::write(&scene, format!(r#"{{"objects": [{object}]}}"#)).expect("written");
    let stderr = refused(&[scene.as_os_str()], None);
    let cli = coulomb_hands::scene::Scene::load(&scene).expect_err("a negative size");
    assert_eq!(stderr, format!("error: {cli}\n"));
    assert!(stderr.contains("negative-size.json") && stderr.contains("half_extents"), "{stderr}");
}

#[test]
fn with_no_display_it_says_so() {
    let stderr = refused(&["grasp-lift".as_ref()], None);
    assert!(stderr.starts_with("error: no display: DISPLAY is not set"), "{stderr}");
    let stderr = refused(&["grasp-lift".as_ref()], Some(":917"));
    assert!(stderr.starts_with("error: no display: cannot reach X server \":917\""), "{stderr}");
}

/// The teal pixels' mean column in `columns` of `img`, or `None`.
fn teal_column(img: &RgbImage, columns: std::ops::Range<u32>) -> Option<f64> {
    let (mut sum, mut n) = (0.0, 0.0);
    for (x, _, p) in img.enumerate_pixels().filter(|(x, ..)| columns.contains(x)) {
        if is_teal(p) {
            (sum, n) = (sum + f64::from(x - columns.start), n + 1.0);
        }
    }
    (n > 50.0).then(|| sum / n)
}

/// Side-by-side stereo (§3.8.2): a ball 0.5 m straight ahead appears in the
/// two halves shifted by the disparity of a pinhole camera pair,
/// f·VCD/d, with f = (H/2)/tan(fov/2) pixels (Bevy's 45° vertical field of
/// view, H = 720): 109.5 px for the human IPD, 69.5 px for the Leap's ICD.
#[test]
fn stereo_halves_differ_by_the_disparity_of_the_virtual_camera_distance() {
    let dir = out_dir();
    let scene = dir.join("ball-ahead.json");
    let ball = r#"{"name": "ball", "shape": {"Sphere": {"radius": 0.02}}, "mass": 0.05,
        "material": "wood", "position": [0, 0.3, 0]}"#;
    std::fs::write(&scene, format!(r#"{{"gravity": [0, 0, 0], "objects": [{ball}]}}"#))
        .expect("written");
    let f = 360.0 / (std::f64::consts::PI / 8.0).tan();
    for (preset, vcd) in [("ipd", 0.063), ("leap", 0.040)] {
        let shot = dir.join(format!("stereo-{preset}.png"));
        fresh(&[&shot]);
        let (ok, stderr) = view(&[
            scene.to_str().expect("a UTF-8 path"),
            "--stereo",
            preset,
            "--view=0,0,0.5",
            "--screenshot",
            &format!("0.1={}", shot.display()),
            "--exit-after",
            "0.1",
        ]);
        assert!(ok, "the viewer failed:\n{stderr}");
        let img = image::open(&shot).expect("the screenshot").to_rgb8();
        let half = img.width() / 2;
        let left = teal_column(&img, 0..half).expect("the ball in the left half");
        let right = teal_column(&img, half..img.width()).expect("the ball in the right half");
        let expected = f * vcd / 0.5;
        let disparity = left - right;
        assert!((disparity - expected).abs() < 3.0, "{preset}: {disparity} px, not {expected}");
    }
}

#[test]
fn a_screenshot_that_cannot_be_saved_is_an_error() {
    let (ok, stderr) =
        view(&["grasp-lift", "--screenshot", "0.05=/proc/no.png", "--exit-after", "1"]);
    assert!(!ok, "exit 0 without the screenshot:\n{stderr}");
    assert!(stderr.contains("error: could not save /proc/no.png"), "{stderr}");
}
