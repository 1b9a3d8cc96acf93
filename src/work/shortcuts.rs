//! The page's keyboard: which key does what, decided here so that a native test reads every
//! rule, and the page only translates a `keydown` into [`Press`] and applies the [`Shortcut`].
//!
//! The rules, in order: a key with Ctrl, Meta or Alt is the browser's; in a story Page Down and
//! Page Up (and, where no map covers the shell, → and ←) move to its next and previous step from
//! anywhere but a field, even when its shell could not be shown; without a shell shown (the
//! gallery) no key is the page's; over the map or the offspring the arrows move among the tiles
//! (but not in a text field or a choice) and Escape leaves them from any control; a key pressed
//! in a field, a button, a disclosure or a link is that control's; otherwise Space plays or
//! pauses, R restarts, S (or → outside a story) steps, E or End finishes, C resets the camera, V
//! switches the views, F goes full screen, + (or =) and − change the speed by half again.

/// The kind of element a key press goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// A field that takes text or a choice (`input`, `select`, `textarea`).
    Field,
    /// A control that takes Space or Enter itself (`button`, `summary`, `a`).
    Control,
    /// Anything else: the page, the canvas.
    Page,
}

impl Target {
    /// The kind of an element by its tag name (any case).
    pub fn of_tag(tag: &str) -> Self {
        match tag.to_ascii_lowercase().as_str() {
            "input" | "select" | "textarea" => Target::Field,
            "button" | "summary" | "a" => Target::Control,
            _ => Target::Page,
        }
    }
}

/// A key press, as the page reads it.
#[derive(Clone, Copy, Debug)]
pub struct Press<'a> {
    /// The key's value (`KeyboardEvent.key`).
    pub key: &'a str,
    /// Ctrl, Meta or Alt is held.
    pub modified: bool,
    /// Where the key goes.
    pub target: Target,
    /// A shell is shown (not the gallery).
    pub shell_shown: bool,
    /// The map or the offspring cover the shell.
    pub covered: bool,
    /// A story's step is shown.
    pub in_story: bool,
}

/// What a key press does; the page then keeps the browser from acting on it too.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shortcut {
    /// Moves among the map's or the offspring's tiles by `(dx, dy)`.
    Tiles(i32, i32),
    /// Leaves the map or breeding.
    Leave,
    PlayPause,
    Restart,
    Step,
    Finish,
    ResetCamera,
    ToggleViews,
    Fullscreen,
    /// Changes the growth speed.
    Speed(SpeedChange),
    /// To the story's next step (true) or its previous one.
    StoryStep(bool),
}

/// A press of + or −: the speed by half again, or back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpeedChange {
    Faster,
    Slower,
}

impl SpeedChange {
    /// The speed after this change of `speed` (the link then clamps it).
    pub fn of(self, speed: f64) -> f64 {
        match self {
            SpeedChange::Faster => speed * SPEED_STEP,
            SpeedChange::Slower => speed / SPEED_STEP,
        }
    }
}

/// How much one press of + or − changes the speed.
const SPEED_STEP: f64 = 1.5;

/// What `press` does, if anything (the rules are the module's).
pub fn shortcut(press: Press<'_>) -> Option<Shortcut> {
    if press.modified {
        return None;
    }
    // A story's step moves on even when its shell could not be shown.
    if press.in_story && press.target != Target::Field {
        match press.key {
            "PageDown" => return Some(Shortcut::StoryStep(true)),
            "PageUp" => return Some(Shortcut::StoryStep(false)),
            "ArrowRight" if !press.covered => return Some(Shortcut::StoryStep(true)),
            "ArrowLeft" if !press.covered => return Some(Shortcut::StoryStep(false)),
            _ => {}
        }
    }
    if !press.shell_shown {
        return None;
    }
    if press.covered {
        let arrow = match press.key {
            "ArrowLeft" => Some((-1, 0)),
            "ArrowRight" => Some((1, 0)),
            "ArrowUp" => Some((0, -1)),
            "ArrowDown" => Some((0, 1)),
            _ => None,
        };
        if let Some((dx, dy)) = arrow.filter(|_| press.target != Target::Field) {
            return Some(Shortcut::Tiles(dx, dy));
        }
        if press.key == "Escape" {
            return Some(Shortcut::Leave);
        }
    }
    if press.target != Target::Page {
        return None;
    }
    Some(match press.key {
        " " => Shortcut::PlayPause,
        "r" => Shortcut::Restart,
        "s" | "ArrowRight" => Shortcut::Step,
        "e" | "End" => Shortcut::Finish,
        "c" => Shortcut::ResetCamera,
        "v" => Shortcut::ToggleViews,
        "f" => Shortcut::Fullscreen,
        "+" | "=" => Shortcut::Speed(SpeedChange::Faster),
        "-" => Shortcut::Speed(SpeedChange::Slower),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn press(key: &str, target: Target, covered: bool) -> Press<'_> {
        Press {
            key,
            modified: false,
            target,
            shell_shown: true,
            covered,
            in_story: false,
        }
    }

    #[test]
    fn the_viewer_keys_play_step_finish_and_change_the_speed() {
        let on_page = |key| shortcut(press(key, Target::Page, false));
        assert_eq!(on_page(" "), Some(Shortcut::PlayPause));
        assert_eq!(on_page("r"), Some(Shortcut::Restart));
        assert_eq!(on_page("s"), Some(Shortcut::Step));
        assert_eq!(on_page("ArrowRight"), Some(Shortcut::Step));
        assert_eq!(on_page("e"), Some(Shortcut::Finish));
        assert_eq!(on_page("End"), Some(Shortcut::Finish));
        assert_eq!(on_page("c"), Some(Shortcut::ResetCamera));
        assert_eq!(on_page("v"), Some(Shortcut::ToggleViews));
        assert_eq!(on_page("f"), Some(Shortcut::Fullscreen));
        assert_eq!(on_page("+"), Some(Shortcut::Speed(SpeedChange::Faster)));
        assert_eq!(on_page("="), Some(Shortcut::Speed(SpeedChange::Faster)));
        assert_eq!(on_page("-"), Some(Shortcut::Speed(SpeedChange::Slower)));
        assert_eq!(SpeedChange::Faster.of(2.0), 3.0);
        assert_eq!(SpeedChange::Slower.of(3.0), 2.0);
        assert_eq!(on_page("x"), None);
    }

    #[test]
    fn a_key_is_the_browsers_with_a_modifier_and_no_ones_in_the_gallery() {
        let mut with_ctrl = press("r", Target::Page, false);
        with_ctrl.modified = true;
        assert_eq!(shortcut(with_ctrl), None, "Ctrl+R reloads");
        let mut gallery = press(" ", Target::Page, false);
        gallery.shell_shown = false;
        assert_eq!(shortcut(gallery), None, "Space scrolls the gallery");
    }

    #[test]
    fn a_control_keeps_its_keys_and_a_field_its_arrows() {
        assert_eq!(shortcut(press(" ", Target::Control, false)), None);
        assert_eq!(shortcut(press("r", Target::Field, false)), None);
        assert_eq!(shortcut(press("ArrowRight", Target::Field, false)), None);
        assert_eq!(
            shortcut(press("ArrowLeft", Target::Field, true)),
            None,
            "a field over the map keeps its caret"
        );
    }

    #[test]
    fn over_the_map_the_arrows_move_among_tiles_and_escape_leaves_from_any_control() {
        assert_eq!(
            shortcut(press("ArrowRight", Target::Page, true)),
            Some(Shortcut::Tiles(1, 0)),
            "not a step of growth"
        );
        assert_eq!(
            shortcut(press("ArrowUp", Target::Control, true)),
            Some(Shortcut::Tiles(0, -1))
        );
        assert_eq!(
            shortcut(press("Escape", Target::Field, true)),
            Some(Shortcut::Leave)
        );
        assert_eq!(
            shortcut(press("Escape", Target::Page, true)),
            Some(Shortcut::Leave)
        );
        assert_eq!(
            shortcut(press(" ", Target::Page, true)),
            Some(Shortcut::PlayPause),
            "the other keys still work the viewer behind"
        );
        assert_eq!(shortcut(press("Escape", Target::Page, false)), None);
    }

    #[test]
    fn in_a_story_the_arrows_and_page_keys_move_between_steps() {
        let story = |key, target, covered| {
            shortcut(Press {
                in_story: true,
                ..press(key, target, covered)
            })
        };
        assert_eq!(
            story("ArrowRight", Target::Page, false),
            Some(Shortcut::StoryStep(true))
        );
        assert_eq!(
            story("ArrowLeft", Target::Page, false),
            Some(Shortcut::StoryStep(false))
        );
        assert_eq!(story("s", Target::Page, false), Some(Shortcut::Step));
        assert_eq!(
            story("PageDown", Target::Control, false),
            Some(Shortcut::StoryStep(true)),
            "from the story's own buttons too"
        );
        assert_eq!(
            story("PageUp", Target::Page, true),
            Some(Shortcut::StoryStep(false)),
            "over a step's map"
        );
        assert_eq!(
            story("ArrowRight", Target::Page, true),
            Some(Shortcut::Tiles(1, 0)),
            "over a step's map the arrows move among its tiles"
        );
        assert_eq!(story("PageDown", Target::Field, false), None);
        assert_eq!(
            story("ArrowLeft", Target::Control, false),
            Some(Shortcut::StoryStep(false)),
            "from Next or Back, just clicked"
        );
        assert_eq!(story("ArrowLeft", Target::Field, false), None);
        let refused = Press {
            in_story: true,
            shell_shown: false,
            ..press("ArrowRight", Target::Page, false)
        };
        assert_eq!(
            shortcut(refused),
            Some(Shortcut::StoryStep(true)),
            "a step whose shell was refused still moves on"
        );
    }

    #[test]
    fn an_elements_kind_is_read_from_its_tag_in_any_case() {
        assert_eq!(Target::of_tag("INPUT"), Target::Field);
        assert_eq!(Target::of_tag("select"), Target::Field);
        assert_eq!(Target::of_tag("BUTTON"), Target::Control);
        assert_eq!(Target::of_tag("A"), Target::Control);
        assert_eq!(Target::of_tag("CANVAS"), Target::Page);
    }
}
