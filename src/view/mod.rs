//! The platform-free half of the viewer: the orbit camera and the gestures that move it, the
//! panes of one or four views, the playback (rows per frame, the growth budget), which frames
//! draw, the preview of a pattern being edited, the plan of a frame-exact recording, and the
//! coarser mesh of a gallery picture. Tested natively; the web runner applies what they return.

pub mod camera;
pub mod draw_pacing;
pub mod drawn_in;
pub mod gestures;
pub mod panes;
pub mod picture;
pub mod playback;
pub mod preview;
pub mod recording;
