//! The viewer's integration tests, in one binary: each test binary links all of Bevy, so
//! one binary instead of four saves CI minutes and gigabytes of disk.

mod ar;
mod camera;
mod ghost;
mod hand_visual;
mod head;
mod keys;
mod leap;
mod mouse_hand;
mod source;
mod task;
mod transport;
mod window;
mod xr_hands;
