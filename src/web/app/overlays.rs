//! The views over the shell: the parameter map and breeding, opened, drawn, left, and stepped
//! through with the keyboard.

use super::App;
use crate::share::lineage::Lineage;
use crate::variation::breeding;
use crate::web::clock::now;

impl App {
    /// Shows the parameter map of the shell shown.
    pub fn open_map(&mut self) {
        let shown = self.session.open_map(now());
        self.apply();
        if let Some((preset, spec)) = shown {
            self.map.open(
                preset,
                &spec,
                None,
                &mut self.workers.borrow_mut(),
                &mut self.pictures,
            );
        }
    }

    /// Draws the map anew over the axes its controls now describe.
    pub fn draw_map(&mut self) {
        if let Some((preset, spec)) = self.session.current() {
            self.map.draw(
                preset,
                spec,
                &mut self.workers.borrow_mut(),
                &mut self.pictures,
            );
        }
    }

    /// A parameter was chosen for the map's axis `name` ("x" or "y").
    pub fn map_chose(&mut self, name: &str) {
        self.map.chose(name);
    }

    pub fn close_map(&mut self) {
        self.map
            .close(&mut self.workers.borrow_mut(), &mut self.pictures);
    }

    /// Whether the map or breeding covers the shell.
    pub fn covered(&self) -> bool {
        self.map.is_open() || self.breed.is_open()
    }

    /// Breeds from the shell shown: it stands among its first eight offspring.
    pub fn open_breeding(&mut self) {
        if let Some((preset, spec)) = self.session.current() {
            let link = breeding::bred_link(preset, spec, &Lineage::default());
            let _ = web_sys::window().map(|w| w.location().set_hash(&link));
        }
    }

    /// The view over the shell closes (Escape): breeding leaves with its parent.
    pub fn escape(&mut self) {
        if self.breed.is_open() {
            self.breed.keep();
        } else {
            self.close_map();
        }
    }

    /// Moves the focus across the map's tiles or the offspring (arrow keys).
    pub fn step_tiles(&self, dx: i32, dy: i32) {
        if self.breed.is_open() {
            self.breed.step(dx, dy);
        } else {
            self.map.step(dx, dy);
        }
    }

    /// Back to the generation before.
    pub fn breed_back(&mut self) {
        self.breed.back();
    }

    /// Leaves breeding with the parent.
    pub fn breed_keep(&mut self) {
        self.breed.keep();
    }

    /// Breeds the generation shown again at `rate`.
    pub fn breed_rate(&mut self, rate: f64) {
        self.breed.set_rate(rate);
    }
}
