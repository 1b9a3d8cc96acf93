//! Work off the page's thread: the protocol between the page and its Web Workers, in the pure
//! core so that it is tested natively. The page sends [`message::Request`]s; each worker runs a
//! [`host::Host`], which grows the shell of a session (sending back only what each request
//! added), makes the pieces of a shell's growth apart, grows gallery pictures whole and
//! computes the tiles of a parameter map; the page keeps its copy of the growing shell in a
//! [`replica::Replica`], which joins pieces in a fixed order so that the number of workers
//! cannot change a bit, and shares jobs out among its workers with a [`pool::Pool`], which
//! also knows what to do again when a worker dies or hangs. A file of the shell is written
//! where that copy is ([`file_writer::FileWriter`]); what the page asks of a viewer and what it
//! reads of it are plain data ([`viewer_command::ViewCommand`], [`viewer_status::ViewStatus`],
//! [`planar_update::PlanarUpdate`]), and what the page shows of that status is decided here
//! too ([`status_readout::Readout`]). What a viewer decides without its canvas is its core
//! state, [`viewer_state::ViewerState`], driven frame by frame onto a
//! [`screen::Screen`] by [`viewer_driver::ViewerDriver`]: the web runner only gives it the
//! renderer.

pub mod device_survival;
pub mod download_menu;
pub mod drawing_link;
pub(crate) mod edge_slots;
pub mod file_writer;
pub mod growth_session;
pub mod host;
pub mod message;
pub mod panel_controls;
pub mod picture_drawer;
pub mod picture_queue;
pub mod planar_update;
pub mod pool;
pub mod recent_pictures;
pub mod recording;
pub mod replica;
pub mod screen;
pub mod session;
pub mod shell_change;
pub mod shortcuts;
pub mod slotted_edge;
pub mod status_readout;
pub mod viewer_command;
pub mod viewer_driver;
pub mod viewer_inbox;
pub mod viewer_message;
pub mod viewer_state;
pub mod viewer_status;
pub mod wire;
