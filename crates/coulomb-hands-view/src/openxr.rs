//! The OpenXR runtime (feature `openxr`): bevy_mod_openxr's plugins, which
//! open the runtime's session, render the scene to the headset, and locate
//! the hand joints that [`crate::xr_hands`] turns into the interaction's
//! hands.
//!
//! Without a runtime, bevy_mod_openxr logs an error and renders to the
//! window alone. The viewer asked for live hands would then show a scene
//! no hand can reach, so [`check_runtime`] refuses first, before any
//! window, by asking the same loader bevy_mod_openxr opens.

use bevy::app::PluginGroupBuilder;
use bevy::prelude::*;
use bevy_mod_xr::session::XrState;

/// Why there are no live hands: no loader, no running runtime, or one
/// without hand tracking.
pub fn check_runtime() -> Result<(), String> {
    // SAFETY: this loads the system's OpenXR loader library by its
    // standard name, as bevy_mod_openxr does when the app starts; the
    // loader is a compliant OpenXR implementation by its contract.
    let entry = unsafe { openxr::Entry::load() }.map_err(|e| {
        format!(
            "--openxr: no OpenXR loader ({e}). Install one (Debian and Ubuntu: \
             libopenxr-dev, which has libopenxr_loader.so) and an OpenXR runtime"
        )
    })?;
    let extensions = entry.enumerate_extensions().map_err(|e| {
        format!(
            "--openxr: no OpenXR runtime is running ({e}). Start one (Monado's \
             monado-service, SteamVR, or Meta Quest Link), or set XR_RUNTIME_JSON \
             to its manifest"
        )
    })?;
    if !extensions.ext_hand_tracking {
        return Err(
            "--openxr: the OpenXR runtime has no hand tracking (XR_EXT_hand_tracking)".into()
        );
    }
    Ok(())
}

/// `plugins` with the OpenXR session, rendering and hand tracking.
pub fn with_openxr(plugins: PluginGroupBuilder) -> PluginGroupBuilder {
    bevy_mod_openxr::add_xr_plugins(plugins)
}

/// Quits with an error if the session could not start after all (the
/// runtime went away between [`check_runtime`] and the app's start).
pub fn exit_without_session(state: Option<Res<XrState>>, mut exit: MessageWriter<AppExit>) {
    if state.is_none_or(|s| *s == XrState::Unavailable) {
        error!("--openxr: the OpenXR session could not start (see the error above)");
        exit.write(AppExit::error());
    }
}
