//! The gallery's and the shape map's pictures drawn: each shell, grown whole by a worker of
//! the pool, is shown by a viewer of its own and read back as a picture, one a frame, in the
//! order and with the care the [`PictureQueue`] decides; the graphics device is kept as the
//! viewer keeps its own ([`ViewerDriver::survive`]). A picture drawn just before the device
//! was lost may be blank: it is forgotten and drawn again on the next device, as is one the
//! device was lost while drawing. The web runner (`web/gallery.rs`) hands each picture to the
//! images that show it.

use super::picture_queue::{PictureQueue, Wanted};
use super::pool::Pool;
use super::screen::Screen;
use super::viewer_driver::ViewerDriver;
use super::viewer_status::Device;

/// What a frame of drawing pictures came to.
pub struct Drew<P> {
    /// Pictures that may have been drawn blank, and are asked again: whatever shows them
    /// is to be forgotten.
    pub forgotten: Vec<Wanted>,
    /// The picture drawn this frame, if any, and what it was wanted for.
    pub drawn: Option<(Wanted, P)>,
}

/// A viewer of pictures and the queue of pictures it draws.
pub struct PictureDrawer<S: Screen> {
    viewer: ViewerDriver<S>,
    queue: PictureQueue,
}

impl<S: Screen> PictureDrawer<S> {
    /// Pictures drawn on `screen` (none where it draws nothing: no card asks for one).
    pub fn new(screen: S, now: f64) -> Self {
        let queue = if screen.backend().is_some() {
            PictureQueue::of_cards()
        } else {
            PictureQueue::default()
        };
        Self {
            viewer: ViewerDriver::new(screen, false, false, now),
            queue,
        }
    }

    pub fn queue(&self) -> &PictureQueue {
        &self.queue
    }

    pub fn queue_mut(&mut self) -> &mut PictureQueue {
        &mut self.queue
    }

    pub fn screen(&self) -> &S {
        self.viewer.screen()
    }

    pub fn screen_mut(&mut self) -> &mut S {
        self.viewer.screen_mut()
    }

    /// Whether it draws pictures at all (not where the browser draws no 3D).
    pub fn draws(&self) -> bool {
        self.viewer.screen().backend().is_some()
    }

    /// One frame at `now`: keeps the device (on a fresh canvas `fresh` makes, when asked for
    /// one; while it makes none, the device stays lost and one is asked for again the next
    /// frame) and draws the next shell waiting, if the device is ready.
    pub fn work(
        &mut self,
        now: f64,
        pool: &mut Pool,
        fresh: impl FnOnce() -> Option<S::Canvas>,
    ) -> Drew<S::Picture> {
        let mut device = self.viewer.survive(now);
        if let Device::NeedsCanvas(_) = &device {
            match fresh() {
                Some(canvas) => self.viewer.give_canvas(canvas),
                None => device = Device::Gone("no fresh canvas could be made".into()),
            }
        }
        if device != Device::Ready {
            return Drew {
                forgotten: self.queue.device_lost(pool),
                drawn: None,
            };
        }
        let nothing = Drew {
            forgotten: Vec::new(),
            drawn: None,
        };
        let Some((wanted, whole)) = self.queue.next(now) else {
            return nothing;
        };
        self.viewer.show_whole(wanted.preset, &wanted.spec, whole);
        let place = wanted.place;
        let picture = self.viewer.picture_at(place.pixels(), place.multisampled());
        if self.viewer.survive(now) != Device::Ready {
            // Lost while drawing: the picture may be blank; it is drawn on the next device.
            self.queue.ask_again(&wanted, pool);
            return Drew {
                forgotten: vec![wanted],
                drawn: None,
            };
        }
        let Ok(picture) = picture else {
            return nothing;
        };
        self.queue.drawn(wanted.clone(), now);
        Drew {
            forgotten: Vec::new(),
            drawn: Some((wanted, picture)),
        }
    }
}
