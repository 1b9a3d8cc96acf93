//! The drawing worker as the page hears it: each change of its graphics device, gone through
//! in order however many of the worker's frames one of the page's takes in (the page says the
//! device was lost, then that it is back); a fresh canvas asked for once, not on every frame
//! the worker asks again until the canvas reaches it; and silence: a worker the page sends
//! frames to that says nothing for [`SILENT_MS`] is taken for hung, and the view moves to the
//! page's thread. The page's [`super::viewer_inbox::Inbox`] holds it and feeds it the worker's
//! messages, on the page as in the simulator.

use super::viewer_status::Device;
use std::collections::VecDeque;

/// Milliseconds the drawing worker may go without a word while the page sends it frames before
/// the page takes it for hung and draws on its own thread.
pub const SILENT_MS: f64 = 15_000.0;

/// What the page has heard of its drawing worker.
#[derive(Debug, Default)]
pub struct DrawingLink {
    /// Each change of the device's state not yet gone through, and the last one the worker
    /// sent.
    devices: VecDeque<Device>,
    last_sent: Option<Device>,
    /// Where the device stands as the page goes through it.
    device: Option<Device>,
    /// A fresh canvas was given since the worker last asked for one.
    gave_canvas: bool,
    /// The page has sent a frame since the worker last said anything.
    ticked: bool,
    /// When the worker last said anything (or the page first waited for it), milliseconds.
    heard: f64,
}

impl DrawingLink {
    /// The worker said something at `now`; a frame's news carries its `device`, kept when it
    /// changed.
    pub fn heard(&mut self, now: f64, device: Option<&Device>) {
        self.heard = now;
        self.ticked = false;
        if let Some(device) = device
            && self.last_sent.as_ref() != Some(device)
        {
            self.last_sent = Some(device.clone());
            self.devices.push_back(device.clone());
        }
    }

    /// The worker failed outside its viewer (it could not load, or threw): its device is gone,
    /// for this reason.
    pub fn failed(&mut self, why: String) {
        self.devices.push_back(Device::Gone(why));
    }

    /// The device as the page goes through it this frame: each change once in order; a device
    /// opened again said once (then ready, with `backend` to show); a fresh canvas asked for
    /// once until the worker says something else.
    pub fn device(&mut self) -> Device {
        if let Some(next) = self.devices.pop_front() {
            self.device = Some(next);
        }
        match self.device.clone().unwrap_or(Device::Ready) {
            Device::Reopened(backend) => {
                // A device lost again at once asks for another fresh canvas.
                self.device = Some(Device::Ready);
                self.gave_canvas = false;
                Device::Reopened(backend)
            }
            Device::NeedsCanvas(why) if !self.gave_canvas => {
                self.gave_canvas = true;
                Device::NeedsCanvas(why)
            }
            Device::NeedsCanvas(why) => Device::Reopening(why),
            device => {
                if !matches!(device, Device::Reopening(_)) {
                    self.gave_canvas = false;
                }
                device
            }
        }
    }

    /// The page sent the worker a frame at `now`.
    pub fn ticked(&mut self, now: f64) {
        if !self.ticked {
            self.ticked = true;
            self.heard = now;
        }
    }

    /// The page takes the worker's news at `now` (`any`: whether there was any): an error in
    /// words when it has said nothing for [`SILENT_MS`] of frames sent to it.
    pub fn took(&mut self, any: bool, now: f64) -> Result<(), String> {
        if any {
            self.ticked = false;
        } else {
            self.silent(now)?;
        }
        Ok(())
    }

    /// Fails, in words, when the worker has said nothing for [`SILENT_MS`] at `now` while the
    /// page sent it frames.
    pub fn silent(&self, now: f64) -> Result<(), String> {
        if self.ticked && now - self.heard > SILENT_MS {
            return Err(format!(
                "the drawing worker has not answered for {} s",
                SILENT_MS / 1000.0
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_change_of_the_device_is_gone_through_once_in_order() {
        let mut link = DrawingLink::default();
        let lost = Device::Reopening("lost".into());
        for device in [
            &lost,
            &lost,
            &Device::Reopened("WebGL2".into()),
            &Device::Ready,
        ] {
            link.heard(0.0, Some(device));
        }
        assert_eq!(link.device(), lost);
        assert_eq!(link.device(), Device::Reopened("WebGL2".into()));
        assert_eq!(link.device(), Device::Ready, "said once, then ready");
        assert_eq!(link.device(), Device::Ready);
    }

    #[test]
    fn a_fresh_canvas_is_asked_for_once_until_the_worker_says_something_else() {
        let mut link = DrawingLink::default();
        link.heard(0.0, Some(&Device::NeedsCanvas("lost".into())));
        assert_eq!(link.device(), Device::NeedsCanvas("lost".into()));
        assert_eq!(link.device(), Device::Reopening("lost".into()));
        link.heard(1.0, Some(&Device::Ready));
        link.heard(2.0, Some(&Device::NeedsCanvas("lost again".into())));
        link.device();
        assert_eq!(link.device(), Device::NeedsCanvas("lost again".into()));
    }

    #[test]
    fn a_device_lost_again_right_after_it_was_opened_again_gets_another_canvas() {
        let mut link = DrawingLink::default();
        link.heard(0.0, Some(&Device::NeedsCanvas("lost".into())));
        assert_eq!(link.device(), Device::NeedsCanvas("lost".into()));
        link.heard(1.0, Some(&Device::Reopened("WebGL2".into())));
        link.heard(2.0, Some(&Device::NeedsCanvas("lost again".into())));
        assert_eq!(link.device(), Device::Reopened("WebGL2".into()));
        assert_eq!(link.device(), Device::NeedsCanvas("lost again".into()));
    }

    #[test]
    fn a_worker_silent_for_long_while_frames_are_sent_is_taken_for_hung() {
        let mut link = DrawingLink::default();
        link.ticked(1000.0);
        assert!(link.took(false, 1000.0 + SILENT_MS).is_ok());
        let hung = link.took(false, 1001.0 + SILENT_MS).unwrap_err();
        assert_eq!(hung, "the drawing worker has not answered for 15 s");
        let mut answers = DrawingLink::default();
        answers.ticked(0.0);
        answers.took(true, 10_000.0).unwrap();
        answers.ticked(10_000.0);
        assert!(
            answers.took(false, 20_000.0).is_ok(),
            "waits from the frame after"
        );
    }

    #[test]
    fn a_worker_that_failed_has_its_device_gone() {
        let mut link = DrawingLink::default();
        link.failed("it threw".into());
        assert_eq!(link.device(), Device::Gone("it threw".into()));
    }
}
