//! The platform-free half of the viewer: the orbit camera and the gestures that move it.
//! Pure arithmetic, tested natively; the web runner applies what it returns.

pub mod camera;
pub mod gestures;
