//! What the page is doing, in words ("growing murex-pecten, row 312"), kept up to date by the
//! viewer and the app so that a panic can say what was being done when it happened.

use std::cell::RefCell;

thread_local! {
    static ACTIVITY: RefCell<String> = RefCell::new("starting".to_string());
}

/// Records what the page is doing now.
pub fn set(what: String) {
    ACTIVITY.with(|a| {
        if let Ok(mut a) = a.try_borrow_mut() {
            *a = what;
        }
    });
}

/// What the page says when the module panics (`info`), on its thread or the drawing worker's.
pub fn crash_words(info: &std::panic::PanicHookInfo<'_>) -> String {
    format!(
        "Something went wrong while {}: {info}. The page cannot go on; reloading the link starts \
         this shell again.",
        describe()
    )
}

/// What the page was doing last, in words.
pub fn describe() -> String {
    ACTIVITY.with(|a| {
        a.try_borrow()
            .map_or_else(|_| "working".to_string(), |a| a.clone())
    })
}
