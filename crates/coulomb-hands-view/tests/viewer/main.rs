//! The viewer's integration tests, in one binary: each test binary links all of Bevy, so
//! one binary instead of four saves CI minutes and gigabytes of disk.

mod hand_visual;
mod keys;
mod mouse_hand;
mod transport;
mod window;
