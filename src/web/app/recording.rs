//! Recording a video of the growth, as the page runs it: Record asks the browser once what it
//! can record with, then grows the shell from its apex and hands each frame the viewer draws to
//! the encoder (`web/record/`); the core says when Record may start and how a recording
//! ended (`work::recording`).

use super::App;
use super::fix_canvas;
use crate::view::recording::RecordingPlan;
use crate::web::clock::now;
use crate::web::dom;
use crate::web::page::{element, set_text, signal};
use crate::web::record::{self, Recording, Step};
use crate::web::webcodecs::VideoFrame;
use crate::work::recording::Ended;
use crate::work::viewer_command::ViewCommand;

impl App {
    /// Shows what the browser can record with, and refuses Record where it cannot.
    pub fn show_support(&self) {
        let support = self.support.borrow();
        signal("encoder", support.signal());
        set_text("record-status", &support.note());
        if let Some(button) = element("record") {
            dom::attr(&button, "aria-disabled", &support.refused().to_string());
        }
    }

    /// Grows the shell from its apex again and records every frame of its growth as a video,
    /// with the options chosen in the panel.
    pub fn record(&mut self) {
        if self.recording.is_some() {
            return;
        }
        let support = self.support.borrow().clone();
        if !support.may_record() {
            set_text("record-status", &support.note());
            return;
        }
        let Some((preset, spec)) = self.session.record(now()) else {
            return;
        };
        self.apply();
        let plan = RecordingPlan::new(
            spec.growth.rows_grown(),
            spec.growth.speed,
            record::options(),
        );
        let size = (plan.width, plan.height);
        match Recording::start(plan, preset.id, &support) {
            Ok(recording) => {
                self.viewer.command(ViewCommand::RecordAt(Some(size)));
                fix_canvas(true);
                signal("record", "recording");
                record::show_recording(Some(&recording));
                self.recording = Some(recording);
            }
            Err(e) => self.ended(Ended::NotStarted(e)),
        }
    }

    /// Stops a recording under way, keeping nothing of it, and says why.
    pub fn stop_recording(&mut self, why: &str) {
        if let Some(recording) = self.recording.take() {
            recording.cancel();
            self.ended(Ended::Cancelled(why.into()));
        }
    }

    /// A recording ended (or never began): the view goes back to the page's size and the page
    /// says how it ended.
    fn ended(&mut self, ended: Ended) {
        self.viewer.command(ViewCommand::RecordAt(None));
        fix_canvas(false);
        record::show_recording(None);
        signal("record", ended.signal());
        set_text("record-status", &ended.words());
    }

    /// One animation frame of a recording under way: the frame the viewer drew (`recorded`)
    /// goes to the encoder, the next is asked for (and worked on in the viewer's next frame).
    pub(super) fn record_frame(&mut self, recorded: Option<Result<VideoFrame, String>>) {
        let Some(recording) = &mut self.recording else {
            return;
        };
        let mut step = recording.step();
        if let Some(frame) = recorded
            && let Err(e) = recording.took(frame)
        {
            step = Step::Failed(e);
        }
        if let Step::Working = step {
            if let Some(ask) = recording.ask() {
                self.viewer.command(ViewCommand::AskFrame(ask));
            }
            record::show_recording(Some(recording));
            return;
        }
        let Some(recording) = self.recording.take() else {
            return;
        };
        let (frames, seconds) = (
            recording.plan().frames(),
            recording.plan().duration_us() as f64 / 1e6,
        );
        signal("recordFrames", &recording.frames_done().to_string());
        let ended = match step {
            Step::Done => match recording.save() {
                Ok(name) => Ended::Saved {
                    name,
                    frames,
                    seconds,
                },
                Err(e) => Ended::Failed(e),
            },
            Step::Failed(e) => {
                recording.cancel();
                Ended::Failed(e)
            }
            Step::Working => unreachable!("handled above"),
        };
        self.ended(ended);
    }
}
