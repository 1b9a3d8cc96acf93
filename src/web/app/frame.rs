//! One animation frame of the page: the workers' replies taken in, the viewer's frames and what
//! they report, the gallery's pictures or the map's and breeding's tiles, the address and the
//! readout, as the session decides.

use super::App;
use crate::web::activity;
use crate::web::clock::now;
use crate::web::page::{show_message, signal};
use crate::work::message::{Reply, Request};
use crate::work::session::{FrameTask, Hearing};
use crate::work::viewer_driver::PoolWorkers;

impl App {
    /// One animation frame.
    pub fn frame(&mut self) -> Result<(), String> {
        if self.viewer.crashed() {
            return Ok(());
        }
        if self.moving.is_some() {
            self.take_moved();
            self.workers.borrow_mut().send();
            return Ok(());
        }
        self.tell_shown();
        let outcome = self.work_and_draw();
        // What this frame asked goes out now, to be worked on before the next frame.
        self.workers.borrow_mut().send();
        if self.moving.is_none() {
            self.viewer.tick();
        }
        outcome
    }

    /// What a frame does: takes in the workers' replies, grows, draws.
    fn work_and_draw(&mut self) -> Result<(), String> {
        if !self.survive()? {
            // Nothing is taken in while the device is not ready, but a drawing worker that
            // failed or fell silent meanwhile is given up.
            if let Err(why) = self.viewer.answering() {
                self.fall_back(why);
            }
            return Ok(());
        }
        self.take_replies();
        let covered = self.covered();
        self.session.hold(covered, self.recording.is_some());
        self.apply();
        let taken = match self.viewer.frames() {
            Ok(taken) => taken,
            Err(why) => {
                self.fall_back(why);
                return Ok(());
            }
        };
        let recording = self.recording.is_some();
        let Hearing {
            task,
            reports,
            recorded,
        } = (self.session).hear(taken, covered, recording, now());
        for report in reports {
            self.downloads.show(report.file);
            if let Some(notice) = report.notice {
                show_message(&notice);
            }
            for update in report.planar {
                if let Some(planar) = &mut self.planar {
                    planar.apply(update);
                }
            }
        }
        self.apply();
        match task {
            FrameTask::Record => self.record_frame(recorded),
            FrameTask::Pictures => {
                self.pictures.work(&mut self.workers.borrow_mut());
                signal("pictures", self.pictures.signal());
            }
            FrameTask::Tiles => {
                if let Some(tile) = self.pictures.work(&mut self.workers.borrow_mut()) {
                    self.map.shown(tile, Ok(()));
                    self.breed.shown(tile, Ok(()));
                }
                activity::set("drawing the parameter map or the offspring".to_string());
            }
            FrameTask::Shown => {}
        }
        Ok(())
    }

    /// Takes in what the workers sent back: the shell's growth and pieces go to the viewer,
    /// gallery shells to the pictures; a worker replaced with the shell's session has it grown
    /// again where the page's copy stands once the replies it sent before are in.
    fn take_replies(&mut self) {
        let polled = self.workers.borrow_mut().poll();
        if let Some(replaced) = &polled.replaced {
            self.session.page_worker_replaced(replaced);
            self.apply();
        }
        let mut shell = Vec::new();
        for (request, reply) in polled.replies {
            match (request, reply) {
                (Request::Whole { job, .. }, Reply::Grown { result, .. }) => {
                    if let Some((tile, why)) = self.pictures.take(job, result) {
                        self.map.shown(tile, Err(why.clone()));
                        self.breed.shown(tile, Err(why));
                    }
                }
                (_, Reply::Tiled { job, result }) => self.map.take(job, result),
                answered => shell.push(answered),
            }
        }
        if let Err(why) = self.viewer.take_all(shell, polled.sessions_lost) {
            self.session.refused(why);
            self.apply();
        }
    }
}
