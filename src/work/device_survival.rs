//! How a viewer keeps its graphics device when the browser takes it away (a WebGPU device lost
//! or destroyed, a driver reset, a WebGL context lost), decided without a device: a lost WebGL
//! context is given [`RESTORE_WAIT_MS`] to come back; then a renderer is opened again on the
//! same canvas when its context can still be had (WebGPU's, or a WebGL context the browser
//! gave back), else — or when that fails: WebGPU gone for good leaves only WebGL2, which a
//! canvas that once had a WebGPU context cannot give — on a fresh canvas the page makes; when
//! that fails too, the device is gone for good, said once with both reasons. A viewer
//! follows it through [`super::viewer_driver::ViewerDriver::survive`]: its screen
//! (`web/viewer/screen.rs`) opens what this asks for and reports the answers; the simulator
//! (`tests/simulator.rs`) loses and restores devices in any order against the same driver.

use super::viewer_status::Device;

/// Milliseconds a lost WebGL context is given to come back before a fresh canvas is used.
pub const RESTORE_WAIT_MS: f64 = 1500.0;

/// What the renderer says of its device this frame, when it lost it.
#[derive(Clone, Debug, PartialEq)]
pub struct Loss {
    /// Why, in the browser's words.
    pub reason: String,
    /// The browser gave a lost WebGL context back (`webglcontextrestored`).
    pub restored: bool,
    /// The renderer draws with WebGL2 (whose context may come back), not WebGPU.
    pub webgl: bool,
}

/// What the runner is to do for the device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Open {
    /// Open a renderer on the same canvas.
    Same,
    /// Open a renderer on the fresh canvas it was given.
    Fresh,
}

/// Where the device stands.
#[derive(Clone, Debug, Default, PartialEq)]
enum Stage {
    #[default]
    Ready,
    /// A WebGL context lost since this time, which the browser may give back.
    Waiting { since: f64 },
    /// Opening on the same canvas.
    Same,
    /// Waiting for the page's fresh canvas; why the same one failed, if it was tried.
    NeedsCanvas { first: Option<String> },
    /// Opening on the fresh canvas; why the same one failed, if it was tried.
    Fresh { first: Option<String> },
    /// No renderer could be opened again: why.
    Gone(String),
}

/// A viewer's graphics device, kept.
#[derive(Debug, Default)]
pub struct Survival {
    stage: Stage,
    /// Why the device was lost, for the words said while it is opened again.
    reason: String,
}

impl Survival {
    /// Once a frame, before anything is drawn, at `now`: `loss` is what the renderer says of
    /// its device (`None`: it draws), `answer` the answer to an opening asked for and not yet
    /// answered, if the browser has given it. Returns the device's state for the page and
    /// what the runner is to open, if anything; [`Device::Reopened`] once a renderer opened
    /// again is to take the old one's place (and be handed everything grown so far).
    pub fn frame(
        &mut self,
        now: f64,
        loss: Option<&Loss>,
        answer: Option<Result<(), String>>,
    ) -> (Device, Option<Open>) {
        match (&mut self.stage, answer) {
            (Stage::Gone(why), _) => return (Device::Gone(why.clone()), None),
            (Stage::Same, Some(Ok(()))) | (Stage::Fresh { .. }, Some(Ok(()))) => {
                self.stage = Stage::Ready;
                return (Device::Reopened(String::new()), None);
            }
            (Stage::Same, Some(Err(e))) => {
                self.stage = Stage::NeedsCanvas { first: Some(e) };
                return (Device::NeedsCanvas(self.reason.clone()), None);
            }
            (Stage::Fresh { first }, Some(Err(e))) => {
                let tried = match first.take() {
                    Some(first) => format!("{first} On a fresh canvas: {e}"),
                    None => e,
                };
                let gone = format!(
                    "The graphics device was lost ({}) and none could be opened again: {tried}",
                    self.reason
                );
                self.stage = Stage::Gone(gone.clone());
                return (Device::Gone(gone), None);
            }
            (Stage::NeedsCanvas { .. }, _) => {
                return (Device::NeedsCanvas(self.reason.clone()), None);
            }
            (Stage::Same | Stage::Fresh { .. }, None) => {
                return (Device::Reopening(self.reason.clone()), None);
            }
            (Stage::Ready | Stage::Waiting { .. }, _) => {}
        }
        let Some(loss) = loss else {
            self.stage = Stage::Ready;
            return (Device::Ready, None);
        };
        self.reason.clone_from(&loss.reason);
        let since = match self.stage {
            Stage::Waiting { since } => since,
            _ => now,
        };
        if loss.webgl && !loss.restored && now - since < RESTORE_WAIT_MS {
            // The browser may give the context back (webglcontextrestored): wait a little.
            self.stage = Stage::Waiting { since };
            return (Device::Reopening(loss.reason.clone()), None);
        }
        if loss.webgl && !loss.restored {
            self.stage = Stage::NeedsCanvas { first: None };
            return (Device::NeedsCanvas(loss.reason.clone()), None);
        }
        self.stage = Stage::Same;
        (Device::Reopening(loss.reason.clone()), Some(Open::Same))
    }

    /// The page gave the fresh canvas asked for ([`Device::NeedsCanvas`]): a renderer is to be
    /// opened on it. A canvas given when none was asked for (twice, say) opens nothing.
    pub fn canvas_given(&mut self) -> Option<Open> {
        let Stage::NeedsCanvas { first } = &mut self.stage else {
            return None;
        };
        self.stage = Stage::Fresh {
            first: first.take(),
        };
        Some(Open::Fresh)
    }

    /// Whether a renderer is being opened again (nothing is drawn meanwhile).
    pub fn reopening(&self) -> bool {
        !matches!(self.stage, Stage::Ready)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn webgl(restored: bool) -> Loss {
        Loss {
            reason: "context lost".into(),
            restored,
            webgl: true,
        }
    }

    #[test]
    fn a_lost_webgl_context_is_waited_for_then_a_fresh_canvas_asked_for() {
        let mut survival = Survival::default();
        let lost = webgl(false);
        assert_eq!(
            survival.frame(0.0, Some(&lost), None),
            (Device::Reopening("context lost".into()), None)
        );
        assert_eq!(survival.frame(1000.0, Some(&lost), None).1, None);
        let (device, open) = survival.frame(1500.0, Some(&lost), None);
        assert_eq!(
            (device, open),
            (Device::NeedsCanvas("context lost".into()), None)
        );
        assert_eq!(survival.canvas_given(), Some(Open::Fresh));
        assert_eq!(
            survival.canvas_given(),
            None,
            "a second canvas opens nothing"
        );
        assert_eq!(
            survival.frame(1600.0, None, None).0,
            Device::Reopening("context lost".into())
        );
        assert_eq!(
            survival.frame(1700.0, None, Some(Ok(()))).0,
            Device::Reopened(String::new())
        );
        assert_eq!(survival.frame(1800.0, None, None).0, Device::Ready);
    }

    #[test]
    fn a_context_given_back_is_opened_on_the_same_canvas_and_a_failure_there_asks_a_fresh_one() {
        let mut survival = Survival::default();
        survival.frame(0.0, Some(&webgl(false)), None);
        let (_, open) = survival.frame(100.0, Some(&webgl(true)), None);
        assert_eq!(open, Some(Open::Same));
        let (device, open) = survival.frame(200.0, None, Some(Err("no context".into())));
        assert_eq!(
            (device, open),
            (Device::NeedsCanvas("context lost".into()), None)
        );
        assert_eq!(survival.canvas_given(), Some(Open::Fresh));
        let (device, _) = survival.frame(300.0, None, Some(Err("no adapter".into())));
        let Device::Gone(why) = device else {
            panic!("{device:?}")
        };
        assert!(
            why.contains("no context On a fresh canvas: no adapter"),
            "{why}"
        );
        assert!(matches!(
            survival.frame(400.0, None, None).0,
            Device::Gone(_)
        ));
    }

    #[test]
    fn a_lost_webgpu_device_is_opened_again_at_once() {
        let mut survival = Survival::default();
        let lost = Loss {
            reason: "destroyed".into(),
            restored: false,
            webgl: false,
        };
        assert_eq!(survival.frame(0.0, Some(&lost), None).1, Some(Open::Same));
        assert!(survival.reopening());
        assert_eq!(
            survival.frame(10.0, None, Some(Ok(()))).0,
            Device::Reopened(String::new())
        );
        assert!(!survival.reopening());
    }
}
