//! Whether there is a display to open a window on, checked before Bevy
//! tries (and panics): the X server `DISPLAY` names must accept a
//! connection. The viewer is built for X11; Wayland desktops run it through
//! XWayland, which sets `DISPLAY`.

use std::net::{TcpStream, ToSocketAddrs};
use std::os::unix::net::UnixStream;
use std::time::Duration;

/// How long to wait for a remote X server.
const TIMEOUT: Duration = Duration::from_secs(2);

/// `Ok` if the X server in `DISPLAY` answers; else why not, and what to do.
pub fn check() -> Result<(), String> {
    let hint = "run it on a desktop, or headless under `xvfb-run -a`";
    let display = std::env::var("DISPLAY").ok().filter(|d| !d.is_empty());
    let Some(display) = display else {
        return Err(format!("no display: DISPLAY is not set ({hint})"));
    };
    let refused =
        |why: String| format!("no display: cannot reach X server {display:?}: {why} ({hint})");
    let (host, rest) = display.rsplit_once(':').ok_or_else(|| refused("not host:number".into()))?;
    let number: u16 = rest
        .split('.')
        .next()
        .and_then(|n| n.parse().ok())
        .ok_or_else(|| refused("no display number".into()))?;
    if host.is_empty() || host == "unix" {
        let socket = format!("/tmp/.X11-unix/X{number}");
        return UnixStream::connect(&socket)
            .map(drop)
            .map_err(|e| refused(format!("{socket}: {e}")));
    }
    let port =
        6000u16.checked_add(number).ok_or_else(|| refused("display number too large".into()))?;
    let address = (host, port).to_socket_addrs().map_err(|e| refused(e.to_string()))?.next();
    let address = address.ok_or_else(|| refused("no address".into()))?;
    TcpStream::connect_timeout(&address, TIMEOUT).map(drop).map_err(|e| refused(e.to_string()))
}
